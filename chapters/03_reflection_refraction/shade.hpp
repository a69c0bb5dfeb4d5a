// What Whitted's recursion (EXERCISE 03.5) calls besides the exercises, given: the local shading
// of a hit, the sky a ray sees when it hits nothing, and the range of t a secondary ray searches.
// The scene query is chapter 02's closest_hit (the slides' QueryScene).
#pragma once

#include "02_spheres_triangles/closest_hit.hpp"
#include "03_reflection_refraction/scene.hpp"
#include "common/interval.hpp"
#include "common/stats.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

// Where a secondary ray may find its first hit. It starts at a hit point, on the surface it
// leaves, and that point is rounded (about 1e-7 of its coordinates): the surface may lie a hair in
// front of it, and the ray would find it again at t near 0 ("acne"). Skipping t below 1e-4, a
// thousand times that rounding at the figure's scale (coordinates of 1 to 10), is the simple fix.
// A fixed bound is a guess that fails at other scales: chapter 04 measures how, and replaces it
// with an offset that scales with the point.
constexpr float secondary_t_min = 1e-4f;

// Whitted's local term, I_a + k_d (N.L), for one directional light, without shadows (a shadow
// feeler per light is chapter 04): the ambient light plus Lambert's cosine, both times the
// surface's diffuse colour. The normal is turned to face the ray, so a surface seen from behind
// is lit as its front would be.
inline color local_shade(const WhittedScene& scene, const Ray& ray, const Hit& hit)
{
    const vec3 n = glm::dot(hit.n, ray.dir) < 0.0f ? hit.n : -hit.n;
    const float lambert = std::max(0.0f, glm::dot(n, scene.sun.to_sun));
    return scene.albedo(hit.object, hit.p) * (scene.ambient + lambert * scene.sun.colour);
}

// What a ray that hits nothing sees: the sky, from its horizon colour (at and below the horizon)
// to its zenith colour straight up, and the sun's glow around the sun's direction. Mirrors and
// glass show the glow as their highlight, because their rays see it.
inline color background(const WhittedScene& scene, const vec3& dir)
{
    // 1 - (1 - y)^3: the deep blue comes in quickly above the horizon, as a real sky's does.
    const float below = 1.0f - std::max(0.0f, dir.y);
    const float up = 1.0f - below * below * below;
    const color sky = (1.0f - up) * scene.shapes.background + up * scene.zenith;
    const float toward_sun = std::max(0.0f, glm::dot(dir, scene.sun.to_sun));
    return sky + scene.sun.glow * std::pow(toward_sun, scene.sun.glow_exponent) * scene.sun.colour;
}

}  // namespace rt
