// Chapter 06's program: renders the figure (a row of spheres, the middle one in focus) through a
// thin lens of any aperture and focus distance and, with --sweep, measures what lens samples per
// pixel cost and buy.
#include "06_depth_of_field/figure.hpp"
#include "06_depth_of_field/nff_scene.hpp"
#include "common/cli.hpp"
#include "common/output.hpp"
#include "common/png.hpp"
#include "common/scene_file.hpp"
#include "common/lesson_table.hpp"
#include "common/trade.hpp"

#include <algorithm>
#include <iostream>
#include <limits>
#include <vector>

using namespace rt;

namespace {

struct Options {
    CommonOptions common;
    float aperture = ch06::figure_aperture_radius;
    float focus = ch06::figure_lens().focus_distance;
    SweepOptions sweep{false, 3, "06_depth_of_field.csv"};
    int reference_spp = 1024;
    std::string scene;
};

ThinLens lens_of(const Options& o)
{
    const ThinLens lens{o.aperture, o.focus};
    check_thin_lens(lens, "--aperture", "--focus");
    return lens;
}

Image render_with(const Options& o, int spp, std::uint64_t seed)
{
    RenderSettings settings = render_settings(o.common);
    settings.spp = spp;
    settings.seed = seed;
    return ch06::render_figure(settings, lens_of(o));
}

// Lens samples per pixel against time and error: RMSE in linear RGB against a many-sample render.
// Each sample of a pixel is one camera ray from its own lens point (and its own point of the
// pixel), so lens samples per pixel are the render's samples per pixel. The reference has a seed of
// its own: with the same seed an N-sample render would be the first N samples of the reference's
// own pixels, and its error would look smaller than it is, the more so the larger N. The repeats are
// interleaved (every row once, then every row again), so that a machine whose load changes
// during the sweep slows every row alike, and each row reports its median.
void sweep(const Options& o)
{
    std::cerr << "rendering the reference at " << o.reference_spp << " spp...\n";
    const Image reference = render_with(o, o.reference_spp, o.common.seed + 1);
    const std::vector<int> counts = {1, 4, 16, 64, 256};
    std::vector<std::uint64_t> rays(counts.size());
    std::vector<Image> images(counts.size());
    std::vector<std::vector<double>> seconds(counts.size());
    for (size_t k = 0; k < counts.size(); ++k) {
        reset_counters();
        images[k] = render_with(o, counts[k], o.common.seed);
        rays[k] = total_rays(total_counts());
    }
    for (int run = 0; run < o.sweep.repeat; ++run)
        for (size_t k = 0; k < counts.size(); ++k) {
            const Timer timer;
            render_with(o, counts[k], o.common.seed);
            seconds[k].push_back(timer.seconds());
        }
    TradeTable table{"06_depth_of_field", "rmse_linear_rgb_vs_" + std::to_string(o.reference_spp) + "spp", {}};
    for (size_t k = 0; k < counts.size(); ++k)
        table.rows.push_back({"lens_samples", std::to_string(counts[k]), timing_of(seconds[k]), rays[k],
                              rmse(images[k], reference)});
    print_trade_table(std::cout, table);
    write_trade_csv(o.sweep.csv, table);
    write_lesson_tables(
        tables_beside(o.sweep.csv),
        {trade_lesson_table(
            "06.lens_samples", table, "lens samples per pixel", "RMSE vs " + std::to_string(o.reference_spp) + " spp",
            true,
            "Release build, one thread per core, median of " + std::to_string(o.sweep.repeat) +
                " interleaved runs; rays counts the camera rays and the shadow feelers of one render.")},
        std::cout);
    std::cout << "wrote " << o.sweep.csv << " and " << tables_beside(o.sweep.csv) << '\n';
}

// How far each sphere lies and how widely the lens blurs it: what the figure should show.
void print_circles_of_confusion(std::ostream& out, const Options& o)
{
    const Camera cam = make_camera(ch06::figure_camera(o.common.width, o.common.height));
    const ThinLens lens = lens_of(o);
    for (size_t k = 0; k < ch06::sphere_centres.size(); ++k) {
        const float depth = ch06::depth_of(cam, ch06::sphere_centres[k]);
        out << "sphere" << k + 1 << "_depth=" << depth << "\nsphere" << k + 1
            << "_circle_of_confusion_pixels=" << circle_of_confusion_pixels(cam, lens, depth) << '\n';
    }
}

}  // namespace

int main(int argc, char** argv)
{
    return run_program("06_depth_of_field", [&] {
        Options o;
        CommandLine cli = program_command_line(
            "06_depth_of_field", "Depth of field: a thin lens, one plane in sharp focus, the rest blurred.", o.common);
        const float most = std::numeric_limits<float>::max();
        cli.option("--aperture", o.aperture, "the lens's radius in scene units (0: a pinhole, all sharp)", -most, most);
        cli.option("--focus", o.focus, "the distance of the plane of sharp focus in front of the eye", -most, most);
        add_sweep_options(cli, o.sweep, "measure lens samples per pixel (1, 4, 16, 64, 256) against time and error");
        cli.option("--reference-spp", o.reference_spp, "samples per pixel of the sweep's reference", 1, 65536);
        add_scene_option(cli, o.scene);
        if (!cli.parse(argc, argv, std::cout))
            return 0;
        lens_of(o);  // a bad lens is bad input, before any work
        check_scene_without_sweep(o.scene, o.sweep.on);
        if (!o.scene.empty()) {
            // Focused on the view's `at` with the figure's ratio of aperture to focus, unless the
            // command line says otherwise.
            const SceneRender file = load_scene_render(o.scene, o.common, cli);
            note_unmodelled_materials(file.scene, "06_depth_of_field");
            const FocusScene scene = focus_scene(file.scene);
            ThinLens lens = nff_lens(file.scene);
            if (cli.given("--focus"))
                lens.focus_distance = o.focus;
            if (cli.given("--aperture"))
                lens.aperture_radius = o.aperture;
            return write_figure(o.common, [&] {
                return render(file.settings, [&](float x, float y, Rng& rng) {
                    return ch06::radiance(
                        scene, file.eye_ray(thin_lens_ray(file.camera, lens, x, y, rng)));
                });
            });
        }
        if (o.sweep.on) {
            check_writable(o.sweep.csv, "CSV");
            sweep(o);
            return 0;
        }
        const int status = write_figure(o.common, [&] { return render_with(o, o.common.spp, o.common.seed); });
        if (o.common.stats)
            print_circles_of_confusion(std::cout, o);
        return status;
    });
}
