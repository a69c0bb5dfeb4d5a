// One shadow feeler, sent the way FeelerSettings say: where it starts (the four offsets the
// chapter measures) and which query answers it. Given; EXERCISE 04.4 calls light_blocked once per
// light, and the program's tables measure both knobs.
#pragma once

#include "04_shadow_feelers/04_shadow_feelers.hpp"
#include "04_shadow_feelers/closest_hit.hpp"
#include "common/float_reach.hpp"
#include "common/stats.hpp"

namespace rt {

// The reader's warning of objects finer than a feeler's offset (common/float_reach.hpp) counts the
// offset's own steps.
static_assert(offset_reach_steps == offset_int_scale, "float_reach.hpp's offset is EXERCISE 04.3's");

// Where a ray leaving the surface point p along dir starts, and the t it accepts from there.
struct RayStart {
    point3 origin;
    float t_min;
};

// n is the surface's unit geometric normal, facing either way; dir need not be unit.
inline RayStart ray_start(const point3& p, const vec3& n, const vec3& dir, Offset offset)
{
    switch (offset) {
    case Offset::none:
        return {p, 0.0f};
    case Offset::t_min:
        return {p, t_min_default};
    case Offset::normal:
        return {p + (glm::dot(n, dir) < 0.0f ? -normal_offset : normal_offset) * n, 0.0f};
    case Offset::robust:
        return {offset_ray_origin(p, n, dir), 0.0f};
    }
    return {p, 0.0f};  // not reached: the switch names every offset
}

// The feeler of EXERCISE 04.2: from `origin` along the unit vector toward the light, accepting t
// strictly between t_min and the light's distance less shadow_epsilon of it.
struct Feeler {
    Ray ray;
    Interval range;
};

inline Feeler feeler(const point3& origin, const point3& light, float t_min)
{
    const vec3 to_light = light - origin;
    const float distance = glm::length(to_light);
    return {Ray{origin, to_light / distance}, Interval{t_min, distance * (1.0f - shadow_epsilon)}};
}

// The same question as occluded (EXERCISE 04.2), asked of the closest-hit query: the nearest hit
// up to the light, then "was there one?". It gives the same answers and tests every object even
// after one has already shadowed the point: the trade table measures what that costs.
inline bool occluded_by_closest_hit(const LitScene& scene, const point3& origin, const point3& light, float t_min)
{
    const Feeler f = feeler(origin, light, t_min);
    return closest_hit(f.ray, scene, f.range).has_value();
}

// The any-hit query of the scene's accelerator, asked as occluded (EXERCISE 04.2) asks it: the same
// feeler, the same range. Chapters 04-06 have no accelerator and call occluded itself.
inline bool occluded_by_accelerator(const LitScene& scene, const point3& origin, const point3& light, float t_min)
{
    const Feeler f = feeler(origin, light, t_min);
    return scene.accelerator->any(f.ray, f.range, objects_of(scene, lit_tests));
}

// Is the light at `light` hidden from the hit point? One shadow feeler, counted, from the hit's
// point and geometric normal, started and answered as `settings` say (ShadowQuery::off sends none:
// every light is seen). An any-hit feeler is your occluded (04.2) until the scene has an
// accelerator (chapter 07 on), whose any-hit query then answers it.
inline bool light_blocked(const LitScene& scene, const Hit& hit, const point3& light, const FeelerSettings& settings)
{
    if (settings.query == ShadowQuery::off)
        return false;
    count(Counter::shadow_rays);
    const RayStart start = ray_start(hit.p, hit.ng, light - hit.p, settings.offset);
    if (settings.query == ShadowQuery::closest_hit)
        return occluded_by_closest_hit(scene, start.origin, light, start.t_min);
    return scene.accelerator ? occluded_by_accelerator(scene, start.origin, light, start.t_min)
                             : occluded(scene, start.origin, light, start.t_min);
}

}  // namespace rt
