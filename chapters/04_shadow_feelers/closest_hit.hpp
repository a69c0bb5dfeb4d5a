// The slides' QueryScene for chapter 04's scene (chapter 01 taught it; here it is given), and the
// hit point a new ray can leave from.
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
// what it should shadow.
constexpr ShapeTests lit_tests{SphereTest::precise, TriangleTest::watertight};

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

// The triangle's unit face normal, (b - a) x (c - a) made unit: the geometric normal, the one a ray
// leaving the surface must be offset along.
inline vec3 face_normal(const Triangle& tri)
{
    return glm::normalize(glm::cross(tri.b - tri.a, tri.c - tri.a));
}

// The nearest hit over all spheres, triangles and cones with t strictly inside `range`, its point on
// the surface and its geometric normal (the sphere's and the cone's outward one, a triangle's face
// normal). With `one_sided`, triangle k with one_sided[k] set is seen from its front only: a ray
// that meets its back passes through (the classic NFF rules' opaque polygons, classic.hpp).
inline std::optional<Hit> closest_hit(const Ray& ray, const LitScene& scene, Interval range,
                                      const std::vector<bool>* one_sided = nullptr)
{
    int nearest = -1;
    TriangleHit<float> nearest_triangle{};
    for (int k = 0; k < static_cast<int>(scene.spheres.size()); ++k)
        if (const std::optional<float> t = hit_sphere(ray, scene.spheres[k], range, lit_tests.sphere)) {
            range.max = *t;  // later objects count only when nearer
            nearest = k;
        }
    for (int k = 0; k < static_cast<int>(scene.triangles.size()); ++k)
        if (const std::optional<TriangleHit<float>> hit = hit_triangle(ray, scene.triangles[k], range, lit_tests.triangle)) {
            if (one_sided && (*one_sided)[k] && glm::dot(face_normal(scene.triangles[k]), ray.dir) > 0.0f)
                continue;  // its back
            range.max = hit->t;
            nearest = static_cast<int>(scene.spheres.size()) + k;
            nearest_triangle = *hit;
        }
    const int first_cone = static_cast<int>(scene.spheres.size() + scene.triangles.size());
    for (int k = 0; k < static_cast<int>(scene.cones.size()); ++k)
        if (const std::optional<float> t = hit_cone_counted(ray, scene.cones[k], range)) {
            range.max = *t;
            nearest = first_cone + k;
        }
    if (nearest < 0)
        return std::nullopt;
    if (scene.object_is_sphere(nearest)) {
        const Sphere& sphere = scene.spheres[nearest];
        const point3 p = sphere_surface_point(sphere, ray.at(range.max));
        return Hit{range.max, p, sphere_normal(sphere, p), nearest};
    }
    if (scene.object_is_cone(nearest)) {
        const Cone& cone = scene.cones[scene.cone_index(nearest)];
        const point3 p = cone_surface_point(cone, ray.at(range.max));
        return Hit{range.max, p, cone_normal(cone, p), nearest};
    }
    const Triangle& tri = scene.triangles[scene.triangle_index(nearest)];
    return Hit{range.max, triangle_surface_point(tri, nearest_triangle), face_normal(tri), nearest};
}

}  // namespace rt
