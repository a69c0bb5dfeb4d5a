// Given: from a sample number to a point on a light. EXERCISE 05.4 calls these two once per feeler.
//
//   light_sample(k, sampling, rng)  the k-th point u of the unit square, by the scheme `sampling`
//                                   names: two fresh uniform numbers, or your stratified sample (05.3)
//   point_on_light(light, u)        u on the light: your 05.1 for a rectangle, 05.2 for a disc
//
// Every number comes from the rng the render gives the pixel (common/render.hpp): each pixel has its
// own stream, so neighbouring pixels get unrelated samples (noise, not a pattern) and the image is
// the same at any thread count.
#pragma once

#include "05_soft_shadows/05_soft_shadows.hpp"

#include <cassert>

namespace rt {

inline sample2 light_sample(int k, const LightSampling& sampling, Rng& rng)
{
    if (sampling.scheme == SampleScheme::stratified) {
        const int n = grid_side(sampling.samples);
        assert(n > 0 && "stratified sampling takes a square number of samples");
        return stratified_sample(k, n, rng);
    }
    // Two statements: x is drawn before y whatever the compiler's order of evaluation.
    const float x = rng.next_float();
    const float y = rng.next_float();
    return {x, y};
}

inline point3 point_on_light(const AreaLight& light, sample2 u)
{
    return light.shape == LightShape::rectangle ? point_on_rectangle(light, u) : point_on_disc(light, u);
}

}  // namespace rt
