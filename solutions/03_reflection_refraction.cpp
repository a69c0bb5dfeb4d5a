// SOLUTION BEGIN
// Chapter 03, reflection and refraction: the reference solution.
//
// This file is also the source of exercises/03_reflection_refraction.cpp: the kit's cutter drops
// every block between SOLUTION BEGIN and SOLUTION END and keeps the STUB lines as code
// (`cmake --build <build> --target cut_exercises`; a test checks that the two agree).
// SOLUTION END
// STUB // Chapter 03, reflection and refraction: your exercises.
// STUB //
// STUB // Each function below says what to compute and gives a hint; its contract is documented in
// STUB // chapters/03_reflection_refraction/03_reflection_refraction.hpp and the lesson in that
// STUB // folder's README.md. Each stub compiles and returns a harmless value, so the chapter's program
// STUB // always runs (until 03.5 is written it shows only the sky).
// STUB // Check your work with:  cmake --build --preset grade --target check_03
#include "03_reflection_refraction/03_reflection_refraction.hpp"
// STUB #include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

#include <algorithm>
#include <cmath>

namespace rt {

vec3 reflect(const vec3& v, const vec3& n)
{
    // EXERCISE 03.1: the slide's mirror direction. v = v_n + v_s with v_n = (v.n) n along the
    // normal and v_s = v - v_n along the surface; the mirror keeps v_s and reverses v_n:
    // r = v_s - v_n = v - 2 (v.n) n.
    // Hint: glm::dot(v, n) is v.n.
    // SOLUTION BEGIN
    return v - 2.0f * glm::dot(v, n) * n;
    // SOLUTION END
    // STUB return stub("03.1", v);
}

std::optional<vec3> refract(const vec3& v, const vec3& n, float ior)
{
    // EXERCISE 03.2: Snell's law, n1 sin(theta_i) = n2 sin(theta_t), as a direction.
    // 1. Which side: cos_i = -v.n. Entering (cos_i >= 0): eta = n1 / n2 = 1 / ior. Leaving
    //    (cos_i < 0): the ray is inside, so eta = ior, and the normal must face the ray: use -n
    //    and cos_i = -cos_i.
    // 2. cos^2(theta_t) = 1 - eta^2 (1 - cos_i^2), written as (1 - eta)(1 + eta) + eta^2 cos_i^2 so
    //    that a small cos_i^2 is not lost: near grazing, 1 - cos_i^2 rounds to 1 in float, and at
    //    ior = 1 a ray a few 1e-4 from grazing would seem totally reflected.
    // 3. cos^2(theta_t) <= 0: total internal reflection, return std::nullopt.
    // 4. cos_t = sqrt(cos^2(theta_t)); t = eta v + (eta cos_i - cos_t) n (the n that faces the ray).
    // Hint: std::sqrt; return the vector itself for a direction.
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
    // EXERCISE 03.3: Fresnel's equations for a clear interface, unpolarised light.
    // 1. cos_i >= 0: the ray arrives from outside, eta = n1 / n2 = 1 / ior. cos_i < 0: from
    //    inside, eta = ior and cos_i = -cos_i.
    // 2. sin^2(theta_t) = eta^2 (1 - cos_i^2) (clamp 1 - cos_i^2 to >= 0); when it is >= 1, total
    //    internal reflection: return exactly 1.
    // 3. cos_t = sqrt(1 - sin^2(theta_t)), then
    //    r_perp = (eta cos_i - cos_t) / (eta cos_i + cos_t), r_par = (cos_i - eta cos_t) / (cos_i + eta cos_t),
    //    and R = (r_perp^2 + r_par^2) / 2.
    // Hint: check total internal reflection before dividing: at grazing incidence with ior = 1
    // both denominators would be 0.
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
    // EXERCISE 03.4: Schlick's approximation, R = R0 + (1 - R0) (1 - c)^5 with
    // R0 = ((n1 - n2) / (n1 + n2))^2, the reflectance at normal incidence (the same from either side).
    // c must be the cosine on the less dense side (the larger angle): cos_i when the ray arrives
    // from the less dense medium; when it arrives from the denser one (eta = n1 / n2 > 1), cos_t
    // from Snell's law, and exactly 1 under total internal reflection. With cos_i there the curve
    // stays near R0 right up to the critical angle, where the true R jumps to 1.
    // Hint: n1 and n2 as in 03.3 (ior may be below 1: the inside is then the less dense side).
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
    // EXERCISE 03.5: Whitted's recursion.
    // 1. hit = closest_hit(ray, scene.shapes, Interval{secondary_t_min, infinity}); none: return
    //    background(scene, ray.dir).
    // 2. colour = local_shade(scene, ray, *hit). At depth == settings.max_depth stop there.
    // 3. m = scene.material(hit->object). k_r = m.mirror, k_t = 0. When m.transparency > 0:
    //    dir = refract(ray.dir, hit->n, m.ior); F = 1 when there is none, else the reflectance
    //    settings.fresnel names, of cos_i = -ray.dir.n; k_r += m.transparency F and
    //    k_t = m.transparency (1 - F).
    // 4. For the reflected ray (along reflect(ray.dir, hit->n)) and the refracted one, each from
    //    hit->p: when k > 0 and weight k >= settings.min_weight, count it, and add
    //    k trace(scene, that ray, settings, depth + 1, weight k).
    // Hint: Ray{hit->p, direction} is a secondary ray; count(Counter::reflected_rays) counts one.
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
