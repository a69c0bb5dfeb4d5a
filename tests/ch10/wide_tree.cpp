// EXERCISE 10.6 at work: the 4-wide tree (wide_bvh.hpp, given) tests each leaf's triangles four at a
// time with your hit_four_triangles, so a lane that answers other than 02.5 shows in the tree's
// answers too: seeded rays through it, against brute force (object and t, bit for bit).
#include "10_hierarchies/figure.hpp"
#include "10_hierarchies/wide_bvh.hpp"
#include "tests/ch07/agreement.hpp"
#include "tests/ch10/wide_suspect.hpp"

#include <string>

using namespace rt;
using namespace rt::grader;
using namespace rt::grader::agreement;

namespace {

// The binary tree under the wide one split at the median (bvh.hpp's own split, which asks nothing
// of 10.1-10.3), so that this case grades 10.6 alone; leaves of up to 4 objects (one block) or 8
// (two blocks, the second often part full).
Build wide(int leaf_size)
{
    return {"the 4-wide tree (median split, leaves of up to " + std::to_string(leaf_size) +
                " objects), its leaves' triangles tested four at a time by your hit_four_triangles (" + lanes_kind + ")",
            [leaf_size](const Objects& objects, float) {
                BvhSettings s;
                s.split = BvhSplit::median;
                s.leaf_size = leaf_size;
                return std::make_unique<WideBvhAccel>(objects, s);
            },
            // A failing case asks 10.6 again on every block for the first ray that differs (wide_suspect.hpp).
            [](const Accelerator& built, const Ray& ray, Interval range, const Objects&) {
                return suspect::diagnose_wide(dynamic_cast<const WideBvhAccel&>(built).tree(), ray, range);
            }};
}

// One triangle the ray from the origin along -z hits at t = 2, in lane 0 of a block.
struct OneBlock {
    Triangle tri{{-1, -1, -2}, {1, -1, -2}, {0, 1, -2}};
    Objects objects;
    FourTriangles block;
    Ray ray{{0, 0, 0}, {0, 0, -1}};
    OneBlock()
    {
        objects.triangles = &tri;
        objects.triangle_count = 1;
        const std::uint32_t index[1] = {0};
        block = four_triangles(objects, index, 1);
    }
};

}  // namespace

GRADED_TEST("the 4-wide tree built on your hit_four_triangles answers every ray as brute force does (object and t)", "10.6", 3)
{
    // The stub's FourHits::not_tested() has the wide tree ask the triangles one by one, which
    // answers right without 10.6: that is not 10.6 at work.
    const OneBlock one;
    const FourHits h = hit_four_triangles(one.block, ray_frame(one.ray), {0.0f, infinity});
    {
        INFO("10.6: hit_four_triangles returned FourHits::not_tested() (the stub), so the wide tree would test its "
             "triangles one by one: write 10.6 first");
        REQUIRE(h.tested);
    }
    check_scene(wide(4), generated_scene(write_mountain, 4, "mountain 4"), 500);
    check_scene(wide(8), generated_scene(write_mountain, 4, "mountain 4"), 300);
    check_scene(wide(4), generated_scene(write_tree, 3, "tree 3"), 400);
    check_scene(wide(8), generated_scene(write_stadium, 2, "stadium 2"), 500);
    check_hard_cases(wide(4));
}

GRADED_TEST("hit_four_triangles counts no test: the wide tree that calls it counts them", "10.6", 1)
{
    const OneBlock one;
    reset_counters();
    const FourHits h = hit_four_triangles(one.block, ray_frame(one.ray), {0.0f, infinity});
    const std::uint64_t tests = total_count(Counter::intersection_tests);
    INFO("10.6: a block of one triangle, hit at t = 2: lanes hit " << h.hit << ", with " << tests
         << " intersection tests counted by hit_four_triangles; expected lane 0 hit and 0 tests counted (the wide tree "
         "counts a block's tests itself: counted here too, each would count twice)");
    CHECK(h.tested);
    CHECK(h.hit == 1u);
    CHECK(tests == 0);
}
