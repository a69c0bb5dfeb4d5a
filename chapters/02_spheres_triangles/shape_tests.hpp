// Which of chapter 02's intersection tests answer a query, and the counted calls the queries make:
// every test is one increment of the intersection_tests counter, the cost the acceleration
// chapters (07-10) set out to cut. With them, the watertight test's own error bound, which its
// bounded form (chapter 04 on) asks.
#pragma once

#include "02_spheres_triangles/02_spheres_triangles.hpp"
#include "02_spheres_triangles/cone.hpp"
#include "02_spheres_triangles/shapes.hpp"
#include "common/ray.hpp"
#include "common/stats.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace rt {

enum class SphereTest { slide, precise };
// watertight_bounded is the watertight test refusing a hit within its own rounding of t = 0, where
// double cannot tell it from the origin either (the bound below): chapter 04 on, where rays leave
// surfaces.
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

// How far the watertight test's t (EXERCISE 02.5) can be from the true distance, from float's
// rounding alone: a conservative bound in the manner of pbrt-v3 (Pharr, Jakob and Humphreys,
// "Physically Based Rendering", 3rd ed., sec. 3.9.6, "Robust Triangle Intersections"). Chapter 04
// refuses any hit nearer than this bound that double cannot place in front of the ray either
// (TriangleTest::watertight_bounded, below): a ray leaving a triangle then never finds
// that triangle again, however large it is or far from the origin (chapter 04's lesson, "Where the
// robust offset stops, and the test's own bound").
//
// The test's t is sum(e_i z_i) / det, where the z_i are the corners' heights along the ray and the
// e_i the edge functions of the corners sheared into the ray's frame. Each step adds a few
// roundings, each at most gamma(n) = n u / (1 - n u) (u = 2^-24) of the magnitudes it combines; the
// magnitudes are those of the corners relative to the ray's origin, so a triangle 1e5 across
// carries errors of 1e5 u whatever the ray's own length.

namespace watertight_detail {

// pbrt's gamma(n): the relative error of n roundings in a row of T, whose unit roundoff is half
// its epsilon (2^-24 for float, 2^-53 for double).
template <class T>
constexpr double gamma(int n)
{
    constexpr double u = std::numeric_limits<T>::epsilon() / 2.0;
    return (n * u) / (1.0 - n * u);
}

template <class T>
double max3(T a, T b, T c)
{
    return std::max(a, std::max(b, c));
}

// The bound from the magnitudes of the test's steps (watertight_t_error, below), for a test in T,
// combined in N: double for one triangle, and four lanes of float for the wide tree's blocks
// (chapter 10's lane_bounds.hpp, which scales the result up by its own rounding). Every term is a
// sum of products of magnitudes, so one formula serves both.
template <class T, class N>
N t_error(N max_x, N max_y, N max_z, N max_zt, N max_e, N abs_det)
{
    // Each corner minus the origin (1 rounding), the shear's S (1), its product (1) and difference
    // (1): gamma(5) of the x and z they combine (|S| <= 1, so |S z| <= |z|). The scaled height:
    // the difference, Sz and the product, gamma(3).
    const N delta_x = N(gamma<T>(5)) * (max_x + N(2.0) * max_z);
    const N delta_y = N(gamma<T>(5)) * (max_y + N(2.0) * max_z);
    const N delta_z = N(gamma<T>(3)) * max_zt;
    // An edge function x0 y1 - y0 x1: two products and a difference of inputs with those errors.
    const N delta_e = N(2.0) * (N(gamma<T>(2)) * max_x * max_y + delta_y * max_x + delta_x * max_y);
    // t det = sum(e_i z_i): three products and two sums of errored terms; then divided by det.
    return N(3.0) * (N(gamma<T>(3)) * max_e * max_zt + delta_e * max_zt + delta_z * max_e) / abs_det;
}

}  // namespace watertight_detail

// The bound on |t - true t| for `ray` meeting `tri`, in the ray's lengths; 0 for a triangle the
// ray is parallel to (the test finds no hit there to refuse). The magnitudes are combined in double,
// where the products of a tiny scene's (1e-15 across: 1e-45 and below) do not underflow to 0.
template <class T>
T watertight_t_error(const BasicRay<T>& ray, const BasicTriangle<T>& tri)
{
    using std::abs;
    using watertight_detail::gamma;
    using watertight_detail::max3;
    // The test's own frame (EXERCISE 02.5, steps 1-3): kz the ray's longest axis.
    const vec3_t<T> ad = glm::abs(ray.dir);
    const int kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    const int kx = (kz + 1) % 3, ky = (kx + 1) % 3;  // the bound is the same for either order
    if (ray.dir[kz] == T(0))
        return T(0);
    const T Sx = ray.dir[kx] / ray.dir[kz], Sy = ray.dir[ky] / ray.dir[kz], Sz = T(1) / ray.dir[kz];
    const vec3_t<T> A = tri.a - ray.origin, B = tri.b - ray.origin, C = tri.c - ray.origin;
    const T Ax = A[kx] - Sx * A[kz], Ay = A[ky] - Sy * A[kz];
    const T Bx = B[kx] - Sx * B[kz], By = B[ky] - Sy * B[kz];
    const T Cx = C[kx] - Sx * C[kz], Cy = C[ky] - Sy * C[kz];
    T U = cross_2d(Cx, Cy, Bx, By), V = cross_2d(Ax, Ay, Cx, Cy), W = cross_2d(Bx, By, Ax, Ay);
    if (U == T(0) || V == T(0) || W == T(0)) {
        // 02.5's fallback, followed here too: the test divides by the det of the edge functions
        // recomputed in double. Without it, a nearly collinear triangle whose float edge functions
        // cancel to det = 0 got a bound of 0 while 02.5 hit it at a t that is all rounding (a ray
        // leaving the triangle's own plane found it again 1e-8 to 3e-8 along).
        U = static_cast<T>(cross_2d<double>(Cx, Cy, Bx, By));
        V = static_cast<T>(cross_2d<double>(Ax, Ay, Cx, Cy));
        W = static_cast<T>(cross_2d<double>(Bx, By, Ax, Ay));
    }
    const T det = U + V + W;
    if (!(det != T(0)))
        return T(0);

    // The magnitudes each step combines: sheared x and y, heights along the ray (scaled by Sz, as
    // t is, and unscaled, as the shear multiplies them), and the edge functions.
    const double max_x = max3(abs(Ax), abs(Bx), abs(Cx));
    const double max_y = max3(abs(Ay), abs(By), abs(Cy));
    const double max_z = max3(abs(A[kz]), abs(B[kz]), abs(C[kz]));
    const double max_zt = abs(double(Sz)) * max_z;
    const double max_e = max3(abs(U), abs(V), abs(W));
    return static_cast<T>(watertight_detail::t_error<T>(max_x, max_y, max_z, max_zt, max_e, abs(double(det))));
}

// Where the float bound cannot decide (a hit nearer than the test's own rounding of t, which grows
// with the corners' distance from the origin: a floor 1e7 across seen from 1 above it), the test is
// taken again in double, whose rounding is 2^29 times finer. Its hit is certainly in front of the
// ray when it lies beyond both its own bound and the slab the origin's rounding leaves across the
// plane; nearer, it is the surface the ray leaves, or nothing that can be told from it. The hit goes
// to `out` as float, as the float test gives it. No range is asked: the caller applies its range to
// this answer (bounded_answer). Rare, so kept out of the callers' loops, and answered through a
// reference (the GCC 12 stall that shape_tests.hpp's hit_triangle_bounded describes).
#if defined(__GNUC__)
[[gnu::cold, gnu::noinline]]
#endif
inline bool hit_triangle_decided_in_double(const Ray& ray, const Triangle& tri, TriangleHit<float>& out)
{
    const BasicRay<double> r{glm::dvec3(ray.origin), glm::dvec3(ray.dir)};
    const BasicTriangle<double> t{glm::dvec3(tri.a), glm::dvec3(tri.b), glm::dvec3(tri.c)};
    const std::optional<TriangleHit<double>> hit =
        hit_triangle_watertight(r, t, BasicInterval<double>{0.0, std::numeric_limits<double>::infinity()});
    if (!hit)
        return false;
    // The origin's own rounding, where it was computed (a point moved off a surface): origin_ulps
    // float steps of each coordinate. Only the part along the plane's normal moves the origin across
    // the plane: a step of x moves it by n_x times that step. So an eye 1 above a floor at y = 0 is
    // 1 from it whatever its x, 4e6 or 0; sized on the largest coordinate instead, the slab was 1.9
    // there and refused the floor. The distance across the plane is t times the rate the ray
    // approaches it.
    constexpr double origin_ulps = 4.0;
    const glm::dvec3 n = glm::normalize(glm::cross(t.b - t.a, t.c - t.a));
    const double approach = std::abs(glm::dot(n, r.dir));
    const double slab = origin_ulps * std::numeric_limits<float>::epsilon() * glm::dot(glm::abs(n), glm::abs(r.origin));
    if (!(hit->t > watertight_t_error(r, t)) || !(hit->t * approach > slab))
        return false;
    out = {static_cast<float>(hit->t), static_cast<float>(hit->beta), static_cast<float>(hit->gamma)};
    return true;
}

// Where the bound on a float t exceeds coarse_t of the t itself, the hit stands (the float test's
// watertight decision is kept: asking double whether a ray through a shared vertex hits would
// decide one neighbour in double and the other in float, and let the ray slip between them), but
// its t is taken again in double, where the ray meets the triangle's plane. On a triangle far larger
// than its distance (a floor 1e8 across seen from 772 away) the float t was off by up to its bound
// (1.6 there), which decided the order of surfaces that close (tiny triangles lying on the floor
// vanished under it). 2^-20, a few times the rounding of an ordinary triangle's t, so the plane is
// asked for only where the corners are far larger than the distance.
constexpr float coarse_t = 0x1p-20f;

// The t at which `ray` meets the plane of `tri`, in double from the float numbers: off by a few
// 2^-53 of the magnitudes it combines.
inline double plane_t(const Ray& ray, const Triangle& tri)
{
    const glm::dvec3 a(tri.a), o(ray.origin), d(ray.dir);
    const glm::dvec3 n = glm::cross(glm::dvec3(tri.b) - a, glm::dvec3(tri.c) - a);
    return glm::dot(n, a - o) / glm::dot(n, d);
}

// bounded_answer's answer (below) for a hit beyond the bound: the hit, its t taken again on the
// plane where the bound is coarse beside it (`coarse`: bound > coarse_t * hit.t). A step of its own
// so that a caller that tells both conditions apart another way (chapter 10's wide tree, four lanes
// at once) asks nothing more of the triangle.
inline void answer_beyond_bound(const Ray& ray, const Triangle& tri, const TriangleHit<float>& hit, bool coarse,
                                TriangleHit<float>& out)
{
    out = hit;
    if (coarse) {
        const double t = plane_t(ray, tri);
        if (t > 0.0 && t < std::numeric_limits<double>::infinity())
            out.t = static_cast<float>(t);
    }
}

// The bounded test's answer for a hit the float test found anywhere along the ray's line, behind
// its origin too: its own t where that lies beyond the bound (the plane's t in double where the
// bound is coarse beside it); nothing where it lies more than the bound behind; in between,
// double's decision. A float t of -0 or a little below can belong to a surface certainly in front
// (a floor 1e9 across seen from 1e-3 above: its t rounds by more than the eye's height), so the
// band is asked around 0 on both sides. The answer depends on the ray and the triangle alone,
// never on a range: a query applies its range to the answer, not to the float t, or two copies of
// one triangle asked in two ranges (the tie rule, closer_than) could answer differently, the float
// t outside the nearer range and double's t inside it.
inline bool bounded_answer(const Ray& ray, const Triangle& tri, const TriangleHit<float>& hit, TriangleHit<float>& out)
{
    const float bound = watertight_t_error(ray, tri);
    if (hit.t > bound) {
        answer_beyond_bound(ray, tri, hit, bound > coarse_t * hit.t, out);
        return true;
    }
    if (hit.t < -bound)
        return false;
    return hit_triangle_decided_in_double(ray, tri, out);
}

// The watertight test refusing a hit within its rounding of the ray's origin, its own surface or
// nothing that can be told from it, unless double finds it certainly in front (above).
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
