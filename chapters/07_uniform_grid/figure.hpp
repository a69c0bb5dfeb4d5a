// Chapter 07's figure: a scene too large for brute force, rendered through the grid with chapter
// 04's shading and shadow feelers, beside a heat map of what each pixel cost.
//
// The scene is the kit's fractal mountain (nff_generate mountain --depth 7: 32768 triangles and
// four balls), generated in memory: brute force tests all 32772 objects for every ray; the grid
// tests a few dozen, most of them on the slopes the ray actually passes.
#pragma once

#include "07_uniform_grid/grid.hpp"
#include "07_uniform_grid/scene_program.hpp"
#include "common/heatmap.hpp"
#include "common/nff.hpp"
#include "common/scene_file.hpp"
#include "common/scenes/nff_generators.hpp"

#include <memory>
#include <sstream>
#include <string>

namespace rt::ch07 {

constexpr int figure_mountain_depth = 7;

// Why 4 cells per object: the lesson's table, on this scene, has its fastest renders at 4 to 8
// cells per object, and the grid's bytes keep growing with lambda past that.
constexpr float default_lambda = 4.0f;

// One of the kit's generated scenes, read back from the NFF text its generator writes.
inline NffScene generated_scene(void (*write)(std::ostream&, int), int depth, const std::string& name)
{
    std::stringstream text;
    write(text, depth);
    return parse_nff(text, name);
}

inline NffScene figure_scene() { return generated_scene(write_mountain, figure_mountain_depth, "mountain, depth 7"); }

// A scene's accelerator by name: none (brute force) or the grid; the program's --accel.
inline std::unique_ptr<Accelerator> make_accelerator(const std::string& name, const Objects& objects, float lambda)
{
    if (name == "brute")
        return nullptr;
    if (name == "grid")
        return std::make_unique<UniformGrid>(objects, lambda);
    throw InputError("--accel takes brute or grid, got '" + name + "'");
}

// A generated figure's scene through the accelerator `make` builds from its objects, with chapter
// 04's shading and feelers; with `cost`, what each pixel cost. Chapters 07-10 render their figures
// (and the picture tests theirs) through it.
template <class Make>
Image render_figure_through(const NffScene& nff, const RenderSettings& settings, const Make& make, CostMap* cost)
{
    const SceneRender file = scene_render(nff, settings);
    LitScene scene = lit_scene(file.scene);
    const std::unique_ptr<Accelerator> accel = make(objects_of(scene, lit_tests));
    scene.accelerator = accel.get();
    return render_lit(file, scene, FeelerSettings{}, cost);
}

// The figure's scene through the grid, lambda cells per object; with `cost`, what each pixel cost.
inline Image render_through_grid(const RenderSettings& settings, float lambda = default_lambda, CostMap* cost = nullptr)
{
    return render_figure_through(figure_scene(), settings,
                                 [&](const Objects& o) { return std::make_unique<UniformGrid>(o, lambda); }, cost);
}

}  // namespace rt::ch07
