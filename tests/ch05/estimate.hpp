// What direct_light's tests share: a white floor seen from the eye, the light's estimate averaged
// over many calls, and the check that the average agrees with the exact answer within the
// tolerance its own spread allows.
//
// Each call of direct_light is one estimate X_j of N samples; M calls, each drawing fresh numbers
// from one stream, are M independent estimates. Their mean has the standard error s / sqrt(M), with
// s the spread of the X_j: the tolerance follows from the samples, never a fudge. 5 standard errors
// make a false failure about one in a million (and the seeded streams make every run the same).
#pragma once

#include "04_shadow_feelers/radiance.hpp"
#include "tests/ch05/describe.hpp"
#include "tests/ch05/exact_irradiance.hpp"

#include <cmath>
#include <sstream>
#include <vector>

namespace rt::grader {

// White and matte: k_d = 1, no highlight, so the estimate is the light's L_e times the projected
// solid angle of what the point sees of it.
const PhongMaterial white_matte{color(1.0f), color(0.0f), 1.0f};

struct FloorView {
    AreaLitScene scene;
    Ray ray;
    Hit hit;
};

// A floor through y = 0, 40 across, facing up, and `occluders` above it, all white matte; the eye
// low over the floor (0.5 up, 4 back) so that its ray meets the floor at `target` under any occluder
// above y = 0.5.
inline FloorView floor_view(const point3& target, const std::vector<Triangle>& occluders = {})
{
    FloorView v;
    LitScene& lit = v.scene.lit;
    const int m = lit.add_material(white_matte);
    lit.add_triangle({{-20, 0, 20}, {20, 0, 20}, {20, 0, -20}}, m);
    lit.add_triangle({{-20, 0, 20}, {20, 0, -20}, {-20, 0, -20}}, m);
    for (const Triangle& t : occluders)
        lit.add_triangle(t, m);
    const point3 eye = target + vec3(0.0f, 0.5f, 4.0f);
    v.ray = Ray{eye, glm::normalize(target - eye)};
    const std::optional<Hit> hit = closest_hit(v.ray, lit, Interval{0.0f, infinity});
    REQUIRE(hit);
    REQUIRE(hit->object < 2);
    v.hit = *hit;
    return v;
}

// A rectangle of half-sizes a and b around `centre`, glowing toward the unit vector `normal`.
inline AreaLight rectangle_facing(const point3& centre, const vec3& normal, float a, float b, const color& radiance)
{
    const AreaLight frame = disc_light(centre, normal, 1.0f, radiance);
    return rectangle_light(centre, a * frame.axis_u, b * frame.axis_v, radiance);
}

struct Estimate {
    dvec3 mean{0.0};
    dvec3 standard_error{0.0};
    bool all_equal = true;  // every call gave the same colour: no fresh samples
    int calls = 0;
    std::uint64_t feelers = 0;
};

inline Estimate estimate(const FloorView& v, const AreaLight& light, const LightSampling& sampling, int calls,
                         std::uint64_t seed)
{
    Estimate e;
    e.calls = calls;
    Rng rng(seed, 7);
    dvec3 sum(0.0), sum_sq(0.0);
    color first(0.0f);
    reset_counters();
    for (int c = 0; c < calls; ++c) {
        const color x = direct_light(v.scene, v.ray, v.hit, light, sampling, rng);
        if (c == 0)
            first = x;
        e.all_equal = e.all_equal && x == first;
        sum += dvec3(x);
        sum_sq += dvec3(x) * dvec3(x);
    }
    e.feelers = total_count(Counter::shadow_rays);
    const double m = calls;
    e.mean = sum / m;
    const dvec3 variance = glm::max(sum_sq - sum * sum / m, dvec3(0.0)) / (m - 1.0);
    e.standard_error = glm::sqrt(variance / m);
    return e;
}

// The z allowed, and the float rounding of one estimate's sum (relative) on top.
constexpr double z_allowed = 5.0;
constexpr double rounding = 1e-5;

inline bool agrees(const Estimate& e, const dvec3& want)
{
    for (int k = 0; k < 3; ++k)
        if (!(std::abs(e.mean[k] - want[k]) <= z_allowed * e.standard_error[k] + rounding * std::abs(want[k]) + 1e-9))
            return false;
    return true;
}

inline std::string describe(const FloorView& v, const AreaLight& light, const LightSampling& sampling,
                            const Estimate& e, const dvec3& want, const std::string& why)
{
    std::ostringstream s;
    s.precision(6);
    s << "direct_light at " << show(v.hit.p) << " (a white matte floor, k_d = 1, normal (0, 1, 0)) from " << show(light)
      << ", " << show(sampling) << ", averaged over " << e.calls << " calls: got (" << e.mean.x << ", " << e.mean.y
      << ", " << e.mean.z << ") +- (" << e.standard_error.x << ", " << e.standard_error.y << ", " << e.standard_error.z
      << ") (one standard error), expected (" << want.x << ", " << want.y << ", " << want.z << ") within "
      << z_allowed << " standard errors: " << why;
    if (e.all_equal && e.calls > 1)
        s << ". Every call returned the same colour: are the samples drawn from the rng passed in?";
    return s.str();
}

}  // namespace rt::grader
