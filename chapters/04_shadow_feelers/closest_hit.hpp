// The slides' QueryScene for chapter 04's scene (chapter 01 taught it; here it is given), and the
// hit point a new ray can leave from. The query goes to the scene's accelerator (scene_query.hpp):
// brute force in chapters 04-06, a grid or a hierarchy from chapter 07 on, with the same answers.
//
// A ray that leaves a hit point (a shadow feeler here; reflected and refracted rays in chapter 03)
// needs that point as exactly on the surface as float allows, for the robust offset of EXERCISE
// 04.3 to be enough: the object list's `surface` computes it from the surface itself, not from
// ray.at(t) (chapter 02's surface_point.hpp says why).
#pragma once

#include "02_spheres_triangles/closest_hit.hpp"
#include "04_shadow_feelers/scene.hpp"
#include "common/hit.hpp"

#include <optional>
#include <vector>

namespace rt {

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
                                      const std::vector<bool>* one_sided = nullptr)
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

}  // namespace rt
