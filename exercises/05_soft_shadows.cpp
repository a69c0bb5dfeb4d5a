// Chapter 05, soft shadows: your exercises.
//
// Each function below states what to compute (not how); its contract is documented in
// chapters/05_soft_shadows/05_soft_shadows.hpp and the lesson in that folder's README.md.
// Each stub compiles and returns a harmless value, so the chapter's program always runs.
// Check your work with:  cmake --build --preset grade --target check_05
// Stuck? Hints in tiers you open one at a time: chapters/05_soft_shadows/hints.md, or
// ./build/grade/hint 05.1 (tier 1, the idea), ./build/grade/hint 05.1 2 (the trap), ... 3 (the walk-through).
//
// This chapter builds on chapter 04: direct_light calls its local_shading (04.1) and its
// shadow feeler (light_blocked, which calls your 04.2 and 04.3).
#include "04_shadow_feelers/04_shadow_feelers.hpp"
#include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises
#include "04_shadow_feelers/radiance.hpp"
#include "05_soft_shadows/05_soft_shadows.hpp"
#include "05_soft_shadows/light_samples.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

point3 point_on_rectangle(const AreaLight& light, sample2 u)
{
    // EXERCISE 05.1: u in [0, 1)^2 to a point of the rectangle light
    // Return the point of the light that u stands for: each coordinate of u stretched from [0, 1) to
    // [-1, 1) in units of the half-axes, so u = (0, 0) is the corner behind both axis_u and axis_v,
    // u = (1/2, 1/2) the centre, and u.x runs along axis_u. Uniform u must give uniform points.
    // Lesson: "Points on a rectangle (EXERCISE 05.1)".
    // Stuck? hint 05.1 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("05.1", light.centre);
}

point3 point_on_disc(const AreaLight& light, sample2 u)
{
    // EXERCISE 05.2: u in [0, 1)^2 to a point of the disc light, by Shirley and Chiu's concentric map
    // Return the light's centre moved by the disc point u stands for, in units of the half-axes (each
    // as long as the radius). Area-preserving: uniform u give uniform points, spread over the whole
    // disc to its rim and never beyond; never a NaN, even at the square's centre u = (1/2, 1/2).
    // Lesson: "Points on a disc (EXERCISE 05.2)".
    // Stuck? hint 05.2 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("05.2", light.centre);
}

sample2 stratified_sample(int k, int n, Rng& rng)
{
    // EXERCISE 05.3: sample k of an n x n jittered grid
    // Return a uniform point of cell k of the unit square cut into n x n cells, numbered along x
    // first, row after row (k from 0 to n^2 - 1). Its two numbers come from rng, x's first; the point
    // stays in [0, 1) even in the last cell with the jitter a hair below 1 (one_minus_epsilon).
    // Lesson: "Stratified samples (EXERCISE 05.3)".
    // Stuck? hint 05.3 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("05.3", sample2{0.5f, 0.5f});
}

color direct_light(const AreaLitScene& scene, const Ray& ray, const Hit& hit, const AreaLight& light,
                   const LightSampling& sampling, Rng& rng)
{
    // EXERCISE 05.4: the light one area light sends to the eye, with N = sampling.samples feelers
    // Return the Monte Carlo estimate of the lesson's integral E, shaded by chapter 04's local_shading:
    // N points on the light, drawn from this rng by the given light_samples.hpp, one feeler each,
    // weighted for points uniform over the light's area. A sample behind the surface, on the
    // light's dark side or at distance 0 adds nothing and sends no feeler; never a NaN.
    // Lesson: "Monte Carlo: the estimator and its weight (EXERCISE 05.4)".
    // Stuck? hint 05.4 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("05.4", color(0.0f));
}

}  // namespace rt
