// EXERCISE 07.7 (open): the grid's shape for a scene. The gate first: on every scene the gate
// builds over, your resolution is valid (1 to max_cells_per_axis cells an axis, within the memory
// budget), and the grid built with it answers every ray as brute force does, on the scenes 07.A
// uses. Then its cost: objects tested plus cells visited times grid_cell_step_cost per closest-hit
// ray on four generated scenes, against the reference's, in three tiers (one case each, so the
// points add up by tier).
#include "07_uniform_grid/figure.hpp"
#include "common/scenes/nff_generators.hpp"
#include "tests/ch07/agreement.hpp"
#include "tests/ch07/grid_suspect.hpp"
#include "tests/grader/open_tiers.hpp"

using namespace rt;
using namespace rt::grader;
using namespace rt::grader::agreement;
using rt::grader::open_exercise::fixed;

namespace {

// A scene's resolution question as the build asks it, your answer and what is wrong with it ("" for
// nothing), each scene the gate or the cost builds over asked once before any grid is built, so
// that an invalid answer is named by its scene and rule, not by a build's exception.
std::string problem_on(const NffScene& nff)
{
    const LitScene scene = lit_scene(nff);
    const Objects objects = objects_of(scene, lit_tests);
    const ResolutionQuestion q = resolution_question(objects, margins_of(objects));
    return grid_resolution_problem(q.box, q.boxes, choose_grid_resolution(q.box, q.boxes));
}

// A failing ray runs the grid's exercises again (grid_suspect.hpp), as 07.A's cases do: the
// resolution is valid by then, so a wrong answer is the walk's or the cells'.
const Build chosen{"the grid at your 07.7's resolution",
                   [](const Objects& objects, float) { return std::make_unique<UniformGrid>(objects, ChosenResolution{}); },
                   [](const Accelerator& built, const Ray& ray, Interval range, const Objects& objects) {
                       return suspect::diagnose_grid(dynamic_cast<const UniformGrid&>(built), ray, range, objects);
                   },
                   [](const Objects&, float) {
                       return std::string("\n  (a scene of the gate's own, built for its rays: twin triangles, or a floor under "
                                          "tiny spheres; every answer must keep the rules on every scene)");
                   },
                   "07.7 choose_grid_resolution, 07.2 cell_of and 07.3 cells_overlapping"};

// The scenes 07.7's cost is measured on (the contract's "four of the kit's generated scenes"),
// with the reference resolution's cost per ray on each (grader.ch07.open_reference_costs... holds
// these to the solution's).
using open_exercise::CostScene;
const CostScene cost_scenes[] = {
    {"teapot in a stadium 3", write_stadium, 3, 159.437744},
    {"teapot in a stadium 4", write_stadium, 4, 226.428711},
    {"sphereflake 3", write_sphereflake, 3, 10.200195},
    {"mountain 5", write_mountain, 5, 11.850830},
};
constexpr int cost_rays = 4096;  // seeded rays per scene (seeded_ray), closest hits

// Every scene the gate and the cost build a grid over, asked for a resolution first: whether each
// answer is valid (a failed check names the first scene and rule broken).
bool check_resolutions()
{
    std::vector<NffScene> scenes;
    for (const auto& entry : std::filesystem::directory_iterator(RT_NFF_SCENES_DIR))
        if (entry.path().extension() == ".nff")
            scenes.push_back(read_nff(entry.path().string()));
    scenes.push_back(generated_scene(write_sphereflake, 2, "sphereflake 2"));
    scenes.push_back(generated_scene(write_mountain, 4, "mountain 4"));
    scenes.push_back(generated_scene(write_sticks, 1, "sticks 1"));
    for (const CostScene& c : cost_scenes)
        scenes.push_back(c.scene());
    for (const NffScene& nff : scenes) {
        const std::string problem = problem_on(nff);
        INFO("your 07.7 on " << nff.name << ": " << (problem.empty() ? "a valid resolution" : problem));
        CHECK(problem.empty());
        if (!problem.empty())
            return false;
    }
    return true;
}

// The gate: a valid resolution on every scene, then 07.A's kinds of scenes and rays (fewer: the
// build ignores lambda), ties, a huge floor, far away. Whether the answer passed it.
bool check_gate()
{
    INFO("the gate of 07.7: a resolution outside the rules or the budget, or a grid that answers a ray differently "
         "from brute force, scores 0 in every 07.7 case");
    return check_resolutions() &&
           open_exercise::agrees_with_brute_force(chosen, 200,
                                                  {{write_sphereflake, 2, "sphereflake 2", 200},
                                                   {write_mountain, 4, "mountain 4", 200},
                                                   {write_sticks, 1, "sticks 1", 200}});
}

// The cost per closest-hit ray of the grid make(objects) builds over a scene: objects tested plus
// cells visited times grid_cell_step_cost, over cost_rays seeded rays.
template <class Make>
double cost_per_ray(const CostScene& c, Make&& make)
{
    const open_exercise::Counted n = open_exercise::count_closest(c.scene(), cost_rays, make);
    return n.per_ray(Counter::intersection_tests) + n.per_ray(Counter::cells_visited) * grid_cell_step_cost;
}

double chosen_cost(const CostScene& c)
{
    return cost_per_ray(c, [](const Objects& o) { return std::make_unique<UniformGrid>(o, ChosenResolution{}); });
}

}  // namespace

OPEN_EXERCISE_TIERS("choose_grid_resolution (open): a valid shape", "", "07.7", 4, check_gate, cost_scenes, chosen_cost,
                    "per ray", "your grid's cost (objects tested + cells visited, per closest-hit ray)")

// The kit's own check (not graded; grader.ch07.open_reference_costs_are_the_solutions runs it on
// the solutions): the reference costs above are what the reference resolution measures now, and
// the lesson's other rows: 07.1's cube-root rule (the given build's plan) at the chapter's default
// lambda, at lambda 1 and at lambda 16, each with its resolution and words an object.
TEST_CASE("07.7's stored reference costs are the reference resolution's", "[.][open_reference_costs]")
{
    for (const CostScene& c : cost_scenes) {
        const LitScene scene = lit_scene(c.scene());
        const Objects objects = objects_of(scene, lit_tests);
        const ResolutionQuestion q = resolution_question(objects, margins_of(objects));
        const auto shown = [&](const cell3& n, double cost, double reference) {
            return std::to_string(n.x) + "x" + std::to_string(n.y) + "x" + std::to_string(n.z) + " " + fixed(cost, 4) +
                   " (" + fixed(cost / reference, 3) + "x, " +
                   fixed(static_cast<double>(grid_words(q.box, q.boxes, n)) / q.boxes.size(), 2) + " words an object)";
        };
        const double reference = chosen_cost(c);
        std::string rows = c.name + std::string(": reference ") + shown(choose_grid_resolution(q.box, q.boxes), reference, reference);
        for (const float lambda : {ch07::default_lambda, 1.0f, 16.0f}) {
            cell3 n;
            const double rule = cost_per_ray(c, [&](const Objects& o) {
                auto grid = std::make_unique<UniformGrid>(o, lambda);
                n = grid->stats().resolution;
                return grid;
            });
            rows += ", 07.1 at lambda " + fixed(lambda, 0) + " " + shown(n, rule, reference);
        }
        WARN(rows);
        CHECK(fixed(reference, 6) == fixed(c.reference, 6));
    }
}

// The kit's own check of 07.7's contract example (not graded; it runs with the stored costs'
// check): 64 boxes of side 0.1, one at the centre of each 0.5 x 0.5 square of a floor 4 x 0.1 x 4,
// take 129 words at 8 x 1 x 8 (65 offsets, 64 references), within the budget of 2048; 64 x 1 x 64
// passes it with its 4097 offsets alone.
TEST_CASE("07.7's contract example: the words of two resolutions of a floor of boxes", "[.][open_reference_costs]")
{
    const Bounds floor{point3(0.0f), point3(4.0f, 0.1f, 4.0f)};
    std::vector<Bounds> boxes;
    for (int i = 0; i < 8; ++i)
        for (int k = 0; k < 8; ++k) {
            const point3 c(0.25f + 0.5f * i, 0.05f, 0.25f + 0.5f * k);
            boxes.push_back({c - vec3(0.05f), c + vec3(0.05f)});
        }
    CHECK(grid_budget_words(boxes.size()) == 2048);
    CHECK(grid_words(floor, boxes, {8, 1, 8}) == 129);
    CHECK(grid_resolution_problem(floor, boxes, {8, 1, 8}).empty());
    CHECK(grid_words(floor, boxes, {64, 1, 64}) > 2048);
    CHECK(grid_resolution_problem(floor, boxes, {64, 1, 64}).find("4097 offsets") != std::string::npos);
    CHECK(grid_resolution_problem(floor, boxes, {0, 1, 8}).find("0 cells along x") != std::string::npos);
}
