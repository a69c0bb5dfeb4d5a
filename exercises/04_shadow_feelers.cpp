// Chapter 04, shadow feelers: your exercises.
//
// Each function below says what to compute and gives a hint; its contract is documented in
// chapters/04_shadow_feelers/04_shadow_feelers.hpp and the lesson in that folder's README.md.
// Each stub compiles and returns a harmless value, so the chapter's program always runs.
// Check your work with:  cmake --build --preset grade --target check_04
//
// This chapter uses chapters 01 and 02 only: the intersection tests of chapter 02 (through
// hit_sphere and hit_triangle) and its normals.
#include "04_shadow_feelers/04_shadow_feelers.hpp"
#include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises
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
    return stub("04.1", color(0.0f));
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
    return stub("04.2", false);
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
    return stub("04.3", p);
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
    return stub("04.4", color(0.0f));
}

}  // namespace rt
