// EXERCISE 10.4: the traversal, on a tree built by hand and against brute force on seeded rays.
#include "10_hierarchies/figure.hpp"
#include "tests/ch07/agreement.hpp"
#include "tests/ch10/closed_sphere.hpp"

#include <filesystem>

using namespace rt;
using namespace rt::grader;
using namespace rt::grader::agreement;

namespace {

std::uint64_t counter(Counter c) { return total_counts()[static_cast<size_t>(c)]; }

// Two spheres along x, one per leaf: node 0 the root (split along x), node 1 the leaf of sphere 0
// at x = 1, node 2 the leaf of sphere 1 at x = 5.
const std::vector<Sphere> two = {{{1, 0, 0}, 0.5f}, {{5, 0, 0}, 0.5f}};

Objects two_objects()
{
    Objects o;
    o.spheres = two.data();
    o.sphere_count = 2;
    return o;
}

Bvh two_leaves()
{
    Bvh b;
    b.nodes = {{{0.5f, -0.5f, -0.5f}, 2, {5.5f, 0.5f, 0.5f}, 0, 0},
               {{0.5f, -0.5f, -0.5f}, 0, {1.5f, 0.5f, 0.5f}, 1, 0},
               {{4.5f, -0.5f, -0.5f}, 1, {5.5f, 0.5f, 0.5f}, 1, 0}};
    b.object_index = {0, 1};
    return b;
}

const Build bvh{"the BVH", [](const Objects& objects, float) { return std::make_unique<BvhAccel>(objects); }};
const Build median{"the BVH split at the median", [](const Objects& objects, float) {
                       BvhSettings s;
                       s.split = BvhSplit::median;
                       return std::make_unique<BvhAccel>(objects, s);
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
             << " after " << counter(Counter::intersection_tests) << " tests and " << counter(Counter::nodes_visited)
             << " nodes; expected sphere " << expected << " after 1 test: the near leaf first, then the far one's box "
             "lies beyond the hit");
        CHECK(found);
        CHECK(hit.object == expected);
        CHECK(counter(Counter::intersection_tests) == 1);
    }
}

GRADED_TEST("bvh_query: the any-hit query stops at the first object hit; a miss is a miss", "10.4", 3)
{
    const Bvh b = two_leaves();
    ObjectHit hit;
    reset_counters();
    const bool any = bvh_query(b, {{-3, 0, 0}, {1, 0, 0}}, {0.0f, infinity}, two_objects(), true, hit);
    INFO("any-hit along +x through both spheres: got " << std::boolalpha << any << " after "
         << counter(Counter::intersection_tests) << " tests; expected true after 1");
    CHECK(any);
    CHECK(counter(Counter::intersection_tests) == 1);
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
    const Escapes e = escapes_from_closed_sphere<BvhAccel>(1000000, 1234);
    INFO("10^6 rays from within 200 of the centre of " << e.scene << ": " << e.escaped << " escaped; the first: " << e.first);
    CHECK(e.escaped == 0);
}
