// A hit point moved onto the surface it hit, for a ray that leaves it (chapter 04 on): ray.at(t)
// carries the intersection test's relative error in t (a few 1e-6 of the distance travelled,
// chapter 02's table) and the rounding of an origin far away, while the robust offset of EXERCISE
// 04.3 is sized for a point a few units in the last place from the surface. So the point is
// computed from the surface itself, as Wachter and Binder (Ray Tracing Gems ch. 6) and pbrt-v4 do.
// The cone's is cone_surface (cone.hpp).
#pragma once

#include "02_spheres_triangles/shapes.hpp"

#include <glm/geometric.hpp>

namespace rt {

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

}  // namespace rt
