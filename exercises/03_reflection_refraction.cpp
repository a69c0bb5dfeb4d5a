// Chapter 03, reflection and refraction: your exercises.
//
// Each function below says what to compute and gives a hint; its contract is documented in
// chapters/03_reflection_refraction/03_reflection_refraction.hpp and the lesson in that
// folder's README.md. Each stub compiles and returns a harmless value, so the chapter's program
// always runs (until 03.5 is written it shows only the sky).
// Check your work with:  cmake --build --preset grade --target check_03
#include "03_reflection_refraction/03_reflection_refraction.hpp"
#include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

#include <algorithm>
#include <cmath>

namespace rt {

vec3 reflect(const vec3& v, const vec3& n)
{
    // EXERCISE 03.1: the slide's mirror direction. v = v_n + v_s with v_n = (v.n) n along the
    // normal and v_s = v - v_n along the surface; the mirror keeps v_s and reverses v_n:
    // r = v_s - v_n = v - 2 (v.n) n.
    // Hint: glm::dot(v, n) is v.n.
    return stub("03.1", v);
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
    return stub("03.2", std::nullopt);
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
    return stub("03.3", 0.0f);
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
    return stub("03.4", 0.0f);
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
    return stub("03.5", background(scene, ray.dir));
}

}  // namespace rt
