// The behaviours every triangle test must show, written once and graded for the slide's test
// (02.3), Moller-Trumbore (02.4) and the watertight test (02.5) in their own files.
#pragma once

#include "02_spheres_triangles/02_spheres_triangles.hpp"
#include "common/random.hpp"
#include "tests/ch02/describe.hpp"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace rt::grader::triangles {

using TriangleTestFn = std::optional<TriangleHit<float>> (*)(const Ray&, const Triangle&, Interval);

inline std::string query(const Ray& ray, const Triangle& tri, Interval range)
{
    return show(ray) + " against " + show(tri) + ", " + show(range);
}

inline point3 at_barycentric(const Triangle& tri, float beta, float gamma)
{
    return tri.a + beta * (tri.b - tri.a) + gamma * (tri.c - tri.a);
}

// t and the barycentric coordinates of a hit on a triangle a few units across are right to a few
// float roundings of their inputs (u = 6e-8 each) when the ray crosses the plane steeply; 1e-5
// leaves room for the longest chain of them and still catches a wrong formula.
constexpr double tolerance = 1e-5;

// A triangle in no special orientation, seen from the origin.
const Triangle tilted{{-1.0f, -1.0f, -4.0f}, {2.0f, -0.5f, -5.0f}, {0.0f, 2.0f, -4.5f}};

inline void inside_and_beside(TriangleTestFn test)
{
    const Ray from_eye{{0, 0, 0}, {0, 0, -1}};
    for (const auto& [beta, gamma] : {std::pair{0.2f, 0.3f}, std::pair{0.6f, 0.1f}, std::pair{0.1f, 0.7f}}) {
        const point3 target = at_barycentric(tilted, beta, gamma);
        const Ray ray{from_eye.origin, glm::normalize(target)};
        const std::optional<TriangleHit<float>> hit = test(ray, tilted, Interval{});
        const exact::Answer want = exact::triangle(ray, tilted, Interval{});
        INFO(query(ray, tilted, Interval{}) << ", aimed at beta = " << beta << ", gamma = " << gamma << ": got "
             << show(hit) << ", expected t = " << static_cast<double>(want.t));
        REQUIRE(hit);
        CHECK(rel_error(hit->t, static_cast<double>(want.t)) <= tolerance);
        CHECK(std::abs(hit->beta - beta) <= static_cast<float>(tolerance));
        CHECK(std::abs(hit->gamma - gamma) <= static_cast<float>(tolerance));
    }
    // Just outside each edge in turn: past a-b (gamma < 0), past c-a (beta < 0), past b-c.
    for (const auto& [beta, gamma] : {std::pair{0.5f, -0.02f}, std::pair{-0.02f, 0.5f}, std::pair{0.55f, 0.47f}}) {
        const Ray ray{from_eye.origin, glm::normalize(at_barycentric(tilted, beta, gamma))};
        const std::optional<TriangleHit<float>> hit = test(ray, tilted, Interval{});
        INFO(query(ray, tilted, Interval{}) << ", aimed just outside, at beta = " << beta << ", gamma = " << gamma
             << ": got " << show(hit) << ", expected no hit");
        CHECK_FALSE(hit);
    }
}

inline void both_faces(TriangleTestFn test)
{
    // The same point from in front (the origin) and from behind: no face is culled.
    const point3 target = at_barycentric(tilted, 0.3f, 0.3f);
    for (const point3& origin : {point3(0, 0, 0), point3(1, 1, -9)}) {
        const Ray ray{origin, glm::normalize(target - origin)};
        const std::optional<TriangleHit<float>> hit = test(ray, tilted, Interval{});
        INFO(query(ray, tilted, Interval{}) << ": got " << show(hit) << ", expected a hit at beta = gamma = 0.3, t = "
             << glm::length(target - origin));
        REQUIRE(hit);
        CHECK(hit->t == Approx(glm::length(target - origin)).epsilon(tolerance));
        CHECK(std::abs(hit->beta - 0.3f) <= static_cast<float>(tolerance));
        CHECK(std::abs(hit->gamma - 0.3f) <= static_cast<float>(tolerance));
    }
}

inline void edges_and_corners(TriangleTestFn test)
{
    // In the plane z = 0 with rays straight down, every number below is exact: the points lie on
    // the edges and corners themselves, which belong to the triangle.
    const Triangle tri{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
    struct Case {
        float x, y, beta, gamma;
        const char* where;
    };
    for (const Case& c : {Case{2, 0, 0.5f, 0, "the middle of edge a-b"}, Case{2, 2, 0.5f, 0.5f, "the middle of edge b-c"},
                          Case{0, 1, 0, 0.25f, "a point of edge c-a"}, Case{0, 0, 0, 0, "corner a"},
                          Case{4, 0, 1, 0, "corner b"}, Case{0, 4, 0, 1, "corner c"}}) {
        const Ray ray{{c.x, c.y, 3}, {0, 0, -1}};
        const std::optional<TriangleHit<float>> hit = test(ray, tri, Interval{});
        INFO(query(ray, tri, Interval{}) << ", through " << c.where << ": got " << show(hit)
             << ", expected t = 3, beta = " << c.beta << ", gamma = " << c.gamma);
        REQUIRE(hit);
        CHECK(hit->t == Approx(3.0f).epsilon(1e-6));
        CHECK(hit->beta == Approx(c.beta).margin(1e-6));
        CHECK(hit->gamma == Approx(c.gamma).margin(1e-6));
    }
}

inline void parallel(TriangleTestFn test)
{
    // In the plane z = -2: rays within the plane and above it, parallel to it, miss; rays tilted
    // toward it by a small angle hit where the exact answer says.
    const Triangle tri{{-1, -1, -2}, {3, -1, -2}, {-1, 3, -2}};
    for (const Ray& ray : {Ray{{-3, 0.5f, -2}, {1, 0, 0}}, Ray{{-3, 0.5f, -1}, {1, 0, 0}},
                           Ray{{0, 0, -1.5f}, glm::normalize(vec3(1, 1, 0))}}) {
        const std::optional<TriangleHit<float>> hit = test(ray, tri, Interval{});
        INFO(query(ray, tri, Interval{}) << ": got " << show(hit) << ", expected no hit: the ray is parallel");
        CHECK_FALSE(hit);
    }
    for (double angle = 1e-1; angle >= 1e-6; angle /= 10) {
        const vec3 dir{static_cast<float>(std::cos(angle)), 0.0f, static_cast<float>(-std::sin(angle))};
        const point3 target{1.0f, 0.5f, -2.0f};
        const Ray ray{target - dir, dir};
        const std::optional<TriangleHit<float>> hit = test(ray, tri, Interval{});
        const exact::Answer want = exact::triangle(ray, tri, Interval{});
        INFO(query(ray, tri, Interval{}) << " (" << angle << " radians from parallel): got " << show(hit)
             << ", expected " << show(want));
        REQUIRE(hit.has_value() == want.hit);
        REQUIRE(hit);
        CHECK(rel_error(hit->t, static_cast<double>(want.t)) <= tolerance);
    }
}

// The right triangle (0, 0, 0), (1, 0, 0), (0, 1, 0) seen straight down and straight up through
// (x, y), inside it and at each edge's midpoint: every quantity a test divides by (n.v, the
// determinant, U + V + W) is exactly 1 or -1 here, an edge's product difference is exactly 0, and
// t = 1, beta = x and gamma = y come out exact.
inline void axis_aligned(TriangleTestFn test)
{
    const Triangle tri{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (const auto& [x, y] : {std::pair{0.25f, 0.25f}, std::pair{0.5f, 0.5f}, std::pair{0.0f, 0.5f}, std::pair{0.5f, 0.0f}})
        for (const float down : {1.0f, -1.0f}) {
            const Ray ray{{x, y, down}, {0, 0, -down}};
            const std::optional<TriangleHit<float>> hit = test(ray, tri, Interval{});
            INFO(query(ray, tri, Interval{}) << ": got " << show(hit) << ", expected t = 1, beta = " << x << ", gamma = " << y
                 << (x == 0 || y == 0 || x + y == 1 ? " (the point is on an edge: edges are inside)" : ""));
            REQUIRE(hit);
            CHECK(hit->t == 1.0f);
            CHECK(hit->beta == x);
            CHECK(hit->gamma == y);
        }
}

inline void range_respected(TriangleTestFn test)
{
    const Triangle tri{{-1, -1, -5}, {1, -1, -5}, {0, 1, -5}};  // straight ahead along -z at t = 5
    const Ray ahead{{0, 0, 0}, {0, 0, -1}}, away{{0, 0, 0}, {0, 0, 1}};
    struct Case {
        Ray ray;
        Interval range;
        bool hits;
    };
    for (const Case& c : {Case{ahead, {1e-4f, 6.0f}, true}, Case{ahead, {4.9f, 5.1f}, true}, Case{ahead, {1e-4f, 4.0f}, false},
                          Case{ahead, {5.5f, infinity}, false}, Case{away, {1e-4f, infinity}, false}}) {
        const std::optional<TriangleHit<float>> hit = test(c.ray, tri, c.range);
        INFO(query(c.ray, tri, c.range) << ": got " << show(hit) << ", expected "
             << (c.hits ? "t = 5" : "no hit"));
        CHECK(hit.has_value() == c.hits);
        if (hit && c.hits)
            CHECK(hit->t == Approx(5.0f).epsilon(1e-6));
    }
}

// The range is open at both ends: the triangle straight ahead is met at t = 5 exactly, and each end
// of the range sits on it and one float step either side.
inline void range_ends(TriangleTestFn test)
{
    const Triangle tri{{-1, -1, -5}, {1, -1, -5}, {0, 1, -5}};
    const Ray ahead{{0, 0, 0}, {0, 0, -1}};
    const float before = std::nextafter(5.0f, 0.0f), past = std::nextafter(5.0f, 6.0f);
    struct Case {
        Interval range;
        bool hits;
    };
    for (const Case& c : {Case{{5.0f, infinity}, false}, Case{{before, infinity}, true}, Case{{past, infinity}, false},
                          Case{{1e-4f, 5.0f}, false}, Case{{1e-4f, past}, true}, Case{{1e-4f, before}, false}}) {
        const std::optional<TriangleHit<float>> hit = test(ahead, tri, c.range);
        INFO(query(ahead, tri, c.range) << " (the triangle is met at t = 5; the range is open): got " << show(hit)
             << ", expected " << (c.hits ? "t = 5" : "no hit"));
        CHECK(hit.has_value() == c.hits);
        if (hit && c.hits)
            CHECK(hit->t == 5.0f);
    }
}

// Edges and corners belong to the triangle, and a float step beyond them does not. In the plane
// z = 0, with corners (1, 1), (5, 1), (1, 5) and rays straight down from z = 3, every difference and
// product is exact: a point one float step outside edge a-b (y just below 1), edge c-a (x just below
// 1) or corner a misses, and one step inside hits. Along edge b-c (x + y = 6) the point (1.5, 4.5)
// has beta = 1/8 and gamma = 7/8, and one float step of y either way moves beta + gamma one float
// step off 1.
inline void edge_steps(TriangleTestFn test)
{
    const Triangle tri{{1, 1, 0}, {5, 1, 0}, {1, 5, 0}};
    const float below_1 = std::nextafter(1.0f, 0.0f), above_1 = std::nextafter(1.0f, 2.0f);
    const float below_45 = std::nextafter(4.5f, 0.0f), above_45 = std::nextafter(4.5f, 5.0f);
    struct Case {
        float x, y;
        bool hits;
        const char* where;
    };
    for (const Case& c : {Case{3, 1, true, "on edge a-b"}, Case{3, below_1, false, "one float step outside edge a-b"},
                          Case{3, above_1, true, "one float step inside edge a-b"},
                          Case{1, 3, true, "on edge c-a"}, Case{below_1, 3, false, "one float step outside edge c-a"},
                          Case{above_1, 3, true, "one float step inside edge c-a"},
                          Case{1.5f, 4.5f, true, "on edge b-c"}, Case{1.5f, above_45, false, "one float step outside edge b-c"},
                          Case{1.5f, below_45, true, "one float step inside edge b-c"},
                          Case{1, 1, true, "on corner a"}, Case{below_1, below_1, false, "one float step outside corner a"},
                          Case{above_1, above_1, true, "one float step inside corner a"}}) {
        const Ray ray{{c.x, c.y, 3}, {0, 0, -1}};
        const std::optional<TriangleHit<float>> hit = test(ray, tri, Interval{});
        std::ostringstream at;
        at << std::setprecision(9) << "(" << c.x << ", " << c.y << ")";
        INFO(query(ray, tri, Interval{}) << ", through " << at.str() << ", " << c.where << ": got " << show(hit)
             << ", expected " << (c.hits ? "a hit at t = 3" : "no hit"));
        CHECK(hit.has_value() == c.hits);
        if (hit && c.hits)
            CHECK(hit->t == Approx(3.0f).epsilon(1e-6));
    }
}

// Rays broken upstream, with a NaN or an infinity in their origin or direction, hit nothing (so a
// NaN never reaches a pixel), and the same triangle is still hit by a sound ray.
inline void broken_rays(TriangleTestFn test)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const Triangle tri{{-1, -1, -5}, {1, -1, -5}, {0, 1, -5}};
    for (const Ray& ray : {Ray{{nan, 0, 0}, {0, 0, -1}}, Ray{{0, 0, 0}, {nan, nan, nan}}, Ray{{0, 0, infinity}, {0, 0, -1}},
                           Ray{{0, 0, 0}, {0, 0, -infinity}}, Ray{{0, 0, 0}, {infinity, 0, -1}}}) {
        const std::optional<TriangleHit<float>> hit = test(ray, tri, Interval{});
        INFO(query(ray, tri, Interval{}) << ": got " << show(hit) << ", expected no hit");
        CHECK_FALSE(hit);
    }
    const Ray sound{{0, 0, 0}, {0, 0, -1}};
    INFO(query(sound, tri, Interval{}) << ": expected a hit at t = 5");
    CHECK(test(sound, tri, Interval{}));
}

// Triangles so small that their edge products underflow (1e-15 to 1e-25 across, ahead at 1): whatever
// a test answers, never a NaN. A miss, or a hit with a finite t near 1 and barycentrics in [0, 1].
inline void underflowing(TriangleTestFn test)
{
    for (const float size : {1e-15f, 1e-20f, 1e-25f}) {
        const Triangle tri{{-size, -size, -1}, {size, -size, -1}, {0, size, -1}};
        const Ray ray{{0, 0, 0}, {0, 0, -1}};
        const std::optional<TriangleHit<float>> hit = test(ray, tri, Interval{});
        INFO(query(ray, tri, Interval{}) << ": got " << show(hit)
             << ", expected no hit, or a hit at t = 1 with barycentrics in [0, 1]");
        const bool sound = !hit || (std::abs(hit->t - 1.0f) <= 1e-6f && hit->beta >= 0 && hit->beta <= 1 &&
                                    hit->gamma >= 0 && hit->gamma <= 1);
        CHECK(sound);
    }
    const Triangle unit{{-1, -1, -1}, {1, -1, -1}, {0, 1, -1}};
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    INFO(query(ray, unit, Interval{}) << ": expected a hit at t = 1");
    CHECK(test(ray, unit, Interval{}));
}

// Runs a triangle test on an extreme case and scores it.
inline extremes::Score run_case(TriangleTestFn test, const extremes::TriangleProbes<float>& probes,
                                std::vector<extremes::TriangleAnswer<float>>& answers)
{
    extremes::run(probes, test, answers);
    return extremes::score(probes, answers);
}

// Degenerate triangles are never hit (and so never give a NaN), while a proper triangle beside
// them is. `which` picks from extremes::degenerate_triangles().
inline void degenerate(TriangleTestFn test, const std::vector<int>& which)
{
    const extremes::TriangleProbes<float> all = extremes::degenerate<float>(200, 13);
    extremes::TriangleProbes<float> probes;
    probes.expect = all.expect;
    probes.triangles = all.triangles;
    for (size_t k = 0; k < all.rays.size(); ++k)
        if (std::find(which.begin(), which.end(), all.targets[k][0]) != which.end())
            probes.add(all.rays[k], all.targets[k]);
    std::vector<extremes::TriangleAnswer<float>> answers;
    const extremes::Score score = run_case(test, probes, answers);
    INFO(describe("rays aimed at the corners and midpoints of triangles without area", probes, answers, score));
    CHECK(score.wrong == 0);

    const Triangle proper{{0.25f, -0.5f, 1.0f}, {1.5f, 0.75f, -0.5f}, {0.0f, 1.0f, 0.0f}};
    const Ray ray{{5, 5, 5}, glm::normalize(at_barycentric(proper, 0.3f, 0.3f) - point3(5, 5, 5))};
    const std::optional<TriangleHit<float>> hit = test(ray, proper, Interval{});
    INFO(query(ray, proper, Interval{}) << ": got " << show(hit) << ", expected a hit: this one has an area");
    CHECK(hit);
}

// Triangles from 1e-4 to 1e6 across, placed as far from the origin as they are large, are hit like
// unit ones: no tolerance in the test may depend on the scene's scale.
inline void every_scale(TriangleTestFn test)
{
    Rng rng(14, 0);
    for (const float scale : {1e-4f, 1e-2f, 1.0f, 1e2f, 1e4f, 1e6f}) {
        const Triangle tri{scale * point3(1.0f, 2.0f, -3.0f), scale * point3(2.2f, 2.1f, -3.4f),
                           scale * point3(1.4f, 3.3f, -2.5f)};
        const vec3 n = glm::normalize(glm::cross(tri.b - tri.a, tri.c - tri.a));
        for (int k = 0; k < 200; ++k) {
            const float beta = 0.05f + 0.4f * rng.next_float(), gamma = 0.05f + 0.4f * rng.next_float();
            const point3 target = at_barycentric(tri, beta, gamma);
            const Ray ray = extremes::ray_towards<float>(target + 3.0f * scale * glm::normalize(n + 0.5f * extremes::random_unit_vector(rng)), target);
            const std::optional<TriangleHit<float>> hit = test(ray, tri, Interval{0.0f, infinity});
            const exact::Answer want = exact::triangle(ray, tri, Interval{0.0f, infinity});
            INFO(query(ray, tri, Interval{0.0f, infinity}) << " (scale " << scale << "): got " << show(hit)
                 << ", expected " << show(want));
            REQUIRE(hit.has_value() == want.hit);
            REQUIRE(hit);
            CHECK(rel_error(hit->t, static_cast<double>(want.t)) <= tolerance);
        }
    }
}

// The contract takes any non-zero direction and measures t in its lengths: 1000 times longer,
// 1000 times smaller t.
inline void any_direction_length(TriangleTestFn test)
{
    const point3 target = at_barycentric(tilted, 0.25f, 0.35f);
    const vec3 unit = glm::normalize(target);
    for (const float length : {1e-3f, 0.5f, 1.0f, 7.0f, 1e3f}) {
        const Ray ray{{0, 0, 0}, length * unit};
        const std::optional<TriangleHit<float>> hit = test(ray, tilted, Interval{0.0f, infinity});
        INFO(query(ray, tilted, Interval{0.0f, infinity}) << " (a direction " << length << " long): got " << show(hit)
             << ", expected t = " << glm::length(target) / length);
        REQUIRE(hit);
        CHECK(hit->t == Approx(glm::length(target) / length).epsilon(tolerance));
    }
}

// In double the test keeps double's precision: seeded rays from near the origin at triangles up to
// 20 away, aimed at barycentric points from -0.3 to 1.2 (about half inside), hit or miss as the
// exact answer says, with t within 1e-10 of it and the barycentrics within 1e-9 of the aimed ones.
// A float slipped into the double version costs 1e-7 there.
inline void keeps_double_precision(std::optional<TriangleHit<double>> (*test)(const BasicRay<double>&,
                                                                              const BasicTriangle<double>&,
                                                                              BasicInterval<double>))
{
    Rng rng(19, 6);
    const auto uniform = [&rng](double lo, double hi) { return lo + (hi - lo) * static_cast<double>(rng.next_float()); };
    const auto random_point = [&](double lo_z, double hi_z) {
        return dvec3(uniform(-10, 10), uniform(-10, 10), uniform(lo_z, hi_z));
    };
    for (int k = 0; k < 2000; ++k) {
        const dvec3 origin = random_point(-1, 1);
        const dvec3 a = random_point(-20, -3);
        const BasicTriangle<double> tri{a, a + dvec3(uniform(-3, 3), uniform(-3, 3), uniform(-1, 1)),
                                        a + dvec3(uniform(-3, 3), uniform(-3, 3), uniform(-1, 1))};
        const double beta = uniform(-0.3, 1.2), gamma = uniform(-0.3, 1.2) * (1.0 - 0.5 * beta);
        const dvec3 target = tri.a + beta * (tri.b - tri.a) + gamma * (tri.c - tri.a);
        const BasicRay<double> ray{origin, glm::normalize(target - origin)};
        const BasicInterval<double> range{};
        const std::optional<TriangleHit<double>> got = test(ray, tri, range);
        const exact::Answer want = exact::triangle(ray, tri, range);
        std::ostringstream answers;
        answers << std::setprecision(17) << "got ";
        (got ? answers << "t = " << got->t << ", beta = " << got->beta << ", gamma = " << got->gamma : answers << "no hit")
            << ", expected ";
        (want.hit ? answers << "t = " << static_cast<double>(want.t) : answers << "no hit");
        INFO("in double: the ray from " << std::setprecision(17) << origin.x << ", " << origin.y << ", " << origin.z
             << " aimed at barycentrics " << beta << ", " << gamma << " of the triangle a = " << tri.a.x << ", "
             << tri.a.y << ", " << tri.a.z << ", b = " << tri.b.x << ", " << tri.b.y << ", " << tri.b.z << ", c = "
             << tri.c.x << ", " << tri.c.y << ", " << tri.c.z << ": " << answers.str());
        REQUIRE(got.has_value() == want.hit);
        if (got) {
            REQUIRE(std::abs(got->t - static_cast<double>(want.t)) <= 1e-10 * static_cast<double>(want.t));
            REQUIRE(std::abs(got->beta - beta) <= 1e-9);
            REQUIRE(std::abs(got->gamma - gamma) <= 1e-9);
        }
    }
}

}  // namespace rt::grader::triangles

// The graded cases every triangle test gets, named after the function and graded as exercise
// `number`: rays inside and just outside, both faces, edges and corners, parallel rays, the range,
// the double version's precision, and (stability) every scale, any direction length, rays with a
// NaN or an infinity, and triangles whose products underflow.
#define RT_TRIANGLE_BEHAVIOURS(function, number)                                                                      \
    GRADED_TEST(#function ": rays into the triangle hit with the right t and barycentrics; just outside an edge, none does", \
                number, 3)                                                                                             \
    {                                                                                                                  \
        rt::grader::triangles::inside_and_beside(&function<float>);                                                   \
    }                                                                                                                  \
    GRADED_TEST(#function ": the triangle is hit from behind as well as from in front", number, 2)                    \
    {                                                                                                                  \
        rt::grader::triangles::both_faces(&function<float>);                                                          \
    }                                                                                                                  \
    GRADED_TEST(#function ": rays through an edge or a corner hit, with barycentrics 0 and 1 there", number, 2)       \
    {                                                                                                                  \
        rt::grader::triangles::edges_and_corners(&function<float>);                                                   \
    }                                                                                                                  \
    GRADED_TEST(#function ": rays parallel to the plane miss; rays nearly parallel hit where the exact answer says",   \
                number, 2)                                                                                             \
    {                                                                                                                  \
        rt::grader::triangles::parallel(&function<float>);                                                            \
    }                                                                                                                  \
    GRADED_TEST(#function ": the unit right triangle in z = 0 seen straight down and up, inside and at each edge: t = 1 and exact barycentrics", \
                number, 1)                                                                                             \
    {                                                                                                                  \
        rt::grader::triangles::axis_aligned(&function<float>);                                                        \
    }                                                                                                                  \
    GRADED_TEST(#function ": only hits inside the range count, never one behind the origin", number, 2)               \
    {                                                                                                                  \
        rt::grader::triangles::range_respected(&function<float>);                                                     \
    }                                                                                                                  \
    GRADED_TEST(#function ": a hit exactly at range.min or range.max does not count; one float step inside does", \
                number, 2)                                                                                             \
    {                                                                                                                  \
        rt::grader::triangles::range_ends(&function<float>);                                                          \
    }                                                                                                                  \
    GRADED_TEST(#function ": one float step outside an edge or a corner misses; on it and one step inside hit",       \
                number, 2)                                                                                             \
    {                                                                                                                  \
        rt::grader::triangles::edge_steps(&function<float>);                                                          \
    }                                                                                                                  \
    GRADED_TEST(#function ": in double, hits and misses as exact with t and barycentrics to 1e-9", number, 1)         \
    {                                                                                                                  \
        rt::grader::triangles::keeps_double_precision(&function<double>);                                             \
    }                                                                                                                  \
    STABILITY_TEST(#function ": triangles 1e-4 to 1e6 across are hit like unit ones", number, 1)                      \
    {                                                                                                                  \
        rt::grader::triangles::every_scale(&function<float>);                                                         \
    }                                                                                                                  \
    STABILITY_TEST(#function ": a direction of any length gives t in lengths of that direction", number, 1)           \
    {                                                                                                                  \
        rt::grader::triangles::any_direction_length(&function<float>);                                                \
    }                                                                                                                  \
    STABILITY_TEST(#function ": rays with a NaN or an infinity in them hit nothing", number, 1)                        \
    {                                                                                                                  \
        rt::grader::triangles::broken_rays(&function<float>);                                                         \
    }                                                                                                                  \
    STABILITY_TEST(#function ": a triangle so small its products underflow gives no NaN", number, 1)                  \
    {                                                                                                                  \
        rt::grader::triangles::underflowing(&function<float>);                                                        \
    }
