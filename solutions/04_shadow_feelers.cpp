// SOLUTION BEGIN
// Chapter 04, shadow feelers: the reference solution.
//
// This file is also the source of exercises/04_shadow_feelers.cpp: the kit's cutter drops every
// block between SOLUTION BEGIN and SOLUTION END and keeps the STUB lines as code
// (`cmake --build <build> --target cut_exercises`; a test checks that the two agree).
// SOLUTION END
// STUB // Chapter 04, shadow feelers: your exercises.
// STUB //
// STUB // Each function below states what to compute (not how); its contract is documented in
// STUB // chapters/04_shadow_feelers/04_shadow_feelers.hpp and the lesson in that folder's README.md.
// STUB // Each stub compiles and returns a harmless value, so the chapter's program always runs.
// STUB // Check your work with:  cmake --build --preset grade --target check_04
// STUB // Stuck? Hints in tiers you open one at a time: chapters/04_shadow_feelers/hints.md, or
// STUB // ./build/grade/hint 04.1 (tier 1, the idea), ./build/grade/hint 04.1 2 (the trap), ... 3 (the walk-through).
// STUB //
// STUB // This chapter uses chapters 01 and 02 only: the intersection tests of chapter 02 (through
// STUB // hit_sphere and hit_triangle) and its normals.
#include "04_shadow_feelers/04_shadow_feelers.hpp"
// STUB #include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises
#include "04_shadow_feelers/radiance.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace rt {

color local_shading(const PhongMaterial& m, const vec3& n, const vec3& to_eye, const vec3& to_light, const color& light)
{
    // EXERCISE 04.1: Blinn-Phong for one light
    // Return what m reflects toward the eye from one light: Lambert's diffuse term plus Blinn's
    // halfway-vector highlight, times `light` (already divided by d^2). n, to_eye, to_light: unit.
    // A light not above the surface (n.to_light <= 0) gives black, highlight included. With to_light
    // exactly opposite to_eye there is no halfway vector and no highlight: the diffuse term alone,
    // never a NaN. Lesson: "Computing the colour of the pixel (EXERCISE 04.1)"
    // Stuck? hint 04.1 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    const float cos_light = glm::dot(n, to_light);
    if (!(cos_light > 0.0f))
        return color(0.0f);
    color reflected = m.diffuse * cos_light;
    const vec3 halfway = to_light + to_eye;
    // l = -v has no halfway vector; normalising 0 would give a NaN.
    if (glm::dot(halfway, halfway) > 0.0f) {
        const float cos_half = glm::dot(n, glm::normalize(halfway));
        if (cos_half > 0.0f)
            reflected += m.specular * std::pow(cos_half, m.shininess);
    }
    return light * reflected;
    // SOLUTION END
    // STUB return stub("04.1", color(0.0f));
}

bool occluded(const LitScene& scene, const point3& origin, const point3& light, float t_min)
{
    // EXERCISE 04.2: the any-hit shadow feeler
    // Return true when any sphere, triangle or cone of the scene lies between origin and the light:
    // t strictly above t_min and strictly below the light's distance less shadow_epsilon of it. Any
    // occluder will do, so stop at the first; the grader counts your intersection tests (the counted
    // ones the contract names, each object asked at most once). Lesson: "The shadow feeler
    // (EXERCISE 04.2)"
    // Stuck? hint 04.2 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    const vec3 to_light = light - origin;
    const float distance = glm::length(to_light);
    const Ray feeler{origin, to_light / distance};
    const Interval range{t_min, distance * (1.0f - shadow_epsilon)};
    for (const Sphere& sphere : scene.spheres)
        if (hit_sphere(feeler, sphere, range, lit_tests.sphere))
            return true;
    for (const Triangle& tri : scene.triangles)
        if (hit_triangle(feeler, tri, range, lit_tests.triangle))
            return true;
    for (const Cone& cone : scene.cones)
        if (hit_cone_counted(feeler, cone, range))
            return true;
    return false;
    // SOLUTION END
    // STUB return stub("04.2", false);
}

point3 offset_ray_origin(const point3& p, const vec3& n, const vec3& dir)
{
    // EXERCISE 04.3: Wachter and Binder's robust ray origin
    // Return p moved off its surface, to the side that dir leaves toward, by a step that scales
    // with p: per coordinate, exactly int(offset_int_scale n_i) floats (truncated toward 0), up or
    // down as n_i's sign says, n turned to dir's side; or the fixed offset_float_scale step where
    // |p_i| < offset_origin. The grader checks the bits exactly. Lesson: "The robust offset
    // (EXERCISE 04.3)"
    // Stuck? hint 04.3 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    const vec3 out = glm::dot(n, dir) < 0.0f ? -n : n;
    point3 moved;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(p[i]) < offset_origin) {
            moved[i] = p[i] + offset_float_scale * out[i];
            continue;
        }
        const auto ulps = static_cast<std::int32_t>(offset_int_scale * out[i]);
        std::int32_t bits;
        std::memcpy(&bits, &p[i], sizeof bits);
        bits += p[i] < 0.0f ? -ulps : ulps;
        std::memcpy(&moved[i], &bits, sizeof bits);
    }
    return moved;
    // SOLUTION END
    // STUB return stub("04.3", p);
}

color shade(const LitScene& scene, const Ray& ray, const Hit& hit, const FeelerSettings& feelers)
{
    // EXERCISE 04.4: the colour of a hit, every light with its feeler
    // Return the ambient term plus your local_shading for each light that is strictly on the side of
    // the surface the eye sees and that light_blocked does not hide, its intensity falling off as
    // 1 / d^2. Send a feeler only for a light that could light the point (the grader counts them);
    // a light in the surface's plane or at the point itself adds nothing.
    // Lesson: "Putting it together (EXERCISE 04.4)"
    // Stuck? hint 04.4 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    const PhongMaterial& m = scene.material_of(hit.object);
    const vec3 n = glm::dot(hit.n, ray.dir) > 0.0f ? -hit.n : hit.n;
    const vec3 to_eye = -ray.dir;
    color c = m.diffuse * scene.ambient;
    for (const PointLight& light : scene.lights) {
        const vec3 to_light = light.position - hit.p;
        const float d2 = glm::dot(to_light, to_light);
        if (!(d2 > 0.0f))
            continue;  // a light at the point itself: no direction to it, and intensity / 0 is infinite
        const vec3 l = to_light / std::sqrt(d2);
        // A feeler costs a ray: send it only for a light that could light the point.
        if (glm::dot(n, l) <= 0.0f || light_blocked(scene, hit, light.position, feelers))
            continue;
        c += local_shading(m, n, to_eye, l, light.intensity / d2);
    }
    return c;
    // SOLUTION END
    // STUB return stub("04.4", color(0.0f));
}

}  // namespace rt
