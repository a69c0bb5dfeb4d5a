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
    StructureChoice structure{ch10::structures(), "bvh"};  // its tuning: lambda, leaf size, depth and split
    SweepOptions sweep{false, 5, "10_hierarchies.csv"};
};

SceneProgram scene_program(const Options& o)
{
    const auto default_structure = [](const std::string& name) {
        return [name](const Objects& objects) { return structure_named(ch10::structures(), name).make(objects); };
    };
    return {"10_hierarchies",
            ch10::figure_scene,
            {{"nodes", Counter::nodes_visited, "nodes visited per pixel"},
             {"tests", Counter::intersection_tests, "intersection tests per pixel"},
             {"cells", Counter::cells_visited, "cells visited per pixel"}},
            &o.structure,
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

// What the sweep's three parts share: the render, the runs, the CSV every row goes to, the figure's
// stadium, and the BVH's picture of it, which every other image must equal.
struct Sweep {
    RenderSettings settings;
    int repeat = 1;
    std::ofstream csv;
    NffScene stadium;
    std::string how;  // for the captions
    std::vector<std::uint8_t> reference;

    static std::size_t objects_in(const NffScene& s) { return s.spheres.size() + s.triangles.size() + s.cones.size(); }

    void csv_row(const NffScene& nff, const std::string& structure, const std::string& setting, const Measurement& m)
    {
        csv << '"' << nff.name << "\"," << objects_in(nff) << ',' << structure << ',' << setting << ','
            << m.build_ms.median << ',' << m.bytes << ',' << m.per_ray(Counter::intersection_tests) << ','
            << m.per_ray(Counter::nodes_visited) << ',' << m.per_ray(Counter::cells_visited) << ','
            << m.render_ms.median << ',' << m.build_ms.min << ',' << m.build_ms.max << ',' << m.render_ms.min << ','
            << m.render_ms.max << ',' << repeat << '\n';
    }
};

// The BVH's leaf size, depth limit and split on the stadium.
LessonTable sweep_bvh(Sweep& w)
{
    LessonTable table{"10.bvh",
                      {{"split"}, {"leaf size"}, {"depth limit"}, {"nodes"}, {"depth"}, {"MB"}, {"build ms", true},
                       {"nodes/ray"}, {"tests/ray"}, {"render ms", true}},
                      {},
                      "The BVH on the " + w.stadium.name + ", " + w.how + "; every image identical."};
    const auto row = [&](BvhSplit split, int leaf, int depth) {
        BvhSettings b;
        b.split = split;
        b.leaf_size = leaf;
        b.max_depth = depth;
        BvhStats tree;
        const Measurement m = measure(w.stadium, keeping_stats<BvhAccel>(tree, b), w.settings, w.repeat);
        if (w.reference.empty())
            w.reference = m.pixels;
        if (m.pixels != w.reference)
            throw std::runtime_error("a BVH's image differs from another's: a bug of the kit");
        const std::string name = split == BvhSplit::sah ? "sah" : "median";
        table.row({split == BvhSplit::sah ? "SAH" : "median", std::to_string(leaf), std::to_string(depth),
                   grouped(static_cast<unsigned long long>(tree.nodes)), std::to_string(tree.depth),
                   fixed(static_cast<double>(m.bytes) / 1e6, 2), ms(m.build_ms),
                   fixed(m.per_ray(Counter::nodes_visited), 1), fixed(m.per_ray(Counter::intersection_tests), 1),
                   ms(m.render_ms)});
        w.csv_row(w.stadium, "bvh", name + ":leaf" + std::to_string(leaf) + ":depth" + std::to_string(depth), m);
    };
    for (const int leaf : {1, 2, 4, 8, 16, 32})
        row(BvhSplit::sah, leaf, 48);
    for (const int depth : {4, 8, 12, 16})
        row(BvhSplit::sah, 4, depth);
    row(BvhSplit::median, 4, 48);
    return table;
}

// The hierarchy of grids' leaf size and depth limit on the stadium.
LessonTable sweep_hgrid(Sweep& w)
{
    LessonTable table{"10.hgrid",
                      {{"leaf size"}, {"depth limit"}, {"grids"}, {"cells"}, {"MB"}, {"build ms", true},
                       {"cells/ray"}, {"tests/ray"}, {"render ms", true}},
                      {},
                      "The hierarchy of grids on the " + w.stadium.name + " (lambda " + fixed(ch07::default_lambda, 0) +
                          " at every level), " + w.how + "; every image identical to the BVH's."};
    for (const int depth : {0, 1, 2, 3})
        for (const int leaf : {4, 8, 16}) {
            if (depth == 0 && leaf != 8)
                continue;  // depth 0 is chapter 07's grid, whatever the leaf size
            HGridSettings h;
            h.leaf_size = leaf;
            h.max_depth = depth;
            HGridStats built;
            const Measurement m = measure(w.stadium, keeping_stats<HGridAccel>(built, h), w.settings, w.repeat);
            if (m.pixels != w.reference)
                throw std::runtime_error("a hierarchy of grids' image differs from the BVH's: a bug of the kit");
            table.row(
                {std::to_string(leaf), std::to_string(depth), grouped(static_cast<unsigned long long>(built.grids)),
                 grouped(static_cast<unsigned long long>(built.cells)), fixed(static_cast<double>(m.bytes) / 1e6, 2),
                 ms(m.build_ms), fixed(m.per_ray(Counter::cells_visited), 1),
                 fixed(m.per_ray(Counter::intersection_tests), 1), ms(m.render_ms)});
            w.csv_row(w.stadium, "hgrid", "leaf" + std::to_string(leaf) + ":depth" + std::to_string(depth), m);
        }
    return table;
}

// Every structure at its defaults on the kit's generated scenes.
LessonTable sweep_structures(Sweep& w)
{
    LessonTable table{"10.structures",
                      {{"scene"}, {"objects"}, {"structure"}, {"MB"}, {"build ms", true}, {"tests/ray"},
                       {"nodes or cells/ray"}, {"render ms", true}},
                      {},
                      "Every structure side by side, " + w.how + "; every image identical to the BVH's."};
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
        const std::string objects = grouped(Sweep::objects_in(nff));
        for (const std::string name : {"bvh", "hgrid", "grid", "hashed"}) {
            const Structure structure = structure_named(ch10::structures(), name);
            const auto make = [&](const Objects& objs) { return structure.make(objs); };
            Measurement m;
            try {
                m = measure(nff, make, w.settings, w.repeat);
            } catch (const InputError& e) {
                table.row({nff.name, objects, name, e.what()});
                continue;
            }
            if (same.empty())
                same = m.pixels;
            if (m.pixels != same)
                throw std::runtime_error("the " + name + "'s image differs from the BVH's on " + nff.name +
                                         ": a bug of the kit");
            const Counter steps = name == "bvh" ? Counter::nodes_visited : Counter::cells_visited;
            table.row({nff.name, objects, name, fixed(static_cast<double>(m.bytes) / 1e6, 2), ms(m.build_ms),
                       fixed(m.per_ray(Counter::intersection_tests), 1), fixed(m.per_ray(steps), 1),
                       ms(m.render_ms)});
            w.csv_row(nff, name, "default", m);
        }
    }
    return table;
}

void sweep(const Options& o, const CommandLine& cli)
{
    Sweep w;
    w.settings = sweep_settings(o.common, cli, 160, 90);
    w.repeat = o.sweep.repeat;
    w.csv.open(o.sweep.csv);
    w.csv << "scene,objects,structure,setting,build_ms,bytes,tests_per_ray,nodes_per_ray,cells_per_ray,render_ms,"
             "build_ms_min,build_ms_max,render_ms_min,render_ms_max,runs\n";
    w.stadium = ch10::figure_scene();
    w.how = std::to_string(w.settings.width) + "x" + std::to_string(w.settings.height) +
            ", release build, 1 thread, medians of " + std::to_string(w.repeat) + " runs";
    std::cerr
        << "measuring the BVH's leaf size, depth and split, the hierarchy of grids' leaf size and depth, then every "
           "structure on six scenes...\n";
    const LessonTable bvh = sweep_bvh(w);
    const LessonTable hgrid = sweep_hgrid(w);
    const LessonTable all = sweep_structures(w);
    write_lesson_tables(tables_beside(o.sweep.csv), {bvh, hgrid, all}, std::cout);
    std::cout << "\nwrote " << o.sweep.csv << " and " << tables_beside(o.sweep.csv) << '\n';
}

}  // namespace

int main(int argc, char** argv)
{
    return run_program("10_hierarchies", [&] {
        Options o;
        StructureTuning& t = o.structure.tuning;
        const auto tree_options = [&](CommandLine& cli) {
            cli.option("--leaf-size", t.leaf_size,
                       "a BVH node of at most this many objects is a leaf (default 4; a larger one is too at the "
                       "depth limit or when no split pays); in the hierarchy of grids, the most a cell lists before "
                       "it gets a grid of its own (default 8)",
                       1, 65535);
            cli.option("--max-depth", t.max_depth,
                       "the deepest a BVH leaf may lie (default 48), or a grid of the hierarchy of grids (default "
                       "2); the root is 0",
                       0, bvh_stack_size - 2);
            cli.option("--split", t.split, "how a BVH node is split: sah (the surface area heuristic), median, or open (your own build, 10.7)");
        };
        const auto check_tree_options = [&](const CommandLine& cli) {
            check_choice(cli, "--split", t.split, {"sah", "median", "open"});
            if (o.structure.accel == "hgrid" && t.max_depth > HGridAccel::max_hgrid_depth)
                throw InputError("--max-depth for the hierarchy of grids must be between 0 and " +
                                 std::to_string(HGridAccel::max_hgrid_depth) + ", got " + std::to_string(t.max_depth));
        };
        return scene_program_main(
            argc, argv, o, scene_program(o),
            {"Hierarchies: a bounding volume hierarchy built by the surface area heuristic.",
             "measure leaf size, depth and split, and every structure side by side"},
            1e6f, tree_options, check_tree_options, [&](const CommandLine& cli) { sweep(o, cli); });
    });
}
