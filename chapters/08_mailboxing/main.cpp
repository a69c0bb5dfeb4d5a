// Chapter 08's program: renders the figure (a pile of sticks through the grid with mailboxes,
// beside the heat map of the tests its mailboxes answered) or any NFF scene (--scene, --classic)
// through brute force or the grid, with or without mailboxes (--accel). --sweep
// measures the trade: tests and time saved by the mailboxes against the grid's density, by ray
// kind (primary, shadow, secondary), on three scenes.
#include "03_reflection_refraction/03_reflection_refraction.hpp"
#include "04_shadow_feelers/04_shadow_feelers.hpp"
#include "08_mailboxing/figure.hpp"
#include "common/cli.hpp"
#include "common/lesson_table.hpp"
#include "common/output.hpp"
#include "common/trade.hpp"
#include "programs/measure.hpp"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace rt;

namespace {

struct Options {
    CommonOptions common;
    SceneOptions scene;
    StructureChoice structure{ch08::structures(), "grid-mailbox"};
    SweepOptions sweep{false, 9, "08_mailboxing.csv"};
};

SceneProgram scene_program(const Options& o)
{
    return {"08_mailboxing",
            ch08::figure_scene,
            {{"saved", Counter::mailbox_hits, "tests answered by mailboxes per pixel"},
             {"tests", Counter::intersection_tests, "intersection tests per pixel"},
             {"cells", Counter::cells_visited, "cells visited per pixel"}},
            &o.structure,
            {{"cells_visited", Counter::cells_visited}, {"tests_answered_by_mailboxes", Counter::mailbox_hits}},
            {}};
}

// --- The trade ---

// The rays of one kind, each with the query it asks.
struct RaySet {
    std::string kind;  // primary, shadow, secondary
    bool any_hit;
    std::vector<Ray> rays;
    std::vector<Interval> ranges;
};

// The scene's primary rays at the settings' size, the shadow feelers from their hits to every
// light the surface faces (from the robust offset, EXERCISE 04.3), and one mirror ray from each
// hit: the three kinds of ray a Whitted tracer sends.
std::vector<RaySet> ray_sets(const SceneRender& file, const LitScene& scene)
{
    RaySet primary{"primary", false, {}, {}}, shadow{"shadow", true, {}, {}}, secondary{"secondary", false, {}, {}};
    for (int j = 0; j < file.settings.height; ++j)
        for (int i = 0; i < file.settings.width; ++i) {
            const Ray ray = file.eye_ray(primary_ray(file.camera, static_cast<float>(i), static_cast<float>(j)));
            primary.rays.push_back(ray);
            primary.ranges.push_back({0.0f, infinity});
            const std::optional<Hit> hit = closest_hit(ray, scene, Interval{0.0f, infinity});
            if (!hit)
                continue;
            for_each_feeler(scene, ray, *hit, [&](const point3& light, const point3& origin) {
                const Feeler f = feeler(origin, light, 0.0f);
                shadow.rays.push_back(f.ray);
                shadow.ranges.push_back(f.range);
            });
            const vec3 n = glm::dot(hit->n, ray.dir) > 0.0f ? -hit->n : hit->n;
            const vec3 r = reflect(ray.dir, n);
            secondary.rays.push_back({offset_ray_origin(hit->p, hit->ng, r), r});
            secondary.ranges.push_back({0.0f, infinity});
        }
    return {primary, shadow, secondary};
}

struct Run {
    Timing ms;
    std::uint64_t tests = 0, saved = 0;
    std::vector<ObjectHit> answers;
};

// Every ray of the set through `accel`, on this thread, once: the answers and what they cost.
Run count_pass(const Accelerator& accel, const RaySet& set, const Objects& objects)
{
    Run r;
    reset_counters();
    for (size_t k = 0; k < set.rays.size(); ++k) {
        ObjectHit h;
        if (set.any_hit)
            h.object = accel.any(set.rays[k], set.ranges[k], objects) ? 1 : -1;
        else if (!accel.closest(set.rays[k], set.ranges[k], objects, h))
            h = ObjectHit{};
        r.answers.push_back(h);
    }
    const Counts counts = total_counts();
    r.tests = counted(counts, Counter::intersection_tests);
    r.saved = counted(counts, Counter::mailbox_hits);
    return r;
}

double timed_pass(const Accelerator& accel, const RaySet& set, const Objects& objects)
{
    const Timer timer;
    for (size_t k = 0; k < set.rays.size(); ++k) {
        ObjectHit h;
        if (set.any_hit)
            accel.any(set.rays[k], set.ranges[k], objects);
        else
            accel.closest(set.rays[k], set.ranges[k], objects, h);
    }
    return 1e3 * timer.seconds();
}

// The two structures on the same rays: a counted pass each, then `repeat` timed passes of each,
// interleaved (a, b, a, b, ...) so that the machine's changing load falls on both alike.
std::pair<Run, Run> compare(const Accelerator& a, const Accelerator& b, const RaySet& set, const Objects& objects,
                            int repeat)
{
    std::pair<Run, Run> runs{count_pass(a, set, objects), count_pass(b, set, objects)};
    std::vector<double> ta, tb;
    for (int rep = 0; rep < repeat; ++rep) {
        ta.push_back(timed_pass(a, set, objects));
        tb.push_back(timed_pass(b, set, objects));
    }
    runs.first.ms = timing_of(ta);
    runs.second.ms = timing_of(tb);
    return runs;
}

bool same_answers(const Run& a, const Run& b)
{
    if (a.answers.size() != b.answers.size())
        return false;
    for (size_t k = 0; k < a.answers.size(); ++k)
        if (a.answers[k].object != b.answers[k].object || (a.answers[k].object >= 0 && a.answers[k].t != b.answers[k].t))
            return false;
    return true;
}

void sweep(const Options& o, const CommandLine& cli)
{
    const RenderSettings settings = sweep_settings(o.common, cli, 320, 180);
    std::cerr << "measuring what the mailboxes save, by density and ray kind, on three scenes...\n";
    std::ofstream csv(o.sweep.csv);
    csv << "scene,objects,lambda,references_per_object,kind,count,tests_per_ray_grid,tests_per_ray_mailboxes,"
           "tests_saved_percent,ms_grid,ms_mailboxes,time_saved_percent,ms_grid_min,ms_grid_max,ms_mailboxes_min,"
           "ms_mailboxes_max,runs\n";
    LessonTable table{"08.saved",
                      {{"scene"}, {"lambda"}, {"refs/object"}, {"rays"}, {"count"}, {"tests/ray"}, {"with mailboxes"},
                       {"tests saved"}, {"ms", true}, {"ms with mailboxes", true}, {"time saved", true}},
                      {},
                      "The grid with and without mailboxes on the same rays (" + std::to_string(settings.width) + "x" +
                          std::to_string(settings.height) +
                          " primary rays, their shadow feelers and mirror rays), release build, 1 thread, medians of " +
                          std::to_string(o.sweep.repeat) + " interleaved runs; the answers of every ray identical."};
    const std::vector<NffScene> scenes = {ch08::figure_scene(),
                                          generated_scene(write_mountain, 7, "mountain, depth 7"),
                                          generated_scene(write_sphereflake, 4, "sphereflake, depth 4")};
    for (const NffScene& nff : scenes) {
        const SceneRender file = scene_render(nff, settings);
        LitScene scene = lit_scene(file.scene);
        const Objects objects = objects_of(scene, lit_tests);
        const UniformGrid finder(objects, ch07::default_lambda);
        scene.accelerator = &finder;
        const std::vector<RaySet> sets = ray_sets(file, scene);
        for (const float lambda : {1.0f, 4.0f, 16.0f, 64.0f}) {
            const UniformGrid grid(objects, lambda);
            const MailboxGrid mailboxed(objects, lambda);
            const double refs = static_cast<double>(grid.stats().references) / objects.size();
            for (const RaySet& set : sets) {
                const auto [a, b] = compare(grid, mailboxed, set, objects, o.sweep.repeat);
                if (!same_answers(a, b))
                    throw std::runtime_error("the grid with mailboxes answered differently on " + nff.name + ": a bug of the kit");
                const double n = static_cast<double>(std::max<size_t>(1, set.rays.size()));
                const double saved = a.tests ? 100.0 * (1.0 - static_cast<double>(b.tests) / a.tests) : 0.0;
                const double faster = 100.0 * (1.0 - b.ms.median / a.ms.median);
                table.row({nff.name, fixed(lambda, 0), fixed(refs, 2), set.kind, std::to_string(set.rays.size()),
                           fixed(a.tests / n, 1), fixed(b.tests / n, 1), fixed(saved, 0) + "%",
                           fixed(a.ms.median, 1) + spread(a.ms), fixed(b.ms.median, 1) + spread(b.ms),
                           fixed(faster, 0) + "%"});
                csv << '"' << nff.name << "\"," << objects.size() << ',' << lambda << ',' << refs << ',' << set.kind << ','
                    << set.rays.size() << ',' << a.tests / n << ',' << b.tests / n << ',' << saved << ','
                    << a.ms.median << ',' << b.ms.median << ',' << faster << ',' << a.ms.min << ',' << a.ms.max << ','
                    << b.ms.min << ',' << b.ms.max << ',' << a.ms.runs << '\n';
            }
        }
    }
    write_lesson_tables(tables_beside(o.sweep.csv), {table}, std::cout);
    std::cout << "\nwrote " << o.sweep.csv << " and " << tables_beside(o.sweep.csv) << '\n';
}

}  // namespace

int main(int argc, char** argv)
{
    return run_program("08_mailboxing", [&] {
        Options o;
        std::string& mailbox = o.structure.tuning.mailbox;
        const auto mailbox_option = [&](CommandLine& cli) {
            cli.option("--mailbox", mailbox,
                       "where grid-mailbox remembers what a ray tested: object (a mailbox per object and thread, "
                       "the default) or cache (your ray cache, 1 KB a thread, 08.4)");
        };
        const auto check_mailbox = [&](const CommandLine& cli) {
            check_choice(cli, "--mailbox", mailbox, {"object", "cache"});
        };
        return scene_program_main(
            argc, argv, o, scene_program(o),
            {"Mailboxing: an object met again in a later cell is answered from its mailbox.",
             "measure the tests and time the mailboxes save, by density and ray kind"},
            1e5f, mailbox_option, check_mailbox, [&](const CommandLine& cli) { sweep(o, cli); });
    });
}
