// Chapter 03's program: renders the figure (Whitted's mirror and glass spheres) and, with --sweep,
// measures what the recursion's depth and weight cut-off cost and buy, and how far Schlick's
// approximation strays from Fresnel's exact reflectance.
#include "03_reflection_refraction/figure.hpp"
#include "03_reflection_refraction/fresnel_table.hpp"
#include "03_reflection_refraction/nff_scene.hpp"
#include "03_reflection_refraction/rounds.hpp"
#include "common/cli.hpp"
#include "common/output.hpp"
#include "common/png.hpp"
#include "common/scene_file.hpp"
#include "common/lesson_table.hpp"
#include "common/trade.hpp"

#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace rt;

namespace {

struct Options {
    CommonOptions common;
    TraceSettings trace;
    std::string fresnel = "exact";
    SweepOptions sweep{false, 5, "03_reflection_refraction.csv"};
    int reference_depth = 32;
    int angles = 1000001;
    std::string scene;
};

FresnelModel model_named(const std::string& name)
{
    if (name == "exact")
        return FresnelModel::exact;
    if (name == "schlick")
        return FresnelModel::schlick;
    throw InputError("--fresnel takes exact or schlick, got '" + name + "'");
}

std::string number(double x)
{
    std::ostringstream s;
    s << x;
    return s.str();
}

// One row to measure: what it varies, and the trace settings it renders the figure with.
struct Trial {
    std::string knob, value;
    TraceSettings trace;
};

// Each trial's rays (one render), RMSE against the reference, and time: the median of `repeat`
// rounds, each rendering every trial once (rounds.hpp).
std::vector<TradeRow> measure(const Options& o, const std::vector<Trial>& trials, const Image& reference)
{
    const RenderSettings settings = render_settings(o.common);
    std::vector<TradeRow> rows;
    std::vector<std::function<void()>> renders;
    for (const Trial& t : trials) {
        reset_counters();
        const Image image = ch03::render_figure(settings, t.trace);
        rows.push_back({t.knob, t.value, {}, total_rays(total_counts()), rmse(image, reference)});
        renders.push_back([&settings, &t] { ch03::render_figure(settings, t.trace); });
    }
    const std::vector<Timing> seconds = time_in_rounds(o.sweep.repeat, renders);
    for (size_t k = 0; k < rows.size(); ++k)
        rows[k].seconds = seconds[k];
    return rows;
}

// The recursion's two limits against time and error: the depth with no weight cut-off, then the
// cut-off at the reference's depth; then the figure's own settings with either reflectance. The
// reference traces every path to `reference_depth` bounces with no cut-off.
void sweep_render(const Options& o, std::vector<LessonTable>& lesson)
{
    TraceSettings deep;
    deep.max_depth = o.reference_depth;
    deep.min_weight = 0.0f;
    std::cerr << "rendering the reference: depth " << o.reference_depth << ", no weight cut-off...\n";
    const Image reference = ch03::render_figure(render_settings(o.common), deep);

    std::vector<Trial> trials;
    for (int d = 1; d <= 16; ++d) {
        TraceSettings t = deep;
        t.max_depth = d;
        trials.push_back({"max_depth", std::to_string(d), t});
    }
    for (const float w : {0.3f, 0.1f, 0.03f, 0.01f, 3e-3f, 1e-3f, 1e-4f}) {
        TraceSettings t = deep;
        t.min_weight = w;
        trials.push_back({"min_weight", number(w), t});
    }
    // The figure's settings (the kit's defaults), with either reflectance, against the reference's.
    trials.push_back({"settings", "reference", deep});
    TraceSettings schlick;
    schlick.fresnel = FresnelModel::schlick;
    trials.push_back({"settings", "default_exact", TraceSettings{}});
    trials.push_back({"settings", "default_schlick", schlick});

    std::cerr << "timing " << trials.size() << " renders, " << o.sweep.repeat << " rounds...\n";
    const std::vector<TradeRow> rows = measure(o, trials, reference);
    const std::string metric = "rmse_linear_rgb_vs_depth_" + std::to_string(o.reference_depth) + "_no_cutoff";
    const std::vector<std::pair<std::string, std::string>> tables = {
        {"max_depth", o.sweep.csv},
        {"min_weight", csv_beside(o.sweep.csv, "_weight")},
        {"settings", csv_beside(o.sweep.csv, "_settings")}};
    for (const auto& [knob, path] : tables) {
        TradeTable table{"03_reflection_refraction", metric, {}};
        for (const TradeRow& row : rows)
            if (row.knob == knob)
                table.rows.push_back(row);
        print_trade_table(std::cout, table);
        std::cout << '\n';
        write_trade_csv(path, table);
        if (knob == "settings")
            for (TradeRow& row : table.rows)
                row.value = row.value == "reference"
                                ? "the reference: depth " + std::to_string(o.reference_depth) + ", no cut-off, exact Fresnel"
                            : row.value == "default_exact" ? "the figure's default: depth 8, min_weight 1e-3, exact Fresnel"
                                                           : "the same with Schlick's reflectance";
        LessonTable t = trade_lesson_table("03." + knob, table, knob == "min_weight" ? "min_weight (at depth 32)" : knob,
                                           "RMSE", false, "");
        t.caption = "Release build, " + std::to_string(o.common.width) + "x" + std::to_string(o.common.height) +
                    ", one sample per pixel, median of " + std::to_string(o.sweep.repeat) +
                    " rounds each rendering every row once; RMSE over linear RGB against depth " +
                    std::to_string(o.reference_depth) + " with no cut-off.";
        lesson.push_back(t);
    }
}

// Schlick against exact, per index of refraction and side, as a trade table (the error is the
// largest absolute difference from the exact reflectance) and as the lesson's summary.
void sweep_fresnel(const Options& o, std::vector<LessonTable>& lesson)
{
    const std::vector<fresnel_table::Row> rows =
        fresnel_table::measure_all({1.333f, 1.5f, 2.4f}, o.angles, o.sweep.repeat);
    TradeTable table{"03_reflection_refraction", "max_abs_error_vs_exact_fresnel", {}};
    for (const fresnel_table::Row& r : rows)
        table.rows.push_back({"ior:side:formula", number(r.ior) + ":" + r.side + ":" + r.formula, r.seconds, r.calls,
                              r.max_error});
    print_trade_table(std::cout, table);
    write_trade_csv(csv_beside(o.sweep.csv, "_schlick"), table);

    // The lesson's view: per index, each Schlick formula's worst error and where; then the cost of a
    // call, from the fastest to the slowest index.
    const auto find = [&](float ior, const std::string& side, const std::string& formula) {
        for (const fresnel_table::Row& r : rows)
            if (r.ior == ior && r.side == side && r.formula == formula)
                return r;
        throw std::logic_error("fresnel_table has no row " + side + " " + formula);
    };
    const auto worst = [](const fresnel_table::Row& r) {
        return fixed(r.max_error, 3) + " at " + fixed(r.at_degrees, 1) + " degrees";
    };
    LessonTable errors{"03.schlick",
                       {{"ior"}, {"entering: Schlick of cos_i"}, {"leaving: Schlick of cos_t"},
                        {"leaving: Schlick of cos_i, the bug"}},
                       {},
                       "The largest absolute difference from exact Fresnel over " + grouped(static_cast<unsigned long long>(o.angles)) +
                           " angles of incidence from 0 to 90 degrees, and the angle where it occurs."};
    for (const auto& [ior, name] : {std::pair<float, std::string>{1.333f, " (water)"}, {1.5f, " (glass)"}, {2.4f, " (diamond)"}})
        errors.row({number(ior) + name, worst(find(ior, "entering", "schlick_cos_i")),
                    worst(find(ior, "leaving", "schlick_cos_t")), "**" + worst(find(ior, "leaving", "schlick_cos_i_bug")) + "**"});
    LessonTable cost{"03.schlick_ns",
                     {{"ns per call (least to most over the three indices)"}, {"exact", true}, {"Schlick", true}},
                     {},
                     "One pass over the angles per row, median of " + std::to_string(o.sweep.repeat) + " rounds."};
    for (const std::string side : {"entering", "leaving"}) {
        std::vector<std::string> cells{side};
        for (const std::string formula : {"exact", side == "entering" ? "schlick_cos_i" : "schlick_cos_t"}) {
            double least = 1e300, most = 0.0;
            for (const fresnel_table::Row& r : rows)
                if (r.side == side && r.formula == formula) {
                    const double ns = 1e9 * r.seconds.median / static_cast<double>(r.calls);
                    least = std::min(least, ns);
                    most = std::max(most, ns);
                }
            const std::string from = fixed(least, 1), to = fixed(most, 1);
            cells.push_back(from == to ? from : from + " to " + to);
        }
        cost.row(cells);
    }
    lesson.push_back(errors);
    lesson.push_back(cost);

    std::cout << "\n| ior | side | formula | max abs error | at (degrees) | ns per call |\n|---|---|---|---|---|---|\n";
    for (const fresnel_table::Row& r : rows)
        std::cout << "| " << number(r.ior) << " | " << r.side << " | " << r.formula << " | " << std::setprecision(3)
                  << r.max_error << " | " << std::fixed << std::setprecision(2) << r.at_degrees << " | "
                  << 1e9 * r.seconds.median / static_cast<double>(r.calls) << " |" << std::defaultfloat
                  << std::setprecision(6) << '\n';
}

}  // namespace

int main(int argc, char** argv)
{
    return run_program("03_reflection_refraction", [&] {
        Options o;
        CommandLine cli = program_command_line(
            "03_reflection_refraction",
            "Reflection and refraction: Whitted's recursion, Snell's law, Fresnel and Schlick.", o.common);
        cli.option("--depth", o.trace.max_depth, "the most bounces a path may take (0: ray casting)", 0, 64);
        cli.option("--min-weight", o.trace.min_weight, "trace a secondary ray only when its weight is at least this",
                   0.0f, 1.0f);
        cli.option("--fresnel", o.fresnel, "the reflectance that splits glass's light: exact or schlick");
        add_sweep_options(cli, o.sweep,
                          "measure depth and weight cut-off against time and error, and Schlick against exact",
                          "where --sweep writes its depth table (the others go beside it)",
                          "timing rounds of the sweep, each running every row once; a row's time is its median");
        cli.option("--reference-depth", o.reference_depth, "depth of the sweep's reference render (no cut-off)", 16,
                   64);
        cli.option("--angles", o.angles, "angles of incidence per row of the Fresnel table", 1001, 100000001);
        add_scene_option(cli, o.scene);
        if (!cli.parse(argc, argv, std::cout))
            return 0;
        o.trace.fresnel = model_named(o.fresnel);
        check_scene_without_sweep(o.scene, o.sweep.on);
        if (!o.scene.empty()) {
            const SceneRender file = load_scene_render(o.scene, o.common, cli);
            const WhittedScene scene = whitted_scene(file.scene);
            return write_figure(o.common, [&] {
                return render(file.settings, [&](float x, float y, Rng&) {
                    return ch03::radiance(scene, file.eye_ray(primary_ray(file.camera, x, y)), o.trace);
                });
            });
        }
        if (o.sweep.on) {
            check_writable(o.sweep.csv, "CSV");
            std::vector<LessonTable> lesson;
            sweep_render(o, lesson);
            sweep_fresnel(o, lesson);
            write_lesson_tables(tables_beside(o.sweep.csv), lesson, std::cout);
            std::cout << "\nwrote " << o.sweep.csv << ", its _weight, _settings and _schlick siblings, and "
                      << tables_beside(o.sweep.csv) << '\n';
            return 0;
        }
        return write_figure(o.common, [&] { return ch03::render_figure(render_settings(o.common), o.trace); });
    });
}
