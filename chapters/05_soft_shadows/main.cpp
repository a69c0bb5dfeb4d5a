// Chapter 05's program: renders the figure (the slides' pair: a hard shadow from a point light
// beside a soft shadow from area lights) with the light sampling of your choice and, with --sweep,
// measures what samples per light cost and buy, random against stratified.
#include "03_reflection_refraction/rounds.hpp"
#include "05_soft_shadows/figure.hpp"
#include "05_soft_shadows/nff_scene.hpp"
#include "common/cli.hpp"
#include "common/heatmap.hpp"
#include "common/output.hpp"
#include "common/png.hpp"
#include "common/scene_file.hpp"
#include "common/lesson_table.hpp"
#include "common/trade.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>

using namespace rt;

namespace {

struct Options {
    CommonOptions common;
    int light_samples = 16;
    std::string sampling = "stratified";
    SweepOptions sweep{false, 5, "05_soft_shadows.csv"};
    int sweep_width = 160;
    int sweep_height = 120;
    int reference_samples = 4096;
    std::string scene;
    float light_size = nff_light_size;
};

SampleScheme scheme_named(const std::string& name)
{
    if (name == "random")
        return SampleScheme::random;
    if (name == "stratified")
        return SampleScheme::stratified;
    throw InputError("--sampling takes random or stratified, got '" + name + "'");
}

LightSampling sampling_of(const Options& o)
{
    const LightSampling sampling{o.light_samples, scheme_named(o.sampling)};
    if (sampling.scheme == SampleScheme::stratified && grid_side(sampling.samples) == 0)
        throw InputError("--light-samples must be a square (1, 4, 9, 16, ...) for stratified sampling, got " +
                         std::to_string(o.light_samples) + " (or use --sampling random)");
    return sampling;
}

// Samples per light against time and error, random against stratified, on the soft panel alone
// at one sample per pixel (the pixel's centre), so that all the noise is the light sampling's.
// The reference is the same panel with reference_samples stratified samples per light, from
// another seed, so that its noise is unrelated to any row's. Times are taken in rounds (chapter
// 03's time_in_rounds), so that a load that comes and goes falls on all rows alike.
void sweep(const Options& o)
{
    RenderSettings settings = render_settings(o.common);
    settings.width = o.sweep_width;
    settings.height = o.sweep_height;
    settings.spp = 1;
    settings.show_progress = false;
    const AreaLitScene scene = ch05::soft_scene();

    std::cerr << "rendering the reference, " << o.reference_samples << " stratified samples per light...\n";
    RenderSettings reference_settings = settings;
    reference_settings.seed = settings.seed + 1000003;
    reference_settings.show_progress = true;
    const Image reference =
        ch05::render_panel(reference_settings, scene, {o.reference_samples, SampleScheme::stratified});

    struct Trial {
        LightSampling sampling;
        std::string name;
    };
    std::vector<Trial> trials;
    for (const auto& [scheme, name] : {std::pair<SampleScheme, std::string>{SampleScheme::random, "random"},
                                       {SampleScheme::stratified, "stratified"}})
        for (const int n : {1, 4, 16, 64, 256})
            trials.push_back({{n, scheme}, name});

    std::vector<Image> images;
    std::vector<std::uint64_t> rays;
    for (const Trial& t : trials) {
        reset_counters();
        images.push_back(ch05::render_panel(settings, scene, t.sampling));
        rays.push_back(total_rays(total_counts()));
    }
    std::cerr << "timing " << trials.size() << " rows, " << o.sweep.repeat << " rounds...\n";
    std::vector<std::function<void()>> renders;
    for (const Trial& t : trials)
        renders.push_back([&settings, &scene, sampling = t.sampling] { ch05::render_panel(settings, scene, sampling); });
    const std::vector<Timing> times = time_in_rounds(o.sweep.repeat, renders);

    TradeTable table{"05_soft_shadows",
                     "rmse_linear_rgb_vs_" + std::to_string(o.reference_samples) + "_stratified_samples_per_light", {}};
    LessonTable lesson{"05.schemes",
                       {{"scheme"}, {"samples per light"}, {"seconds", true}, {"rays"}, {"rays/second", true}, {"RMSE"},
                        {"RMSE × √N"}, {"order since N/4"}},
                       {},
                       "The soft panel at " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                           ", one sample per pixel (its centre), release build, one thread per core, median of " +
                           std::to_string(o.sweep.repeat) + " interleaved runs; RMSE over linear RGB against " +
                           std::to_string(o.reference_samples) + " stratified samples per light."};
    for (size_t k = 0; k < trials.size(); ++k) {
        const Trial& t = trials[k];
        const Timing seconds = times[k];
        const double error = rmse(images[k], reference);
        const double n = static_cast<double>(t.sampling.samples);
        // The measured order p in error ~ N^-p, from this row and the one with a quarter the samples.
        const std::string order =
            t.sampling.samples > 1 ? fixed(std::log(rmse(images[k - 1], reference) / error) / std::log(4.0), 2) : "";
        lesson.row({t.name, std::to_string(t.sampling.samples), significant(seconds.median, 3) + spread(seconds),
                    grouped(rays[k]), fixed(static_cast<double>(rays[k]) / seconds.median / 1e6, 1) + " M",
                    scientific(error, 3), scientific(error * std::sqrt(n), 3), order});
        table.rows.push_back({"scheme:samples_per_light", t.name + ":" + std::to_string(t.sampling.samples), seconds,
                              rays[k], error});
    }
    write_lesson_tables(tables_beside(o.sweep.csv), {lesson}, std::cout);
    // Random rows from most samples to fewest, then stratified from fewest to most: the plot's
    // line (common/trade_plot.gnuplot joins the rows in order) runs down one scheme and up the
    // other, through the 1-sample point they share, instead of jumping back across the plot.
    std::reverse(table.rows.begin(), table.rows.begin() + static_cast<long>(trials.size() / 2));
    std::cout << '\n';
    print_trade_table(std::cout, table);
    write_trade_csv(o.sweep.csv, table);
    std::cout << "wrote " << o.sweep.csv << " and " << tables_beside(o.sweep.csv) << '\n';
}

}  // namespace

int main(int argc, char** argv)
{
    return run_program("05_soft_shadows", [&] {
        Options o;
        CommandLine cli = program_command_line(
            "05_soft_shadows",
            "Soft shadows: area lights sampled with many shadow feelers, beside the hard shadow of a point.", o.common);
        // Two panels of 400 x 320 side by side.
        o.common.width = 800;
        o.common.height = 320;
        cli.option("--light-samples", o.light_samples, "points (shadow feelers) per area light per shading point", 1,
                   65536);
        cli.option("--sampling", o.sampling, "how the points are picked: random or stratified (a square number)");
        add_sweep_options(cli, o.sweep,
                          "measure samples per light (1 to 256), random against stratified, against error");
        cli.option("--sweep-width", o.sweep_width, "the sweep's image width (the soft panel alone)", 1, 16384);
        cli.option("--sweep-height", o.sweep_height, "the sweep's image height", 1, 16384);
        cli.option("--reference-samples", o.reference_samples,
                   "stratified samples per light of the sweep's reference (a square)", 1, 1048576);
        add_scene_option(cli, o.scene);
        cli.option("--light-size", o.light_size,
                   "with --scene: each light's disc radius, as a fraction of its distance to the view's 'at'", 0.0f, 10.0f);
        if (!cli.parse(argc, argv, std::cout))
            return 0;
        const LightSampling sampling = sampling_of(o);
        check_scene_without_sweep(o.scene, o.sweep.on);
        if (o.scene.empty() && cli.given("--light-size"))
            throw InputError("--light-size sizes a scene file's lights: it needs --scene FILE.nff");
        if (!o.scene.empty()) {
            const SceneRender file = load_scene_render(o.scene, o.common, cli);
            note_unmodelled_materials(file.scene, "05_soft_shadows");
            const AreaLitScene scene = area_lit_scene(file.scene, o.light_size);
            return write_figure(o.common, [&] {
                return render(file.settings, [&](float x, float y, Rng& rng) {
                    return radiance(scene, file.eye_ray(primary_ray(file.camera, x, y)), sampling, rng);
                });
            });
        }
        if (o.sweep.on) {
            check_writable(o.sweep.csv, "CSV");
            if (grid_side(o.reference_samples) == 0)
                throw InputError("--reference-samples must be a square (1, 4, 9, 16, ...), got " +
                                 std::to_string(o.reference_samples));
            sweep(o);
            return 0;
        }
        return write_figure(o.common, [&] {
            Image figure = ch05::render_figure(render_settings(o.common), sampling);
            // The slides' two captions, so a slide or a handout needs no legend.
            draw_label(figure, 6, 6, "point lights: hard shadows");
            draw_label(figure, figure.width / 2 + 6, 6, "area lights: soft shadows");
            return figure;
        });
    });
}
