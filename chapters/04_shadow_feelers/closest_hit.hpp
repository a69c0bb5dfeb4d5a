// The slides' QueryScene for chapter 04's scene (chapter 01 taught it; here it is given), and the
// hit point a new ray can leave from. The query goes to the scene's accelerator (scene_query.hpp):
// brute force in chapters 04-06, a grid or a hierarchy from chapter 07 on, with the same answers.
//
// A ray that leaves a hit point (a shadow feeler here; reflected and refracted rays in chapter 03)
// needs that point as exactly on the surface as float allows: the robust offset of EXERCISE 04.3
// moves it by a few hundred units in the last place, which is only enough when its error is a few
// units in the last place of its own coordinates. ray.at(t) is not: t carries the intersection
// test's relative error (up to a few 1e-6 of the distance travelled, chapter 02's table), and a
// point computed from an origin far away inherits that origin's rounding. So the point is computed
// from the surface itself, as Wachter and Binder (Ray Tracing Gems ch. 6) and pbrt-v4 do: from the
// barycentric weights on a triangle, and projected onto the sphere for a sphere.
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

// The point of the sphere nearest p, which lies within rounding of the sphere (pbrt-v4's
// reprojection, `Sphere::BasicIntersect`).
inline point3 sphere_surface_point(const Sphere& sphere, const point3& p)
{
    return sphere.centre + sphere.radius * glm::normalize(p - sphere.centre);
}

// The hit point as the weighted sum of the corners: its error is a few ulps of the corners, the
// form whose error Wachter and Binder's offset is sized for.
inline point3 triangle_surface_point(const Triangle& tri, const TriangleHit<float>& hit)
{
    const float alpha = 1.0f - hit.beta - hit.gamma;
    return alpha * tri.a + hit.beta * tri.b + hit.gamma * tri.c;
}

// The nearest hit over all spheres, triangles and cones with t strictly inside `range`, its point on
// the surface and its normals: the sphere's and the cone's outward one, a triangle's face normal,
// and for a smooth patch its corner normals interpolated as the shading normal n (ng stays the
// face's). With `one_sided`, triangle k with one_sided[k] set is seen from its front only: a ray
// that meets its back passes through (the classic NFF rules' opaque polygons, classic.hpp).
inline std::optional<Hit> closest_hit(const Ray& ray, const LitScene& scene, Interval range,
                                      const std::vector<bool>* one_sided = nullptr)
{
    ObjectHit h;
    if (!query_of(scene).closest(ray, range, objects_of(scene, lit_tests, one_sided), h))
        return std::nullopt;
    const ObjectRef o = object_ref(scene, h.object);
    switch (o.kind) {
    case ObjectKind::sphere: {
        const Sphere& sphere = scene.spheres[o.index];
        const point3 p = sphere_surface_point(sphere, ray.at(h.t));
        return Hit{h.t, p, sphere_normal(sphere, p), h.object};
    }
    case ObjectKind::triangle: {
        const Triangle& tri = scene.triangles[o.index];
        const TriangleHit<float> on{h.t, h.beta, h.gamma};
        const vec3 ng = face_normal(tri);
        const CornerNormals* smooth = scene.smooth_normals(o.index);
        return Hit{h.t, triangle_surface_point(tri, on), smooth ? interpolated_normal(*smooth, on) : ng, h.object, ng};
    }
    case ObjectKind::cone:
        break;
    }
    const ConeSurfacePoint on = cone_surface(scene.cones[o.index], ray.at(h.t));
    return Hit{h.t, on.p, on.n, h.object};
}

}  // namespace rt
