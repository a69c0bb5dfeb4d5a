// EXERCISE 10.4: the traversal, on a tree built by hand and against brute force on seeded rays.
#include "10_hierarchies/figure.hpp"
#include "tests/ch07/agreement.hpp"
#include "tests/ch10/bvh_suspect.hpp"
#include "tests/ch10/closed_sphere.hpp"
#include "tests/ch10/two_leaves.hpp"

#include <filesystem>
#include <iomanip>
#include <limits>

using namespace rt;
using namespace rt::grader;
using namespace rt::grader::agreement;

namespace {

// A failing case runs the BVH's exercises again on the first ray that differs (bvh_suspect.hpp).
std::string suspect_bvh(const Accelerator& built, const Ray& ray, Interval range, const Objects& objects)
{
    return suspect::diagnose_bvh(dynamic_cast<const BvhAccel&>(built).bvh(), ray, range, objects);
}

const char* const bvh_build_asks = "10.1 sah_cost, 10.2 best_split and 10.3 make_leaf";

const Build bvh{"the BVH", [](const Objects& objects, float) { return std::make_unique<BvhAccel>(objects); }, suspect_bvh, {},
                bvh_build_asks};
const Build median{"the BVH split at the median",
                   [](const Objects& objects, float) {
                       BvhSettings s;
                       s.split = BvhSplit::median;
                       return std::make_unique<BvhAccel>(objects, s);
                   },
                   [](const Accelerator& built, const Ray& ray, Interval range, const Objects& objects) {
                       BvhSettings s;
                       s.split = BvhSplit::median;
                       return suspect::diagnose_bvh(dynamic_cast<const BvhAccel&>(built).bvh(), ray, range, objects, s);
                   }};

}  // namespace

GRADED_TEST("bvh_query: the near child first, so the far one is passed over once a nearer hit is found", "10.4", 5)
{
    const Bvh b = two_leaves();
    for (const float dir : {1.0f, -1.0f}) {
        const Ray ray{{dir > 0 ? -3.0f : 9.0f, 0, 0}, {dir, 0, 0}};
        ObjectHit hit;
        reset_counters();
        const bool found = bvh_query(b, ray, {0.0f, infinity}, two_objects(), false, hit);
        const int expected = dir > 0 ? 0 : 1;
        INFO(show(ray) << " through spheres at x = 1 and x = 5, each in its own leaf: got " << (found ? show(hit) : "no hit")
             << " after " << total_count(Counter::intersection_tests) << " tests and " << total_count(Counter::nodes_visited)
             << " nodes; expected sphere " << expected << " after 1 test: the near leaf first, then the far one's box "
             "lies beyond the hit");
        CHECK(found);
        CHECK(hit.object == expected);
        CHECK(total_count(Counter::intersection_tests) == 1);
    }
}

GRADED_TEST("bvh_query: the any-hit query stops at the first object hit; a miss is a miss", "10.4", 3)
{
    const Bvh b = two_leaves();
    ObjectHit hit;
    reset_counters();
    const bool any = bvh_query(b, {{-3, 0, 0}, {1, 0, 0}}, {0.0f, infinity}, two_objects(), true, hit);
    INFO("any-hit along +x through both spheres: got " << std::boolalpha << any << " after "
         << total_count(Counter::intersection_tests) << " tests; expected true after 1");
    CHECK(any);
    CHECK(total_count(Counter::intersection_tests) == 1);
    const bool miss = bvh_query(b, {{-3, 2, 0}, {1, 0, 0}}, {0.0f, infinity}, two_objects(), false, hit);
    const bool nan = bvh_query(b, {{-3, std::nanf(""), 0}, {1, 0, 0}}, {0.0f, infinity}, two_objects(), false, hit);
    INFO("a ray passing above both, and a NaN ray: got " << miss << " and " << nan << ", expected no hits");
    CHECK(!miss);
    CHECK(!nan);
    // A tree of no nodes (a scene with nothing in it) has no root to read: every ray misses.
    const bool empty = bvh_query(Bvh{}, {{-3, 0, 0}, {1, 0, 0}}, {0.0f, infinity}, Objects{}, false, hit);
    INFO("a BVH of no nodes: got " << empty << ", expected no hit (and no read of node 0)");
    CHECK(!empty);
}

GRADED_TEST("the BVH answers every ray as brute force does, on the kit's scenes and generated ones (SAH and median)", "10.A", 5)
{
    for (const auto& entry : std::filesystem::directory_iterator(RT_NFF_SCENES_DIR))
        if (entry.path().extension() == ".nff") {
            check_scene(bvh, read_nff(entry.path().string()), 600);
            check_scene(median, read_nff(entry.path().string()), 300);
        }
    check_scene(bvh, generated_scene(write_stadium, 2, "stadium 2"), 600);
    check_scene(bvh, generated_scene(write_sticks, 1, "sticks 1"), 600);
    check_scene(bvh, generated_scene(write_tree, 3, "tree 3"), 400);
}

STABILITY_TEST("the BVH answers as brute force does on ties, a huge floor and far from the origin", "10.A", 3)
{
    check_hard_cases(bvh);
}

STABILITY_TEST("watertight together: 10^6 rays from inside a closed sphere of triangles far from the origin all hit it", "10.A", 4)
{
    // The BVH's robust slab test and the watertight triangle test must let no ray out.
    const Escapes e = escapes_from_closed_sphere<BvhAccel>(1000000, 1234, [](const BvhAccel& tree, const Ray& ray, const Objects& o) {
        return suspect::diagnose_bvh(tree.bvh(), ray, {0.0f, infinity}, o);
    });
    INFO("10^6 rays from within 200 of the centre of " << e.scene << ": " << e.escaped << " escaped; the first: " << e.first);
    CHECK(e.escaped == 0);
}

namespace {

// One triangle across the ray from the origin along +x, in the plane x = `x`, in the y-z square
// (-1, -1) to (3, 3): 02.5's edge functions are -8, -4 and -4 there, so at x = 4 the hit is t = 4
// exactly.
Triangle across_at(float x) { return {{x, -1, -1}, {x, 3, -1}, {x, -1, 3}}; }

Objects triangles_over(const std::vector<Triangle>& tris)
{
    Objects o;
    o.triangles = tris.data();
    o.triangle_count = static_cast<int>(tris.size());
    o.tests = {SphereTest::precise, TriangleTest::watertight};
    return o;
}

// Two leaves under a root split along x: node 1, the first child (the near one along +x), holds
// object 1 in `near_box`; node 2 holds object 0 in `far_box`; the root's box is around both.
Bvh two_leaves(const Bounds& near_box, const Bounds& far_box)
{
    Bounds root = near_box;
    root.grow(far_box);
    Bvh b;
    b.nodes = {{root.min, 2, root.max, 0, 0}, {near_box.min, 0, near_box.max, 1, 0}, {far_box.min, 1, far_box.max, 1, 0}};
    b.object_index = {1, 0};
    return b;
}

// Object 1 at x = 4 in the near leaf; object 0 in the far one, its box starting at x = `second_min_x`.
Bvh tie_tree(const std::vector<Triangle>& tris, float second_min_x)
{
    return two_leaves({{4, -1, -1}, {4, 3, 3}}, {{second_min_x, -1, -1}, {tris[0].a.x, 3, 3}});
}

}  // namespace

GRADED_TEST("bvh_query: a box the ray enters exactly at the best hit's t (or a float step before) is searched, for a lower-numbered object may tie there",
            "10.4", 3)
{
    const Ray ray{{0, 0, 0}, {1, 0, 0}};
    const float four = 4.0f, before = std::nextafter(four, 0.0f), after = std::nextafter(four, infinity);
    const struct {
        float second_min_x;  // where the ray enters the second leaf's box
        float object0_x;     // the plane of object 0, in that leaf
        int object;          // the answer
        const char* why;
    } cases[] = {{four, four, 0, "the second leaf's box is entered exactly at the best hit's t, 4, and holds object 0 "
                                 "hit at t = 4 too: the tie goes to the lower number"},
                 {before, four, 0, "the second leaf's box is entered one float step before t = 4, and holds object 0 "
                                   "hit at t = 4: the tie goes to the lower number"},
                 {after, after, 1, "the second leaf's box is entered one float step past t = 4, and object 0 in it is hit "
                                   "there: farther than object 1's hit, it cannot win"}};
    for (const auto& c : cases) {
        const std::vector<Triangle> tris = {across_at(c.object0_x), across_at(four)};
        const Objects objects = triangles_over(tris);
        ObjectHit want;
        REQUIRE(brute_force().closest(ray, {0.0f, infinity}, objects, want));
        REQUIRE(want.object == c.object);  // the case's own set-up: brute force's answer
        ObjectHit hit;
        reset_counters();
        const bool found = bvh_query(tie_tree(tris, c.second_min_x), ray, {0.0f, infinity}, objects, false, hit);
        const std::uint64_t tests = total_count(Counter::intersection_tests), nodes = total_count(Counter::nodes_visited);
        INFO("10.4: " << show(ray) << "; the near leaf holds object 1, hit at t = 4; " << c.why << ". Got "
             << answer(found, hit) << " after " << tests << " tests and " << nodes << " nodes visited; expected "
             << show(want) << (c.object == 0 ? " after 2 tests" : "") << ", 3 nodes visited (the root and both leaves, "
             "each box tested): a box is searched up to and including the best hit's t");
        CHECK(found);
        CHECK(hit.object == want.object);
        CHECK(hit.t == want.t);
        CHECK(nodes == 3);
        if (c.object == 0)
            CHECK(tests == 2);
    }
}

GRADED_TEST("bvh_query: a direction of 0 or -0 along the node's axis is not positive, so the second child is searched first",
            "10.4", 2)
{
    // The two leaves of two_leaves(), the root marked as split along y: along y the ray's
    // direction is +0 or -0, so the second child (sphere 1, at x = 5) comes first, and the first
    // (sphere 0, at x = 1) is still entered, its box nearer than that hit.
    Bvh b = two_leaves();
    b.nodes[0].axis = 1;
    for (const float zero : {0.0f, -0.0f}) {
        const Ray ray{{-3, 0, 0}, {1, zero, 0}};
        ObjectHit hit;
        reset_counters();
        const bool found = bvh_query(b, ray, {0.0f, infinity}, two_objects(), false, hit);
        const std::uint64_t tests = total_count(Counter::intersection_tests), nodes = total_count(Counter::nodes_visited);
        INFO("10.4: " << show(ray) << " (y component " << (std::signbit(zero) ? "-0" : "+0") << "), the root split along y, "
             "its first child holding sphere 0 (x = 1), its second sphere 1 (x = 5): got " << answer(found, hit) << " after "
             << tests << " tests and " << nodes << " nodes; expected sphere 0 at t = 3.5 after 2 tests and 3 nodes: the "
             "first child goes first only when the direction along the node's axis is positive, so here the second is "
             "searched first, and the first after it");
        CHECK(found);
        CHECK(hit.object == 0);
        CHECK(tests == 2);
        CHECK(nodes == 3);
    }
}

GRADED_TEST("bvh_query: the any-hit query answers with the first object it hits, at once, though a nearer one follows in the leaf",
            "10.4", 1)
{
    // One leaf holding both spheres, sphere 1 (x = 5) listed before sphere 0 (x = 1): along +x the
    // first object tested is hit, and any-hit stops there; only a closest-hit query goes on to
    // sphere 0.
    Bvh b;
    b.nodes = {{{0.5f, -0.5f, -0.5f}, 0, {5.5f, 0.5f, 0.5f}, 2, 0}};
    b.object_index = {1, 0};
    const Ray ray{{-3, 0, 0}, {1, 0, 0}};
    ObjectHit hit;
    reset_counters();
    const bool any = bvh_query(b, ray, {0.0f, infinity}, two_objects(), true, hit);
    const std::uint64_t tests = total_count(Counter::intersection_tests);
    INFO("10.4: any-hit, " << show(ray) << ", one leaf listing sphere 1 (x = 5) before sphere 0 (x = 1): got "
         << answer(any, hit) << " after " << tests << " tests; expected sphere 1 after 1 test: the first object hit "
         "ends an any-hit query at once, nearer or not");
    CHECK(any);
    CHECK(hit.object == 1);
    CHECK(tests == 1);
}

GRADED_TEST("bvh_query: the least positive direction along the node's axis is positive, so the first child is searched first",
            "10.4", 1)
{
    // The two leaves of two_leaves(), the root marked as split along y; the ray's y component the
    // least float above 0 (1.4e-45): positive, so the first child (sphere 0, x = 1) comes first,
    // is hit, and the second's box lies beyond it: 1 test.
    Bvh b = two_leaves();
    b.nodes[0].axis = 1;
    const Ray ray{{-3, 0, 0}, {1, std::numeric_limits<float>::denorm_min(), 0}};
    ObjectHit hit;
    reset_counters();
    const bool found = bvh_query(b, ray, {0.0f, infinity}, two_objects(), false, hit);
    const std::uint64_t tests = total_count(Counter::intersection_tests);
    INFO("10.4: " << show(ray) << " (y component 1.4e-45, the least float above 0), the root split along y, its first "
         "child holding sphere 0 (x = 1), its second sphere 1 (x = 5): got " << answer(found, hit) << " after " << tests
         << " tests; expected sphere 0 after 1 test: any direction above 0 along the node's axis, however small, is "
         "positive, so the first child goes first");
    CHECK(found);
    CHECK(hit.object == 0);
    CHECK(tests == 1);
}

namespace {

// Each of two triangles in a leaf of its own (two_leaves), its box exactly its corners' box: no
// margin, so a flat triangle's box is met where its plane is.
Bvh own_leaves(const std::vector<Triangle>& tris)
{
    const auto box_of = [](const Triangle& t) {
        Bounds b;
        b.grow(t.a), b.grow(t.b), b.grow(t.c);
        return b;
    };
    return two_leaves(box_of(tris[1]), box_of(tris[0]));
}

}  // namespace

GRADED_TEST("bvh_query: a box the ray enters one float step past the best hit's t is searched, for its triangle may be hit at that t",
            "10.4", 2)
{
    // Two triangles in the plane x = 3, both crossed by the ray from the origin along (1, 0.1, 0.1),
    // which meets the plane at t = 3 exactly. 02.5's watertight test rounds both hits to the float
    // below 3, 2.99999976; the slab test enters each triangle's flat box at 3 itself: one float
    // step past those hits. Object 1's leaf comes first; object 0, in the other leaf, ties it and
    // has the lower number.
    const Ray ray{{0, 0, 0}, {1, 0.1f, 0.1f}};
    const std::vector<Triangle> tris = {{{3, -3, -3}, {3, 3, -3}, {3, -3, 8}}, {{3, -3, -3}, {3, 5, -3}, {3, -3, 6}}};
    const Objects objects = triangles_over(tris);
    const Bvh b = own_leaves(tris);
    const float below = std::nextafter(3.0f, 0.0f);
    ObjectHit want, first;
    REQUIRE(brute_force().closest(ray, {0.0f, infinity}, objects, want));
    REQUIRE(objects.intersect(1, ray, {0.0f, infinity}, first));
    const std::optional<Interval> far_box = slab_interval(b.nodes[2].bounds(), RaySlabs(ray), {0.0f, infinity});
    // The case's own set-up: both hits at the float below 3, the far leaf's box entered at 3.
    REQUIRE((want.object == 0 && want.t == below && first.t == below && far_box && far_box->min == 3.0f));
    ObjectHit hit;
    reset_counters();
    const bool found = bvh_query(b, ray, {0.0f, infinity}, objects, false, hit);
    const std::uint64_t tests = total_count(Counter::intersection_tests);
    INFO("10.4: " << show(ray) << "; the near leaf holds object 1, hit at t = " << std::setprecision(9) << below
         << "; the far leaf's box is entered at t = 3, one float step past that hit, and holds object 0, hit at "
         << below << " too (the triangle test rounds below where the slab test enters its box). Got " << answer(found, hit)
         << " after " << tests << " tests; expected " << show(want) << " after 2 tests: a box entered one float step past "
         "the best hit's t is searched, and the tie goes to the lower number");
    CHECK(found);
    CHECK(hit.object == want.object);
    CHECK(hit.t == want.t);
    CHECK(tests == 2);
}
