// Chapter 04's tests in words: materials, lights, scenes and feelers, so that a failure names what
// went in, what was expected and what came back.
#pragma once

#include "04_shadow_feelers/radiance.hpp"
#include "04_shadow_feelers/self_intersection.hpp"
#include "tests/grader/graded.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>

namespace rt::grader {

inline std::string show(const PhongMaterial& m)
{
    std::ostringstream s;
    s << "the material k_d = " << show(m.diffuse) << ", k_s = " << show(m.specular) << ", p = " << m.shininess;
    return s.str();
}

inline std::string show(const Sphere& sphere)
{
    std::ostringstream s;
    s.precision(9);
    s << "the sphere at " << show(sphere.centre) << " of radius " << sphere.radius;
    return s.str();
}

inline std::string show(const Triangle& tri)
{
    return "the triangle " + show(tri.a) + ", " + show(tri.b) + ", " + show(tri.c);
}

inline std::string show(const Cone& cone)
{
    std::ostringstream s;
    s.precision(9);
    s << "the open cone from " << show(cone.base) << " (radius " << cone.base_radius << ") to " << show(cone.apex)
      << " (radius " << cone.apex_radius << ")";
    return s.str();
}

// The scene's objects, or how many when there are too many to list.
inline std::string show(const LitScene& scene)
{
    if (scene.spheres.size() + scene.triangles.size() + scene.cones.size() > 4) {
        std::ostringstream s;
        s << scene.spheres.size() << " spheres, " << scene.triangles.size() << " triangles and " << scene.cones.size()
          << " cones";
        return s.str();
    }
    std::string s;
    for (const Sphere& sphere : scene.spheres)
        s += (s.empty() ? "" : " and ") + show(sphere);
    for (const Triangle& tri : scene.triangles)
        s += (s.empty() ? "" : " and ") + show(tri);
    for (const Cone& cone : scene.cones)
        s += (s.empty() ? "" : " and ") + show(cone);
    return s.empty() ? "an empty scene" : s;
}

inline std::string show(bool blocked)
{
    return blocked ? "blocked (true)" : "not blocked (false)";
}

// Colours equal to 1e-5 relative per channel (1e-7 absolute near 0): float rounding of the same formula.
inline bool same_colour(const color& got, const color& want)
{
    for (int k = 0; k < 3; ++k)
        if (!(std::abs(got[k] - want[k]) <= 1e-5f * std::abs(want[k]) + 1e-7f))
            return false;
    return true;
}

inline std::uint32_t bits_of(float x)
{
    std::uint32_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

// A float and its bit pattern, for the offset's failures.
inline std::string show_bits(float x)
{
    std::ostringstream s;
    s.precision(9);
    s << x << " (bits 0x" << std::hex << bits_of(x) << ')';
    return s.str();
}

inline std::string show(const self_intersection::Feeler& f)
{
    return "the feeler from " + show(f.ray.origin) + " along " + show(f.ray.dir) + " (it left the point " +
           show(f.from.p) + " with normal " + show(f.from.n) + ")";
}

// A scene of objects of one plain material.
inline LitScene scene_of(const std::vector<Sphere>& spheres, const std::vector<Triangle>& triangles,
                         const std::vector<Cone>& cones = {})
{
    LitScene scene;
    const int m = scene.add_material({color(0.5f), color(0.0f), 1.0f});
    for (const Sphere& s : spheres)
        scene.add_sphere(s, m);
    for (const Triangle& t : triangles)
        scene.add_triangle(t, m);
    for (const Cone& c : cones)
        scene.add_cone(c, m);
    return scene;
}

// A square of side 2 h centred on `centre`, in the plane y = centre.y, as two triangles facing +y.
inline std::vector<Triangle> square_facing_up(const point3& centre, float h)
{
    const point3 a = centre + vec3(-h, 0, h), b = centre + vec3(h, 0, h), c = centre + vec3(h, 0, -h),
                 d = centre + vec3(-h, 0, -h);
    return {{a, b, c}, {a, c, d}};
}

}  // namespace rt::grader
