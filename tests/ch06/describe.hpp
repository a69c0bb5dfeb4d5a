// Chapter 06's tests in words and numbers: lenses, cameras and points of the disc, the exact
// answers the tests compare with (worked in double), and seeded random cameras, so that a failure
// names what went in, what was expected and what came back.
#pragma once

#include "01_ray_casting/01_ray_casting.hpp"
#include "06_depth_of_field/06_depth_of_field.hpp"
#include "tests/grader/graded.hpp"

#include <cmath>
#include <sstream>
#include <string>

namespace rt::grader {

inline std::string show(const point2& p)
{
    std::ostringstream s;
    s.precision(9);
    s << '(' << p.x << ", " << p.y << ')';
    return s.str();
}

inline std::string show(const ThinLens& lens)
{
    std::ostringstream s;
    s.precision(9);
    s << "a lens of radius R = " << lens.aperture_radius << " focused at F = " << lens.focus_distance;
    return s.str();
}

inline std::string show(const Camera& cam)
{
    std::ostringstream s;
    s.precision(9);
    s << "the camera at " << show(cam.eye) << " (u = " << show(cam.u) << ", v = " << show(cam.v) << ", w = " << show(cam.w)
      << ", window [" << cam.l << ", " << cam.r << "] x [" << cam.b << ", " << cam.t << "], " << cam.nx << "x" << cam.ny
      << " pixels)";
    return s.str();
}

inline bool finite(const vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

inline dvec3 to_double(const vec3& v) { return dvec3(v); }

// Shirley and Chiu's concentric map worked in double: the answer EXERCISE 06.1 rounds.
inline glm::dvec2 concentric_reference(point2 square)
{
    const double a = 2.0 * double(square.x) - 1.0, b = 2.0 * double(square.y) - 1.0;
    if (a == 0.0 && b == 0.0)
        return {0.0, 0.0};
    const double quarter = pi / 4.0;
    const bool wide = std::abs(a) >= std::abs(b);
    const double r = wide ? a : b;
    const double phi = wide ? quarter * (b / a) : 2.0 * quarter - quarter * (a / b);
    return {r * std::cos(phi), r * std::sin(phi)};
}

// Where a ray from the eye along the unit vector `dir` meets the plane F in front of the eye
// (along -w), in double: eye + (F / dir.(-w)) dir.
inline dvec3 focal_point_reference(const Camera& cam, double focus, const vec3& dir)
{
    const dvec3 d = glm::normalize(to_double(dir));
    return to_double(cam.eye) + (focus / glm::dot(d, -to_double(cam.w))) * d;
}

// The point of `ray` at depth `depth` in front of the eye (along -w), in double.
inline dvec3 at_depth(const Camera& cam, const Ray& ray, double depth)
{
    const dvec3 o = to_double(ray.origin), d = to_double(ray.dir), back = to_double(cam.w);
    const double t = (depth - glm::dot(o - to_double(cam.eye), -back)) / glm::dot(d, -back);
    return o + t * d;
}

// A seeded camera somewhere in a box `spread` wide around `centre`, looking any way but straight
// up or down, with a field of view between 20 and 100 degrees, 64x48 pixels.
inline Camera random_camera(Rng& rng, float spread = 10.0f, const point3& centre = point3(0.0f))
{
    const auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * rng.next_float(); };
    CameraSpec spec;
    spec.from = centre + spread * point3(uniform(-0.5f, 0.5f), uniform(-0.5f, 0.5f), uniform(-0.5f, 0.5f));
    const vec3 look{uniform(-1.0f, 1.0f), uniform(-0.6f, 0.6f), uniform(-1.0f, 1.0f)};
    spec.at = spec.from + (glm::length(look) > 0.1f ? look : vec3(0.0f, 0.0f, -1.0f));
    spec.up = {0.0f, 1.0f, 0.0f};
    spec.vfov_degrees = uniform(20.0f, 100.0f);
    spec.width = 64;
    spec.height = 48;
    return make_camera(spec);
}

// A seeded case for the thin-lens ray: a random camera, a lens of radius 0.05 to 0.55 focused
// 0.5 to 20.5 in front of it, and a pixel position anywhere in its 64x48 image.
struct LensCase {
    Camera cam;
    ThinLens lens;
    float x, y;
};

inline LensCase random_lens_case(Rng& rng)
{
    LensCase c{random_camera(rng), {}, 0.0f, 0.0f};
    c.lens = {0.05f + 0.5f * rng.next_float(), 0.5f + 20.0f * rng.next_float()};
    c.x = 63.0f * rng.next_float();
    c.y = 47.0f * rng.next_float();
    return c;
}

inline std::string show(const LensCase& c)
{
    std::ostringstream s;
    s.precision(9);
    s << show(c.cam) << ", " << show(c.lens) << ", pixel position (" << c.x << ", " << c.y << ")";
    return s.str();
}

}  // namespace rt::grader
