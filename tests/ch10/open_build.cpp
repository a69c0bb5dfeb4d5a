// EXERCISE 10.7 (open): your own build of the BVH. The gate first: the tree keeps 10.7's rules
// (bvh_problem) and answers every ray as brute force does, on the scenes 10.A uses. Then its cost:
// nodes visited and objects tested per closest-hit ray (the SAH's weights) on five generated
// scenes, against the reference's, in three tiers (one case each, so the points add up by tier).
#include "10_hierarchies/bvh.hpp"
#include "chapters/programs/scene_program.hpp"
#include "common/scenes/nff_generators.hpp"
#include "tests/ch07/agreement.hpp"
#include "tests/ch10/bvh_suspect.hpp"
#include "tests/ch10/two_leaves.hpp"
#include "tests/grader/open_tiers.hpp"


using namespace rt;
using namespace rt::grader;
using namespace rt::grader::agreement;
using rt::grader::open_exercise::fixed;

namespace {

BvhSettings open_settings()
{
    BvhSettings s;
    s.split = BvhSplit::open;
    return s;
}

const Build open_build{"your BVH (10.7)",
                       [](const Objects& objects, float) { return std::make_unique<BvhAccel>(objects, open_settings()); },
                       [](const Accelerator& built, const Ray& ray, Interval range, const Objects& objects) {
                           return suspect::diagnose_bvh(dynamic_cast<const BvhAccel&>(built).bvh(), ray, range, objects,
                                                        open_settings());
                       },
                       [](const Objects&, float) { return std::string(); }, "10.7 build_bvh"};

// The gate's edges, on boxes alone: no objects (no nodes), one, 300 boxes at one point (no plane
// separates them: the build must still end) and 66000 there, more than a leaf can count (65535).
bool check_edge_trees()
{
    const Bounds dot{point3(1, 2, 3), point3(1.5f, 2, 3)};
    bool valid = true;
    for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{300}, std::size_t{66000}}) {
        const std::vector<Bounds> boxes(n, dot);
        const WorkingOn on([&] { return "build_bvh of " + std::to_string(n) + " copies of " + show(dot); });
        const Bvh tree = build_bvh(boxes);
        BvhStats shape;
        const std::string problem = bvh_problem(tree, boxes, shape);
        INFO("build_bvh of " << n << " copies of " << show(dot) << ": "
                             << (problem.empty() ? "a valid tree" : problem));
        CHECK(problem.empty());
        valid = valid && problem.empty();
    }
    return valid;
}

// The instrument: 10.7's cost is counted through 10.4, so 10.4 must count as its contract's
// example says (1 test, 3 nodes visited, for the ray along +x through two_leaves()).
bool check_counting()
{
    ObjectHit hit;
    reset_counters();
    const bool found = bvh_query(two_leaves(), {{-3, 0, 0}, {1, 0, 0}}, {0.0f, infinity}, two_objects(), false, hit);
    const Counts counts = total_counts();
    const auto tests = counts[static_cast<size_t>(Counter::intersection_tests)];
    const auto nodes = counts[static_cast<size_t>(Counter::nodes_visited)];
    INFO("10.7's cost is counted through your 10.4: on its contract's example (spheres at x = 1 and 5, a leaf each, the "
         "ray from (-3, 0, 0) along +x) it found "
         << (found ? show(hit) : "no hit") << " after " << tests << " tests and " << nodes
         << " nodes visited; its contract says sphere 0 after 1 test and 3 nodes: start with 10.4's own cases");
    CHECK(found);
    CHECK(tests == 1);
    CHECK(nodes == 3);
    return found && tests == 1 && nodes == 3;
}

// The gate: 10.A's scenes and rays (fewer: a BVH ignores lambda), ties, a huge floor, far away.
// Whether the tree passed it: every rule kept, every ray answered as brute force does.
bool check_gate()
{
    INFO("the gate of 10.7: a tree that breaks a rule or answers a ray differently from brute force scores 0 in every "
         "10.7 case");
    bool passed = check_counting();
    passed = check_edge_trees() && passed;
    return open_exercise::agrees_with_brute_force(open_build, 200,
                                                  {{write_stadium, 2, "stadium 2", 200},
                                                   {write_sticks, 1, "sticks 1", 200},
                                                   {write_tree, 3, "tree 3", 200}}) &&
           passed;
}

// The scenes 10.7's cost is measured on (the contract's "five of the kit's generated scenes"), with
// the reference build's cost per ray on each (ch10.open_reference_costs holds these to the solution's).
using open_exercise::CostScene;
const CostScene cost_scenes[] = {
    {"teapot in a stadium 4", write_stadium, 4, 3.929626},
    {"sticks 3", write_sticks, 3, 13.969360},
    {"sphereflake 3", write_sphereflake, 3, 1.214966},
    {"mountain 5", write_mountain, 5, 1.689636},
    {"tree 4", write_tree, 4, 1.266846},
};
constexpr int cost_rays = 4096;  // seeded rays per scene (seeded_ray), closest hits

// The cost per closest-hit ray of the tree built with `settings` over a scene: nodes visited times
// sah_traversal_cost plus objects tested times sah_intersect_cost, over cost_rays seeded rays.
double cost_per_ray(const CostScene& c, const BvhSettings& settings)
{
    const open_exercise::Counted n = open_exercise::count_closest(
        c.scene(), cost_rays,
        [&](const Objects& objects) { return std::make_unique<BvhAccel>(objects, settings); });
    return n.per_ray(Counter::nodes_visited) * sah_traversal_cost + n.per_ray(Counter::intersection_tests) * sah_intersect_cost;
}

// The cost of your build (open_settings) on one scene.
double open_cost_per_ray(const CostScene& c) { return cost_per_ray(c, open_settings()); }

}  // namespace

OPEN_EXERCISE_TIERS("build_bvh (open): a correct tree", "", "10.7", 4, check_gate, cost_scenes, open_cost_per_ray,
                    "per ray", "your tree's cost (nodes visited / 8 + objects tested, per closest-hit ray)")

// The kit's own check (not graded; ch10.open_reference_costs runs it on the solutions): the
// reference costs above are what the reference build measures now, and the lesson's other builds.
TEST_CASE("10.7's stored reference costs are the reference build's", "[.][open_reference_costs]")
{
    for (const CostScene& c : cost_scenes) {
        const double reference = cost_per_ray(c, open_settings());
        BvhSettings binned, median, median1;
        median.split = median1.split = BvhSplit::median;
        median1.leaf_size = 1;
        WARN(c.name << ": reference " << fixed(reference, 6) << ", given binned SAH " << fixed(cost_per_ray(c, binned), 4)
                    << ", median (leaf 4) " << fixed(cost_per_ray(c, median), 4) << ", median (leaf 1) "
                    << fixed(cost_per_ray(c, median1), 4));
        CHECK(fixed(reference, 6) == fixed(c.reference, 6));
    }
}
