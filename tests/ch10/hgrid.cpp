// EXERCISE 10.5: the child grid's descent, on hierarchies built by hand and against brute force on
// seeded rays through hierarchies built by hgrid.hpp.
#include "10_hierarchies/figure.hpp"
#include "tests/ch07/agreement.hpp"
#include "tests/ch10/hgrid_suspect.hpp"

#include <filesystem>
#include <iomanip>

using namespace rt;
using namespace rt::grader;
using namespace rt::grader::agreement;

namespace {

// A root of two cells along x over the box (0, -1, -1) to (5, 3, 2): cell 0 is x in [0, 2.5],
// cell 1 x in [2.5, 5]. The ray from (-1, 0.5, 0.5) along +x enters cell 0 at t = 1 and cell 1 at
// t = 3.5.
const Ray along_x{{-1, 0.5f, 0.5f}, {1, 0, 0}};
const Bounds root_box{{0, -1, -1}, {5, 3, 2}};

// Object 0: a sphere at x = 3 (hit at x = 2.7, t = 3.7), in cell 1 only. Object 1: a sphere at
// x = 1.5 (hit at x = 1.3, t = 2.3), in cell 0. Object 2: a triangle in the plane x + y = 4, its
// box from x = 1.5 to 4.5 (both cells), crossing the ray at x = 3.5 (t = 4.5), in cell 1.
const std::vector<Sphere> spheres = {{{3, 0.5f, 0.5f}, 0.3f}, {{1.5f, 0.5f, 0.5f}, 0.2f}};
const std::vector<Triangle> triangles = {{{4.5f, -0.5f, -1}, {4.5f, -0.5f, 2}, {1.5f, 2.5f, 0.5f}}};

Objects objects() { return objects_over(spheres, triangles); }

// A grid over `box` cut `n` ways along x, with `lists[c]` in cell c and no children.
GridNode node_of(const Bounds& box, int n, const std::vector<std::vector<std::uint32_t>>& lists)
{
    GridNode node;
    node.grid.shape = grid_shape(box, {n, 1, 1});
    node.grid.cell_start = {0};
    for (const auto& list : lists) {
        node.grid.object_index.insert(node.grid.object_index.end(), list.begin(), list.end());
        node.grid.cell_start.push_back(static_cast<std::uint32_t>(node.grid.object_index.size()));
    }
    node.child.assign(static_cast<size_t>(n), -1);
    return node;
}

// The root above, with cell 0 holding a grid of its own (grid 1: two cells along x over cell 0's
// box) that lists `in_child` in both its cells; the root's cell 0 lists `in_root_cell0`.
HGrid two_levels(const std::vector<std::uint32_t>& in_root_cell0, const std::vector<std::uint32_t>& in_child)
{
    HGrid h;
    h.grids.push_back(node_of(root_box, 2, {in_root_cell0, {0, 2}}));
    h.grids.push_back(node_of({{0, -1, -1}, {2.5f, 3, 2}}, 2, {in_child, in_child}));
    h.grids[0].child[0] = 1;
    return h;
}

// Small leaves and a deep limit, so the kit's small scenes get grids within grids.
const Build hgrid{"the hierarchy of grids", [](const Objects& objects, float lambda) {
                      HGridSettings s;
                      s.lambda = lambda;
                      s.leaf_size = 2;
                      s.max_depth = 3;
                      return std::make_unique<HGridAccel>(objects, s);
                  },
                  // A failing case asks 10.5 again on the first ray that differs (hgrid_suspect.hpp).
                  [](const Accelerator& built, const Ray& ray, Interval range, const Objects& objects) {
                      return suspect::diagnose_hgrid(dynamic_cast<const HGridAccel&>(built).hgrid(), ray, range, objects);
                  }};

}  // namespace

GRADED_TEST("hgrid_closest: a cell holding a grid of its own is asked through that grid", "10.5", 4)
{
    // The root's cell 0 lists nothing itself; its grid lists sphere 1.
    const HGrid h = two_levels({}, {1});
    ObjectHit best;
    reset_counters();
    const bool found = hgrid_closest(h, 0, along_x, {0.0f, infinity}, {0.0f, infinity}, objects(), best);
    INFO(show(along_x) << " into a root cell that lists nothing but holds a grid listing the sphere at x = 1.5: got "
         << answer(found, best) << " after " << total_count(Counter::cells_visited)
         << " cells; expected object 1 at t = 2.3 after 3 cells (the root's cell 0, then the child's cells 0 and 1)");
    CHECK(found);
    CHECK(best.object == 1);
    CHECK(std::abs(best.t - 2.3f) < 1e-5f);
    // The child's cell 0 is x in [0, 1.25]; the hit at x = 1.3 lies in its cell 1. Every level counts.
    CHECK(total_count(Counter::cells_visited) == 3);
}

GRADED_TEST("hgrid_closest: a child grid keeps no hit beyond its parent's cell, where a nearer object may come first",
            "10.5", 5)
{
    // The triangle is listed in the child of cell 0 (its box reaches there) but crosses the ray at
    // t = 4.5, in cell 1, behind sphere 0 at t = 3.7.
    const HGrid h = two_levels({2}, {2});
    ObjectHit best;
    const bool found = hgrid_closest(h, 0, along_x, {0.0f, infinity}, {0.0f, infinity}, objects(), best);
    INFO(show(along_x) << ": the child of cell 0 lists a triangle hit at t = 4.5, beyond cell 0 (which ends at t = 3.5); "
         "cell 1 lists sphere 0 at t = 3.7. Got " << answer(found, best) << ", expected object 0 at t = 3.7: the child's "
         "walk is over the part of the ray inside its cell, and its last cell keeps hits up to that cell's end only");
    CHECK(found);
    CHECK(best.object == 0);
    CHECK(std::abs(best.t - 3.7f) < 1e-5f);
}

GRADED_TEST("hgrid_closest: a hit in a child grid ends the walk; a walk over a part the grid misses finds nothing",
            "10.5", 3)
{
    const HGrid h = two_levels({1}, {1});
    ObjectHit best;
    reset_counters();
    const bool found = hgrid_closest(h, 0, along_x, {0.0f, infinity}, {0.0f, infinity}, objects(), best);
    INFO("the sphere at x = 1.5 found in the child of the root's cell 0: got " << answer(found, best) << " after "
         << total_count(Counter::intersection_tests) << " tests; expected object 1 and no test in the root's cell 1");
    CHECK(found);
    CHECK(best.object == 1);
    CHECK(total_count(Counter::intersection_tests) <= 2);

    ObjectHit none;
    const Ray above{{-1, 5, 0.5f}, {1, 0, 0}};
    const bool miss = hgrid_closest(h, 0, above, {0.0f, infinity}, {0.0f, infinity}, objects(), none);
    const bool nan = hgrid_closest(h, 0, {{-1, std::nanf(""), 0.5f}, {1, 0, 0}}, {0.0f, infinity}, {0.0f, infinity},
                                   objects(), none);
    INFO("a ray passing above the root's box, and a NaN ray: got " << miss << " and " << nan << ", expected no hits");
    CHECK(!miss);
    CHECK(!nan);
}

GRADED_TEST("hgrid_closest: a walk over a part the grid misses visits no cell and tests nothing, where one through it visits its cells", "10.5", 1)
{
    const HGrid h = two_levels({1}, {1});
    // The same grid is walked, and visited, by a ray through it.
    ObjectHit best;
    reset_counters();
    const bool found = hgrid_closest(h, 0, along_x, {0.0f, infinity}, {0.0f, infinity}, objects(), best);
    INFO("10.5: " << show(along_x) << ", through the root's box: got " << answer(found, best) << " after "
         << total_count(Counter::cells_visited) << " cells visited; expected object 1, its cell visited");
    CHECK(found);
    CHECK(total_count(Counter::cells_visited) > 0);
    ObjectHit none;
    const Ray above{{-1, 5, 0.5f}, {1, 0, 0}};
    reset_counters();
    const bool miss = hgrid_closest(h, 0, above, {0.0f, infinity}, {0.0f, infinity}, objects(), none);
    INFO("10.5: " << show(above) << ", passing above the root's box: got " << answer(miss, none) << " after "
         << total_count(Counter::cells_visited) << " cells visited and " << total_count(Counter::intersection_tests)
         << " tests; expected no hit, no cell visited and no test: a walk that misses the box has no cell to visit");
    CHECK(!miss);
    CHECK(total_count(Counter::cells_visited) == 0);
    CHECK(total_count(Counter::intersection_tests) == 0);
}

GRADED_TEST("the hierarchy of grids answers every ray as brute force does, on the kit's scenes and generated ones",
            "10.5", 5)
{
    for (const auto& entry : std::filesystem::directory_iterator(RT_NFF_SCENES_DIR))
        if (entry.path().extension() == ".nff")
            check_scene(hgrid, read_nff(entry.path().string()), 400);
    check_scene(hgrid, generated_scene(write_stadium, 2, "stadium 2"), 600);
    check_scene(hgrid, generated_scene(write_sticks, 1, "sticks 1"), 600);
    check_scene(hgrid, generated_scene(write_tree, 3, "tree 3"), 400);
}

STABILITY_TEST("the hierarchy of grids answers as brute force does on ties, a huge floor and far from the origin", "10.5",
               3)
{
    check_hard_cases(hgrid);
}

TEST_CASE("the hierarchy of grids subdivides only crowded cells, and no deeper than its limit")
{
    const NffScene nff = generated_scene(write_stadium, 2, "stadium 2");
    const LitScene scene = lit_scene(nff);
    const Objects objs = objects_of(scene, lit_tests);
    for (const int depth : {0, 1, 3}) {
        HGridSettings s;
        s.leaf_size = 8;
        s.max_depth = depth;
        const HGridAccel accel(objs, s);
        const HGrid& h = accel.hgrid();
        INFO("stadium 2, " << objs.size() << " objects, depth limit " << depth << ": " << h.grids.size() << " grids, depth "
             << accel.stats().depth);
        CHECK(accel.stats().depth <= depth);
        CHECK((depth == 0) == (h.grids.size() == 1));
        for (const GridNode& node : h.grids)
            for (int p = 0; p < node.grid.shape.cell_count(); ++p)
                if (node.child[p] >= 0) {
                    INFO("a cell with a grid of its own lists " << node.grid.cell_start[p + 1] - node.grid.cell_start[p]
                         << " objects");
                    CHECK(node.grid.cell_start[p + 1] - node.grid.cell_start[p] > 8u);
                }
    }
}

GRADED_TEST("hgrid_closest: a child grid keeps a hit exactly where its parent's cell ends; one float step beyond, the parent's next cell finds it",
            "10.5", 3)
{
    // A triangle across the ray in the plane x = 2.5, where the root's cell 0 (and its child
    // grid's cell 1) ends and cell 1 begins, then one float step beyond it. Listed in both root
    // cells and in the child grid's cell 1.
    const std::vector<Sphere> no_spheres;
    const float at = 2.5f, beyond = std::nextafter(2.5f, infinity);
    for (const float x : {at, beyond}) {
        const std::vector<Triangle> tris = {{{x, -1, -1}, {x, 3, -1}, {x, -1, 3}}};
        const Objects o = objects_over(no_spheres, tris);
        HGrid h;
        h.grids.push_back(node_of(root_box, 2, {{0}, {0}}));
        h.grids.push_back(node_of({{0, -1, -1}, {2.5f, 3, 2}}, 2, {{}, {0}}));
        h.grids[0].child[0] = 1;
        ObjectHit want;
        REQUIRE(brute_force().closest(along_x, {0.0f, infinity}, o, want));
        REQUIRE((x == at ? want.t == 3.5f : want.t > 3.5f));  // the case's own set-up
        ObjectHit best;
        reset_counters();
        const bool found = hgrid_closest(h, 0, along_x, {0.0f, infinity}, {0.0f, infinity}, o, best);
        const std::uint64_t cells = total_count(Counter::cells_visited);
        const int expected_cells = x == at ? 3 : 4;
        INFO("10.5: " << show(along_x) << "; the root's cell 0 ends at t = 3.5 and holds a grid of its own; a triangle in "
             "the plane x = " << std::setprecision(9) << x << ", hit at t = " << want.t << ", listed in the child's cell 1 and "
             "the root's cell 1. Got " << answer(found, best) << " after " << cells << " cells visited; expected "
             << show(want) << " after " << expected_cells << " cells: "
             << (x == at ? "the child's last cell keeps a hit up to and including where the parent's cell ends (the root's "
                           "cell 0, the child's cells 0 and 1)"
                         : "a hit one float step past the parent's cell is not the child's: the root goes on to its cell 1"));
        CHECK(found);
        CHECK(best.object == 0);
        CHECK(best.t == want.t);
        CHECK(cells == static_cast<std::uint64_t>(expected_cells));
    }
}
