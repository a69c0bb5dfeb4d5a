// The BVH's build (chapter 10's bvh.hpp, given): each node's box is the box around what it holds,
// every object lies in one leaf, a child holds the objects on its side of its parent's plane, and
// the plane is the cheapest of the three axes, not only of the axis the centres spread along most.
#include "10_hierarchies/bvh.hpp"
#include "10_hierarchies/figure.hpp"
#include "tests/ch07/agreement.hpp"
#include "tests/structures/sah_splits.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

using namespace rt;
using namespace rt::grader;

namespace {


bool same_box(const Bounds& a, const Bounds& b) { return a.min == b.min && a.max == b.max; }

// What a subtree holds: the box around its objects' boxes, and the box around their centres.
struct Held {
    Bounds box, centres;
};

// Checks node n and everything under it; returns what it holds, counting each object's leaves in
// `seen`. `margins`: chapter 07's margins for the scene, by which the build grows each object's box.
Held check_node(const Objects& objects, const Margins& margins, const Bvh& bvh, std::uint32_t n, std::map<std::uint32_t, int>& seen)
{
    const BvhNode& node = bvh.nodes[n];
    INFO("node " << n << " of " << bvh.nodes.size() << ": " << show(node.bounds()));
    Held held;
    if (node.count > 0) {
        REQUIRE(node.first + node.count <= bvh.object_index.size());
        for (std::uint32_t j = node.first; j < node.first + node.count; ++j) {
            INFO("its object " << bvh.object_index[j]);
            REQUIRE(bvh.object_index[j] < static_cast<std::uint32_t>(objects.size()));
            const Bounds own = objects.bounds(static_cast<int>(bvh.object_index[j]));
            const Bounds box = grown(own, margins.of(own));
            held.box.grow(box);
            held.centres.grow(box.centre());
            ++seen[bvh.object_index[j]];
        }
    } else {
        REQUIRE(node.first > n + 1);
        REQUIRE(node.first < bvh.nodes.size());
        const Held first = check_node(objects, margins, bvh, n + 1, seen);
        const Held second = check_node(objects, margins, bvh, node.first, seen);
        for (const Held& child : {first, second}) {
            held.box.grow(child.box);
            held.centres.grow(child.centres);
        }
        // The first child holds the lower centres along the node's axis (the traversal's near
        // child when the ray goes the positive way).
        const int a = node.axis;
        REQUIRE(a < 3);
        INFO("along axis " << a << ", the first child's centres lie in " << show(first.centres) << ", the second's in "
                           << show(second.centres));
        CHECK(first.centres.max[a] <= second.centres.min[a]);
    }
    // No looser (a ray would enter it for nothing), no tighter (it would miss what it holds).
    INFO("the box around what it holds: " << show(held.box));
    CHECK(same_box(node.bounds(), held.box));
    return held;
}

}  // namespace

TEST_CASE("the BVH's build: each box is the box around what it holds, and every object lies in one leaf", "[structures]")
{
    struct Case {
        std::string name;
        NffScene nff;
    };
    const std::vector<Case> cases{{"stadium 2", generated_scene(write_stadium, 2, "stadium 2")},
                                  {"tree 3", generated_scene(write_tree, 3, "tree 3")},
                                  {"mountain 5", generated_scene(write_mountain, 5, "mountain 5")}};
    struct Setting {
        const char* name;
        BvhSettings settings;
    };
    BvhSettings leaves_of_1, shallow, median;
    leaves_of_1.leaf_size = 1;
    shallow.max_depth = 4;
    median.split = BvhSplit::median;
    const std::vector<Setting> settings{{"SAH, leaves of 4", {}},
                                        {"SAH, leaves of 1", leaves_of_1},
                                        {"SAH, depth limit 4", shallow},
                                        {"median split", median}};
    for (const Case& c : cases)
        for (const Setting& setting : settings) {
            INFO(c.name << ", " << setting.name);
            const LitScene scene = lit_scene(c.nff);
            const Objects objects = objects_of(scene, lit_tests);  // reads the scene's arrays
            const BvhAccel bvh(objects, setting.settings);
            std::map<std::uint32_t, int> seen;
                        check_node(objects, margins_of(objects), bvh.bvh(), 0, seen);
            INFO("depth " << bvh.stats().depth << ", limit " << setting.settings.max_depth);
            CHECK(bvh.stats().depth <= setting.settings.max_depth);
            CHECK(static_cast<int>(seen.size()) == objects.size());
            for (const auto& [k, times] : seen) {
                INFO("object " << k);
                CHECK(times == 1);
            }
        }
}

TEST_CASE("the BVH splits two long rows apart, across the axis along which their centres spread most", "[structures]")
{
    // Two rows of 64 small spheres along x, 100 long, one at y = 0 and one at y = 10: the centres
    // spread 10 times further along x, yet the cheapest plane lies between the rows (each child's
    // box 100 x 1 x 1, against 50 x 11 x 1 for a plane across x). A build that bins only the
    // widest axis cuts the rows in two along x.
    LitScene scene;
    scene.add_material({});
    for (int row = 0; row < 2; ++row)
        for (int i = 0; i < 64; ++i)
            scene.add_sphere({point3(100.0f * static_cast<float>(i) / 63.0f, 10.0f * static_cast<float>(row), 0.0f), 0.5f}, 0);
    const Objects objects = objects_of(scene, lit_tests);
    const BvhAccel bvh(objects);
    const Bvh& b = bvh.bvh();
    REQUIRE(b.nodes.size() > 1);
    REQUIRE(b.nodes[0].count == 0);
    INFO("the root's axis: " << b.nodes[0].axis << "; its children's boxes: " << show(b.nodes[1].bounds()) << " and "
                             << show(b.nodes[b.nodes[0].first].bounds()));
    CHECK(b.nodes[0].axis == 1);
    CHECK(b.nodes[1].bounds().max.y < 5.0f);
    CHECK(b.nodes[b.nodes[0].first].bounds().min.y > 5.0f);
}

TEST_CASE("the BVH refuses a bin count it cannot use, and names it", "[structures]")
{
    LitScene scene;
    scene.add_material({});
    scene.add_sphere({point3(0.0f), 1.0f}, 0);
    const Objects objects = objects_of(scene, lit_tests);
    for (const int bins : {-1, 0, 1, 1025}) {
        BvhSettings s;
        s.bins = bins;
        INFO(bins << " bins");
        CHECK_THROWS_WITH(BvhAccel(objects, s), rt::grader::contains_text("between 2 and 1024, got " + std::to_string(bins)));
    }
    for (const int bins : {2, 1024}) {
        BvhSettings s;
        s.bins = bins;
        INFO(bins << " bins");
        CHECK_NOTHROW(BvhAccel(objects, s));
    }
}

TEST_CASE("more objects at one centre than a leaf can count are halved, each object still in one leaf", "[structures]")
{
    // 70000 spheres around one point: no plane separates them, and a leaf counts at most 65535.
    LitScene scene;
    scene.add_material({});
    for (int i = 0; i < 70000; ++i)
        scene.add_sphere({point3(1.0f, 2.0f, 3.0f), 0.5f + 1e-6f * static_cast<float>(i % 7)}, 0);
    const Objects objects = objects_of(scene, lit_tests);
    const BvhAccel bvh(objects);
    std::map<std::uint32_t, int> seen;
    check_node(objects, margins_of(objects), bvh.bvh(), 0, seen);
    CHECK(static_cast<int>(seen.size()) == objects.size());
    INFO(bvh.stats().nodes << " nodes, " << bvh.stats().leaves << " leaves");
    CHECK(bvh.stats().leaves >= 2);
}

TEST_CASE("each SAH split is 10.2's cheapest plane over bins filled box by box, and the first child holds its bins", "[structures]")
{
    // With up to 2, 7 and 32 bins a node: the build's count, the lesser of these and 4 + n / 20,
    // and its bins' sizes, at their edges. The same check runs on the plain lanes in
    // wide_bvh_test.cpp.
    for (const auto& [name, nff] : {std::pair{"stadium 2", generated_scene(write_stadium, 2, "stadium 2")},
                                    std::pair{"tree 3", generated_scene(write_tree, 3, "tree 3")},
                                    std::pair{"mountain 5", generated_scene(write_mountain, 5, "mountain 5")}})
        for (const int bins : {2, 7, 32}) {
            BvhSettings settings;
            settings.bins = bins;
            const LitScene scene = lit_scene(nff);
            const Objects objects = objects_of(scene, lit_tests);
            INFO(name << ", at most " << bins << " bins");
            CHECK(check_sah_splits(objects, settings, name) > 10);
        }
}
