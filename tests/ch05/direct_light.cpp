// EXERCISE 05.4: the light of one area light, estimated with N shadow feelers, each sample
// weighted by L_e cos(theta_light) / d^2 * A / N; compared with the exact answer (Lambert's
// polygon formula, exact_irradiance.hpp) within the tolerance the estimates' own spread allows.
#include "04_shadow_feelers/04_shadow_feelers.hpp"
#include "tests/ch05/estimate.hpp"

#include <cmath>
#include <cstdint>
#include <sstream>
#include <tuple>

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

namespace {

// The floor seen at `target`, its hit point set to exactly `target` (a point of the floor y = 0,
// which the floor's own rounding would move by a float step): the boundary cases below need the
// point's coordinates exact.
FloorView exact_floor_view(const point3& target_point)
{
    FloorView v = floor_view(target_point);
    v.hit.p = target_point;
    return v;
}

// Rng(826214, 7), the stream estimate() gives direct_light with this seed, draws 0.557104766 and
// then exactly 0.5 (found by search): one random sample u = (0.557..., 1/2), which a rectangle maps
// to centre + 0.114 axis_u + 0 axis_v, exactly on the line through its centre along axis_u.
constexpr std::uint64_t seed_half = 826214;

}  // namespace

GRADED_TEST("direct_light: a sample exactly in the surface's plane (n.l = 0) or in the light's own plane (cos_light = 0) sends no feeler; a hair off it does", "05.4", 1)
{
    const point3 p{0.25f, 0.0f, 0.0f};
    const FloorView v = exact_floor_view(p);
    {
        Rng check_rng(seed_half, 7);
        const float x = check_rng.next_float(), y = check_rng.next_float();
        INFO("the seeded stream's first two numbers are " << x << " and " << y << "; the case needs the second to be 0.5");
        REQUIRE(y == 0.5f);
    }
    // A light standing upright 2 beyond the point, facing it (-x); its one sample lies on the line
    // through its centre along axis_u (z), at the centre's height h: the sample's n.l is h / d.
    const LightSampling one{1, SampleScheme::random};
    for (const auto& [h, feelers, why] :
         {std::tuple<float, std::uint64_t, const char*>{0.0f, 0, "the sample lies exactly in the floor's plane: n.l = 0, skip it before its feeler"},
          {-1e-20f, 0, "the sample lies 1e-20 below the floor's plane: n.l < 0, skip it"},
          {1e-20f, 1, "the sample lies 1e-20 above the floor's plane: n.l > 0, one feeler"}}) {
        const AreaLight upright = rectangle_light(point3(2.25f, h, 0.0f), {0, 0, 0.5f}, {0, 0.5f, 0}, warm);
        const Estimate e = estimate(v, upright, one, 1, seed_half);
        INFO("direct_light at " << show(v.hit.p) << " (floor normal (0, 1, 0)) from " << show(upright) << ", "
             << show(one) << ", the sample u = (0.557104766, 0.5), so the point on the light is at height " << h
             << ": it sent " << e.feelers << " shadow feelers, expected " << feelers << ": " << why);
        CHECK(e.feelers == feelers);
        CHECK((std::isfinite(e.mean.x) && std::isfinite(e.mean.y) && std::isfinite(e.mean.z)));
    }
    // A light glowing toward +z in the plane z = z0, above the floor beside the point: every sample
    // has l.z = z0 / d, so cos_light = -z0 / d: 0 in the plane through the point.
    for (const auto& [z0, feelers, why] :
         {std::tuple<float, std::uint64_t, const char*>{0.0f, 0, "the point lies in the light's plane: cos_light = 0 for every sample, skip each before its feeler"},
          {1e-20f, 0, "the point lies 1e-20 behind the light's plane: cos_light < 0, skip each"},
          {-1e-20f, 16, "the point lies 1e-20 in front of the light's plane: cos_light > 0, one feeler a sample"}}) {
        const AreaLight edge_on = rectangle_light(point3(1.25f, 1.0f, z0), {0.5f, 0, 0}, {0, 0.5f, 0}, warm);
        const Estimate e = estimate(v, edge_on, stratified16, 1, 74);
        INFO("direct_light at " << show(v.hit.p) << " from " << show(edge_on) << " (glowing toward +z), "
             << show(stratified16) << ": it sent " << e.feelers << " shadow feelers, expected " << feelers << ": " << why);
        CHECK(e.feelers == feelers);
        CHECK((std::isfinite(e.mean.x) && std::isfinite(e.mean.y) && std::isfinite(e.mean.z)));
    }
}

GRADED_TEST("direct_light: one call's value is the sum over its samples of local_shading(m, n, v, l, L_e cos_light / d^2 * A / N), sample by sample", "05.4", 2)
{
    // A single estimate's geometry is exact, not noisy: with the stream's numbers known, each
    // sample's point, its two cosines, its distance and its weight A / N follow, and the call must
    // return their sum. The floor is shiny here, so the highlight checks v = -ray.dir too.
    const point3 p{0.25f, 0.0f, 0.0f};
    FloorView v = exact_floor_view(p);
    const PhongMaterial shiny{{0.6f, 0.5f, 0.4f}, color(0.5f), 4.0f};
    for (PhongMaterial& m : v.scene.lit.materials)
        m = shiny;
    const vec3 n{0, 1, 0}, to_eye = -v.ray.dir;
    const AreaLight slanted = rectangle_facing(p + vec3(1.4f, 1.3f, -0.6f), glm::normalize(vec3(-1.0f, -0.6f, 0.9f)), 0.5f, 0.3f, warm);
    for (const int samples : {1, 3, 8}) {
        const LightSampling sampling{samples, SampleScheme::random};
        for (std::uint64_t seed = 80; seed < 85; ++seed) {
            Rng rng(seed, 7), copy(seed, 7);
            const color got = direct_light(v.scene, v.ray, v.hit, slanted, sampling, rng);
            const dvec3 pd(p), c(slanted.centre), a(slanted.axis_u), b(slanted.axis_v);
            const dvec3 light_n = glm::normalize(glm::cross(a, b));
            const double area = 4.0 * glm::length(glm::cross(a, b));
            dvec3 want(0.0);
            std::ostringstream samples_said;
            for (int k = 0; k < samples; ++k) {
                const double ux = copy.next_float(), uy = copy.next_float();
                const dvec3 y = c + (2.0 * ux - 1.0) * a + (2.0 * uy - 1.0) * b;
                const double d = glm::length(y - pd);
                const dvec3 l = (y - pd) / d;
                const double cos_light = -glm::dot(light_n, l), cos_surface = glm::dot(dvec3(n), l);
                samples_said << "\n  sample " << k << ": u = (" << ux << ", " << uy << "), d = " << d
                             << ", n.l = " << cos_surface << ", cos_light = " << cos_light;
                if (cos_surface > 0 && cos_light > 0)
                    want += dvec3(local_shading(shiny, n, to_eye, vec3(l), color(dvec3(warm) * (cos_light / (d * d) * area / samples))));
            }
            INFO("direct_light at " << show(p) << " (a shiny floor, k_d = (0.6, 0.5, 0.4), k_s = 0.5, p = 4, normal (0, 1, 0), toward the eye "
                 << show(to_eye) << ") from " << show(slanted) << " (area " << area << "), " << show(sampling)
                 << ", stream (" << seed << ", 7): got " << show(got) << ", expected " << show(color(want))
                 << " = the sum of local_shading(m, n, v, l, L_e cos_light / d^2 * A / N) over" << samples_said.str());
            CHECK(rel_error(got.x, want.x) <= 1e-5);
            CHECK(rel_error(got.y, want.y) <= 1e-5);
            CHECK(rel_error(got.z, want.z) <= 1e-5);
        }
    }
}

GRADED_TEST("direct_light: a floor seen from below is lit by a light below it, its normal turned to the eye, and not by one above", "05.4", 2)
{
    // The eye under the floor (whose triangles face up): n must be turned to face the eye, as
    // chapter 04's shade turns it, so the light below lights the underside and the one above,
    // behind the surface the eye sees, lights nothing and costs no feeler.
    FloorView v = floor_view(target);
    const point3 eye = target + vec3(0.0f, -0.5f, 4.0f);
    v.ray = Ray{eye, glm::normalize(target - eye)};
    const std::optional<Hit> hit = closest_hit(v.ray, v.scene.lit, Interval{0.0f, infinity});
    REQUIRE(hit);
    REQUIRE(hit->n.y > 0.0f);  // the floor's own normal points up, away from the eye
    v.hit = *hit;
    const dvec3 p(v.hit.p), under(0, -1, 0);
    const AreaLight below = disc_light(target + vec3(0.3f, -2.0f, 0.1f), {0, 1, 0}, 0.5f, warm);
    for (const LightSampling& sampling : {random16, stratified16})
        check(v, below, sampling, 1000, 75, exact_light(below, p, under),
              "the eye and the light are both under the floor: with n turned to the eye, (0, -1, 0), the light "
              "falls on the side the eye sees");
    const AreaLight above = disc_light(target + vec3(0.3f, 2.0f, 0.1f), down, 0.5f, warm);
    const Estimate e = estimate(v, above, stratified16, 10, 76);
    INFO(describe(v, above, stratified16, e, dvec3(0.0), "the light is above the floor, the eye below it")
         << "; it sent " << e.feelers << " shadow feelers, expected none");
    CHECK(e.mean == dvec3(0.0));
    CHECK(e.feelers == 0);
}

GRADED_TEST("direct_light: a sample the least float from the point (d^2 = 2^-149, the least positive float) sends its feeler; one exactly at the point sends none", "05.4", 1)
{
    // d > 0 is the clause: the sample at the point itself is skipped, any other one is not, however
    // near. The one random sample of seed_half is u = (0.557..., 1/2): the point centre + 0.114 axis_u
    // + 0 axis_v. axis_v = (-8192, 0, 0) is long (so that the light's area, 2^-61, and its normal stay
    // normal floats) but is multiplied by 2 * 1/2 - 1 = 0; axis_u = (0, 0, 2^-76) moves the sample by
    // 0.114 * 2^-76, whose square is far below the least float. The centre is h = 1.5 * 2^-75 above
    // the point, so d^2 = h^2 = 2.25 * 2^-150 rounds to 2^-149.
    const point3 p{0.25f, 0.0f, 0.0f};
    const FloorView v = exact_floor_view(p);
    const LightSampling one{1, SampleScheme::random};
    const float h = std::ldexp(1.5f, -75), side = std::ldexp(1.0f, -76);
    const AreaLight hair = rectangle_light(p + vec3(0.0f, h, 0.0f), {0.0f, 0.0f, side}, {-8192.0f, 0.0f, 0.0f}, warm);
    {
        Rng check_rng(seed_half, 7);
        const float x = check_rng.next_float(), y = check_rng.next_float();
        const vec3 to_light{0.0f, h, (2.0f * x - 1.0f) * side};
        const float d2 = glm::dot(to_light, to_light);
        INFO("the seeded stream's first two numbers are " << x << " and " << y << ", the sample " << show(to_light)
             << " from the point, d^2 = " << d2 << "; the case needs y = 0.5 and d^2 = 2^-149");
        REQUIRE(y == 0.5f);
        REQUIRE(d2 == std::ldexp(1.0f, -149));
        REQUIRE(std::isnormal(light_area(hair)));
    }
    const Estimate near = estimate(v, hair, one, 1, seed_half);
    INFO("direct_light at " << show(v.hit.p) << " (floor normal (0, 1, 0)) from " << show(hair) << ", " << show(one)
         << ": its one sample lies " << h << " straight above the point (d^2 = 2^-149, the least positive float, n.l > 0, "
         << "cos_light > 0): it sent " << near.feelers << " shadow feelers, expected 1 (only a sample at distance 0 is skipped); "
         << "it returned (" << near.mean.x << ", " << near.mean.y << ", " << near.mean.z << "), expected no NaN");
    CHECK(near.feelers == 1);
    CHECK(!std::isnan(near.mean.x));
    const AreaLight none = disc_light(p, down, 0.0f, warm);
    const Estimate at = estimate(v, none, stratified16, 1, seed_half);
    INFO("direct_light at " << show(v.hit.p) << " from " << show(none) << ", " << show(stratified16)
         << ": every sample is the point itself (d = 0): it sent " << at.feelers << " shadow feelers, expected none, "
         << "and returned (" << at.mean.x << ", " << at.mean.y << ", " << at.mean.z << "), expected 0");
    CHECK(at.feelers == 0);
    CHECK(at.mean == dvec3(0.0));
}

GRADED_TEST("direct_light: a light the least float above the surface's plane and facing it (n.l = cos_light = 2^-149) gets a feeler a sample; the least float below it, or facing up, none", "05.4", 1)
{
    // The boundaries n.l > 0 and cos_light > 0 at the float's own resolution: a light 1 x 1 lying flat
    // beside the point, 2 to 3 away, at the height H = 2^-148 (the least float but one). Every point
    // of it, by any way of writing 05.1, lies exactly H above the floor, so l.y = H / d rounds to
    // 2^-149, the least positive float: n.l = 2^-149 > 0, and for the light glowing down
    // cos_light = l.y = 2^-149 > 0 too. At -H both are negative; glowing up, cos_light is.
    const point3 p{0.25f, 0.0f, 0.0f};
    const FloorView v = exact_floor_view(p);
    const float H = std::ldexp(1.0f, -148);
    const vec3 along_x{0.5f, 0.0f, 0.0f}, along_z{0.0f, 0.0f, 0.5f};
    for (const auto& [height, glows_down, feelers, why] :
         {std::tuple<float, bool, std::uint64_t, const char*>{H, true, 16, "n.l = cos_light = 2^-149 > 0 for every sample: one feeler a sample"},
          {-H, true, 0, "the light lies 2^-148 below the floor's plane: n.l = -2^-149 < 0, skip each sample"},
          {H, false, 0, "the light glows up, away from the point below it: cos_light = -2^-149 < 0, skip each sample"}}) {
        const point3 centre = p + vec3(2.5f, height, 0.0f);
        const AreaLight flat = glows_down ? rectangle_light(centre, along_x, along_z, warm)
                                          : rectangle_light(centre, along_z, along_x, warm);
        const Estimate e = estimate(v, flat, stratified16, 1, 78);
        INFO("direct_light at " << show(v.hit.p) << " (floor normal (0, 1, 0)) from " << show(flat) << ", "
             << show(stratified16) << ", every sample " << height << " above the floor and 2 to 3 away: it sent "
             << e.feelers << " shadow feelers, expected " << feelers << ": " << why);
        CHECK(e.feelers == feelers);
        CHECK(!std::isnan(e.mean.x));
    }
}

GRADED_TEST("direct_light: an eye ray climbing the least float (n.dir = 2^-149) sees the floor's underside; one along it (n.dir = 0) or sinking the least float, its top", "05.4", 1)
{
    // The normal is turned toward the eye as chapter 04's shade turns it: when n.dir > 0 the ray came
    // from behind the surface. At the float's resolution: the ray climbing 2^-149 per unit (from
    // 4 * 2^-149 below the floor) sees the underside, lit by a light below; the one sinking 2^-149
    // sees the top, lit by a light above, and so does one exactly along the floor (n.dir = 0: n kept).
    const point3 p{0.25f, 0.0f, 0.0f};
    FloorView v = exact_floor_view(p);
    v.hit.n = v.hit.ng = vec3(0.0f, 1.0f, 0.0f);
    const float least = std::ldexp(1.0f, -149);
    const AreaLight above = disc_light(p + vec3(0.3f, 2.0f, 0.1f), down, 0.5f, warm);
    const AreaLight below = disc_light(p + vec3(0.3f, -2.0f, 0.1f), {0, 1, 0}, 0.5f, warm);
    for (const float climb : {least, 0.0f, -least}) {
        const vec3 dir{0.0f, climb, -1.0f};
        v.ray = Ray{p - 4.0f * dir, dir};
        REQUIRE(glm::dot(v.hit.n, v.ray.dir) == climb);
        const bool underside = climb > 0.0f;
        for (const AreaLight* light : {&above, &below}) {
            const bool lights = (light == &below) == underside;
            const Estimate e = estimate(v, *light, stratified16, 10, 77);
            INFO("direct_light at " << show(v.hit.p) << " (floor normal (0, 1, 0)) seen along " << show(v.ray.dir)
                 << " (n.dir = " << climb << ", so the eye is " << (underside ? "below" : "above") << " the floor) from "
                 << show(*light) << ", " << show(stratified16) << " over 10 calls: got (" << e.mean.x << ", " << e.mean.y
                 << ", " << e.mean.z << ") with " << e.feelers << " shadow feelers; expected "
                 << (lights ? "light and 160 feelers" : "0 and no feeler") << ": with n turned toward the eye, "
                 << (underside ? "(0, -1, 0)" : "(0, 1, 0)") << ", the light " << (lights ? "falls on" : "lies behind")
                 << " the side the eye sees");
            CHECK(e.feelers == (lights ? 160u : 0u));
            CHECK((lights ? e.mean.x > 0.0 : e.mean == dvec3(0.0)));
        }
    }
}
