// Chapter 04's shading of a whole ray: the nearest hit's Phong colour with its shadow feelers, or
// the background. Every later chapter that renders a lit scene (a generated figure or a scene
// file, through any accelerator) shades its rays with it.
#pragma once

#include "01_ray_casting/01_ray_casting.hpp"
#include "04_shadow_feelers/04_shadow_feelers.hpp"
#include "04_shadow_feelers/closest_hit.hpp"
#include "04_shadow_feelers/nff_scene.hpp"
#include "common/heatmap.hpp"
#include "common/render.hpp"
#include "common/scene_file.hpp"

namespace rt {

namespace ch04 {

// The slides' Render(ray): the nearest object's colour, or the background. A primary ray starts at
// the eye, on no surface, so it accepts any t > 0.
inline color radiance(const LitScene& scene, const Ray& ray, const FeelerSettings& feelers)
{
    count(Counter::primary_rays);
    const std::optional<Hit> hit = closest_hit(ray, scene, Interval{0.0f, infinity});
    return hit ? shade(scene, ray, *hit, feelers) : scene.background;
}

}  // namespace ch04

// Chapter 04's render of a scene file (its shading with feelers), through whatever accelerator the
// scene holds; with `cost`, also what each pixel cost.
inline Image render_lit(const SceneRender& file, const LitScene& scene, const FeelerSettings& feelers,
                        CostMap* cost = nullptr)
{
    const auto radiance = [&](float x, float y, Rng&) {
        return ch04::radiance(scene, file.eye_ray(primary_ray(file.camera, x, y)), feelers);
    };
    return cost ? render(file.settings, with_cost(*cost, radiance)) : render(file.settings, radiance);
}

}  // namespace rt
