// Given: the colour of a hit in a scene with area lights, and of a primary ray. Chapter 04's shade
// does the ambient term and the point lights (hard shadows, one feeler each); your direct_light
// (EXERCISE 05.4) adds each area light (soft shadows, N feelers each).
#pragma once

#include "04_shadow_feelers/04_shadow_feelers.hpp"
#include "04_shadow_feelers/radiance.hpp"
#include "05_soft_shadows/05_soft_shadows.hpp"
#include "common/stats.hpp"

namespace rt {

inline color shade_area_lit(const AreaLitScene& scene, const Ray& ray, const Hit& hit, const LightSampling& sampling,
                            Rng& rng)
{
    color c = shade(scene.lit, ray, hit, FeelerSettings{});
    for (const AreaLight& light : scene.area_lights)
        c += direct_light(scene, ray, hit, light, sampling, rng);
    return c;
}

// The slides' Render(ray) for this scene. A primary ray starts at the eye, on no surface, so it
// accepts any t > 0.
inline color radiance(const AreaLitScene& scene, const Ray& ray, const LightSampling& sampling, Rng& rng)
{
    count(Counter::primary_rays);
    const std::optional<Hit> hit = closest_hit(ray, scene.lit, Interval{0.0f, infinity});
    return hit ? shade_area_lit(scene, ray, *hit, sampling, rng) : scene.lit.background;
}

}  // namespace rt
