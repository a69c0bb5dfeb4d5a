// The behaviours every sphere test must show, written once and graded for the slide's test (02.1)
// and the precise one (02.2) in their own files.
#pragma once

#include "02_spheres_triangles/02_spheres_triangles.hpp"
#include "common/random.hpp"
#include "tests/ch02/describe.hpp"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace rt::grader::spheres {

using SphereTestFn = std::optional<float> (*)(const Ray&, const Sphere&, Interval);

inline std::string query(const Ray& ray, const Sphere& sphere, Interval range)
{
    return show(ray) + " against " + show(sphere) + ", " + show(range);
}

// Checks one answer against the exact one: the same hit or miss, and t within `tolerance`.
inline void check_against_exact(SphereTestFn test, const Ray& ray, const Sphere& sphere, Interval range,
                                double tolerance = 1e-6)
{
    const std::optional<float> got = test(ray, sphere, range);
    const exact::Answer want = exact::sphere(ray, sphere, range);
    INFO(query(ray, sphere, range) << ": got " << show(got) << ", expected " << show(want));
    REQUIRE(got.has_value() == want.hit);
    if (got)
        CHECK(rel_error(*got, static_cast<double>(want.t)) <= tolerance);
}

inline void centre_and_beside(SphereTestFn test)
{
    const Sphere sphere{{1, 2, -10}, 2};
    const Ray at_centre{{1, 2, 0}, {0, 0, -1}};  // |EO| = 10: the near side is 8 away
    const std::optional<float> t = test(at_centre, sphere, Interval{});
    INFO(query(at_centre, sphere, Interval{}) << ": got " << show(t) << ", expected t = 8 (|EO| - r)");
    REQUIRE(t);
    CHECK(*t == Approx(8.0f).epsilon(1e-6));
    for (const Ray& beside : {Ray{{3.5f, 2, 0}, {0, 0, -1}}, Ray{{1, -0.01f, 0}, {0, 0, -1}},
                              Ray{{1, 2, 0}, glm::normalize(vec3(0.3f, 0, -1))}}) {
        const std::optional<float> none = test(beside, sphere, Interval{});
        INFO(query(beside, sphere, Interval{}) << ": got " << show(none) << ", expected no hit: it passes beside");
        CHECK_FALSE(none);
    }
}

inline void off_centre(SphereTestFn test)
{
    const Sphere sphere{{-0.5f, 1.0f, -6.0f}, 1.5f};
    for (const vec3 towards : {vec3(-0.2f, 0.3f, -5.5f), vec3(0.5f, 1.8f, -5.0f), vec3(-1.7f, 0.2f, -7.0f)}) {
        const Ray ray{{0.3f, 0.1f, 0.4f}, glm::normalize(towards - vec3(0.3f, 0.1f, 0.4f))};
        check_against_exact(test, ray, sphere, Interval{});
        if (const std::optional<float> t = test(ray, sphere, Interval{})) {
            const float from_centre = glm::length(ray.at(*t) - sphere.centre);
            INFO(query(ray, sphere, Interval{}) << ": the point at t = " << *t << " lies " << from_centre
                 << " from the centre, expected the radius 1.5");
            CHECK(std::abs(from_centre - 1.5f) <= 1e-5f);
        }
    }
}

inline void from_inside(SphereTestFn test)
{
    // From the centre every way out is r long; from off-centre, the far side along +x is at 3 - 1.
    const Sphere sphere{{0, 0, 0}, 3};
    for (const vec3 dir : {vec3(1, 0, 0), vec3(0, 0, -1), glm::normalize(vec3(1, -2, 3))}) {
        const Ray ray{{0, 0, 0}, dir};
        const std::optional<float> t = test(ray, sphere, Interval{});
        INFO(query(ray, sphere, Interval{}) << ": the ray starts at the centre; got " << show(t)
             << ", expected t = 3 (e + d: the near root is behind the ray)");
        REQUIRE(t);
        CHECK(*t == Approx(3.0f).epsilon(1e-6));
    }
    const Ray off{{1, 0, 0}, {1, 0, 0}};
    const std::optional<float> t = test(off, sphere, Interval{});
    INFO(query(off, sphere, Interval{}) << ": got " << show(t) << ", expected t = 2");
    REQUIRE(t);
    CHECK(*t == Approx(2.0f).epsilon(1e-6));
}

inline void range_respected(SphereTestFn test)
{
    const Sphere sphere{{0, 0, -5}, 1};  // along -z from the origin: the near side at 4, the far at 6
    struct Case {
        Ray ray;
        Interval range;
        float expected;  // 0: no hit
    };
    const Ray ahead{{0, 0, 0}, {0, 0, -1}}, away{{0, 0, 0}, {0, 0, 1}};
    for (const Case& c : {Case{ahead, {1e-4f, 3.0f}, 0}, Case{ahead, {1e-4f, 5.0f}, 4}, Case{ahead, {4.5f, infinity}, 6},
                          Case{ahead, {6.5f, infinity}, 0}, Case{away, {1e-4f, infinity}, 0}}) {
        const std::optional<float> t = test(c.ray, sphere, c.range);
        INFO(query(c.ray, sphere, c.range) << ": got " << show(t) << ", expected "
             << (c.expected > 0 ? "t = " + std::to_string(c.expected) : std::string("no hit")));
        CHECK(t.has_value() == (c.expected > 0));
        if (t && c.expected > 0)
            CHECK(*t == Approx(c.expected).epsilon(1e-6));
    }
}

// The range is open at both ends: along -z from the origin the unit sphere at (0, 0, -5) is met at
// t = 4 and t = 6 exactly (every product is exact), and each end of the range sits on one of them
// and one float step either side.
inline void range_ends(SphereTestFn test)
{
    const Sphere sphere{{0, 0, -5}, 1};
    const Ray ahead{{0, 0, 0}, {0, 0, -1}};
    const float before_4 = std::nextafter(4.0f, 0.0f), past_4 = std::nextafter(4.0f, 5.0f);
    const float before_6 = std::nextafter(6.0f, 0.0f), past_6 = std::nextafter(6.0f, 7.0f);
    struct Case {
        Interval range;
        float expected;  // 0: no hit
    };
    for (const Case& c : {Case{{4.0f, infinity}, 6}, Case{{before_4, infinity}, 4}, Case{{past_4, infinity}, 6},
                          Case{{1e-4f, 4.0f}, 0}, Case{{1e-4f, past_4}, 4}, Case{{4.0f, 6.0f}, 0},
                          Case{{4.0f, past_6}, 6}, Case{{6.0f, infinity}, 0}, Case{{before_6, infinity}, 6}}) {
        const std::optional<float> t = test(ahead, sphere, c.range);
        std::ostringstream expected;
        expected << std::setprecision(9);
        (c.expected > 0 ? expected << "t = " << c.expected : expected << "no hit");
        INFO(query(ahead, sphere, c.range) << " (the sphere is met at t = 4 and t = 6; the range is open): got "
             << show(t) << ", expected " << expected.str());
        CHECK(t.has_value() == (c.expected > 0));
        if (t && c.expected > 0)
            CHECK(*t == c.expected);
    }
}

// Tangent rays along +x at height y past a unit sphere whose centre lies `distance` ahead: at
// y = 1 the discriminant is exactly 0 (no hit); one float step below 1 the ray enters (a hit,
// near t = distance); one step above it passes by. Axis-aligned, so every product is exact.
inline void tangent(SphereTestFn test, float distance)
{
    const Sphere sphere{{distance - 3.0f, 0, -2}, 1};
    const float at = 1.0f, inside = std::nextafter(1.0f, 0.0f), outside = std::nextafter(1.0f, 2.0f);
    for (const float y : {at, inside, outside}) {
        const Ray ray{{-3.0f, y, -2}, {1, 0, 0}};
        const std::optional<float> t = test(ray, sphere, Interval{});
        const exact::Answer want = exact::sphere(ray, sphere, Interval{});
        INFO(query(ray, sphere, Interval{}) << " (height " << y << " above the centre): got " << show(t)
             << ", expected " << show(want));
        REQUIRE(t.has_value() == want.hit);
        CHECK(t.has_value() == (y == inside));
        if (t)
            CHECK(rel_error(*t, static_cast<double>(want.t)) <= 1e-6);
    }
}

// Rays broken upstream, with a NaN or an infinity in their origin or direction, hit nothing (so a
// NaN never reaches a pixel), and the same sphere is still hit by a sound ray.
inline void broken_rays(SphereTestFn test)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const Sphere sphere{{0, 0, -5}, 1};
    for (const Ray& ray : {Ray{{nan, 0, 0}, {0, 0, -1}}, Ray{{0, 0, 0}, {nan, nan, nan}}, Ray{{0, 0, infinity}, {0, 0, -1}},
                           Ray{{0, 0, 0}, {0, 0, -infinity}}, Ray{{-infinity, 0, -5}, {1, 0, 0}}}) {
        const std::optional<float> t = test(ray, sphere, Interval{});
        INFO(query(ray, sphere, Interval{}) << ": got " << show(t) << ", expected no hit");
        CHECK_FALSE(t);
    }
    const Ray sound{{0, 0, 0}, {0, 0, -1}};
    INFO(query(sound, sphere, Interval{}) << ": expected a hit at t = 4");
    CHECK(test(sound, sphere, Interval{}));
}

// Runs a sphere test on an extreme case and scores it against the exact answers.
inline extremes::Score run_case(SphereTestFn test, const std::vector<extremes::SphereProbe<float>>& probes,
                                std::vector<std::optional<float>>& answers)
{
    extremes::run(probes, test, answers);
    return extremes::score(probes, answers);
}

// Rays from inside always hit, on the far side. Their t is small when the ray starts near the
// surface and heads out, and c = |f|^2 - r^2 then cancels: from 0.999 r out, c is 0.002 r^2 and
// keeps about 3 u / 0.002 of relative error (u = 2^-24), so t is checked to 1e-4.
inline void from_inside_everywhere(SphereTestFn test)
{
    const std::vector<extremes::SphereProbe<float>> probes = extremes::inside_sphere<float>(20000, 11);
    std::vector<std::optional<float>> answers;
    const extremes::Score score = run_case(test, probes, answers);
    INFO(describe("rays from inside a unit sphere, in every direction", probes, answers, score));
    CHECK(score.wrong == 0);
    CHECK(score.max_rel_t_error <= 1e-4);
}

// In double the test keeps double's precision: seeded rays from near the origin at spheres up to 20
// away, aimed up to 1.5 r from the centre, hit or miss as the exact answer says and t is within
// 1e-10 of it (a ray that close to tangent, where double cannot tell, is one in 1e14). A float
// slipped into the double version (a float local, a float literal in a product) costs 1e-7 there.
inline void keeps_double_precision(std::optional<double> (*test)(const BasicRay<double>&, const BasicSphere<double>&,
                                                                 BasicInterval<double>))
{
    Rng rng(17, 5);
    const auto uniform = [&rng](double lo, double hi) { return lo + (hi - lo) * static_cast<double>(rng.next_float()); };
    for (int k = 0; k < 2000; ++k) {
        const dvec3 origin{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
        const dvec3 centre{uniform(-20, 20), uniform(-20, 20), uniform(-20, -2)};
        const double radius = uniform(0.1, 1.5);
        // A target across the ray's way, up to 1.5 r from the centre: about half the rays hit.
        const dvec3 across = glm::normalize(glm::cross(centre - origin, dvec3(uniform(-1, 1), 1, uniform(-1, 1))));
        const dvec3 target = centre + uniform(0, 1.5) * radius * across;
        const BasicRay<double> ray{origin, glm::normalize(target - origin)};
        const BasicSphere<double> sphere{centre, radius};
        const BasicInterval<double> range{};
        const std::optional<double> got = test(ray, sphere, range);
        const exact::Answer want = exact::sphere(ray, sphere, range);
        std::ostringstream answers;
        answers << std::setprecision(17) << "got ";
        (got ? answers << "t = " << *got : answers << "no hit") << ", expected ";
        (want.hit ? answers << "t = " << static_cast<double>(want.t) : answers << "no hit");
        INFO("in double: the ray from " << std::setprecision(17) << origin.x << ", " << origin.y << ", " << origin.z
             << " along " << ray.dir.x << ", " << ray.dir.y << ", " << ray.dir.z << " against the sphere at "
             << centre.x << ", " << centre.y << ", " << centre.z << " of radius " << radius << ": " << answers.str());
        REQUIRE(got.has_value() == want.hit);
        if (got)
            REQUIRE(std::abs(*got - static_cast<double>(want.t)) <= 1e-10 * static_cast<double>(want.t));
    }
}

}  // namespace rt::grader::spheres

// The graded cases every sphere test gets, named after the function and graded as exercise
// `number`: a ray at the centre and rays beside it, off-centre rays, rays from inside, the range,
// the double version's precision, and (stability) rays from inside in every direction and rays
// with a NaN or an infinity.
#define RT_SPHERE_BEHAVIOURS(function, number)                                                                   \
    GRADED_TEST(#function ": a ray aimed at the centre hits the near side, rays beside the sphere miss", number, 3) \
    {                                                                                                              \
        rt::grader::spheres::centre_and_beside(&function<float>);                                                 \
    }                                                                                                              \
    GRADED_TEST(#function ": off-centre rays hit where the exact answer says, on the surface", number, 2)          \
    {                                                                                                              \
        rt::grader::spheres::off_centre(&function<float>);                                                        \
    }                                                                                                              \
    GRADED_TEST(#function ": a ray that starts inside hits the far side (t = e + d)", number, 2)                   \
    {                                                                                                              \
        rt::grader::spheres::from_inside(&function<float>);                                                       \
    }                                                                                                              \
    GRADED_TEST(#function ": only hits inside the range count; past the near side comes the far one", number, 2)  \
    {                                                                                                              \
        rt::grader::spheres::range_respected(&function<float>);                                                   \
    }                                                                                                              \
    GRADED_TEST(#function ": a hit exactly at range.min or range.max does not count; one float step inside does", number, 2) \
    {                                                                                                              \
        rt::grader::spheres::range_ends(&function<float>);                                                        \
    }                                                                                                              \
    GRADED_TEST(#function ": in double, hits and misses as exact and t within 1e-10 of it", number, 1)               \
    {                                                                                                              \
        rt::grader::spheres::keeps_double_precision(&function<double>);                                           \
    }                                                                                                              \
    STABILITY_TEST(#function ": rays from inside, in every direction, all hit the far side", number, 1)           \
    {                                                                                                              \
        rt::grader::spheres::from_inside_everywhere(&function<float>);                                            \
    }                                                                                                              \
    STABILITY_TEST(#function ": rays with a NaN or an infinity in them hit nothing", number, 1)                   \
    {                                                                                                              \
        rt::grader::spheres::broken_rays(&function<float>);                                                       \
    }
