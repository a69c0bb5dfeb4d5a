// A hit point moved onto the surface it hit, for a ray that leaves it (chapter 04 on): ray.at(t)
// carries the intersection test's relative error in t (a few 1e-6 of the distance travelled,
// chapter 02's table) and the rounding of an origin far away, while the robust offset of EXERCISE
// 04.3 is sized for a point a few units in the last place from the surface. So the point is
// computed from the surface itself, as Wachter and Binder (Ray Tracing Gems ch. 6) and pbrt-v4 do.
// The cone's is cone_surface (cone.hpp).
//
// The bound each point carries, by how it is computed: in double from the float inputs, which are
// exact, and rounded to float once at the end, so it lies within half a float step of each of its
// own coordinates from the surface, plus double's rounding of the inputs it combined (2^-53 of
// their magnitudes a step, four steps: below half a float step of the point unless the inputs are
// 2^27 times larger than it, and 04.3 moves a coordinate below 1/32 by a fixed 2^-16 instead). That is the rounding the offset of EXERCISE 04.3 and the bounded triangle
// test's slab (watertight_error.hpp) are sized on: a few float steps of the point's own
// coordinates. pbrt-v4 instead carries the float sum's larger error with the point and offsets by
// it (sec. 6.8.6); a point that is accurate needs no such offset.
#pragma once

#include "02_spheres_triangles/shapes.hpp"

#include <glm/geometric.hpp>

namespace rt {

// The point of the sphere nearest p, which lies within rounding of the sphere (pbrt-v4's
// reprojection, `Sphere::BasicIntersect`). Worked out in double from the float centre and radius,
// which are exact, and rounded to float once, however far the centre is.
inline point3 sphere_surface_point(const Sphere& sphere, const point3& p)
{
    const dvec3 c(sphere.centre);
    return point3(c + double(sphere.radius) * glm::normalize(dvec3(p) - c));
}

// The hit point from the test's barycentrics, a + beta (b - a) + gamma (c - a): a point of the
// triangle's plane whatever beta and gamma are, so only the sum's rounding moves it off the plane.
// In float that rounding is a few float steps of the corners (pbrt-v4 sec. 6.8.5, gamma(7) times
// |alpha a| + |beta b| + |gamma c|): 0.01 for corners 1e5 from the origin, far more than the offset
// of EXERCISE 04.3 moves a point near the origin, and its feelers found the triangle again. So it
// is summed in double.
inline point3 triangle_surface_point(const Triangle& tri, const TriangleHit<float>& hit)
{
    const dvec3 a(tri.a);
    return point3(a + double(hit.beta) * (dvec3(tri.b) - a) + double(hit.gamma) * (dvec3(tri.c) - a));
}

// Where `ray` meets the plane of `tri`, in double from the float ray and corners, rounded once: the
// hit point a new ray leaves from. The barycentric sum above is as good as the test's beta and
// gamma, which carry the test's own rounding, a few float steps of the corners: on a floor 1e8
// across, the point slid 1.6 along a ray that met it 772 away, and the feelers' shadows moved with
// it (the scale families, tests/structures/scale_families.hpp). The plane's t in double is off by
// 2^-50 or so of the distances it combines, whatever the triangle's size.
inline point3 triangle_surface_point(const Triangle& tri, const Ray& ray)
{
    const dvec3 a(tri.a), o(ray.origin), d(ray.dir);
    const dvec3 n = glm::cross(dvec3(tri.b) - a, dvec3(tri.c) - a);
    const double t = glm::dot(n, a - o) / glm::dot(n, d);
    return point3(o + t * d);
}

}  // namespace rt
