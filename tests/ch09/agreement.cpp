// The hashed grid as a whole (EXERCISES 09.1-09.5 with chapter 07's walk and the given build):
// brute force's answers on every ray, at resolutions far beyond the dense grid's.
#include "09_hashed_voxels/figure.hpp"
#include "tests/ch07/agreement.hpp"
#include "tests/ch09/hashed_suspect.hpp"

using namespace rt;
using namespace rt::grader;
using namespace rt::grader::agreement;

namespace {

// The agreement tests' densities times 100: 30 to 900 cells per object.
// A failing case replays the query on the first ray that differs, exercise by exercise (hashed_suspect.hpp).
const Build hashed{"the hashed grid",
                   [](const Objects& objects, float lambda) { return std::make_unique<HashedGrid>(objects, 100.0f * lambda); },
                   [](const Accelerator& built, const Ray& ray, Interval range, const Objects& objects) {
                       return suspect::diagnose_hashed(dynamic_cast<const HashedGrid&>(built), ray, range, objects);
                   }};

}  // namespace

GRADED_TEST("the hashed grid answers every ray as brute force does, on the kit's scenes and generated ones", "09.A", 4)
{
    check_scene_files(hashed, RT_NFF_SCENES_DIR, 600);
    check_scene(hashed, generated_scene(write_stadium, 2, "stadium 2"), 600);
    check_scene(hashed, generated_scene(write_mountain, 4, "mountain 4"), 400);
}

STABILITY_TEST("the hashed grid answers as brute force does on ties, a huge floor and far from the origin", "09.A", 3)
{
    check_hard_cases(hashed);
}
