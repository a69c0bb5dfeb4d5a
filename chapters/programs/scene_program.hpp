// What every program from chapter 07 on does besides its sweep: render its figure (a generated
// scene, beside the heat map of what each pixel cost) or a scene file (--scene), with chapter 04's
// shading and shadow feelers or by the classic NFF rules (--classic), through the accelerator its
// options name; --heatmap writes the heat map, --stats adds the structure's own lines. Each
// chapter says what its figure is, how to build its accelerators and what to print of them.
//
// chapters/programs/ holds what the programs of chapters 07-10 and the benchmark share (this file,
// and measure.hpp for their sweeps): given code of no one chapter, built on chapter 04's shading
// (04_shadow_feelers/radiance.hpp) and chapter 02's scene query.
#pragma once

#include "04_shadow_feelers/classic.hpp"
#include "04_shadow_feelers/radiance.hpp"
#include "04_shadow_feelers/nff_scene.hpp"
#include "common/cli.hpp"
#include "common/heatmap.hpp"
#include "common/nff.hpp"
#include "common/output.hpp"
#include "common/png.hpp"
#include "common/scene_file.hpp"
#include "programs/structures.hpp"

#include <algorithm>
#include <functional>
#include <iostream>
#include <memory>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rt {

// One of the kit's generated scenes, read back from the NFF text its generator writes.
inline NffScene generated_scene(void (*write)(std::ostream&, int), int depth, const std::string& name)
{
    std::stringstream text;
    write(text, depth);
    return parse_nff(text, name);
}

// A generated figure's scene through the accelerator `make` builds from its objects, with chapter
// 04's shading and feelers; with `cost`, what each pixel cost. Chapters 07-10 render their
// figures (and the picture tests theirs) through it.
template <class Make>
Image render_figure_through(const NffScene& nff, const RenderSettings& settings, const Make& make, CostMap* cost)
{
    const SceneRender file = scene_render(nff, settings);
    LitScene scene = lit_scene(file.scene);
    const std::unique_ptr<Accelerator> accel = make(objects_of(scene, lit_tests));
    scene.accelerator = accel.get();
    return render_lit(file, scene, FeelerSettings{}, cost);
}

// The options the scene programs share.
struct SceneOptions {
    std::string scene;
    bool classic = false;
    bool two_sided = false;
    std::string heatmap;
    std::string heat_of;  // a name from SceneProgram::heat; empty: its first
};

struct SceneProgram {
    std::string name;                  // the program's, for messages
    std::function<NffScene()> figure;  // the figure's scene, generated
    // What a heat map may count (--heat-of): a name, the counter, its caption. The first is the default.
    struct Heat {
        std::string name;
        Counter counter;
        std::string caption;
    };
    std::vector<Heat> heat;
    // The structure --accel chose, which the program builds for a scene's objects (nullptr: brute
    // force). What --stats adds to the render's lines: accel=<its name>, objects=N, the counters of
    // stats_counters (name=count), then the structure's own report (Accelerator::report).
    const StructureChoice* structure;
    std::vector<std::pair<std::string, Counter>> stats_counters;
    // Structures the figure compares (chapter 10: the grid, the hierarchy of grids and the BVH):
    // when given, the figure is the render beside one heat map for each, on one scale, in place of
    // its own accelerator's map. The maps count what every structure does, the program's heat named
    // "tests" (intersection tests). Each must render the same picture, byte for byte.
    struct Compared {
        std::string name;
        std::function<std::unique_ptr<Accelerator>(const Objects&)> make;
    };
    std::vector<Compared> compare;
};

// "a, b or c": the heat maps' names, for help and messages.
inline std::string heat_names(const SceneProgram& program)
{
    std::string names;
    for (size_t k = 0; k < program.heat.size(); ++k)
        names += (k == 0 ? "" : k + 1 == program.heat.size() ? " or " : ", ") + program.heat[k].name;
    return names;
}

inline void add_scene_program_options(CommandLine& cli, SceneOptions& o, const SceneProgram& program)
{
    add_scene_option(cli, o.scene);
    cli.flag("--classic", o.classic, "the classic NFF test rules (corner rays, depth 5, SPD counts)");
    cli.flag("--two-sided", o.two_sided, "with --classic: every polygon seen from both sides (SPD's teapot)");
    cli.option("--heatmap", o.heatmap, "also write a heat map of what each pixel cost to this PNG");
    cli.option("--heat-of", o.heat_of, "what the heat map counts: " + heat_names(program));
}

inline const SceneProgram::Heat& heat_named(const SceneProgram& program, const std::string& name)
{
    for (const SceneProgram::Heat& h : program.heat)
        if (name.empty() || h.name == name)
            return h;
    throw InputError("--heat-of takes " + heat_names(program) + ", got '" + name + "'");
}

// Checks the options against each other before any work (InputError otherwise).
inline void check_scene_program_options(const SceneProgram& program, const SceneOptions& o, const CommonOptions& common)
{
    heat_named(program, o.heat_of);
    classic::check_classic_options(o.classic, o.scene, common.spp, o.two_sided);
}

// The figure's comparison: one render per compared structure, each with its heat map. Rendered
// before the figure's own render, and its counts dropped, so --stats and the time are the figure's
// accelerator's alone.
struct Comparison {
    std::vector<Image> images;
    std::vector<CostMap> maps;
};

inline Comparison compare_structures(const SceneProgram& program, const SceneRender& file, const LitScene& lit,
                                     const Objects& objects)
{
    const SceneProgram::Heat& heat = heat_named(program, "tests");
    Comparison c;
    for (const SceneProgram::Compared& structure : program.compare) {
        LitScene scene = lit;
        const std::unique_ptr<Accelerator> accel = structure.make(objects);
        scene.accelerator = accel.get();
        c.maps.emplace_back(file.settings.width, file.settings.height, heat.counter);
        c.images.push_back(render_lit(file, scene, FeelerSettings{}, &c.maps.back()));
    }
    reset_counters();
    return c;
}

// The figure: `image` beside the comparison's heat maps, on one logarithmic scale up to the largest
// of their tops (the structures differ a hundredfold), each captioned with its structure's name;
// three maps go in two rows under and beside the render, a shape that fits a slide. Each
// structure's render must equal the figure's `image`.
inline Image compared_heat_maps(const SceneProgram& program, const Comparison& c, const Image& image)
{
    const SceneProgram::Heat& heat = heat_named(program, "tests");
    double top = 0.0;
    for (size_t k = 0; k < c.maps.size(); ++k) {
        if (c.images[k].pixels != image.pixels)
            throw std::logic_error("the " + program.compare[k].name + "'s render differs from the figure's: a bug of the kit");
        top = std::max(top, heat_top(c.maps[k]));
    }
    std::vector<Image> maps;
    for (size_t k = 0; k < c.maps.size(); ++k)
        maps.push_back(heat_image(c.maps[k], program.compare[k].name + ": " + heat.caption, top, HeatScale::log));
    if (maps.size() == 3) {
        const Image render = above_below(image, Image(maps[0].width, 0));  // padded to a map's width
        return above_below(side_by_side(render, maps[0]), side_by_side(maps[1], maps[2]));
    }
    Image row = image;
    for (const Image& map : maps)
        row = side_by_side(row, map);
    return row;
}

inline int render_scene_program(const SceneProgram& program, const CommonOptions& common, const SceneOptions& o,
                                 const CommandLine& cli)
{
    if (!o.heatmap.empty())
        check_writable(o.heatmap, "PNG");
    const SceneProgram::Heat& heat = heat_named(program, o.heat_of);
    const bool figure = o.scene.empty();
    const SceneRender file = figure ? scene_render(program.figure(), render_settings(common))
                                    : load_scene_render(o.scene, common, cli);
    const int width = file.settings.width, height = file.settings.height;
    const auto stats = [&](StatsPrinter base, const Accelerator* accel, int objects) {
        return [=, &program](std::ostream& out, const Counts& counts, double seconds) {
            base(out, counts, seconds);
            out << "accel=" << program.structure->accel << '\n' << "objects=" << objects << '\n';
            for (const auto& [name, counter] : program.stats_counters)
                out << name << '=' << counted(counts, counter) << '\n';
            if (accel)
                accel->report(out);
        };
    };
    if (o.classic) {
        classic::ClassicScene scene = classic::classic_scene(file.scene, o.two_sided);
        const Objects objects = objects_of(scene.lit, lit_tests);
        const std::unique_ptr<Accelerator> accel = program.structure->make(objects);
        scene.lit.accelerator = accel.get();
        CostMap corners(width + 1, height + 1, heat.counter);
        return write_figure(common, [&] {
            const Image image = classic::render_classic(file, scene, o.heatmap.empty() ? nullptr : &corners);
            if (!o.heatmap.empty())
                write_png(o.heatmap, heat_image(classic::pixel_cost_of_corners(corners), heat.caption));
            return image;
        }, stats(print_classic_stats, accel.get(), objects.size()));
    }
    if (!figure)
        note_unmodelled_materials(file.scene, program.name);
    LitScene scene = lit_scene(file.scene);
    const Objects objects = objects_of(scene, lit_tests);
    const std::unique_ptr<Accelerator> accel = program.structure->make(objects);
    scene.accelerator = accel.get();
    check_writable(common.out, "PNG");
    const Comparison comparison = figure ? compare_structures(program, file, scene, objects) : Comparison{};
    return write_figure(common, [&] {
        CostMap cost(width, height, heat.counter);
        const Image image = render_lit(file, scene, FeelerSettings{}, &cost);
        const Image map = heat_image(cost, heat.caption);
        if (!o.heatmap.empty())
            write_png(o.heatmap, map);
        // The figure is the render with its heat map; a scene file is the render alone.
        if (!figure)
            return image;
        if (program.compare.empty())
            return side_by_side(image, map);
        return compared_heat_maps(program, comparison, image);
    }, stats(print_stats, accel.get(), objects.size()));
}

// What a scene program does once its own options are checked: checks the shared ones, then runs
// its sweep (--sweep, writing sweep.csv) or renders.
inline int finish_scene_program(const SceneProgram& program, const CommonOptions& common, const SceneOptions& o,
                                const CommandLine& cli, const SweepOptions& sweep,
                                const std::function<void()>& run_sweep)
{
    check_scene_without_sweep(o.scene, sweep.on);
    check_scene_program_options(program, o, common);
    if (sweep.on) {
        check_writable(sweep.csv, "CSV");
        // Each row as it is measured, in a log too: a sweep takes minutes.
        std::cout << std::unitbuf;
        run_sweep();
        return 0;
    }
    return render_scene_program(program, common, o, cli);
}

// What a program of chapters 07-10 says of itself in --help: one line, what --sweep measures, and
// where it writes.
struct SceneProgramHelp {
    std::string summary, sweep;
    std::string csv = "where --sweep writes its table";
};

// The main of a program of chapters 07-10, whose Options hold `common`, `scene`, `structure` (a
// StructureChoice) and `sweep`: its command line (the common options, the scene program's, --accel
// and --lambda, the chapter's own from `own_options`, --sweep's), parsed; the structure's options
// and the chapter's own checked (`own_checks`); then the figure, a scene file or the sweep.
template <class Options>
int scene_program_main(int argc, char** argv, Options& o, const SceneProgram& program, const SceneProgramHelp& help,
                       float most_lambda, const std::function<void(CommandLine&)>& own_options,
                       const std::function<void(const CommandLine&)>& own_checks,
                       const std::function<void(const CommandLine&)>& sweep)
{
    CommandLine cli = program_command_line(program.name, help.summary, o.common);
    add_scene_program_options(cli, o.scene, program);
    o.structure.add_options(cli, most_lambda);
    if (own_options)
        own_options(cli);
    add_sweep_options(cli, o.sweep, help.sweep, help.csv);
    if (!cli.parse(argc, argv, std::cout))
        return 0;
    o.structure.chosen(cli);
    if (own_checks)
        own_checks(cli);
    return finish_scene_program(program, o.common, o.scene, cli, o.sweep, [&] { sweep(cli); });
}

}  // namespace rt
