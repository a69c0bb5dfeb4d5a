// Where float cannot hold what the eye sees: a scene on a lattice too coarse for it, objects finer
// than a feeler's offset where they lie, or a view whose pixels are finer than float places its
// rays. The NFF reader says so once (a warning), and chapter 04's lesson measures where it happens
// ("The right picture at every scale").
#pragma once

#include "common/vec.hpp"

#include <string>
#include <vector>

namespace rt {

struct Box {
    point3 lo, hi;
};

// How far the robust offset (chapter 04, EXERCISE 04.3: offset_int_scale) moves a point off its
// surface: this many float steps of its coordinates. An occluder nearer than that to the surface is
// jumped over, so shadows between objects smaller than it are lost.
constexpr double offset_reach_steps = 256.0;

// Empty when the objects (their boxes) are within float's reach; else one sentence naming the
// cause. Two causes, the first found said:
//  - Fewer than 2^14 float steps across the whole scene at its farthest coordinate: a coordinate is
//    rounded to the step between floats at its size (2^-23 to 2^-24 of it), so the scene is drawn on
//    a lattice of that step; coarser than 1/16384 of it, round shapes show facets and stairs, normals
//    and shadows flicker, and an accelerator's cells cannot be finer than the rounding.
//  - An object smaller than offset_reach_steps float steps of its own largest coordinate (where that
//    is at least 1/32, the offset's own rule): a feeler leaving it starts beyond its neighbours.
std::string scene_beyond_float(const std::vector<Box>& objects);

// Empty when float places the rays of this view within a pixel of where they go; else one sentence
// naming the cause. from and at as the view gives them, the full field of view in degrees across
// `width` pixels.
//
// Why this bound: a ray is placed by float numbers twice over. Its direction is rounded to a
// relative u = 2^-24 on each axis, which turns it by up to about u radians: at distance D, u D off.
// Its tests subtract the ray's origin from the shapes' coordinates (chapter 02's tests all do), each
// difference rounded to u of the larger magnitude M, the eye's or the point's. A few such roundings
// follow (the watertight test's shear, product and difference: four in all, pbrt-v4 sec. 6.8's
// gamma(4)), so where the eye looks, D away, a ray lands within 4 u (M + D) of where it is aimed. A
// pixel there is 2 D tan(angle / 2) / width across. When the first exceeds the second, neighbouring
// pixels' rays cannot be told apart by the tests, and no tolerance can draw the picture the view
// asks for: an eye 1e6 times a scene's size away with the angle that frames it, or a scene 1e-3
// across 1e5 from the origin (where floats are 0.008 apart).
std::string view_beyond_float(const point3& from, const point3& at, float angle_degrees, int width);

}  // namespace rt
