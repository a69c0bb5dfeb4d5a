// Small scenes whose trace can be worked out by hand, for EXERCISE 03.5: a dull wall, a mirror
// floor before a wall, two mirrors facing each other (a ray between them bounces forever, unless
// the recursion stops it), and a glass sphere. The sky is one colour and the sun has no glow, so
// every ray that escapes sees the same colour.
#pragma once

#include "03_reflection_refraction/03_reflection_refraction.hpp"
#include "tests/grader/graded.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>

namespace rt::grader::traces {

const color sky{0.2f, 0.3f, 0.8f};
const color ambient{0.2f};
const color sun_colour{0.8f};

inline WhittedScene empty_scene(const vec3& to_sun = glm::normalize(vec3(0.2f, 1.0f, 0.5f)))
{
    WhittedScene scene;
    scene.shapes.background = sky;
    scene.zenith = sky;
    scene.sun.to_sun = to_sun;
    scene.sun.colour = sun_colour;
    scene.sun.glow = 0.0f;
    scene.ambient = ambient;
    return scene;
}

// A square of two triangles centred at `centre`, reaching `half` along the unit vectors a and b;
// its normal is a x b. (Rays in the tests keep off its diagonal, the edge its triangles share.)
inline void add_square(WhittedScene& scene, const point3& centre, const vec3& a, const vec3& b, float half,
                       const color& albedo, const Material& material)
{
    const point3 p00 = centre - half * a - half * b, p10 = centre + half * a - half * b;
    const point3 p11 = centre + half * a + half * b, p01 = centre - half * a + half * b;
    scene.add_triangle({p00, p10, p11}, albedo, material);
    scene.add_triangle({p00, p11, p01}, albedo, material);
}

inline Material mirror(float k_s)
{
    Material m;
    m.mirror = k_s;
    return m;
}

inline Material glass(float ior, float transparency = 1.0f)
{
    Material m;
    m.transparency = transparency;
    m.ior = ior;
    return m;
}

// The scene most of 03.5's cases look at: a square of one material, 4 across, centred on the -z
// axis at z = -5 (normal +z), and the ray that meets it head-on from (0.3, 0.2, 0).
const color square_albedo{0.6f, 0.5f, 0.3f};
const Ray head_on{{0.3f, 0.2f, 0}, {0, 0, -1}};

inline void add_square_across(WhittedScene& scene, float z, const color& albedo, const Material& material)
{
    add_square(scene, {0, 0, z}, {1, 0, 0}, {0, 1, 0}, 2.0f, albedo, material);
}

inline WhittedScene square_ahead(const Material& material)
{
    WhittedScene scene = empty_scene();
    add_square_across(scene, -5.0f, square_albedo, material);
    return scene;
}

inline TraceSettings with_min_weight(float min_weight)
{
    TraceSettings settings;
    settings.min_weight = min_weight;
    return settings;
}

// Whitted's local term by hand: albedo (ambient + max(0, n.L) sun), n facing the ray.
inline color lit(const WhittedScene& scene, const color& albedo, const vec3& n_facing_ray)
{
    return albedo * (scene.ambient + std::max(0.0f, glm::dot(n_facing_ray, scene.sun.to_sun)) * scene.sun.colour);
}

// Two mirrors facing each other across z = 0 (normal +z) and z = -2 (normal -z), lit only by the
// ambient light (the sun shines along them), so every bounce adds albedo * ambient.
const color mirror_albedo{0.5f, 0.4f, 0.3f};

inline WhittedScene facing_mirrors(float k_s)
{
    WhittedScene scene = empty_scene({0, 1, 0});
    add_square(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 2.0f, mirror_albedo, mirror(k_s));
    add_square(scene, {0, 0, -2}, {0, 1, 0}, {1, 0, 0}, 2.0f, mirror_albedo, mirror(k_s));
    return scene;
}

// A ray between them, square to both.
const Ray between_mirrors{{0.3f, 0.1f, -1.0f}, {0, 0, -1}};

// A glass sphere of radius 1 at (0, 0, -3), seen from the origin.
inline WhittedScene glass_sphere(float ior)
{
    WhittedScene scene = empty_scene();
    scene.add_sphere({{0, 0, -3}, 1}, color(0.0f), glass(ior));
    return scene;
}

struct Rays {
    std::uint64_t reflected, refracted;
};

inline Rays secondary_rays()
{
    const Counts c = total_counts();
    return {c[static_cast<size_t>(Counter::reflected_rays)], c[static_cast<size_t>(Counter::refracted_rays)]};
}

inline std::string show(const TraceSettings& s)
{
    std::ostringstream out;
    out << "max_depth = " << s.max_depth << ", min_weight = " << s.min_weight << ", "
        << (s.fresnel == FresnelModel::exact ? "exact Fresnel" : "Schlick");
    return out.str();
}

inline std::string show(const Rays& r)
{
    return std::to_string(r.reflected) + " reflected and " + std::to_string(r.refracted) + " refracted rays";
}

// Traces `ray` with fresh counters; says what went in and came out.
struct Traced {
    color colour;
    Rays rays;
    std::string report;
};

inline Traced run(const WhittedScene& scene, const Ray& ray, const TraceSettings& settings)
{
    reset_counters();
    Traced t;
    t.colour = trace(scene, ray, settings);
    t.rays = secondary_rays();
    t.report = "trace(" + grader::show(ray) + ", " + show(settings) + ") returned " + grader::show(t.colour) +
               " after " + show(t.rays);
    return t;
}

inline bool near(const color& a, const color& b, float tolerance = 1e-5f)
{
    return glm::length(a - b) <= tolerance;
}

}  // namespace rt::grader::traces
