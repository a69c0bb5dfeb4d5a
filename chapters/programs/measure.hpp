// How the sweeps of chapters 07-10 measure a structure on a scene: its build (the median of
// several, after one untimed), one counted render (its picture, to hold against brute force's,
// and its work per ray), and the median time of several more renders. One thread unless asked, since a single thread's
// times vary least from run to run.
#pragma once

#include "common/progress.hpp"
#include "common/trade.hpp"
#include "programs/scene_program.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace rt {

struct Measurement {
    std::unique_ptr<Accelerator> structure;  // what the renders went through (nullptr: brute force)
    int objects = 0;
    Timing build_ms, render_ms;
    std::size_t bytes = 0;
    std::uint64_t rays = 0;
    Counts counts{};                   // of the counted render
    std::vector<std::uint8_t> pixels;  // its 8-bit sRGB picture

    double per_ray(Counter c) const { return rays ? static_cast<double>(counted(counts, c)) / static_cast<double>(rays) : 0.0; }
};

using StructureMaker = std::function<std::unique_ptr<Accelerator>(const Objects&)>;

// A maker of structure S (built as S(objects, args...)) that keeps S's own statistics (its
// stats()) in `stats` at each build: a sweep that knows what it builds reads them there.
template <class S, class Stats, class... Args>
StructureMaker keeping_stats(Stats& stats, Args... args)
{
    return [&stats, args...](const Objects& objects) -> std::unique_ptr<Accelerator> {
        auto structure = std::make_unique<S>(objects, args...);
        stats = structure->stats();
        return structure;
    };
}

// The sweep's progress: each structure measured is a step (a sweep of chapter 07 measures for
// more than a minute, which would otherwise pass without a word).
inline StepProgress& sweep_progress()
{
    static StepProgress progress("structures measured");
    return progress;
}

// `builds` builds (1 is enough for brute force, which builds nothing) and `renders` timed renders.
inline Measurement measure_structure(const NffScene& nff, const StructureMaker& make, const RenderSettings& settings,
                                     int builds, int renders)
{
    const SceneRender file = scene_render(nff, settings);
    LitScene scene = lit_scene(file.scene);
    const Objects objects = objects_of(scene, lit_tests);
    Measurement m;
    m.objects = objects.size();
    // One untimed build first when several are timed: the first of a process pays for the memory
    // it is the first to touch (page faults), which no later build does.
    if (builds > 1)
        m.structure = make(objects);
    m.build_ms = scaled(time_runs(builds, [&] { m.structure = make(objects); }), 1e3);
    if (!m.structure)
        m.build_ms = Timing{};
    m.bytes = m.structure ? m.structure->bytes() : 0;
    scene.accelerator = m.structure.get();
    reset_counters();
    m.pixels = to_srgb8(render_lit(file, scene, FeelerSettings{}));
    m.counts = total_counts();
    m.rays = total_rays(m.counts);
    m.render_ms = scaled(time_runs(renders, [&] { render_lit(file, scene, FeelerSettings{}); }), 1e3);
    sweep_progress().step();
    return m;
}

// The sweeps' render: the options' settings, with no progress line, one thread unless --threads
// was given, and the sweep's own size unless --width or --height was.
inline RenderSettings sweep_settings(const CommonOptions& common, const CommandLine& cli, int width, int height)
{
    RenderSettings s = render_settings(common);
    s.show_progress = false;
    if (!cli.given("--threads"))
        s.threads = 1;
    if (!cli.given("--width"))
        s.width = width;
    if (!cli.given("--height"))
        s.height = height;
    return s;
}

}  // namespace rt
