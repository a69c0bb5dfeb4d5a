// Chapter 09's figure: the teapot in a stadium (a small dense mesh of 20480 triangles in a stadium
// 130 across) through the hashed grid, fine enough for the small mesh, beside the heat map of
// intersection tests per pixel.
#pragma once

#include "07_uniform_grid/figure.hpp"
#include "09_hashed_voxels/hashed_grid.hpp"

#include <memory>
#include <string>

namespace rt::ch09 {

constexpr int figure_stadium_depth = 5;

// Why 256 cells per object: the lesson's table, on the stadium, has the hashed grid's fastest
// renders from 64 to 1024 cells per object: cells small enough for the dense mesh, most of them
// empty, which is what the hash table is for (the dense grid's 4 would put the mesh in one cell).
constexpr float default_hashed_lambda = 256.0f;

inline NffScene figure_scene()
{
    return ch07::generated_scene(write_stadium, figure_stadium_depth, "teapot in a stadium, depth 5");
}

// The accelerator by name (--accel): brute force (none), the dense grid or the hashed one.
inline std::unique_ptr<Accelerator> make_accelerator(const std::string& name, const Objects& objects, float lambda,
                                                     std::uint32_t table_size)
{
    if (name == "hashed")
        return std::make_unique<HashedGrid>(objects, lambda, table_size);
    if (name == "grid" || name == "brute")
        return ch07::make_accelerator(name, objects, lambda);
    throw InputError("--accel takes hashed, grid or brute, got '" + name + "'");
}

// The figure's scene through the hashed grid; with `cost`, what each pixel cost.
inline Image render_through_hashed(const RenderSettings& settings, float lambda = default_hashed_lambda,
                                   CostMap* cost = nullptr)
{
    const SceneRender file = scene_render(figure_scene(), settings);
    LitScene scene = lit_scene(file.scene);
    const HashedGrid grid(objects_of(scene, lit_tests), lambda);
    scene.accelerator = &grid;
    return render_lit(file, scene, FeelerSettings{}, cost);
}

}  // namespace rt::ch09
