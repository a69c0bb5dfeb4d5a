// Chapter 10's figure: the teapot in a stadium (chapter 09's scene) through the bounding volume
// hierarchy, beside three heat maps of the intersection tests each pixel cost, on one scale: under
// chapter 07's uniform grid, the hierarchy of grids and the BVH.
#pragma once

#include "09_hashed_voxels/figure.hpp"
#include "10_hierarchies/bvh.hpp"
#include "10_hierarchies/hgrid.hpp"
#include "10_hierarchies/wide_bvh.hpp"

#include <memory>
#include <string>

namespace rt::ch10 {

inline NffScene figure_scene() { return ch09::figure_scene(); }

// The BVH's settings as the options set them: each field the options leave alone keeps its default.
inline BvhSettings bvh_settings(const StructureTuning& t)
{
    BvhSettings b;
    if (t.leaf_size > 0)
        b.leaf_size = t.leaf_size;
    if (t.max_depth >= 0)
        b.max_depth = t.max_depth;
    if (t.split == "median")
        b.split = BvhSplit::median;
    else if (t.split == "open")
        b.split = BvhSplit::open;
    return b;
}

// Chapter 09's structures and the three trees (programs/structures.hpp).
inline Structures structures()
{
    return followed_by(
        ch09::structures(),
        {{"hgrid", "the hierarchy of grids", 10, ch07::default_lambda, {"--lambda", "--leaf-size", "--max-depth"},
          [](const Objects& o, const StructureTuning& t) {
              HGridSettings h;
              h.lambda = t.lambda;
              if (t.leaf_size > 0)
                  h.leaf_size = t.leaf_size;
              if (t.max_depth >= 0)
                  h.max_depth = t.max_depth;
              return std::make_unique<HGridAccel>(o, h);
          }},
         {"bvh", "the bounding volume hierarchy", 10, 0.0f, {"--leaf-size", "--max-depth", "--split"},
          [](const Objects& o, const StructureTuning& t) { return std::make_unique<BvhAccel>(o, bvh_settings(t)); }},
         {"bvh4", "the same tree, four children to a node", 10, 0.0f, {"--leaf-size", "--max-depth", "--split"},
          [](const Objects& o, const StructureTuning& t) {
              return std::make_unique<WideBvhAccel>(o, bvh_settings(t));
          }}});
}

// The figure's scene through the BVH; with `cost`, what each pixel cost.
inline Image render_through_bvh(const RenderSettings& settings, const BvhSettings& bvh = {}, CostMap* cost = nullptr)
{
    return render_figure_through(figure_scene(), settings,
                                       [&](const Objects& o) { return std::make_unique<BvhAccel>(o, bvh); }, cost);
}

}  // namespace rt::ch10
