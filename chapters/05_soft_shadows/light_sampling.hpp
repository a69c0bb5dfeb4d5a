// How a shading point picks its points on an area light: how many, and by which scheme. The knobs
// the chapter's program turns and its table measures; the rendering code passes them through.
//
// Each light sample is a point u of the unit square [0, 1)^2, which EXERCISE 05.1 or 05.2 then maps
// onto the light. Two ways to pick the N points of the square (pbrt-v4, "Sampling and
// Reconstruction": the independent and the stratified sampler):
#pragma once

#include <glm/vec2.hpp>

#include <cmath>

namespace rt {

// A point of the unit square [0, 1)^2: the two uniform numbers a sample is made from.
using sample2 = glm::vec2;

enum class SampleScheme {
    random,      // N independent uniform points: clumps and gaps; error falls as 1/sqrt(N)
    stratified,  // the square cut into an n x n grid, one jittered point per cell (EXERCISE 05.3):
                 // no clumps, no gaps; error falls faster (the README measures how much)
};

struct LightSampling {
    int samples = 16;  // N, points (and shadow feelers) per light per shading point; a square for stratified
    SampleScheme scheme = SampleScheme::stratified;
};

// The side n of an n x n grid of `samples` points, or 0 when `samples` is not a square.
inline int grid_side(int samples)
{
    const int n = static_cast<int>(std::lround(std::sqrt(static_cast<double>(samples))));
    return n * n == samples ? n : 0;
}

}  // namespace rt
