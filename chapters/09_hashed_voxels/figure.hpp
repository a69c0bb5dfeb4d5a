// Chapter 09's figure: the teapot in a stadium (a small dense mesh of 20480 triangles in a stadium
// 130 across) through the hashed grid, fine enough for the small mesh, beside the heat map of
// intersection tests per pixel.
#pragma once

#include "08_mailboxing/figure.hpp"
#include "09_hashed_voxels/hashed_grid.hpp"

#include <memory>
#include <string>

namespace rt::ch09 {

constexpr int figure_stadium_depth = 5;

static_assert(dense_grid_lambda == ch07::default_lambda,
              "the hashed grid weighs its memory against chapter 07's grid at that grid's default lambda");

// Why 256 cells per object: on the stadium the hashed grid renders far faster than at the dense
// grid's 4 (where the small mesh fills a few cells), and a finer grid takes more memory for no time
// saved. The figures are the lesson's table 09.structures.
constexpr float default_hashed_lambda = 256.0f;

inline NffScene figure_scene()
{
    return generated_scene(write_stadium, figure_stadium_depth, "teapot in a stadium, depth 5");
}

// Chapter 08's structures and the hashed grid (programs/structures.hpp): its cells in bucket p mod M,
// or with --table-hash open in the buckets of your hash (09.6).
inline Structures structures()
{
    return followed_by(ch08::structures(),
                       {{"hashed", "the hashed grid, its occupied cells in a hash table", 9, default_hashed_lambda,
                         {"--lambda", "--table-size", "--table-hash"}, [](const Objects& o, const StructureTuning& t) {
                             if (t.table_hash == "open")
                                 return std::make_unique<HashedGrid>(o, t.lambda, OpenHashing{});
                             return std::make_unique<HashedGrid>(o, t.lambda, t.table_size);
                         }}});
}

// The figure's scene through the hashed grid; with `cost`, what each pixel cost.
inline Image render_through_hashed(const RenderSettings& settings, float lambda = default_hashed_lambda,
                                   CostMap* cost = nullptr)
{
    return render_figure_through(figure_scene(), settings,
                                       [&](const Objects& o) { return std::make_unique<HashedGrid>(o, lambda); }, cost);
}

}  // namespace rt::ch09
