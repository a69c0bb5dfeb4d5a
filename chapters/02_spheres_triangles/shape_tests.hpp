// Which of chapter 02's intersection tests answer a query, and the counted calls the queries make:
// every test is one increment of the intersection_tests counter, the cost the acceleration
// chapters (07-10) set out to cut.
#pragma once

#include "02_spheres_triangles/02_spheres_triangles.hpp"
#include "02_spheres_triangles/cone.hpp"
#include "02_spheres_triangles/watertight_error.hpp"
#include "common/stats.hpp"

#include <optional>

namespace rt {

enum class SphereTest { slide, precise };
// watertight_bounded is the watertight test refusing a hit within its own rounding of t = 0
// (watertight_error.hpp): chapter 04 on, where rays leave surfaces.
enum class TriangleTest { slide, moller_trumbore, watertight, watertight_bounded };

struct ShapeTests {
    SphereTest sphere = SphereTest::precise;
    TriangleTest triangle = TriangleTest::moller_trumbore;
};

inline std::optional<float> hit_sphere(const Ray& ray, const Sphere& sphere, Interval range, SphereTest test)
{
    count(Counter::intersection_tests);
    return test == SphereTest::slide ? hit_sphere_slide(ray, sphere, range) : hit_sphere_precise(ray, sphere, range);
}

// The watertight test refusing a hit within its rounding of the ray's origin: its own surface, or
// nothing that can be told from it. The hit is returned as a new optional built from its fields:
// returning the test's optional itself (or nullopt) made GCC 12 copy it through the stack, 16 bytes
// read back right after two 8-byte writes, a stall on every test, hit or not: chapter 04's figure
// took 18% longer that way, 3% longer this way.
inline std::optional<TriangleHit<float>> hit_triangle_bounded(const Ray& ray, const Triangle& tri, Interval range)
{
    const std::optional<TriangleHit<float>> hit = hit_triangle_watertight(ray, tri, range);
    if (hit && hit->t > watertight_t_error(ray, tri))
        return TriangleHit<float>{hit->t, hit->beta, hit->gamma};
    return std::nullopt;
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
    case TriangleTest::watertight_bounded:
        return hit_triangle_bounded(ray, tri, range);
    }
    return std::nullopt;  // not reached: the switch names every test
}

inline std::optional<float> hit_cone_counted(const Ray& ray, const Cone& cone, Interval range)
{
    count(Counter::intersection_tests);
    return hit_cone(ray, cone, range);
}

// The triangle's unit face normal, (b - a) x (c - a) made unit: the geometric normal, the one a ray
// leaving the surface must be offset along, and the side a one-sided triangle is seen from.
inline vec3 face_normal(const Triangle& tri)
{
    return glm::normalize(glm::cross(tri.b - tri.a, tri.c - tri.a));
}

}  // namespace rt
