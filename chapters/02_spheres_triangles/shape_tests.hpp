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
// watertight_bounded is the watertight test refusing a hit within its own rounding of t = 0, where
// double cannot tell it from the origin either (watertight_error.hpp): chapter 04 on, where rays
// leave surfaces.
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

// The watertight test refusing a hit within its rounding of the ray's origin, its own surface or
// nothing that can be told from it, unless double finds it certainly in front (watertight_error.hpp).
// The float test is asked along the whole line, and the range applied to the answer (bounded_answer:
// a hit within the bound of t = 0, on either side, is answered by double's t, which may lie inside
// the range when the float t does not). The hit is returned as a new optional built from its
// fields: returning the test's optional itself (or nullopt) made GCC 12 copy it through the stack,
// 16 bytes read back right after two 8-byte writes, a stall on every test, hit or not (chapter 04's
// lesson, "Where the robust offset stops, and the test's own bound").
inline std::optional<TriangleHit<float>> hit_triangle_bounded(const Ray& ray, const Triangle& tri, Interval range)
{
    const std::optional<TriangleHit<float>> hit = hit_triangle_watertight(ray, tri, Interval{-infinity, infinity});
    TriangleHit<float> answer;
    if (!hit || !bounded_answer(ray, tri, *hit, answer) || !range.surrounds(answer.t))
        return std::nullopt;
    return TriangleHit<float>{answer.t, answer.beta, answer.gamma};
}

// One counted triangle test, its hit written into `hit`: true when the ray hits. Each test's
// optional is opened where it is returned (in registers): a switch whose cases all return one
// optional made GCC 12 merge them in memory and read the 16 bytes back right after narrower writes,
// a stall on every test that cost the BVH (chapter 10) about a tenth of its time.
inline bool hit_triangle(const Ray& ray, const Triangle& tri, Interval range, TriangleTest test,
                         TriangleHit<float>& hit)
{
    count(Counter::intersection_tests);
    const auto keep = [&hit](const std::optional<TriangleHit<float>>& h) {
        if (h)
            hit = *h;
        return h.has_value();
    };
    switch (test) {
    case TriangleTest::slide:
        return keep(hit_triangle_slide(ray, tri, range));
    case TriangleTest::moller_trumbore:
        return keep(hit_triangle_moller_trumbore(ray, tri, range));
    case TriangleTest::watertight:
        return keep(hit_triangle_watertight(ray, tri, range));
    case TriangleTest::watertight_bounded:
        return keep(hit_triangle_bounded(ray, tri, range));
    }
    return false;  // not reached: the switch names every test
}

inline std::optional<TriangleHit<float>> hit_triangle(const Ray& ray, const Triangle& tri, Interval range,
                                                      TriangleTest test)
{
    TriangleHit<float> hit;
    if (hit_triangle(ray, tri, range, test, hit))
        return hit;
    return std::nullopt;
}

inline std::optional<float> hit_cone_counted(const Ray& ray, const Cone& cone, Interval range)
{
    count(Counter::intersection_tests);
    return hit_cone(ray, cone, range);
}

// The triangle's unit face normal, (b - a) x (c - a) made unit: the geometric normal, the one a ray
// leaving the surface must be offset along, and the side a one-sided triangle is seen from. In
// double: the cross product's squared length is the fourth power of the triangle's size, past
// float's 3.4e38 for a triangle 1e10 across (its normal came out 0, and its floor was unlit).
inline vec3 face_normal(const Triangle& tri)
{
    const dvec3 a(tri.a);
    return vec3(glm::normalize(glm::cross(dvec3(tri.b) - a, dvec3(tri.c) - a)));
}

}  // namespace rt
