// Chapter 09's program: renders the figure (the teapot in a stadium through the hashed grid,
// beside its heat map) or any NFF scene (--scene, --classic) through brute force, the dense grid
// or the hashed one (--accel). --sweep measures the trade: the table size M against collisions,
// bytes and time; the hashed grid against the dense one at equal resolution and past the dense
// grid's limit.
#include "09_hashed_voxels/figure.hpp"
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
    StructureChoice structure{ch09::structures(), "hashed"};
    int table_size = 0;  // the tuning's table_size, read as an int
    SweepOptions sweep{false, 5, "09_hashed_voxels.csv"};
};

StructureTuning tuning(float lambda, std::uint32_t table_size)
{
    StructureTuning t;
    t.lambda = lambda;
    t.table_size = table_size;
    return t;
}

SceneProgram scene_program(const Options& o)
{
    return {"09_hashed_voxels",
            ch09::figure_scene,
            {{"tests", Counter::intersection_tests, "intersection tests per pixel"},
             {"cells", Counter::cells_visited, "cells visited per pixel"},
             {"lookups", Counter::table_lookups, "table lookups per pixel"}},
            &o.structure,
            {{"cells_visited", Counter::cells_visited},
             {"table_probes", Counter::table_probes},
             {"table_lookups", Counter::table_lookups},
             {"table_lookups_skipped", Counter::table_lookups_skipped}},
            {}};
}

// --- The trade ---

struct Measured {
    std::string structure;
    Timing build_ms, render_ms;
    std::size_t bytes = 0;
    cell3 resolution{1};
    long long occupied = 0, references = 0, collisions = 0;
    std::uint32_t M = 0;
    double tests_per_ray = 0.0, cells_per_ray = 0.0, lookups_per_ray = 0.0, skipped_per_ray = 0.0;
    std::vector<std::uint8_t> pixels;
};

Measured measure(const NffScene& nff, const std::string& accel, float lambda, std::uint32_t table_size,
                 const RenderSettings& settings, int repeat)
{
    HashedGridStats hashed;
    GridStats grid;
    const StructureMaker make =
        accel == "hashed" ? keeping_stats<HashedGrid>(hashed, lambda, table_size)
        : accel == "grid"
            ? keeping_stats<UniformGrid>(grid, lambda)
            : [&](const Objects& objects) {
                  return structure_named(ch09::structures(), accel).make(objects, tuning(lambda, table_size));
              };
    const Measurement r = measure_structure(nff, make, settings, accel == "brute" ? 1 : repeat, repeat);
    Measured m;
    m.structure = accel;
    m.build_ms = r.build_ms;
    m.render_ms = r.render_ms;
    m.bytes = r.bytes;
    m.pixels = r.pixels;
    m.tests_per_ray = r.per_ray(Counter::intersection_tests);
    m.cells_per_ray = r.per_ray(Counter::cells_visited);
    m.lookups_per_ray = r.per_ray(Counter::table_lookups);
    m.skipped_per_ray = r.per_ray(Counter::table_lookups_skipped);
    if (accel == "hashed") {
        m.resolution = hashed.resolution;
        m.occupied = hashed.occupied;
        m.references = hashed.references;
        m.collisions = hashed.collisions;
        m.M = hashed.M;
    } else if (accel == "grid") {
        m.resolution = grid.resolution;
        m.references = grid.references;
    }
    return m;
}

std::string resolution(const cell3& n)
{
    std::ostringstream s;
    s << n.x << 'x' << n.y << 'x' << n.z;
    return s.str();
}

std::string ms(const Timing& t)
{
    return fixed(t.median, 1) + spread(t);
}

void sweep(const Options& o, const CommandLine& cli)
{
    const RenderSettings settings = sweep_settings(o.common, cli, 160, 90);
    std::cerr << "measuring the hashed grid against the dense one, then the table size (a few minutes)...\n";
    const NffScene stadium = ch09::figure_scene();
    const Measured brute = measure(stadium, "brute", 1.0f, 0, settings, 1);
    std::ofstream csv(o.sweep.csv);
    csv << "scene,structure,lambda,resolution,occupied_cells,references,table_size,collisions,bytes,build_ms,"
           "tests_per_ray,cells_per_ray,lookups_per_ray,skipped_per_ray,render_ms,build_ms_min,build_ms_max,"
           "render_ms_min,render_ms_max,runs\n";
    const std::string how = std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                            ", release build, 1 thread, medians of " + std::to_string(o.sweep.repeat) + " runs";
    LessonTable structures{
        "09.structures",
        {{"structure"}, {"lambda"}, {"resolution"}, {"cells"}, {"occupied"}, {"MB"}, {"bytes/reference"},
         {"build ms", true}, {"tests/ray"}, {"cells/ray"}, {"lookups/ray"}, {"skipped by bits/ray"}, {"render ms", true}},
        {},
        "The teapot in a stadium (" + fixed(brute.tests_per_ray, 0) + " tests per ray by brute force), " + how +
            "; every image identical to brute force's."};
    const auto row = [&](const Measured& m, float lambda) {
        if (m.pixels != brute.pixels)
            throw std::runtime_error("the " + m.structure + "'s image differs from brute force's: a bug of the kit");
        const double cells = static_cast<double>(m.resolution.x) * m.resolution.y * m.resolution.z;
        structures.row({m.structure, fixed(lambda, 0), resolution(m.resolution), fixed(cells / 1e6, 1) + " M",
                        m.occupied ? grouped(static_cast<unsigned long long>(m.occupied)) : std::string("-"),
                        fixed(static_cast<double>(m.bytes) / 1e6, 1),
                        fixed(m.references ? static_cast<double>(m.bytes) / m.references : 0.0, 1), ms(m.build_ms),
                        fixed(m.tests_per_ray, 1), fixed(m.cells_per_ray, 1), fixed(m.lookups_per_ray, 1),
                        fixed(m.skipped_per_ray, 1), ms(m.render_ms)});
        csv << "\"" << stadium.name << "\"," << m.structure << ',' << lambda << ',' << resolution(m.resolution) << ','
            << m.occupied << ',' << m.references << ',' << m.M << ',' << m.collisions << ',' << m.bytes << ','
            << m.build_ms.median << ',' << m.tests_per_ray << ',' << m.cells_per_ray << ',' << m.lookups_per_ray << ','
            << m.skipped_per_ray << ',' << m.render_ms.median << ',' << m.build_ms.min << ',' << m.build_ms.max << ','
            << m.render_ms.min << ',' << m.render_ms.max << ',' << o.sweep.repeat << '\n';
    };
    for (const float lambda : {4.0f, 16.0f, 64.0f, 256.0f, 1024.0f, 4096.0f}) {
        try {
            row(measure(stadium, "grid", lambda, 0, settings, o.sweep.repeat), lambda);
        } catch (const InputError&) {
            structures.row({"grid", fixed(lambda, 0), "the dense grid cannot hold it (over 2^25 cells)"});
            // A row all the same, so that the plot's rows still alternate dense, hashed.
            csv << "\"" << stadium.name << "\",grid," << lambda << ",refused,,,,,nan,nan,nan,nan,nan,nan,nan,,,,,\n";
        }
        row(measure(stadium, "hashed", lambda, 0, settings, o.sweep.repeat), lambda);
    }

    // The table size M, the default (the least prime at least twice the occupied cells) among sizes
    // around it and a power of two.
    const Measured base = measure(stadium, "hashed", ch09::default_hashed_lambda, 0, settings, 1);
    const std::uint64_t occupied = static_cast<std::uint64_t>(base.occupied);
    LessonTable sizes{"09.table_size",
                      {{"M"}, {"load"}, {"collisions"}, {"MB"}, {"render ms", true}},
                      {},
                      "The hashed grid at lambda " + fixed(ch09::default_hashed_lambda, 0) + " (" +
                          grouped(occupied) + " occupied cells in a grid of " +
                          grouped(static_cast<unsigned long long>(base.resolution.x) * base.resolution.y *
                                  base.resolution.z) +
                          "), " + how + "."};
    for (const std::uint64_t size :
         {occupied / 8, occupied / 2, occupied, std::uint64_t{1} << 20, std::uint64_t{base.M}, 2 * occupied, 8 * occupied}) {
        const auto M = static_cast<std::uint32_t>(std::max<std::uint64_t>(1, size));
        const Measured m = measure(stadium, "hashed", ch09::default_hashed_lambda, M, settings, o.sweep.repeat);
        if (m.pixels != brute.pixels)
            throw std::runtime_error("the hashed grid's image differs from brute force's: a bug of the kit");
        sizes.row({grouped(M) + (M == (1u << 20) ? " (2^20)" : M == base.M ? " (the default, prime)" : ""),
                   fixed(static_cast<double>(m.occupied) / M, 2), grouped(static_cast<unsigned long long>(m.collisions)),
                   fixed(static_cast<double>(m.bytes) / 1e6, 1), ms(m.render_ms)});
    }
    write_lesson_tables(tables_beside(o.sweep.csv), {structures, sizes}, std::cout);
    std::cout << "\nwrote " << o.sweep.csv << " and " << tables_beside(o.sweep.csv) << '\n';
}

}  // namespace

int main(int argc, char** argv)
{
    return run_program("09_hashed_voxels", [&] {
        Options o;
        std::string& table_hash = o.structure.tuning.table_hash;
        const auto table_size = [&](CommandLine& cli) {
            cli.option("--table-size", o.table_size,
                       "the hash table's size M (0: the least prime at least twice the occupied cells)", 0, 1 << 30);
            cli.option("--table-hash", table_hash,
                       "how the hashed grid files its cells: mod (bucket p mod M, the default) or open (your hash "
                       "and table size, 09.6)");
        };
        const auto take_table_size = [&](const CommandLine& cli) {
            check_choice(cli, "--table-hash", table_hash, {"mod", "open"});
            if (table_hash == "open" && cli.given("--table-size"))
                throw InputError("--table-size is the size of p mod M; with --table-hash open your 09.6 chooses it");
            o.structure.tuning.table_size = static_cast<std::uint32_t>(o.table_size);
        };
        return scene_program_main(
            argc, argv, o, scene_program(o),
            {"Hashed voxels: a grid too fine for an array, its occupied cells in a hash table.",
             "measure the hashed grid against the dense one, and the table size"},
            1e6f, table_size, take_table_size, [&](const CommandLine& cli) { sweep(o, cli); });
    });
}
