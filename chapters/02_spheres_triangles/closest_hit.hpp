// The slides' QueryScene for chapter 02's scene (chapter 01 taught it; here it is given): every
// sphere and every triangle is tested with one of your intersection tests, every cone (from scene
// files) with the given one (cone.hpp), the nearest hit wins, and the hit's normal comes from
// your normals (EXERCISE 02.6).
//
// Which sphere and which triangle test answer is a choice (`ShapeTests`), so the program can
// render the figure with any of them; the kit's default is the precise sphere and Moller-Trumbore.
#pragma once

#include "02_spheres_triangles/02_spheres_triangles.hpp"
#include "02_spheres_triangles/cone.hpp"
#include "02_spheres_triangles/scene.hpp"
#include "common/hit.hpp"
#include "common/stats.hpp"

#include <optional>

namespace rt {

enum class SphereTest { slide, precise };
enum class TriangleTest { slide, moller_trumbore, watertight };

struct ShapeTests {
    SphereTest sphere = SphereTest::precise;
    TriangleTest triangle = TriangleTest::moller_trumbore;
};

inline std::optional<float> hit_sphere(const Ray& ray, const Sphere& sphere, Interval range, SphereTest test)
{
    count(Counter::intersection_tests);
    return test == SphereTest::slide ? hit_sphere_slide(ray, sphere, range) : hit_sphere_precise(ray, sphere, range);
}

inline std::optional<TriangleHit<float>> hit_triangle(const Ray& ray, const Triangle& tri, Interval range,
                                                      TriangleTest test)
{
    count(Counter::intersection_tests);
    switch (test) {
    case TriangleTest::slide:
        return hit_triangle_slide(ray, tri, range);
    case TriangleTest::moller_trumbore:
        return hit_triangle_moller_trumbore(ray, tri, range);
    case TriangleTest::watertight:
        return hit_triangle_watertight(ray, tri, range);
    }
    return std::nullopt;  // not reached: the switch names every test
}

inline std::optional<float> hit_cone_counted(const Ray& ray, const Cone& cone, Interval range)
{
    count(Counter::intersection_tests);
    return hit_cone(ray, cone, range);
}

// The nearest hit over all spheres, triangles and cones with t strictly inside `range`. Its normal
// is the sphere's, the triangle's corner normals interpolated at the hit, or the cone's; `object`
// counts the spheres first, then the triangles, then the cones (ShapeScene::object_is_sphere).
inline std::optional<Hit> closest_hit(const Ray& ray, const ShapeScene& scene, Interval range, ShapeTests tests = {})
{
    int nearest = -1;
    TriangleHit<float> nearest_triangle{};
    for (int k = 0; k < static_cast<int>(scene.spheres.size()); ++k)
        if (const std::optional<float> t = hit_sphere(ray, scene.spheres[k], range, tests.sphere)) {
            range.max = *t;  // later objects count only when nearer
            nearest = k;
        }
    for (int k = 0; k < static_cast<int>(scene.triangles.size()); ++k)
        if (const std::optional<TriangleHit<float>> hit = hit_triangle(ray, scene.triangles[k], range, tests.triangle)) {
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
    const point3 p = ray.at(range.max);
    if (scene.object_is_sphere(nearest))
        return Hit{range.max, p, sphere_normal(scene.spheres[nearest], p), nearest};
    if (scene.object_is_cone(nearest))
        return Hit{range.max, p, cone_normal(scene.cones[scene.cone_index(nearest)], p), nearest};
    const vec3 n = interpolated_normal(scene.corner_normals[scene.triangle_index(nearest)], nearest_triangle);
    return Hit{range.max, p, n, nearest};
}

}  // namespace rt
