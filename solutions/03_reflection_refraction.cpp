// SOLUTION BEGIN
// Chapter 03, reflection and refraction: the reference solution.
//
// This file is also the source of exercises/03_reflection_refraction.cpp: the kit's cutter drops
// every block between SOLUTION BEGIN and SOLUTION END and keeps the STUB lines as code
// (`cmake --build <build> --target cut_exercises`; a test checks that the two agree).
// SOLUTION END
// STUB // Chapter 03, reflection and refraction: your exercises.
// STUB //
// STUB // Each function below states what to compute (not how); its contract is documented in
// STUB // chapters/03_reflection_refraction/03_reflection_refraction.hpp and the lesson in that
// STUB // folder's README.md. Each stub compiles and returns a harmless value, so the chapter's program
// STUB // always runs (until 03.5 is written it shows only the sky).
// STUB // Check your work with:  cmake --build --preset grade --target check_03
// STUB // Stuck? Hints in tiers you open one at a time: chapters/03_reflection_refraction/hints.md, or
// STUB // ./build/grade/hint 03.1 (tier 1, the idea), ./build/grade/hint 03.1 2 (the trap), ... 3 (the walk-through).
#include "03_reflection_refraction/03_reflection_refraction.hpp"
// STUB #include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

#include <algorithm>
#include <cmath>

namespace rt {

vec3 reflect(const vec3& v, const vec3& n)
{
    // EXERCISE 03.1: the mirror direction
    // Return the direction v takes after a mirror whose unit normal is n: its part along the surface
    // kept, its part along the normal reversed. Either sign of n gives the same answer, and a ray
    // skimming the surface (v.n = 0) goes on unchanged.
    // Lesson: "Reflection (EXERCISE 03.1)"
    // Stuck? hint 03.1 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    return v - 2.0f * glm::dot(v, n) * n;
    // SOLUTION END
    // STUB return stub("03.1", v);
}

std::optional<vec3> refract(const vec3& v, const vec3& n, float ior)
{
    // EXERCISE 03.2: the refracted direction, by Snell's law
    // Return the unit direction in which v goes on through the interface (n: the object's outward
    // normal; ior: inside relative to outside), for a ray entering or leaving: the sign of v.n says
    // which. No direction (std::nullopt) under total internal reflection. It must hold in float too:
    // at ior = 1 a ray a hair from grazing still gets through. Lesson: "Refraction (EXERCISE 03.2)"
    // Stuck? hint 03.2 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    float cos_i = -glm::dot(v, n);
    float eta = 1.0f / ior;
    vec3 facing = n;
    if (cos_i < 0.0f) {  // from inside: the indices swap and the normal turns toward the ray
        cos_i = -cos_i;
        eta = ior;
        facing = -n;
    }
    // cos^2(theta_t) = 1 - eta^2 sin^2(theta_i), with 1 - eta^2 factored (exact for eta near 1)
    // and the cos_i^2 term kept whole: no cancellation near grazing or at eta = 1. v and n are
    // unit only to rounding, so cos_i may be a hair above 1: min(cos_i^2, 1) keeps sin^2 >= 0.
    const float cos2_t = (1.0f - eta) * (1.0f + eta) + eta * eta * std::min(cos_i * cos_i, 1.0f);
    if (!(cos2_t > 0.0f))
        return std::nullopt;
    const float cos_t = std::sqrt(cos2_t);
    // The part of v along the surface, scaled by eta (Snell), plus the part along -facing that
    // makes the result unit: eta v_s - cos_t facing, with v_s = v + cos_i facing.
    return eta * v + (eta * cos_i - cos_t) * facing;
    // SOLUTION END
    // STUB return stub("03.2", std::nullopt);
}

float fresnel_dielectric(float cos_i, float ior)
{
    // EXERCISE 03.3: Fresnel's reflectance, exact
    // Return R in [0, 1], the share of unpolarised light that a clear interface of index ior
    // reflects, for cos_i (that is, -v.n): negative when the ray is inside, and the indices swap.
    // Exactly 1 under total internal reflection; never a NaN, even at grazing incidence, ior = 1.
    // Lesson: "Fresnel's reflectance (EXERCISE 03.3)"
    // Stuck? hint 03.3 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    float eta = 1.0f / ior;
    if (cos_i < 0.0f) {
        cos_i = -cos_i;
        eta = ior;
    }
    const float sin2_t = eta * eta * std::max(0.0f, 1.0f - cos_i * cos_i);
    if (sin2_t >= 1.0f)
        return 1.0f;
    const float cos_t = std::sqrt(1.0f - sin2_t);
    const float r_perp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const float r_par = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5f * (r_perp * r_perp + r_par * r_par);
    // SOLUTION END
    // STUB return stub("03.3", 0.0f);
}

float fresnel_schlick(float cos_i, float ior)
{
    // EXERCISE 03.4: Schlick's approximation
    // Return Schlick's polynomial for the reflectance of 03.3 (same cos_i and ior), with R0 the
    // reflectance head-on. Its cosine is the one on the less dense side, which is not always the
    // ray's own (and ior may be below 1). Exactly 1 under total internal reflection.
    // Lesson: "Schlick's approximation (EXERCISE 03.4)"
    // Stuck? hint 03.4 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    float eta = 1.0f / ior;
    if (cos_i < 0.0f) {
        cos_i = -cos_i;
        eta = ior;
    }
    const float r0 = (ior - 1.0f) / (ior + 1.0f);
    const float R0 = r0 * r0;
    float c = cos_i;
    if (eta > 1.0f) {  // from the denser side: the transmitted angle is the larger one
        const float sin2_t = eta * eta * std::max(0.0f, 1.0f - cos_i * cos_i);
        if (sin2_t >= 1.0f)
            return 1.0f;
        c = std::sqrt(1.0f - sin2_t);
    }
    const float m = 1.0f - c;
    return R0 + (1.0f - R0) * (m * m) * (m * m) * m;
    // SOLUTION END
    // STUB return stub("03.4", 0.0f);
}

color trace(const WhittedScene& scene, const Ray& ray, const TraceSettings& settings, int depth, float weight)
{
    // EXERCISE 03.5: Whitted's recursion
    // Return the colour seen along ray: the sky if it hits nothing, else the hit's local shade plus,
    // while depth is below the settings' limit, k_r times what the reflected ray sees and k_t times
    // what the refracted one sees (glass's share split by Fresnel). A secondary ray is traced, and
    // counted, only if its share of the pixel is worth it. Lesson: "The recursion (EXERCISE 03.5)"
    // Stuck? hint 03.5 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    const std::optional<Hit> hit = closest_hit(ray, scene.shapes, Interval{secondary_t_min, infinity});
    if (!hit)
        return background(scene, ray.dir);
    color colour = local_shade(scene, ray, *hit);
    if (depth >= settings.max_depth)
        return colour;

    // Whitted's k_s S + k_t T: the mirror's share, and the glass's share split by Fresnel.
    const Material& m = scene.material(hit->object);
    float k_reflected = m.mirror, k_refracted = 0.0f;
    std::optional<vec3> refracted;
    if (m.transparency > 0.0f) {
        refracted = refract(ray.dir, hit->n, m.ior);
        const float cos_i = -glm::dot(ray.dir, hit->n);
        const float F = !refracted ? 1.0f
                        : settings.fresnel == FresnelModel::schlick ? fresnel_schlick(cos_i, m.ior)
                                                                     : fresnel_dielectric(cos_i, m.ior);
        k_reflected += m.transparency * F;
        k_refracted = m.transparency * (1.0f - F);
    }

    // Each secondary ray only when its share of the pixel is worth a ray (Hall and Greenberg's
    // adaptive depth control, 1983): a path's weight only falls as it bounces.
    if (k_reflected > 0.0f && weight * k_reflected >= settings.min_weight) {
        count(Counter::reflected_rays);
        colour += k_reflected * trace(scene, Ray{hit->p, reflect(ray.dir, hit->n)}, settings, depth + 1,
                                      weight * k_reflected);
    }
    if (refracted && k_refracted > 0.0f && weight * k_refracted >= settings.min_weight) {
        count(Counter::refracted_rays);
        colour += k_refracted * trace(scene, Ray{hit->p, *refracted}, settings, depth + 1, weight * k_refracted);
    }
    return colour;
    // SOLUTION END
    // STUB return stub("03.5", background(scene, ray.dir));
}

}  // namespace rt
