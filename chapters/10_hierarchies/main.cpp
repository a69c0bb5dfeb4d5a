// Chapter 10's program: renders the figure (the teapot in a stadium through the BVH, beside the
// heat maps of the uniform grid, the hierarchy of grids and the BVH) or any NFF scene (--scene,
// --classic) through any structure of chapters 07-10 (--accel). --sweep measures the trade: leaf
// size and depth limit against build time, bytes, nodes per ray and render time; SAH against a
// median split; the hierarchy of grids' leaf size and depth; and every structure side by side on
// the kit's generated scenes.
#include "10_hierarchies/figure.hpp"
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
    std::string accel = "bvh";
    float lambda = ch07::default_lambda;
    BvhSettings bvh;
    HGridSettings hgrid;
    int leaf_size = 0, max_depth = -1;  // given: for the BVH or the hierarchy of grids, whichever --accel names
    std::string split = "sah";
    SweepOptions sweep{false, 5, "10_hierarchies.csv"};
};

SceneProgram scene_program(const Options& o)
{
    const auto default_structure = [](const std::string& name) {
        return [name](const Objects& objects) {
            return ch10::make_accelerator(name, objects, ch07::default_lambda, BvhSettings{});
        };
    };
    return {"10_hierarchies",
            ch10::figure_scene,
            {{"nodes", Counter::nodes_visited, "nodes visited per pixel"},
             {"tests", Counter::intersection_tests, "intersection tests per pixel"},
             {"cells", Counter::cells_visited, "cells visited per pixel"}},
            [&o](const Objects& objects) { return ch10::make_accelerator(o.accel, objects, o.lambda, o.bvh, o.hgrid); },
            [&o] { return o.accel; },
            {{"nodes_visited", Counter::nodes_visited}, {"cells_visited", Counter::cells_visited}},
            {{"uniform grid", default_structure("grid")},
             {"hierarchy of grids", default_structure("hgrid")},
             {"BVH", default_structure("bvh")}}};
}

// --- The trade ---

// One structure on one scene (measure.hpp): `repeat` builds and timed renders, medians.
Measurement measure(const NffScene& nff, const StructureMaker& make, const RenderSettings& settings, int repeat)
{
    return measure_structure(nff, make, settings, repeat, repeat);
}

std::string ms(const Timing& t)
{
    return fixed(t.median, 1) + spread(t);
}

void sweep(const Options& o, const CommandLine& cli)
{
    const RenderSettings settings = sweep_settings(o.common, cli, 160, 90);
    std::cerr << "measuring the BVH's leaf size, depth and split, the hierarchy of grids' leaf size and depth, then every "
                 "structure on six scenes...\n";
    std::ofstream csv(o.sweep.csv);
    csv << "scene,objects,structure,setting,build_ms,bytes,tests_per_ray,nodes_per_ray,cells_per_ray,render_ms,"
           "build_ms_min,build_ms_max,render_ms_min,render_ms_max,runs\n";
    const auto csv_times = [&](const Measurement& m) {
        csv << ',' << m.build_ms.min << ',' << m.build_ms.max << ',' << m.render_ms.min << ',' << m.render_ms.max << ','
            << o.sweep.repeat << '\n';
    };
    const NffScene stadium = ch10::figure_scene();
    const auto objects_in = [](const NffScene& s) { return s.spheres.size() + s.triangles.size() + s.cones.size(); };
    const std::string how = std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                            ", release build, 1 thread, medians of " + std::to_string(o.sweep.repeat) + " runs";
    LessonTable bvh_table{"10.bvh",
                          {{"split"}, {"leaf size"}, {"depth limit"}, {"nodes"}, {"depth"}, {"MB"}, {"build ms", true},
                           {"nodes/ray"}, {"tests/ray"}, {"render ms", true}},
                          {},
                          "The BVH on the " + stadium.name + ", " + how + "; every image identical."};
    std::vector<std::uint8_t> reference;
    const auto bvh_row = [&](BvhSplit split, int leaf, int depth) {
        BvhSettings b;
        b.split = split;
        b.leaf_size = leaf;
        b.max_depth = depth;
        BvhStats tree;
        const Measurement m = measure(stadium, keeping_stats<BvhAccel>(tree, b), settings, o.sweep.repeat);
        if (reference.empty())
            reference = m.pixels;
        if (m.pixels != reference)
            throw std::runtime_error("a BVH's image differs from another's: a bug of the kit");
        bvh_table.row({split == BvhSplit::sah ? "SAH" : "median", std::to_string(leaf), std::to_string(depth),
                       grouped(static_cast<unsigned long long>(tree.nodes)), std::to_string(tree.depth),
                       fixed(static_cast<double>(m.bytes) / 1e6, 2), ms(m.build_ms),
                       fixed(m.per_ray(Counter::nodes_visited), 1), fixed(m.per_ray(Counter::intersection_tests), 1),
                       ms(m.render_ms)});
        csv << '"' << stadium.name << "\"," << objects_in(stadium) << ",bvh,"
            << (split == BvhSplit::sah ? "sah" : "median") << ":leaf" << leaf << ":depth" << depth << ','
            << m.build_ms.median << ',' << m.bytes << ',' << m.per_ray(Counter::intersection_tests) << ','
            << m.per_ray(Counter::nodes_visited) << ",0," << m.render_ms.median;
        csv_times(m);
    };
    for (const int leaf : {1, 2, 4, 8, 16, 32})
        bvh_row(BvhSplit::sah, leaf, 48);
    for (const int depth : {4, 8, 12, 16})
        bvh_row(BvhSplit::sah, 4, depth);
    for (const int leaf : {4})
        bvh_row(BvhSplit::median, leaf, 48);

    LessonTable hgrid_table{"10.hgrid",
                            {{"leaf size"}, {"depth limit"}, {"grids"}, {"cells"}, {"MB"}, {"build ms", true},
                             {"cells/ray"}, {"tests/ray"}, {"render ms", true}},
                            {},
                            "The hierarchy of grids on the " + stadium.name + " (lambda " +
                                fixed(ch07::default_lambda, 0) + " at every level), " + how + "; every image identical to the BVH's."};
    for (const int depth : {0, 1, 2, 3})
        for (const int leaf : {4, 8, 16}) {
            if (depth == 0 && leaf != 8)
                continue;  // depth 0 is chapter 07's grid, whatever the leaf size
            HGridSettings h;
            h.leaf_size = leaf;
            h.max_depth = depth;
            HGridStats built;
            const Measurement m = measure(stadium, keeping_stats<HGridAccel>(built, h), settings, o.sweep.repeat);
            if (m.pixels != reference)
                throw std::runtime_error("a hierarchy of grids' image differs from the BVH's: a bug of the kit");
            hgrid_table.row(
                {std::to_string(leaf), std::to_string(depth), grouped(static_cast<unsigned long long>(built.grids)),
                 grouped(static_cast<unsigned long long>(built.cells)), fixed(static_cast<double>(m.bytes) / 1e6, 2),
                 ms(m.build_ms), fixed(m.per_ray(Counter::cells_visited), 1),
                 fixed(m.per_ray(Counter::intersection_tests), 1), ms(m.render_ms)});
            csv << '"' << stadium.name << "\"," << objects_in(stadium) << ",hgrid,leaf" << leaf << ":depth" << depth
                << ',' << m.build_ms.median << ',' << m.bytes << ',' << m.per_ray(Counter::intersection_tests) << ",0,"
                << m.per_ray(Counter::cells_visited) << ',' << m.render_ms.median;
            csv_times(m);
        }

    LessonTable all{"10.structures",
                    {{"scene"}, {"objects"}, {"structure"}, {"MB"}, {"build ms", true}, {"tests/ray"},
                     {"nodes or cells/ray"}, {"render ms", true}},
                    {},
                    "Every structure side by side, " + how + "; every image identical to the BVH's."};
    const std::vector<NffScene> scenes = {
        generated_scene(write_stadium, 5, "teapot in a stadium 5"),
        generated_scene(write_sticks, 5, "sticks 5"),
        generated_scene(write_mountain, 7, "mountain 7"),
        generated_scene(write_sphereflake, 4, "sphereflake 4"),
        generated_scene(write_pyramid, 7, "pyramid 7"),
        generated_scene(write_mountain, 10, "mountain 10"),
    };
    for (const NffScene& nff : scenes) {
        std::vector<std::uint8_t> same;
        for (const std::string name : {"bvh", "hgrid", "grid", "hashed"}) {
            const float lambda = name == "hashed" ? ch09::default_hashed_lambda : ch07::default_lambda;
            Measurement m;
            try {
                m = measure(nff, [&](const Objects& objs) { return ch10::make_accelerator(name, objs, lambda, BvhSettings{}); },
                            settings, o.sweep.repeat);
            } catch (const InputError& e) {
                all.row({nff.name, grouped(objects_in(nff)), name, e.what()});
                continue;
            }
            if (same.empty())
                same = m.pixels;
            if (m.pixels != same)
                throw std::runtime_error("the " + name + "'s image differs from the BVH's on " + nff.name + ": a bug of the kit");
            all.row({nff.name, grouped(objects_in(nff)), name, fixed(static_cast<double>(m.bytes) / 1e6, 2),
                     ms(m.build_ms), fixed(m.per_ray(Counter::intersection_tests), 1),
                     fixed(name == "bvh" ? m.per_ray(Counter::nodes_visited) : m.per_ray(Counter::cells_visited), 1),
                     ms(m.render_ms)});
            csv << '"' << nff.name << "\"," << objects_in(nff) << ',' << name << ",default," << m.build_ms.median << ','
                << m.bytes << ',' << m.per_ray(Counter::intersection_tests) << ',' << m.per_ray(Counter::nodes_visited)
                << ',' << m.per_ray(Counter::cells_visited) << ',' << m.render_ms.median;
            csv_times(m);
        }
    }
    write_lesson_tables(tables_beside(o.sweep.csv), {bvh_table, hgrid_table, all}, std::cout);
    std::cout << "\nwrote " << o.sweep.csv << " and " << tables_beside(o.sweep.csv) << '\n';
}

}  // namespace

int main(int argc, char** argv)
{
    return run_program("10_hierarchies", [&] {
        Options o;
        CommandLine cli = program_command_line(
            "10_hierarchies", "Hierarchies: a bounding volume hierarchy built by the surface area heuristic.",
            o.common);
        const SceneProgram program = scene_program(o);
        add_scene_program_options(cli, o.scene, program);
        cli.option("--accel", o.accel,
                   "what answers the queries: bvh, hgrid (the hierarchy of grids), hashed (chapter 09), grid (07) or brute");
        cli.option("--lambda", o.lambda, "with grid, hgrid or hashed: cells per object", 0.0f, 1e6f);
        cli.option("--leaf-size", o.leaf_size,
                   "with bvh: a node of at most this many objects is a leaf (default 4; a larger one is too at the "
                   "depth limit or when no split pays); with hgrid: the most a cell lists before it "
                   "gets a grid of its own (default 8)",
                   1, 65535);
        cli.option("--max-depth", o.max_depth,
                   "with bvh: the deepest a leaf may lie (default 48); with hgrid: the deepest a grid may lie (default "
                   "2); the root is 0",
                   0, bvh_stack_size - 2);
        cli.option("--split", o.split, "with bvh: sah (the surface area heuristic) or median");
        add_sweep_options(cli, o.sweep, "measure leaf size, depth and split, and every structure side by side");
        if (!cli.parse(argc, argv, std::cout))
            return 0;
        if (o.accel != "bvh" && o.accel != "hgrid" && o.accel != "hashed" && o.accel != "grid" && o.accel != "brute")
            throw InputError("--accel takes bvh, hgrid, hashed, grid or brute, got '" + o.accel + "'");
        if (o.split != "sah" && o.split != "median")
            throw InputError("--split takes sah or median, got '" + o.split + "'");
        o.bvh.split = o.split == "sah" ? BvhSplit::sah : BvhSplit::median;
        if (o.accel != "bvh" && cli.given("--split"))
            throw InputError("--split shapes the BVH; it applies to --accel bvh only");
        if (o.accel != "bvh" && o.accel != "hgrid" && (cli.given("--leaf-size") || cli.given("--max-depth")))
            throw InputError("--leaf-size and --max-depth shape the BVH and the hierarchy of grids; they apply to "
                             "--accel bvh or hgrid only");
        if ((o.accel == "bvh" || o.accel == "brute") && cli.given("--lambda"))
            throw InputError("--lambda sets a grid's density; it applies to --accel grid, hgrid or hashed only");
        if (o.accel == "hgrid" && o.max_depth > HGridAccel::max_hgrid_depth)
            throw InputError("--max-depth for the hierarchy of grids must be between 0 and " +
                             std::to_string(HGridAccel::max_hgrid_depth) + ", got " + std::to_string(o.max_depth));
        if (cli.given("--leaf-size"))
            o.bvh.leaf_size = o.hgrid.leaf_size = o.leaf_size;
        if (cli.given("--max-depth"))
            o.bvh.max_depth = o.hgrid.max_depth = o.max_depth;
        if (o.accel == "hashed" && !cli.given("--lambda"))
            o.lambda = ch09::default_hashed_lambda;
        return finish_scene_program(program, o.common, o.scene, cli, o.sweep, [&] { sweep(o, cli); });
    });
}
