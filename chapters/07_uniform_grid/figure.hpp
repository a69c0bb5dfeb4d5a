// Chapter 07's figure: a scene too large for brute force, rendered through the grid with chapter
// 04's shading and shadow feelers, beside a heat map of what each pixel cost.
//
// The scene is the kit's fractal mountain (nff_generate mountain --depth 7: 32768 triangles and
// four balls), generated in memory: brute force tests all 32772 objects for every ray; the grid
// tests a few dozen, most of them on the slopes the ray actually passes.
#pragma once

#include "07_uniform_grid/grid.hpp"
#include "common/heatmap.hpp"
#include "common/scenes/nff_generators.hpp"
#include "programs/scene_program.hpp"
#include "programs/structures.hpp"

#include <memory>
#include <string>

namespace rt::ch07 {

constexpr int figure_mountain_depth = 7;

// Why 4 cells per object: the lesson's table, on this scene, has its fastest renders at 4 to 8
// cells per object, and the grid's bytes keep growing with lambda past that.
constexpr float default_lambda = 4.0f;

inline NffScene figure_scene() { return generated_scene(write_mountain, figure_mountain_depth, "mountain, depth 7"); }

// The structures chapters 01-07 bring (programs/structures.hpp): brute force and the grid. Brute
// force builds nothing: with no accelerator the scene asks chapter 02's query and chapter 04's
// feeler (EXERCISE 04.2), as chapter 04's program does. The grid's resolution is 07.1's rule at
// lambda, or with --resolution open your 07.7's (chapter 07's program; lambda is then not asked).
inline Structures structures()
{
    return {{brute_force_name, "every object, every ray", 2, 0.0f, {},
             [](const Objects&, const StructureTuning&) { return std::unique_ptr<Accelerator>{}; }},
            {"grid", "the uniform grid", 7, default_lambda, {"--lambda", "--resolution"},
             [](const Objects& o, const StructureTuning& t) {
                 if (t.resolution == "open")
                     return std::make_unique<UniformGrid>(o, ChosenResolution{});  // your 07.7
                 return std::make_unique<UniformGrid>(o, t.lambda);
             }}};
}

// The figure's scene through the grid, lambda cells per object; with `cost`, what each pixel cost.
inline Image render_through_grid(const RenderSettings& settings, float lambda = default_lambda, CostMap* cost = nullptr)
{
    return render_figure_through(figure_scene(), settings,
                                 [&](const Objects& o) { return std::make_unique<UniformGrid>(o, lambda); }, cost);
}

}  // namespace rt::ch07
