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

// The accelerator by name (--accel): every structure of chapters 07-10.
// The hierarchy of grids' settings come from `hgrid`, except its lambda, which is `lambda`.
inline std::unique_ptr<Accelerator> make_accelerator(const std::string& name, const Objects& objects, float lambda,
                                                     const BvhSettings& bvh, HGridSettings hgrid = {})
{
    if (name == "bvh")
        return std::make_unique<BvhAccel>(objects, bvh);
    if (name == "bvh4")
        return std::make_unique<WideBvhAccel>(objects, bvh);
    if (name == "hgrid") {
        hgrid.lambda = lambda;
        return std::make_unique<HGridAccel>(objects, hgrid);
    }
    if (name == "hashed")
        return ch09::make_accelerator(name, objects, lambda, 0);
    if (name == "grid" || name == "brute")
        return ch07::make_accelerator(name, objects, lambda);
    throw InputError("--accel takes bvh, bvh4, hgrid, hashed, grid or brute, got '" + name + "'");
}

// The figure's scene through the BVH; with `cost`, what each pixel cost.
inline Image render_through_bvh(const RenderSettings& settings, const BvhSettings& bvh = {}, CostMap* cost = nullptr)
{
    return render_figure_through(figure_scene(), settings,
                                       [&](const Objects& o) { return std::make_unique<BvhAccel>(o, bvh); }, cost);
}

}  // namespace rt::ch10
