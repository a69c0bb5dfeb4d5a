// EXERCISE 05.4: the light of one area light, estimated with N shadow feelers, each sample
// weighted by L_e cos(theta_light) / d^2 * A / N; compared with the exact answer (Lambert's
// polygon formula, exact_irradiance.hpp) within the tolerance the estimates' own spread allows.
#include "tests/ch05/estimate.hpp"

#include <cmath>

using namespace rt;
using namespace rt::grader;

namespace {

// Off the floor's diagonal, so the eye's ray meets one triangle cleanly.
const point3 target{0.13f, 0.0f, -0.07f};
const vec3 down{0.0f, -1.0f, 0.0f};
const color warm{3.0f, 1.8f, 0.9f};

const LightSampling random16{16, SampleScheme::random};
const LightSampling stratified16{16, SampleScheme::stratified};

void check(const FloorView& v, const AreaLight& light, const LightSampling& sampling, int calls, std::uint64_t seed,
           const dvec3& want, const std::string& why)
{
    const Estimate e = estimate(v, light, sampling, calls, seed);
    INFO(describe(v, light, sampling, e, want, why));
    CHECK(agrees(e, want));
}

}  // namespace

GRADED_TEST("direct_light: a square light straight above gives L_e times its projected solid angle (Lambert's formula)", "05.4", 3)
{
    const FloorView v = floor_view(target);
    const dvec3 p(v.hit.p), up(0, 1, 0);
    // Small and high, where cos_light is nearly 1 and the light nearly a point of intensity L_e A;
    // then wide and low, where the slant and the distance vary over it.
    for (const AreaLight& light : {rectangle_light(target + vec3(0, 2, 0), {0.25f, 0, 0}, {0, 0, 0.25f}, warm),
                                   rectangle_light(target + vec3(0, 1, 0), {0.6f, 0, 0}, {0, 0, 0.4f}, warm)})
        for (const LightSampling& sampling : {random16, stratified16})
            check(v, light, sampling, 1000, 62, exact_light(light, p, up),
                  "each sample weighs L_e cos_light / d^2 times A / N (1 / N pdf, pdf = 1 / A), and the surface's "
                  "cos comes from local_shading");
}

GRADED_TEST("direct_light: a disc light straight above gives the textbook L_e pi sin^2(alpha)", "05.4", 2)
{
    constexpr double pi = 3.14159265358979323846;
    const FloorView v = floor_view(target);
    for (const float height : {1.0f, 3.0f}) {
        const float radius = 0.5f;
        const AreaLight light = disc_light(target + vec3(0, height, 0), down, radius, warm);
        // alpha is the half-angle the disc subtends: sin^2(alpha) = r^2 / (r^2 + h^2).
        const double sin2 = radius * radius / (radius * radius + static_cast<double>(height) * height);
        for (const LightSampling& sampling : {random16, stratified16})
            check(v, light, sampling, 1000, 63, dvec3(warm) * pi * sin2,
                  "a disc of radius r at height h subtends sin^2(alpha) = r^2 / (r^2 + h^2); its area is pi r^2");
    }
}

GRADED_TEST("direct_light: a slanted light off to the side, both cosines count (the surface's and the light's)", "05.4", 3)
{
    const FloorView v = floor_view(target);
    const dvec3 p(v.hit.p), up(0, 1, 0);
    // Seen at about 50 degrees from the floor's normal, and turned 40 degrees away from the point.
    const point3 centre = target + vec3(1.4f, 1.3f, -0.6f);
    const vec3 toward = glm::normalize(target - centre);
    const vec3 turned = glm::normalize(toward + 0.8f * glm::normalize(glm::cross(toward, vec3(0, 1, 0))));
    for (const AreaLight& light : {rectangle_facing(centre, turned, 0.5f, 0.3f, warm),
                                   disc_light(centre, turned, 0.45f, warm)})
        for (const LightSampling& sampling : {random16, stratified16})
            check(v, light, sampling, 1000, 64, exact_light(light, p, up),
                  "the light is seen at a slant (cos_light about 0.77) from a surface it lights at a slant; "
                  "each sample needs cos_light / d^2 and the surface's cos (in local_shading)");
}

GRADED_TEST("direct_light: a light facing away from the point, or below its surface, lights nothing and sends no feeler", "05.4", 2)
{
    const FloorView v = floor_view(target);
    // The same light turned to face the point lights it, one feeler a sample.
    const AreaLight facing_down = rectangle_light(target + vec3(0, 2, 0), {0.5f, 0, 0}, {0, 0, 0.5f}, warm);
    const Estimate lit = estimate(v, facing_down, stratified16, 10, 65);
    INFO(describe(v, facing_down, stratified16, lit, exact_light(facing_down, dvec3(v.hit.p), {0, 1, 0}),
                  "the light faces the point") << "; it sent " << lit.feelers << " shadow feelers, expected 160");
    REQUIRE(agrees(lit, exact_light(facing_down, dvec3(v.hit.p), {0, 1, 0})));
    REQUIRE(lit.feelers == 160);
    const AreaLight facing_up = rectangle_light(target + vec3(0, 2, 0), {0, 0, 0.5f}, {0.5f, 0, 0}, warm);
    const AreaLight below = disc_light(target + vec3(0.5f, -2, 0), {0, 1, 0}, 0.5f, warm);
    for (const auto& [light, why] : {std::pair<AreaLight, const char*>{facing_up, "it glows upward, away from the point"},
                                     {below, "it lies below the floor, behind the surface the eye sees"}}) {
        const Estimate e = estimate(v, light, stratified16, 10, 65);
        INFO(describe(v, light, stratified16, e, dvec3(0.0), why) << "; it sent " << e.feelers
             << " shadow feelers, expected none: skip a sample before its feeler when cos_light <= 0 or n.l <= 0");
        CHECK(e.mean == dvec3(0.0));
        CHECK(e.feelers == 0);
    }
}

GRADED_TEST("direct_light: an occluder hiding part of the light dims it by that part: each feeler aims at its own sample", "05.4", 3)
{
    // A square light 1 across, 2 above the point, and a wide board just under it (at 1.99) that
    // covers everything beyond x = 0.2 (or, the second time, before it). Seen from the point, the
    // board's edge crosses the light at 0.2 * 2 / 1.99; the rest of the light shines as if alone.
    const float x_edge = 0.2f, board = 1.99f;
    const double seen_edge = static_cast<double>(x_edge) * 2.0 / static_cast<double>(board);
    for (const bool beyond : {true, false}) {
        const float x0 = target.x + x_edge, x1 = target.x + (beyond ? 10.0f : -10.0f);
        const Triangle a{{x0, board, -10}, {x1, board, -10}, {x1, board, 10}};
        const Triangle b{{x0, board, -10}, {x1, board, 10}, {x0, board, 10}};
        const FloorView v = floor_view(target, {a, b});
        const AreaLight light = rectangle_light(target + vec3(0, 2, 0), {0.5f, 0, 0}, {0, 0, 0.5f}, warm);
        const dvec3 p(v.hit.p), c(light.centre);
        const double lo = beyond ? -0.5 : seen_edge, hi = beyond ? seen_edge : 0.5;
        const std::vector<dvec3> visible = {c + dvec3(lo, 0, -0.5), c + dvec3(hi, 0, -0.5), c + dvec3(hi, 0, 0.5),
                                            c + dvec3(lo, 0, 0.5)};
        const dvec3 want = dvec3(warm) * projected_solid_angle(visible, p, {0, 1, 0});
        for (const LightSampling& sampling : {random16, stratified16})
            check(v, light, sampling, 1000, 66, want,
                  std::string("a board at y = 1.99 hides the light ") + (beyond ? "beyond" : "before") +
                      " x = 0.2 (the light's centre is " + (beyond ? "seen" : "hidden") +
                      "); only the samples whose own feeler is unblocked count, each with its own weight");
    }
}

GRADED_TEST("direct_light: each call draws fresh samples from the rng it is given, so 1-sample estimates average to the answer", "05.4", 2)
{
    // A wide light close above: one sample alone is far off (its value varies ninefold over the
    // light), so only fresh samples on every call average out. A sequence restarted on every
    // call would give every pixel the same samples: a pattern instead of noise.
    const FloorView v = floor_view(target);
    const AreaLight light = rectangle_light(target + vec3(0, 1, 0), {1, 0, 0}, {0, 0, 1}, warm);
    const LightSampling one{1, SampleScheme::random};
    const Estimate e = estimate(v, light, one, 20000, 67);
    const dvec3 want = exact_light(light, dvec3(v.hit.p), {0, 1, 0});
    INFO(describe(v, light, one, e, want, "1 sample a call; the calls share one stream, each must draw from it"));
    CHECK_FALSE(e.all_equal);
    CHECK(agrees(e, want));
}

GRADED_TEST("direct_light: one shadow feeler per sample that could light the point", "05.4", 1)
{
    const FloorView v = floor_view(target);
    const AreaLight light = disc_light(target + vec3(0.3f, 2, 0), down, 0.5f, warm);
    for (const LightSampling& sampling : {LightSampling{5, SampleScheme::random}, stratified16}) {
        const Estimate e = estimate(v, light, sampling, 1, 68);
        INFO("direct_light at " << show(v.hit.p) << " from " << show(light) << " wholly above it and facing it, "
             << show(sampling) << ": it sent " << e.feelers << " shadow feelers (light_blocked counts them), expected "
             << sampling.samples);
        CHECK(e.feelers == static_cast<std::uint64_t>(sampling.samples));
    }
}

GRADED_TEST("direct_light: uses the sampling it is given, 16 stratified samples give under half the variance of 16 random ones", "05.4", 2)
{
    const FloorView v = floor_view(target);
    const AreaLight light = rectangle_light(target + vec3(0, 1, 0), {1, 0, 0}, {0, 0, 1}, warm);
    const Estimate stratified = estimate(v, light, stratified16, 1000, 69);
    const Estimate random = estimate(v, light, random16, 1000, 69);
    // About a quarter for the solution: stratification removes the variance between the cells.
    const double ratio = glm::pow(stratified.standard_error.x / random.standard_error.x, 2.0);
    INFO("direct_light at " << show(v.hit.p) << " from " << show(light) << ", 1000 calls of 16 samples: the variance "
         << "of the estimates is " << 1000.0 * glm::pow(stratified.standard_error.x, 2.0) << " with stratified samples and "
         << 1000.0 * glm::pow(random.standard_error.x, 2.0) << " with random ones (ratio " << ratio
         << "); expected below a half: get each sample from light_sample(k, sampling, rng)");
    CHECK(ratio < 0.5);
}

STABILITY_TEST("direct_light: never a NaN, from a light lying on the surface, one edge-on to it, one 1e-3 above it", "05.4", 1)
{
    const FloorView v = floor_view(target);
    const dvec3 p(v.hit.p), up(0, 1, 0);
    // Lying on the floor around the point, glowing up: every sample in the surface's plane, n.l = 0
    // (and d = 0 when a sample lands on the point). Standing on its edge with its plane through the
    // point: cos_light = 0 for every sample. Both give exactly 0.
    const AreaLight lying = rectangle_light(target, {0, 0, 0.5f}, {0.5f, 0, 0}, warm);
    const AreaLight edge_on = rectangle_light(target + vec3(0, 0.5f, 1), {0, 0.5f, 0}, {0, 0, 0.5f}, warm);
    for (const AreaLight& light : {lying, edge_on}) {
        const Estimate e = estimate(v, light, stratified16, 20, 70);
        INFO(describe(v, light, stratified16, e, dvec3(0.0), "the light lies in a plane through the point"));
        REQUIRE((std::isfinite(e.mean.x) && std::isfinite(e.mean.y) && std::isfinite(e.mean.z)));
        // 0, or the rounding of a hit point a float step off the light's plane.
        CHECK(glm::length(e.mean) <= 1e-6);
    }
    // A tiny disc 1e-3 above: 1 / d^2 = 1e6, the area 3e-8: finite, and the exact answer.
    const AreaLight tiny = disc_light(target + vec3(0, 1e-3f, 0), down, 1e-4f, warm);
    const Estimate e = estimate(v, tiny, stratified16, 100, 71);
    const dvec3 want = exact_light(tiny, p, up);
    INFO(describe(v, tiny, stratified16, e, want, "a disc of radius 1e-4 just 1e-3 above the point"));
    REQUIRE((std::isfinite(e.mean.x) && std::isfinite(e.mean.y) && std::isfinite(e.mean.z)));
    CHECK(agrees(e, want));
}

STABILITY_TEST("direct_light: a light of no size at the shaded point itself gives 0 and no NaN; a real one still lights", "05.4", 1)
{
    // Every sample of a disc of radius 0 centred on the point is the point: d^2 = 0, no direction
    // to the light, and 1 / d^2 infinite. The sample must be skipped before anything divides by d.
    const FloorView v = floor_view(target);
    const AreaLight none = disc_light(v.hit.p, down, 0.0f, warm);
    const Estimate e = estimate(v, none, stratified16, 4, 72);
    INFO(describe(v, none, stratified16, e, dvec3(0.0), "a light of radius 0 exactly at the shaded point"));
    REQUIRE((std::isfinite(e.mean.x) && std::isfinite(e.mean.y) && std::isfinite(e.mean.z)));
    CHECK(e.mean == dvec3(0.0));
    const AreaLight real = rectangle_light(target + vec3(0, 2, 0), {0.5f, 0, 0}, {0, 0, 0.5f}, warm);
    const Estimate lit = estimate(v, real, stratified16, 10, 73);
    const dvec3 want = exact_light(real, dvec3(v.hit.p), {0, 1, 0});
    INFO(describe(v, real, stratified16, lit, want, "a square light 2 above the point"));
    CHECK(agrees(lit, want));
}
