// EXERCISE 10.6: four triangles at once, each lane against the watertight test (02.5) on its own
// triangle: hit or miss, t, beta and gamma to the bit.
#include "10_hierarchies/10_hierarchies.hpp"
#include "common/random.hpp"
#include "tests/ch02/triangle_cases.hpp"
#include "tests/grader/graded.hpp"

#include <cstdio>
#include <string>

using namespace rt;
using namespace rt::grader;

namespace {

// A float to the last bit that tells two floats apart (9 significant digits).
std::string nine_digits(float x)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", static_cast<double>(x));
    return text;
}

struct Tally {
    int lanes_checked = 0, hits = 0, on_edges = 0, without_area = 0;
};

// Blocks of 1-4 triangles of corners from `point`, one in ten without area (a repeated corner, or
// three in a line), each ray from `point` along `direction` (or, with `at_edges`, half the rays at
// the middle of an edge of one of the block's triangles), in the range (0 or 0.5, infinity or 2).
// Every lane must say what hit_triangle_watertight says of its triangle; an empty lane is never hit.
template <class Point, class Direction>
Tally check_blocks(Rng& rng, int blocks, Point point, Direction direction, bool at_edges)
{
    Tally tally;
    for (int k = 0; k < blocks; ++k) {
        Triangle tris[4];
        const std::uint32_t n = 1 + static_cast<std::uint32_t>(rng.next_float() * 4.0f) % 4;
        for (std::uint32_t i = 0; i < n; ++i) {
            tris[i] = {point(), point(), point()};
            const float r = rng.next_float();
            if (r < 0.05f)
                tris[i].c = tris[i].a;  // a repeated corner
            else if (r < 0.1f)
                tris[i].c = tris[i].a + 2.0f * (tris[i].b - tris[i].a);  // three in a line
        }
        Objects objects;
        objects.triangles = tris;
        objects.triangle_count = static_cast<int>(n);
        const std::uint32_t index[4] = {0, 1, 2, 3};
        const FourTriangles g = four_triangles(objects, index, n);
        Ray ray{point(), direction()};
        if (at_edges && rng.next_float() < 0.5f) {
            // At the middle of an edge: its edge function is a difference of two nearly equal
            // products, which float often rounds to exactly 0 where double does not.
            const Triangle& t = tris[static_cast<std::uint32_t>(rng.next_float() * 4.0f) % n];
            ray.dir = 0.5f * (t.a + t.b) - ray.origin;
        }
        if (ray.dir == vec3(0.0f))
            continue;
        const Interval range{rng.next_float() < 0.7f ? 0.0f : 0.5f, rng.next_float() < 0.7f ? infinity : 2.0f};
        const FourHits got = hit_four_triangles(g, ray_frame(ray), range);
        for (std::uint32_t i = 0; i < 4; ++i) {
            const bool hit = got.hit >> i & 1u;
            if (i >= n) {
                INFO("lane " << i << " of a block of " << n << " triangles (" << lanes_kind << ") is empty, yet hit");
                REQUIRE(!hit);
                continue;
            }
            const std::optional<TriangleHit<float>> want = hit_triangle_watertight(ray, tris[i], range);
            INFO(show(ray) << ", t in (" << nine_digits(range.min) << ", " << nine_digits(range.max) << "), triangle " << show(tris[i].a) << ", "
                 << show(tris[i].b) << ", " << show(tris[i].c) << " in lane " << i << " of " << n << " (" << lanes_kind
                 << "): the watertight test says "
                 << (want ? "t = " + nine_digits(want->t) + ", beta = " + nine_digits(want->beta) + ", gamma = " + nine_digits(want->gamma)
                          : std::string("missed"))
                 << "; hit_four_triangles "
                 << (hit ? "t = " + nine_digits(got.t[i]) + ", beta = " + nine_digits(got.V[i] / got.det[i]) +
                               ", gamma = " + nine_digits(got.W[i] / got.det[i])
                         : std::string("missed")));
            REQUIRE(hit == want.has_value());
            ++tally.lanes_checked;
            tally.without_area += !(g.with_area >> i & 1u);
            if (!hit)
                continue;
            REQUIRE(got.t[i] == want->t);
            REQUIRE(got.V[i] / got.det[i] == want->beta);
            REQUIRE(got.W[i] / got.det[i] == want->gamma);
            ++tally.hits;
            tally.on_edges += want->beta == 0.0f || want->gamma == 0.0f || want->beta + want->gamma == 1.0f;
        }
    }
    return tally;
}

}  // namespace

GRADED_TEST("hit_four_triangles: each lane answers as the watertight test does, through edges and corners, from both sides, in blocks of one to four",
            "10.6", 5)
{
    // Corners on a coarse lattice, rays from lattice points along lattice directions (some with a 0
    // or -0 component): hits on edges and at corners, from either side, back faces included.
    Rng rng(31, 7);
    const auto lattice = [&] { return static_cast<float>(static_cast<int>(rng.next_float() * 5.0f) - 2); };
    const auto point = [&] { return point3(lattice(), lattice(), lattice()); };
    const auto direction = [&] {
        vec3 d(lattice(), lattice(), lattice());
        if (rng.next_float() < 0.2f)
            d[static_cast<int>(rng.next_float() * 3.0f) % 3] = rng.next_float() < 0.5f ? 0.0f : -0.0f;
        return d;
    };
    const Tally t = check_blocks(rng, 30000, point, direction, false);
    INFO(t.lanes_checked << " lanes: " << t.hits << " hit, " << t.on_edges << " of them on an edge or corner; "
                         << t.without_area << " triangles without area");
    CHECK(t.hits > t.lanes_checked / 40);
    CHECK(t.on_edges > 100);
    CHECK(t.without_area > 1000);
}

STABILITY_TEST("hit_four_triangles: where float rounds an edge function to 0, the lane is decided in double, as 02.5 decides it",
               "10.6", 3)
{
    // Corners anywhere in a cube of side 8, rays from anywhere, half of them at the middle of an
    // edge: the lanes where one edge function is 0 in float, and 02.5 asks double.
    Rng rng(32, 7);
    const auto anywhere = [&] { return 8.0f * rng.next_float() - 4.0f; };
    const auto point = [&] { return point3(anywhere(), anywhere(), anywhere()); };
    const auto direction = [&] { return vec3(anywhere(), anywhere(), anywhere()); };
    const Tally t = check_blocks(rng, 30000, point, direction, true);
    INFO(t.lanes_checked << " lanes: " << t.hits << " hit, " << t.on_edges << " of them on an edge");
    CHECK(t.hits > t.lanes_checked / 40);
    CHECK(t.on_edges > 100);
}

GRADED_TEST("hit_four_triangles: a hit counts only with t strictly inside the range", "10.6", 2)
{
    // One triangle in the plane z = -2, the ray straight down -z from the origin: t = 2 exactly.
    const Triangle tri{{-1, -1, -2}, {1, -1, -2}, {0, 1, -2}};
    Objects objects;
    objects.triangles = &tri;
    objects.triangle_count = 1;
    const std::uint32_t index[1] = {0};
    const FourTriangles g = four_triangles(objects, index, 1);
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    const struct {
        Interval range;
        bool hit;
    } cases[] = {{{0.0f, infinity}, true}, {{0.0f, 2.0f}, false}, {{2.0f, infinity}, false},
                 {{0.0f, std::nextafter(2.0f, infinity)}, true}, {{std::nextafter(2.0f, 0.0f), 3.0f}, true}};
    for (const auto& c : cases) {
        const FourHits got = hit_four_triangles(g, ray_frame(ray), c.range);
        INFO(show(ray) << " at the triangle " << show(tri.a) << ", " << show(tri.b) << ", " << show(tri.c)
                       << " (t = 2), range (" << nine_digits(c.range.min) << ", " << nine_digits(c.range.max) << "): lanes hit "
                       << got.hit << ", lane 0's t " << (got.hit & 1u ? nine_digits(got.t[0]) : std::string("-")));
        CHECK(got.hit == (c.hit ? 1u : 0u));
        if (c.hit && (got.hit & 1u))
            CHECK(got.t[0] == 2.0f);
    }
}

namespace {

// 10.6 asked of one triangle, as 02.5 is: the triangle in one lane of a block (a different lane
// each call), the other lanes holding a triangle the ray hits, which must not change its answer.
std::optional<TriangleHit<float>> one_lane_of_four(const Ray& ray, const Triangle& tri, Interval range)
{
    static int calls = 0;
    const std::uint32_t lane = static_cast<std::uint32_t>(calls++ % 4);
    Triangle tris[4];
    for (std::uint32_t i = 0; i < 4; ++i) {
        const point3 p = ray.at(1.0f);
        const vec3 side = glm::normalize(glm::cross(ray.dir, vec3(0.3f, 0.5f, 0.7f)));
        const vec3 up = glm::cross(ray.dir, side);
        tris[i] = i == lane ? tri : Triangle{p - side - up, p + side - up, p + up};
    }
    Objects objects;
    objects.triangles = tris;
    objects.triangle_count = 4;
    const std::uint32_t index[4] = {0, 1, 2, 3};
    const FourHits got = hit_four_triangles(four_triangles(objects, index, 4), ray_frame(ray), range);
    if (!(got.hit >> lane & 1u))
        return std::nullopt;
    return TriangleHit<float>{got.t[lane], got.V[lane] / got.det[lane], got.W[lane] / got.det[lane]};
}

}  // namespace

GRADED_TEST("hit_four_triangles: triangles without area are never hit, pbrt-v4's BadCase included", "10.6", 2)
{
    triangles::degenerate(&one_lane_of_four, {0, 1, 2, 3, 4, 5, 6});
}

GRADED_TEST("hit_four_triangles: a ray lying in a triangle's own plane (det = 0) does not hit it", "10.6", 1)
{
    // The triangle in the plane z = 0, the ray in that plane too, through the triangle's middle:
    // 02.5's U, V and W are all 0 there, det is 0, and t = 0 / 0 is no number: never a hit, even in
    // a range from -infinity to infinity.
    const Triangle tri{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    Objects objects;
    objects.triangles = &tri;
    objects.triangle_count = 1;
    const std::uint32_t index[1] = {0};
    const FourTriangles g = four_triangles(objects, index, 1);
    for (const Interval range : {Interval{0.0f, infinity}, Interval{-infinity, infinity}}) {
        const Ray ray{{-2, 0, 0}, {1, 0, 0}};
        const FourHits got = hit_four_triangles(g, ray_frame(ray), range);
        INFO("10.6: " << show(ray) << ", in the plane of the triangle " << show(tri.a) << ", " << show(tri.b) << ", "
             << show(tri.c) << ", t in (" << range.min << ", " << range.max << "): lanes hit " << got.hit
             << (got.hit & 1u ? ", lane 0's t " + nine_digits(got.t[0]) + ", det " + nine_digits(got.det[0]) : std::string())
             << "; expected none: a lane hits only where det is not 0");
        CHECK(got.tested);
        CHECK(got.hit == 0u);
    }
}

namespace {

// Lane 0 of a block of one, against 02.5 on the same triangle: hit or miss, t, beta and gamma to
// the bit. `why` says what the case is about; a failure prints both answers.
void check_one_lane(const Ray& ray, const Triangle& tri, const std::string& why)
{
    Objects objects;
    objects.triangles = &tri;
    objects.triangle_count = 1;
    const std::uint32_t index[1] = {0};
    const FourTriangles g = four_triangles(objects, index, 1);
    const Interval range{0.0f, infinity};
    const std::optional<TriangleHit<float>> want = hit_triangle_watertight(ray, tri, range);
    const FourHits got = hit_four_triangles(g, ray_frame(ray), range);
    const bool hit = got.hit & 1u;
    INFO("10.6: " << show(ray) << ", the triangle (" << nine_digits(tri.a.x) << ", " << nine_digits(tri.a.y) << ", "
         << nine_digits(tri.a.z) << "), (" << nine_digits(tri.b.x) << ", " << nine_digits(tri.b.y) << ", " << nine_digits(tri.b.z)
         << "), (" << nine_digits(tri.c.x) << ", " << nine_digits(tri.c.y) << ", " << nine_digits(tri.c.z) << ") in lane 0 ("
         << lanes_kind << "): the watertight test (02.5) says "
         << (want ? "t = " + nine_digits(want->t) + ", beta = " + nine_digits(want->beta) + ", gamma = " + nine_digits(want->gamma)
                  : std::string("missed"))
         << "; hit_four_triangles "
         << (!got.tested ? std::string("tested nothing")
                         : hit ? "t = " + nine_digits(got.t[0]) + ", beta = " + nine_digits(got.V[0] / got.det[0]) +
                                     ", gamma = " + nine_digits(got.W[0] / got.det[0]) + ", det = " + nine_digits(got.det[0])
                               : std::string("missed"))
         << ": " << why);
    CHECK(got.tested);
    CHECK(hit == want.has_value());
    if (hit && want) {
        CHECK(got.t[0] == want->t);
        CHECK(got.V[0] / got.det[0] == want->beta);
        CHECK(got.W[0] / got.det[0] == want->gamma);
    }
}

// The triangle with its corners taken in turn: (a, b, c), (b, c, a), (c, a, b). The winding
// stays; the edge that was b-c (U's) becomes c-a's (V) and then a-b's (W).
std::vector<Triangle> turns(const Triangle& t) { return {t, {t.b, t.c, t.a}, {t.c, t.a, t.b}}; }

}  // namespace

GRADED_TEST("hit_four_triangles: an edge that float puts through the ray, and double 2^-46 beside it, is decided in double, whichever of the three edges it is",
            "10.6", 2)
{
    // 02.5's example: the edge from (1 + 2^-23, 1 + 2^-22, -4) to (-1, -1 - 2^-23, -5) passes 2^-46
    // beside the ray from the origin along -z; its edge function is 0 in float and -2^-46 in
    // double. With the third corner at (2, -2, -4.5) the other two edge functions are positive:
    // the ray is outside that edge, a miss. With it at (-2, 2, -4.5) they are negative too: a hit.
    // Each triangle taken three ways round, so that edge is U's, V's and W's in turn.
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    const point3 b{1 + 0x1p-23f, 1 + 0x1p-22f, -4}, c{-1, -1 - 0x1p-23f, -5};
    for (const point3 a : {point3(2, -2, -4.5f), point3(-2, 2, -4.5f)})
        for (const Triangle& tri : turns({a, b, c}))
            check_one_lane(ray, tri, a.x > 0 ? "the ray passes 2^-46 outside the edge through (1, 1, -4) and (-1, -1, -5): "
                                               "its edge function is 0 in float, and double's -2^-46 decides a miss"
                                             : "the ray passes 2^-46 inside that edge: double's -2^-46 has the other two's sign, a hit");
}

GRADED_TEST("hit_four_triangles: an edge function of the least float (1.4e-45) is positive: the ray that far outside a triangle misses it",
            "10.6", 1)
{
    // A triangle of denormal size, corners at multiples of q = 2^-75 in the plane z = -1: (2q, q),
    // (2q, 0) and (0, q) in x and y. The ray from the origin along -z passes outside its edge from
    // (2q, 0) to (0, q), by so little that that edge's function is 2q^2 = 2^-149, the least float
    // above 0, and the other two are -2^-149: their signs differ, a miss (02.5's own answer). All
    // three are exact in float (products of powers of 2), so no fallback to double changes them.
    const float q = 0x1p-75f;
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    for (const Triangle& tri : turns({{2 * q, q, -1}, {2 * q, 0, -1}, {0, q, -1}}))
        check_one_lane(ray, tri, "one edge function is the least positive float, 2^-149 (1.4e-45), the other two -2^-149: "
                                 "positive and negative, a miss, however small the positive one");
}

GRADED_TEST("hit_four_triangles: a det of the least float (1.4e-45) is not 0: the ray at a corner of a triangle that small hits it",
            "10.6", 1)
{
    // The triangle (0, 0), (2q, 0), (0, q) in x and y (q = 2^-75), in the plane z = -1, its corner
    // a on the ray from the origin along -z: U = 2q^2 = 2^-149, V = W = 0, so det = 2^-149, the
    // least float above 0, and 02.5 hits it at t = 1 (beta = gamma = 0). Only det = 0 is no hit.
    const float q = 0x1p-75f;
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    for (const Triangle& tri : turns({{0, 0, -1}, {2 * q, 0, -1}, {0, q, -1}}))
        check_one_lane(ray, tri, "det = U + V + W is 2^-149 (1.4e-45), the least float above 0, not 0: a hit at t = 1, at "
                                 "the corner on the ray");
}
