// SOLUTION BEGIN
// Chapter 05, soft shadows: the reference solution.
//
// This file is also the source of exercises/05_soft_shadows.cpp: the kit's cutter drops every
// block between SOLUTION BEGIN and SOLUTION END and keeps the STUB lines as code
// (`cmake --build <build> --target cut_exercises`; a test checks that the two agree).
// SOLUTION END
// STUB // Chapter 05, soft shadows: your exercises.
// STUB //
// STUB // Each function below says what to compute and gives a hint; its contract is documented in
// STUB // chapters/05_soft_shadows/05_soft_shadows.hpp and the lesson in that folder's README.md.
// STUB // Each stub compiles and returns a harmless value, so the chapter's program always runs.
// STUB // Check your work with:  cmake --build --preset grade --target check_05
// STUB //
// STUB // This chapter builds on chapter 04: direct_light calls its local_shading (04.1) and its
// STUB // shadow feeler (light_blocked, which calls your 04.2 and 04.3).
#include "04_shadow_feelers/04_shadow_feelers.hpp"
// STUB #include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises
#include "04_shadow_feelers/feeler.hpp"
#include "05_soft_shadows/05_soft_shadows.hpp"
#include "05_soft_shadows/light_samples.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

point3 point_on_rectangle(const AreaLight& light, sample2 u)
{
    // EXERCISE 05.1: u in [0, 1)^2 to the rectangle: stretch [0, 1) to [-1, 1) along each axis.
    // Hint: light.centre + (2 u.x - 1) light.axis_u + (2 u.y - 1) light.axis_v.
    // SOLUTION BEGIN
    return light.centre + (2.0f * u.x - 1.0f) * light.axis_u + (2.0f * u.y - 1.0f) * light.axis_v;
    // SOLUTION END
    // STUB return stub("05.1", light.centre);
}

point3 point_on_disc(const AreaLight& light, sample2 u)
{
    // EXERCISE 05.2: Shirley and Chiu's concentric map, then onto the light.
    // 1. Stretch u to the square [-1, 1]^2: a = 2 u.x - 1, b = 2 u.y - 1. At a = b = 0 return the
    //    centre (step 2 would divide 0 by 0).
    // 2. Each square around the centre, |a| = const or |b| = const, goes to a circle: when
    //    |a| > |b|: r = a, phi = (pi/4) (b / a); otherwise r = b, phi = pi/2 - (pi/4) (a / b).
    //    (r may be negative: that is the half-turn that puts the square's left and bottom halves
    //    on the disc's left and bottom.)
    // 3. The disc point (x, y) = (r cos phi, r sin phi); return centre + x axis_u + y axis_v.
    // SOLUTION BEGIN
    constexpr float pi = 3.14159265358979f;
    const float a = 2.0f * u.x - 1.0f, b = 2.0f * u.y - 1.0f;
    if (a == 0.0f && b == 0.0f)
        return light.centre;
    float r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = (pi / 4.0f) * (b / a);
    } else {
        r = b;
        phi = pi / 2.0f - (pi / 4.0f) * (a / b);
    }
    return light.centre + (r * std::cos(phi)) * light.axis_u + (r * std::sin(phi)) * light.axis_v;
    // SOLUTION END
    // STUB return stub("05.2", light.centre);
}

sample2 stratified_sample(int k, int n, Rng& rng)
{
    // EXERCISE 05.3: sample k of an n x n jittered grid.
    // 1. Its cell: column a = k % n, row b = k / n.
    // 2. A uniform point inside: x = (a + rng.next_float()) / n, then y = (b + rng.next_float()) / n,
    //    in that order (draw x's number first).
    // 3. Clamp each to at most one_minus_epsilon: in float, (n - 1 + 0.99999994) / n can round to 1.
    // Hint: static_cast<float>(a) before adding; std::min(x, one_minus_epsilon).
    // SOLUTION BEGIN
    const int a = k % n, b = k / n;
    const float side = static_cast<float>(n);
    const float x = std::min((static_cast<float>(a) + rng.next_float()) / side, one_minus_epsilon);
    const float y = std::min((static_cast<float>(b) + rng.next_float()) / side, one_minus_epsilon);
    return {x, y};
    // SOLUTION END
    // STUB return stub("05.3", sample2{0.5f, 0.5f});
}

color direct_light(const AreaLitScene& scene, const Ray& ray, const Hit& hit, const AreaLight& light,
                   const LightSampling& sampling, Rng& rng)
{
    // EXERCISE 05.4: one area light, N = sampling.samples feelers, each sample weighted by A / N.
    // 1. m = scene.lit.material_of(hit.object); n = hit.n turned to face the eye (flip it when
    //    n.ray.dir > 0); v = -ray.dir; the light's normal light_normal(light) and area light_area(light).
    // 2. For k = 0 .. N - 1 (draw every sample, even those you then skip):
    //    y = point_on_light(light, light_sample(k, sampling, rng)); to_light = y - hit.p, d2 its
    //    squared length, l = to_light / sqrt(d2), cos_light = -(light normal . l).
    //    Skip the sample when d2 = 0, n.l <= 0 or cos_light <= 0; then when
    //    light_blocked(scene.lit, hit, y, FeelerSettings{}) (the feeler costs a ray: ask last).
    //    Else add local_shading(m, n, v, l, light.radiance * (cos_light * A / (N d2))).
    // Hint: the point light of chapter 04 is the case N = 1 with intensity L_e A and cos_light = 1.
    // SOLUTION BEGIN
    const PhongMaterial& m = scene.lit.material_of(hit.object);
    const vec3 n = glm::dot(hit.n, ray.dir) > 0.0f ? -hit.n : hit.n;
    const vec3 to_eye = -ray.dir;
    const vec3 light_n = light_normal(light);
    // Points drawn uniformly on the light have pdf 1 / A: each of the N samples weighs 1 / (N pdf).
    const float weight = light_area(light) / static_cast<float>(sampling.samples);
    color sum(0.0f);
    for (int k = 0; k < sampling.samples; ++k) {
        const point3 y = point_on_light(light, light_sample(k, sampling, rng));
        const vec3 to_light = y - hit.p;
        const float d2 = glm::dot(to_light, to_light);
        if (!(d2 > 0.0f))
            continue;  // a light touching the point: no direction to it, and 1 / d^2 is infinite
        const vec3 l = to_light / std::sqrt(d2);
        const float cos_light = -glm::dot(light_n, l);
        if (glm::dot(n, l) <= 0.0f || cos_light <= 0.0f || light_blocked(scene.lit, hit, y, FeelerSettings{}))
            continue;
        sum += local_shading(m, n, to_eye, l, light.radiance * (cos_light * weight / d2));
    }
    return sum;
    // SOLUTION END
    // STUB return stub("05.4", color(0.0f));
}

}  // namespace rt
