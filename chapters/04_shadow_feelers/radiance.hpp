// Chapter 04's path of one ray, top to bottom in the order it runs: the render asks each pixel's
// radiance; radiance asks for the closest hit and shades it (your shade, EXERCISE 04.4); shading
// asks, once per light, whether a shadow feeler is blocked (light_blocked, at the end). Every later
// chapter that renders a lit scene (a generated figure or a scene file, through any accelerator)
// shades its rays here; chapter 03's reflected and refracted rays leave the same hit points.
#pragma once

#include "01_ray_casting/01_ray_casting.hpp"
#include "02_spheres_triangles/closest_hit.hpp"
#include "04_shadow_feelers/04_shadow_feelers.hpp"
#include "04_shadow_feelers/nff_scene.hpp"
#include "04_shadow_feelers/scene.hpp"
#include "common/float_reach.hpp"
#include "common/heatmap.hpp"
#include "common/hit.hpp"
#include "common/render.hpp"
#include "common/scene_file.hpp"
#include "common/stats.hpp"

#include <optional>
#include <vector>

namespace rt {

namespace ch04 {
inline color radiance(const LitScene& scene, const Ray& ray, const FeelerSettings& feelers);
}
inline std::optional<Hit> closest_hit(const Ray& ray, const LitScene& scene, Interval range,
                                      const std::vector<bool>* one_sided = nullptr);

// 1. The render of a scene file (chapter 04's shading, with feelers), through whatever accelerator
// the scene holds: each pixel's sample is the radiance along its eye ray; with `cost`, the render
// also keeps what each pixel cost.
inline Image render_lit(const SceneRender& file, const LitScene& scene, const FeelerSettings& feelers,
                        CostMap* cost = nullptr)
{
    const auto radiance = [&](float x, float y, Rng&) {
        return ch04::radiance(scene, file.eye_ray(primary_ray(file.camera, x, y)), feelers);
    };
    return render(file.settings, radiance, nullptr, cost);
}

// 2. The slides' Render(ray): the nearest object's colour, or the background. A primary ray starts at
// the eye, on no surface, so it accepts any t > 0.
inline color ch04::radiance(const LitScene& scene, const Ray& ray, const FeelerSettings& feelers)
{
    count(Counter::primary_rays);
    const std::optional<Hit> hit = closest_hit(ray, scene, Interval{0.0f, infinity});
    return hit ? shade(scene, ray, *hit, feelers) : scene.background;
}

// 3. The slides' QueryScene (chapter 01 taught it; here it is given), and the hit point a new ray can
// leave from. The query goes to the scene's accelerator (scene_query.hpp): brute force in chapters
// 04-06, a grid or a hierarchy from chapter 07 on, with the same answers.
//
// A ray that leaves a hit point (a shadow feeler here; reflected and refracted rays in chapter 03)
// needs that point as exactly on the surface as float allows, for the robust offset of EXERCISE
// 04.3 to be enough: the object list's `surface` computes it from the surface itself, not from
// ray.at(t) (chapter 02's objects.hpp says why).
//
// The tests this chapter's queries ask (chapter 02's): the precise sphere (02.2), and the
// watertight triangle (02.5), so no feeler slips between the triangles of a closed mesh and lights
// what it should shadow, refusing any hit within its own rounding of the ray's origin, so no ray
// leaving a triangle finds it again (README.md, "Where the robust offset stops, and the test's own
// bound").
constexpr ShapeTests lit_tests{SphereTest::precise, TriangleTest::watertight_bounded};

// The accelerator that answers the scene's queries: the scene's own (chapter 07 on), or brute force.
inline const Accelerator& query_of(const LitScene& scene)
{
    return scene.accelerator ? *scene.accelerator : brute_force();
}

// The nearest hit over all spheres, triangles and cones with t strictly inside `range`, its point on
// the surface and its normals: the sphere's and the cone's outward one, a triangle's face normal,
// and for a smooth patch its corner normals interpolated as the shading normal n (ng stays the
// face's). With `one_sided`, triangle k with one_sided[k] set is seen from its front only: a ray
// that meets its back passes through (the classic NFF rules' opaque polygons, classic.hpp).
inline std::optional<Hit> closest_hit(const Ray& ray, const LitScene& scene, Interval range,
                                      const std::vector<bool>* one_sided)
{
    const Objects objects = objects_of(scene, lit_tests, one_sided);
    ObjectHit h;
    if (!query_of(scene).closest(ray, range, objects, h))
        return std::nullopt;
    const OnSurface on = objects.surface(ray, h);
    const ObjectRef o = objects.ref(h.object);
    const CornerNormals* smooth = o.kind == ObjectKind::triangle ? scene.smooth_normals(o.index) : nullptr;
    if (smooth)
        return Hit{h.t, on.p, interpolated_normal(*smooth, {h.t, h.beta, h.gamma}), h.object, on.n};
    return Hit{h.t, on.p, on.n, h.object};
}

// 4. Your shade (EXERCISE 04.4) lights the hit: the ambient term, then each light it can see. One
// shadow feeler a light decides that, sent the way FeelerSettings say: where it starts (the four
// offsets the chapter measures) and which query answers it; the program's tables measure both knobs.

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

// 5. Is the light at `light` hidden from the hit point? One shadow feeler, counted, from the hit's
// point and geometric normal, started and answered as `settings` say (ShadowQuery::off sends none:
// every light is seen). An any-hit feeler is your occluded (04.2) until the scene has an
// accelerator (chapter 07 on), whose any-hit query then answers it. Back in your shade, each light
// not blocked adds its local_shading (04.1).
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

// The feelers your shade sends from the hit of `ray` (EXERCISE 04.4): one toward each light on the
// side the eye sees, from the robust offset (04.3); visit(light, origin) for each. For programs that
// replay shade's feelers to measure them (chapter 04's per-feeler table, chapter 08's ray sets).
template <class Visit>
void for_each_feeler(const LitScene& scene, const Ray& ray, const Hit& hit, const Visit& visit)
{
    const vec3 n = glm::dot(hit.n, ray.dir) > 0.0f ? -hit.n : hit.n;
    for (const PointLight& light : scene.lights)
        if (glm::dot(n, light.position - hit.p) > 0.0f)
            visit(light.position, offset_ray_origin(hit.p, hit.ng, light.position - hit.p));
}

}  // namespace rt
