// An open exercise's cost and tiers (08.4's, 09.6's and 10.7's graded cases): seeded rays cast over a
// generated scene and counted, the student's cost over the reference's as a geometric mean over the
// scenes, and one tier case: the gate first, then (only for answers that passed it: only those are
// ranked) the measure reported for the leaderboard and the tier asked.
#pragma once

#include "tests/ch07/agreement.hpp"
#include "tests/grader/graded.hpp"
#include "tests/grader/measure.hpp"

#include <cmath>
#include <initializer_list>
#include <iomanip>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>

namespace rt::grader::open_exercise {

inline std::string fixed(double v, int digits)
{
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << v;
    return s.str();
}

// One generated scene of an open exercise's gate: its generator, depth and name, and the seeded rays
// asked a density (agreement::check_scene).
struct GateScene {
    void (*write)(std::ostream&, int);
    int depth;
    const char* name;
    int rays;
};

// The agreement half of an open exercise's gate: the kit's scene files (`file_rays` rays a density),
// each generated scene, and the hard cases (ties, a huge floor, far away), every ray answered as
// brute force does, closest and any hit. Whether all agreed (each disagreement a failed check that
// names its first ray).
inline bool agrees_with_brute_force(const agreement::Build& build, int file_rays, std::initializer_list<GateScene> scenes)
{
    bool passed = agreement::check_scene_files(build, RT_NFF_SCENES_DIR, file_rays);
    for (const GateScene& g : scenes)
        passed = agreement::check_scene(build, generated_scene(g.write, g.depth, g.name), g.rays) && passed;
    return agreement::check_hard_cases(build) && passed;
}

// One generated scene an open exercise's cost is measured on (07.7's, 10.7's): its name, generator
// and depth, and the reference's cost per ray there (the exercise's [open_reference_costs] check
// holds it to the solution's).
struct CostScene {
    const char* name;
    void (*write)(std::ostream&, int);
    int depth;
    double reference;

    NffScene scene() const { return generated_scene(write, depth, name); }
};

// The counts of `rays` closest-hit queries (agreement::seeded_ray, seed 77: from the view's eye and
// from in and around the scene) of the structure make(objects) builds over a scene's objects, and
// how many rays were cast.
struct Counted {
    Counts counts;
    int rays = 0;

    double per_ray(Counter c) const { return static_cast<double>(counts[static_cast<size_t>(c)]) / rays; }
};

template <class Make>
Counted count_closest(const NffScene& nff, int rays, Make&& make)
{
    const LitScene scene = lit_scene(nff);
    const Objects objects = objects_of(scene, lit_tests);
    const std::unique_ptr<Accelerator> structure = make(objects);
    Bounds box;
    for (int k = 0; k < objects.size(); ++k)
        box.grow(objects.bounds(k));
    Rng rng(77, 3);
    reset_counters();
    Counted c;
    for (int k = 0; k < rays; ++k)
        if (const std::optional<agreement::SeededRay> r = agreement::seeded_ray(rng, nff.view, box, k)) {
            ObjectHit hit;
            structure->closest(r->ray, r->range, objects, hit);
            ++c.rays;
        }
    c.counts = total_counts();
    return c;
}

// The geometric mean over `scenes` (each with a name and the reference's cost) of cost(scene) over
// the reference's, with each scene's figures in words ("<name>: 1.23 <unit>, the reference 1.00").
template <class Scenes, class Cost>
double geometric_ratio(const Scenes& scenes, Cost&& cost, const std::string& unit, std::string& words)
{
    double log_sum = 0.0;
    for (const auto& c : scenes) {
        const double mine = cost(c);
        log_sum += std::log(mine / c.reference);
        words += std::string("\n  ") + c.name + ": " + fixed(mine, 2) + " " + unit + ", the reference " + fixed(c.reference, 2);
    }
    return std::exp(log_sum / static_cast<double>(std::size(scenes)));
}

// One tier case: gate() first (false: the failed checks say why, and nothing is measured or
// ranked), then the geometric mean over `scenes` of cost(scene) over the reference's (each scene's
// figures said in `unit`), reported as `measure` to three decimals (as the leaderboard shows it),
// at most `tier`. `what` names the cost in the message: "your tree's cost (...)".
template <class Gate, class Scenes, class Cost>
void check_tier(Gate&& gate, const Scenes& scenes, Cost&& cost, const std::string& unit, const std::string& measure,
                const std::string& what, double tier)
{
    if (!gate())
        return;
    std::string words;
    const double ratio = geometric_ratio(scenes, cost, unit, words);
    report_measure(measure, std::round(ratio * 1000.0) / 1000.0, 1.0, words);
    INFO(what << " is " << fixed(ratio, 3) << " times the reference's (the geometric mean over the scenes);" << words
              << "\nthis tier asks at most " << fixed(tier, 2) << " times");
    CHECK(ratio <= tier);
}

}  // namespace rt::grader::open_exercise

// An open exercise's three graded cases, one a tier (at most 2, 1.5 and 1.02 times the reference's
// cost: the points add up by tier), each worth `points`: `what` opens each case's name ("build_bvh
// (open): a correct tree"), `unit` ends it ("" or " tests"), and each is check_tier(gate, scenes,
// cost, the scenes' unit, the exercise's measure ("10.7 cost"), the cost in words, its tier).
#define OPEN_EXERCISE_TIERS(what, unit, number, points, gate, scenes, cost, scene_unit, cost_words)                 \
    GRADED_TEST(what " costing at most 2 times the reference's" unit, number, points)                               \
    {                                                                                                               \
        rt::grader::open_exercise::check_tier(gate, scenes, cost, scene_unit, number " cost", cost_words, 2.0);     \
    }                                                                                                               \
    GRADED_TEST(what " costing at most 1.5 times the reference's" unit, number, points)                             \
    {                                                                                                               \
        rt::grader::open_exercise::check_tier(gate, scenes, cost, scene_unit, number " cost", cost_words, 1.5);     \
    }                                                                                                               \
    GRADED_TEST(what " costing at most 1.02 times the reference's" unit, number, points)                            \
    {                                                                                                               \
        rt::grader::open_exercise::check_tier(gate, scenes, cost, scene_unit, number " cost", cost_words, 1.02);    \
    }
