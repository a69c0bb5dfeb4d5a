// The small picture that chapter 05's picture test renders, shared with make_references so that
// the reference and the test render exactly the same thing, only with more samples per pixel.
//
// Both panels of the figure, 4 stratified samples per light at each shading point (so 05.1, 05.2,
// 05.3 and 05.4 all take part), a few samples per pixel: a noisy picture, compared by blocks with
// a tolerance from its own variance (tests/grader/picture.hpp).
#pragma once

#include "05_soft_shadows/figure.hpp"

namespace rt::pictures {

constexpr int ch05_width = 96;
constexpr int ch05_height = 48;
constexpr LightSampling ch05_sampling{4, SampleScheme::stratified};
constexpr int ch05_test_spp = 16;
// The reference's samples per pixel: its noise is 1/64 of the test's variance, and it renders in a
// few seconds.
constexpr int ch05_reference_spp = 1024;

inline Image ch05(int spp, Image* variance_of_mean = nullptr)
{
    const RenderSettings s = quiet_render(ch05_width, ch05_height, spp);
    return ch05::render_figure(s, ch05_sampling, variance_of_mean);
}

}  // namespace rt::pictures
