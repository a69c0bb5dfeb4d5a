// Chapter 07's program: renders the figure (the fractal mountain through the uniform grid, beside
// its heat map) or any NFF scene (--scene) with chapter 04's shading and shadow feelers, or by the
// classic NFF rules (--classic), through brute force or the grid (--accel); --heatmap writes what
// each pixel cost. --sweep measures the trade: the grid's density lambda against build time,
// bytes, tests, cells and render time, and brute force against the grid as the scene grows.
#include "07_uniform_grid/figure.hpp"
#include "common/cli.hpp"
#include "common/lesson_table.hpp"
#include "common/output.hpp"
#include "common/png.hpp"
#include "common/random.hpp"
#include "common/scene_file.hpp"
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
    StructureChoice structure{ch07::structures(), "grid", at_density(ch07::default_lambda)};
    SweepOptions sweep{false, 5, "07_uniform_grid.csv"};
};

SceneProgram scene_program(const Options& o)
{
    return {"07_uniform_grid",
            ch07::figure_scene,
            {{"tests", Counter::intersection_tests, "intersection tests per pixel"},
             {"cells", Counter::cells_visited, "cells visited per pixel"}},
            &o.structure,
            {{"cells_visited", Counter::cells_visited}},
            {}};
}

// --- The trade ---

// A measurement (measure.hpp) with the grid's own statistics and the runs it took.
struct Measured : Measurement {
    GridStats grid;
    int runs = 0;
};

// One structure on one scene (measure.hpp): its build (median of `runs`), one counted render, and
// the render's median time over `runs` more.
Measured measure(const NffScene& nff, const std::string& accel, float lambda, const RenderSettings& settings, int runs)
{
    Measured m;
    const StructureMaker make =
        accel == "grid" ? keeping_stats<UniformGrid>(m.grid, lambda)
                        : [&](const Objects& objects) {
                              return structure_named(ch07::structures(), accel).make(objects, at_density(lambda));
                          };
    static_cast<Measurement&>(m) = measure_structure(nff, make, settings, accel == "brute" ? 1 : runs, runs);
    m.runs = runs;
    return m;
}

std::ofstream open_csv(const std::string& path, const std::string& header)
{
    std::ofstream out(path);
    if (!out)
        throw InputError("cannot write the CSV file '" + path + "'");
    out << header << '\n';
    return out;
}

std::string ms(const Timing& t)
{
    return fixed(t.median, 1) + spread(t);
}

std::string settings_text(const RenderSettings& settings)
{
    return std::to_string(settings.width) + "x" + std::to_string(settings.height) + ", " +
           (settings.threads == 1 ? std::string("1 thread") : std::to_string(settings.threads) + " threads (0: all)");
}

// The density lambda against the grid's cost, on the figure's scene.
LessonTable sweep_lambda(const Options& o, const RenderSettings& settings)
{
    const NffScene nff = ch07::figure_scene();
    std::ofstream csv = open_csv(o.sweep.csv,
                                 "scene,objects,lambda,resolution,cells,empty_cells_percent,references_per_object,"
                                 "bytes,build_ms,tests_per_ray,cells_per_ray,render_ms,build_ms_min,build_ms_max,"
                                 "render_ms_min,render_ms_max,runs");
    LessonTable table{"07.lambda",
                      {{"lambda"}, {"resolution"}, {"empty cells"}, {"refs/object"}, {"MB"}, {"build ms", true},
                       {"tests/ray"}, {"cells/ray"}, {"render ms", true}},
                      {},
                      "The " + nff.name + ", " + settings_text(settings) + ", release build, medians of " +
                          std::to_string(o.sweep.repeat) + " runs."};
    for (const float lambda : {0.125f, 0.25f, 0.5f, 1.0f, 2.0f, 4.0f, 8.0f, 16.0f, 32.0f}) {
        const Measured m = measure(nff, "grid", lambda, settings, o.sweep.repeat);
        std::ostringstream res;
        res << m.grid.resolution.x << 'x' << m.grid.resolution.y << 'x' << m.grid.resolution.z;
        const double empty = 100.0 * static_cast<double>(m.grid.empty_cells) / static_cast<double>(m.grid.cells);
        const double refs = static_cast<double>(m.grid.references) / m.objects;
        const double tests = m.per_ray(Counter::intersection_tests), cells = m.per_ray(Counter::cells_visited);
        table.row({fixed(lambda, 3), res.str(), fixed(empty, 0) + "%", fixed(refs, 2),
                   fixed(static_cast<double>(m.bytes) / 1e6, 2), ms(m.build_ms), fixed(tests, 1), fixed(cells, 1),
                   ms(m.render_ms)});
        csv << '"' << nff.name << "\"," << m.objects << ',' << lambda << ',' << res.str() << ',' << m.grid.cells << ','
            << empty << ',' << refs << ',' << m.bytes << ',' << m.build_ms.median << ',' << tests << ',' << cells << ','
            << m.render_ms.median << ',' << m.build_ms.min << ',' << m.build_ms.max << ',' << m.render_ms.min << ','
            << m.render_ms.max << ',' << m.runs << '\n';
    }
    return table;
}

// Brute force against the grid on one scene, same rays: one table row each, and the images must
// be the same byte for byte (and the ray counts equal), or the kit has a bug.
void compare_on(const NffScene& nff, const Options& o, const RenderSettings& settings, std::ofstream& csv,
                LessonTable& table)
{
    // Brute force on the largest scenes takes minutes a render: one run there, said in the caption.
    const int brute_runs = nff.triangles.size() + nff.spheres.size() + nff.cones.size() > 20000 ? 1 : o.sweep.repeat;
    const float lambda = o.structure.tuning.lambda;
    const Measured brute = measure(nff, "brute", lambda, settings, brute_runs);
    const Measured grid = measure(nff, "grid", lambda, settings, o.sweep.repeat);
    if (brute.pixels != grid.pixels || brute.rays != grid.rays)
        throw std::runtime_error("the grid's image or ray count differs from brute force's on " + nff.name +
                                 ": a bug of the kit");
    for (const auto& [name, m] : {std::pair<const char*, const Measured&>{"brute", brute}, {"grid", grid}}) {
        const double speedup = brute.render_ms.median / m.render_ms.median;
        const double tests = m.per_ray(Counter::intersection_tests), cells = m.per_ray(Counter::cells_visited);
        table.row({nff.name, std::to_string(m.objects), name, fixed(tests, 1), fixed(cells, 1), ms(m.render_ms),
                   ms(m.build_ms), fixed(static_cast<double>(m.bytes) / 1e6, 2), fixed(speedup, 0) + "x"});
        csv << '"' << nff.name << "\"," << m.objects << ',' << name << ',' << tests << ',' << cells
            << ',' << m.render_ms.median << ',' << m.build_ms.median << ',' << m.bytes << ',' << m.runs << ','
            << speedup << ',' << m.render_ms.min << ',' << m.render_ms.max << ',' << m.build_ms.min << ','
            << m.build_ms.max << '\n';
    }
}

// The next-boundary t three ways, against the exact one: boundary_t (t_first + k t_delta in double,
// rounded once), the same formula in float, and t_max += t_delta in float, once per step. Cells of size 1 from a random origin
// in the first cell along random directions; the error is in cells, |t - t_exact| |d_x| / s.
LessonTable measure_drift(int rays)
{
    Rng rng(2026, 7);
    std::vector<double> direct[2], in_float[2], summed[2];
    const int checks[2] = {10000, 100000};
    for (int r = 0; r < rays; ++r) {
        const float o = rng.next_float();
        const float dx = 0.05f + 0.95f * rng.next_float();  // the x component of a unit direction
        GridWalk w;
        w.t_first[0] = (1.0 - o) / dx;
        w.t_delta[0] = 1.0 / dx;
        float t_max = static_cast<float>(w.t_first[0]);
        for (int k = 1, c = 0; k <= checks[1]; ++k) {
            t_max += static_cast<float>(w.t_delta[0]);
            if (k == checks[c]) {
                const long double exact = (1.0L + k - o) / dx;
                direct[c].push_back(static_cast<double>(std::abs(boundary_t(w, 0, k) - exact) * dx));
                const float formula =
                    static_cast<float>(w.t_first[0]) + static_cast<float>(k) * static_cast<float>(w.t_delta[0]);
                in_float[c].push_back(static_cast<double>(std::abs(formula - exact) * dx));
                summed[c].push_back(static_cast<double>(std::abs(t_max - exact) * dx));
                ++c;
            }
        }
    }
    LessonTable table{"07.drift",
                      {{"steps k"}, {"t_first + k t_delta (double, rounded once)"}, {"t_first + k t_delta (float)"},
                       {"t_max += t_delta (float)"}},
                      {},
                      "The next boundary's t after k steps, error in cells, median / max over " + std::to_string(rays) +
                          " seeded rays."};
    const auto worst = [](const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); };
    const auto cells = [](double v) { return v < 0.01 ? scientific(v, 2) : v >= 100.0 ? fixed(v, 0) : significant(v, 2); };
    for (int c = 0; c < 2; ++c)
        table.row({"10^" + std::to_string(c + 4), cells(median(direct[c])) + " / " + cells(worst(direct[c])),
                   cells(median(in_float[c])) + " / " + cells(worst(in_float[c])),
                   cells(median(summed[c])) + " / " + cells(worst(summed[c]))});
    return table;
}

const char* comparison_header = "scene,objects,structure,tests_per_ray,cells_per_ray,render_ms,build_ms,bytes,runs,speedup,"
                                "render_ms_min,render_ms_max,build_ms_min,build_ms_max";

LessonTable comparison_table(const std::string& name, const std::string& what, const RenderSettings& settings, int repeat)
{
    return {name,
            {{"scene"}, {"objects"}, {"structure"}, {"tests/ray"}, {"cells/ray"}, {"render ms", true},
             {"build ms", true}, {"MB"}, {"speedup", true}},
            {},
            what + ", " + settings_text(settings) + ", release build, images identical to brute force; medians of " +
                std::to_string(repeat) + " runs (brute force on scenes over 20,000 objects: 1 run)."};
}

void sweep(const Options& o, const CommandLine& cli)
{
    const RenderSettings settings = sweep_settings(o.common, cli, 64, 36);
    std::cerr << "measuring brute force against the grid as the scene grows, then lambda (minutes)...\n";
    std::ofstream n_csv = open_csv(csv_beside(o.sweep.csv, "_n"), comparison_header);
    std::ostringstream what;
    what << "Brute force against the grid as the mountain grows (lambda " << o.structure.tuning.lambda << ")";
    LessonTable growth = comparison_table("07.growth", what.str(), settings, o.sweep.repeat);
    for (int depth = 1; depth <= 8; ++depth)
        compare_on(generated_scene(write_mountain, depth, "mountain " + std::to_string(depth)), o, settings, n_csv,
                   growth);
    std::ofstream scenes_csv = open_csv(csv_beside(o.sweep.csv, "_scenes"), comparison_header);
    LessonTable scenes =
        comparison_table("07.scenes", "The kit's generated scenes near 10k objects", settings, o.sweep.repeat);
    compare_on(generated_scene(write_mountain, 6, "mountain 6"), o, settings, scenes_csv, scenes);
    compare_on(generated_scene(write_sphereflake, 4, "sphereflake 4"), o, settings, scenes_csv, scenes);
    compare_on(generated_scene(write_pyramid, 5, "pyramid 5"), o, settings, scenes_csv, scenes);
    compare_on(generated_scene(write_tree, 7, "tree 7"), o, settings, scenes_csv, scenes);
    const LessonTable lambda = sweep_lambda(o, sweep_settings(o.common, cli, 320, 180));
    write_lesson_tables(tables_beside(o.sweep.csv), {growth, scenes, lambda, measure_drift(1000)}, std::cout);
    std::cout << "\nwrote " << o.sweep.csv << ", " << csv_beside(o.sweep.csv, "_n") << ", "
              << csv_beside(o.sweep.csv, "_scenes") << " and " << tables_beside(o.sweep.csv) << '\n';
}

}  // namespace

int main(int argc, char** argv)
{
    return run_program("07_uniform_grid", [&] {
        Options o;
        std::string& resolution = o.structure.tuning.resolution;
        const auto resolution_option = [&](CommandLine& cli) {
            cli.option("--resolution", resolution,
                       "how the grid chooses its cells along each axis: rule (07.1's cube-root rule at --lambda, "
                       "the default) or open (your choose_grid_resolution, 07.7)");
        };
        const auto check_resolution = [&](const CommandLine& cli) {
            check_choice(cli, "--resolution", resolution, {"rule", "open"});
        };
        return scene_program_main(
            argc, argv, o, scene_program(o),
            {"The uniform grid: a scene's rays walk its cells, testing only the objects there.",
             "measure brute force against the grid as scenes grow, and lambda's trade",
             "where --sweep writes its tables (*_n.csv and *_scenes.csv beside it)"},
            1e5f, resolution_option, check_resolution, [&](const CommandLine& cli) { sweep(o, cli); });
    });
}
