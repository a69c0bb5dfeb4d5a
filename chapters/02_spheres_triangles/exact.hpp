// The exact answers the chapter measures its tests against: the same shapes and rays, solved in
// long double (a 64-bit significand on x86-64, 11 bits more than double and 40 more than float)
// and by formulas that do not cancel. The stability tests and the program's trade table both judge
// float and double answers by these: a float result is judged against an exact one, never against
// another float.
//
// Where long double is only double (MSVC, Apple's ARM), the references for float stay far more
// precise than what they judge, but the table's double rows then measure double against itself.
#pragma once

#include "02_spheres_triangles/shapes.hpp"
#include "common/interval.hpp"
#include "common/ray.hpp"

#include <cmath>
#include <initializer_list>

namespace rt::exact {

using Real = long double;
using rvec3 = vec3_t<Real>;

struct Answer {
    bool hit = false;
    Real t = 0;
};

template <class T>
rvec3 widen(const vec3_t<T>& v)
{
    return rvec3(v);
}

// The nearer of the roots inside the range. The ray need not be unit: the roots are solved for t
// along the given direction, which is what a float direction a few ulps off unit length really
// describes. The discriminant comes from the perpendicular distance, so it does not cancel.
template <class T>
Answer sphere(const BasicRay<T>& ray, const BasicSphere<T>& sphere, BasicInterval<T> range)
{
    const rvec3 f = widen(ray.origin) - widen(sphere.centre), v = widen(ray.dir);
    const Real vv = glm::dot(v, v);
    const Real along = glm::dot(f, v) / vv;  // the foot of the perpendicular from the centre
    const rvec3 perp = f - along * v;
    const Real r = sphere.radius;
    const Real disc = r * r - glm::dot(perp, perp);
    if (!(disc > 0))
        return {};
    const Real half_chord = std::sqrt(disc / vv);
    for (const Real t : {-along - half_chord, -along + half_chord})
        if (Real(range.min) < t && t < Real(range.max))
            return {true, t};
    return {};
}

// Whether the ray meets the triangle inside the range (edges included), and where it meets the
// triangle's plane: t is that even when the point lies outside, so a test's t can be judged on
// any hit. Barycentric coordinates from the sub-triangles' areas against the whole.
template <class T>
Answer triangle(const BasicRay<T>& ray, const BasicTriangle<T>& tri, BasicInterval<T> range)
{
    const rvec3 a = widen(tri.a), e1 = widen(tri.b) - a, e2 = widen(tri.c) - a;
    const rvec3 u = widen(ray.origin), v = widen(ray.dir);
    const rvec3 n = glm::cross(e1, e2);
    const Real nv = glm::dot(n, v), nn = glm::dot(n, n);
    if (nv == 0 || nn == 0)
        return {};
    const Real t = glm::dot(n, a - u) / nv;
    const rvec3 p = u + t * v;
    const Real beta = glm::dot(glm::cross(p - a, e2), n) / nn;
    const Real gamma = glm::dot(glm::cross(e1, p - a), n) / nn;
    const bool inside = beta >= 0 && gamma >= 0 && beta + gamma <= 1;
    if (!inside || !(Real(range.min) < t && t < Real(range.max)))
        return {false, t};
    return {true, t};
}

}  // namespace rt::exact
