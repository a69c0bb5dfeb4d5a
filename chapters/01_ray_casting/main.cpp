// Chapter 01's program: renders the figure (discs over a checkered floor) and, with --sweep,
// measures what samples per pixel cost and buy.
#include "01_ray_casting/figure.hpp"
#include "common/cli.hpp"
#include "common/output.hpp"
#include "common/png.hpp"
#include "common/lesson_table.hpp"
#include "common/trade.hpp"

#include <iostream>

using namespace rt;

namespace {

struct Options {
    CommonOptions common;
    float fov = ch01::figure_vfov_degrees;
    SweepOptions sweep{false, 3, "01_ray_casting.csv"};
    int reference_spp = 1024;
};

Image render_with(const Options& o, int spp, std::uint64_t seed)
{
    RenderSettings settings = render_settings(o.common);
    settings.spp = spp;
    settings.seed = seed;
    return ch01::render_figure(settings, o.fov);
}

// Samples per pixel against time and error: RMSE in linear RGB against a many-sample render.
void sweep(const Options& o)
{
    std::cerr << "rendering the reference at " << o.reference_spp << " spp...\n";
    // The reference gets its own seed: with the same one, each sweep image would be the first
    // samples of the reference's own, and the error would look smaller than it is.
    const Image reference = render_with(o, o.reference_spp, o.common.seed + 1);
    TradeTable table{"01_ray_casting", "rmse_linear_rgb_vs_" + std::to_string(o.reference_spp) + "spp", {}};
    for (const int spp : {1, 4, 16, 64}) {
        Image image;
        reset_counters();
        render_with(o, spp, o.common.seed);
        const std::uint64_t rays = total_rays(total_counts());
        const Timing seconds = time_runs(o.sweep.repeat, [&] { image = render_with(o, spp, o.common.seed); });
        table.rows.push_back({"spp", std::to_string(spp), seconds, rays, rmse(image, reference)});
    }
    print_trade_table(std::cout, table);
    write_trade_csv(o.sweep.csv, table);
    write_lesson_tables(
        tables_beside(o.sweep.csv),
        {trade_lesson_table(
            "01.spp", table, "spp", "RMSE vs " + std::to_string(o.reference_spp) + " spp", true,
            "Release build, one thread per core, median of " + std::to_string(o.sweep.repeat) + " runs.")},
        std::cout);
    std::cout << "wrote " << o.sweep.csv << " and " << tables_beside(o.sweep.csv) << '\n';
}

}  // namespace

int main(int argc, char** argv)
{
    return run_program("01_ray_casting", [&] {
        Options o;
        CommandLine cli =
            program_command_line("01_ray_casting", "Ray casting: a ray per pixel, the nearest disc wins.", o.common);
        cli.option("--fov", o.fov, "vertical field of view in degrees", 0.0f, 180.0f);
        add_sweep_options(cli, o.sweep, "measure samples per pixel (1, 4, 16, 64) against time and error");
        cli.option("--reference-spp", o.reference_spp, "samples per pixel of the sweep's reference", 1, 65536);
        if (!cli.parse(argc, argv, std::cout))
            return 0;
        if (o.sweep.on) {
            check_writable(o.sweep.csv, "CSV");
            sweep(o);
            return 0;
        }
        return write_figure(o.common, [&] { return render_with(o, o.common.spp, o.common.seed); });
    });
}
