// The small pictures that chapter 06's picture test renders, shared with make_references so that
// the reference and the test render exactly the same scene. The figure is noisy (each sample sees
// it from another point of the lens), so the reference is rendered with many samples and the test
// with few, and they are compared within the test's own noise (tests/grader/picture.hpp).
#pragma once

#include "06_depth_of_field/figure.hpp"

namespace rt::pictures {

constexpr int ch06_width = 64, ch06_height = 36;  // the figure's 16:9, small
constexpr int ch06_reference_spp = 1024;          // converged: its noise is 1/8 of a 16-spp render's

// The figure at `spp` samples per pixel with the given seed, and its per-pixel variance of the mean.
inline Image ch06_render(int spp, std::uint64_t seed, Image* variance_of_mean)
{
    RenderSettings s = quiet_render(ch06_width, ch06_height, spp);
    s.seed = seed;
    return ch06::render_figure(s, ch06::figure_lens(), variance_of_mean);
}

// The reference: seed 1. The test renders with another seed, so that its noise is independent of
// the reference's, as the comparison's tolerance assumes.
inline Image ch06() { return ch06_render(ch06_reference_spp, 1, nullptr); }

}  // namespace rt::pictures
