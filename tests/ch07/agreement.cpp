// The grid as a whole (EXERCISES 07.1-07.6 with the given build): on seeded rays over the kit's
// scene files and its generated scenes, at several densities, it must answer every query as
// brute force does: the same object at the same t, bit for bit, and the same any-hit answer.
#include "07_uniform_grid/figure.hpp"
#include "tests/ch07/agreement.hpp"
#include "tests/ch07/grid_suspect.hpp"

using namespace rt;
using namespace rt::grader;
using namespace rt::grader::agreement;

namespace {

// A failing case runs the grid's exercises again on the first ray that differs (grid_suspect.hpp).
const Build grid{"the grid", [](const Objects& objects, float lambda) { return std::make_unique<UniformGrid>(objects, lambda); },
                 [](const Accelerator& built, const Ray& ray, Interval range, const Objects& objects) {
                     return suspect::diagnose_grid(dynamic_cast<const UniformGrid&>(built), ray, range, objects);
                 },
                 suspect::diagnose_grid_build, "07.1 grid_resolution, 07.2 cell_of and 07.3 cells_overlapping"};

}  // namespace

GRADED_TEST("the grid answers every ray as brute force does, object and t, on the kit's scene files", "07.A", 4)
{
    check_scene_files(grid, RT_NFF_SCENES_DIR, 1500);
}

GRADED_TEST("the grid answers every ray as brute force does on the generated sphereflake, pyramid, tree and mountain", "07.A", 4)
{
    check_scene(grid, generated_scene(write_sphereflake, 2, "sphereflake 2"), 800);
    check_scene(grid, generated_scene(write_pyramid, 3, "pyramid 3"), 800);
    check_scene(grid, generated_scene(write_tree, 3, "tree 3"), 800);
    check_scene(grid, generated_scene(write_mountain, 4, "mountain 4"), 800);
}

STABILITY_TEST("the grid answers as brute force does on ties, a huge floor under tiny objects, and far from the origin", "07.A", 4)
{
    check_hard_cases(grid);
}
