// SOLUTION BEGIN
// Chapter 04, shadow feelers: the reference solution.
//
// This file is also the source of exercises/04_shadow_feelers.cpp: the kit's cutter drops every
// block between SOLUTION BEGIN and SOLUTION END and keeps the STUB lines as code
// (`cmake --build <build> --target cut_exercises`; a test checks that the two agree).
// SOLUTION END
// STUB // Chapter 04, shadow feelers: your exercises.
// STUB //
// STUB // Each function below says what to compute and gives a hint; its contract is documented in
// STUB // chapters/04_shadow_feelers/04_shadow_feelers.hpp and the lesson in that folder's README.md.
// STUB // Each stub compiles and returns a harmless value, so the chapter's program always runs.
// STUB // Check your work with:  cmake --build --preset grade --target check_04
// STUB //
// STUB // This chapter uses chapters 01 and 02 only: the intersection tests of chapter 02 (through
// STUB // hit_sphere and hit_triangle) and its normals.
#include "04_shadow_feelers/04_shadow_feelers.hpp"
// STUB #include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises
#include "04_shadow_feelers/closest_hit.hpp"
#include "04_shadow_feelers/feeler.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace rt {

color local_shading(const PhongMaterial& m, const vec3& n, const vec3& to_eye, const vec3& to_light, const color& light)
{
    // EXERCISE 04.1: Blinn-Phong for one light. n, to_eye (v) and to_light (l) are unit vectors.
    // 1. cos = n.l. A light behind the surface (cos <= 0) gives nothing: return black.
    // 2. Diffuse (Lambert): k_d cos. The light spreads over an area 1 / cos larger when it
    //    arrives at a slant.
    // 3. Specular: h = normalize(l + v), the direction halfway between light and eye; the highlight
    //    is k_s max(0, n.h)^p, brightest where n is that halfway direction (a mirror would reflect
    //    the light straight to the eye). When l + v is 0 there is no halfway direction: no highlight.
    // 4. Both times `light`.
    // Hint: std::pow(x, m.shininess); m.diffuse and m.specular are colours (multiply per channel).
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
    // EXERCISE 04.2: the any-hit shadow feeler.
    // 1. The feeler runs from origin toward the light: to_light = light - origin, its length d is
    //    the light's distance, and the ray's direction is to_light / d (unit, as the sphere test needs).
    // 2. It looks only at t in Interval{t_min, d * (1 - shadow_epsilon)}: not behind the origin,
    //    not at the light, not beyond it.
    // 3. Test every sphere, every triangle and every cone with
    //    hit_sphere(ray, sphere, range, lit_tests.sphere), hit_triangle(ray, tri, range,
    //    lit_tests.triangle) and hit_cone_counted(ray, cone, range): return true at the first hit,
    //    without looking further. false when nothing is in the way.
    // Hint: unlike closest_hit (closest_hit.hpp), never shrink the range: any hit will do.
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
    // EXERCISE 04.3: Wachter and Binder's robust offset (Ray Tracing Gems ch. 6).
    // 1. Turn n to the side the ray leaves toward: when n.dir < 0, use -n.
    // 2. For each coordinate i (p[i], n[i]):
    //    - when |p[i]| < offset_origin: p[i] + offset_float_scale * n[i];
    //    - else: the step k = int(offset_int_scale * n[i]) in units in the last place. Read the
    //      float's 32 bits as a std::int32_t, add k (or -k when p[i] < 0: a negative float's bit
    //      pattern grows with its magnitude), and read the bits back as a float.
    // Hint: std::memcpy(&bits, &value, 4) reads a float's bits into an integer (and back) without
    // breaking C++'s aliasing rules.
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
    // EXERCISE 04.4: the colour of the hit, every light with its feeler.
    // 1. m = scene.material_of(hit.object). n = hit.n, turned to face the eye (flip it when
    //    n.ray.dir > 0: a triangle seen from behind); v = -ray.dir.
    // 2. Start with the ambient term: m.diffuse * scene.ambient.
    // 3. For each light of scene.lights: to_light = light.position - hit.p, d2 = its squared
    //    length, l = to_light / sqrt(d2). Skip the light when d2 = 0 or n.l <= 0 (it lies behind the
    //    surface: no feeler needed), or when light_blocked(scene, hit, light.position, feelers).
    //    Else add local_shading(m, n, v, l, light.intensity / d2).
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
