// SOLUTION BEGIN
// Chapter 02, spheres and triangles: the reference solution.
//
// This file is also the source of exercises/02_spheres_triangles.cpp: the kit's cutter drops every
// block between SOLUTION BEGIN and SOLUTION END and keeps the STUB lines as code
// (`cmake --build <build> --target cut_exercises`; a test checks that the two agree).
// SOLUTION END
// STUB // Chapter 02, spheres and triangles: your exercises.
// STUB //
// STUB // Each function below states what to compute (not how); its contract is documented in
// STUB // chapters/02_spheres_triangles/02_spheres_triangles.hpp and the lesson in that folder's
// STUB // README.md. Each stub compiles and returns a harmless value, so the chapter's program always runs.
// STUB // Check your work with:  cmake --build --preset grade --target check_02
// STUB // Stuck? Hints in tiers you open one at a time: chapters/02_spheres_triangles/hints.md, or
// STUB // ./build/grade/hint 02.1 (tier 1, the idea), ./build/grade/hint 02.1 2 (the trap), ... 3 (the walk-through).
// STUB //
// STUB // The intersection tests are templates: write T where you would write float (T(0), T(1) for
// STUB // constants, vec3_t<T> for a vector). The last lines of the file compile them for float and double.
#include "02_spheres_triangles/02_spheres_triangles.hpp"
// STUB #include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

// SOLUTION BEGIN
#include <glm/gtc/type_ptr.hpp>  // glm::value_ptr: 02.5 reads each vector in the ray's frame
// SOLUTION END
#include <cmath>
#include <initializer_list>
#include <utility>

namespace rt {

template <class T>
std::optional<T> hit_sphere_slide(const BasicRay<T>& ray, const BasicSphere<T>& sphere, BasicInterval<T> range)
{
    // EXERCISE 02.1: the slide's geometric sphere test.
    // Return the nearest t strictly inside `range` where the ray meets the sphere, or nothing. A tangent
    // ray misses; a ray that starts inside (the case the slide leaves out) hits the far side. The
    // slide's E, V, O and r are the ray's origin and unit direction, the sphere's centre and radius.
    // Write T wherever you would write float. Lesson: "The sphere, as the slide tests it (EXERCISE 02.1)".
    // Stuck? hint 02.1 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    const vec3_t<T> EO = sphere.centre - ray.origin;
    const T e = glm::dot(EO, ray.dir);
    const T disc = sphere.radius * sphere.radius - (glm::dot(EO, EO) - e * e);
    // The slide's quick rejection: every ray that misses (and every tangent one) leaves here,
    // before the square root.
    if (disc <= 0)
        return std::nullopt;
    const T d = std::sqrt(disc);
    for (const T t : {e - d, e + d})
        if (range.surrounds(t))
            return t;
    return std::nullopt;
    // SOLUTION END
    // STUB return stub("02.1", std::nullopt);
}

template <class T>
std::optional<T> hit_sphere_precise(const BasicRay<T>& ray, const BasicSphere<T>& sphere, BasicInterval<T> range)
{
    // EXERCISE 02.2: the same sphere, without the cancellation (Ray Tracing Gems ch. 7).
    // The same answers as 02.1 (the nearest t strictly inside `range`, a tangent ray misses, a ray from
    // inside hits the far side), keeping their precision for distant, tiny and huge spheres: from 1
    // above a sphere of radius 1e4, t stays within 1e-6, which float arithmetic cannot reach.
    // DETAIL BEGIN: how, step by step (kept by an introductory course's handout, CONTRACTS=detailed)
    // No subtraction whose rounding float cannot afford: the discriminant from a vector, not from
    // the slide's difference of two squares, the two roots each by a stable form, and every step in
    // double whatever T is.
    // DETAIL END
    // Lesson: "Why the slide's sphere fails far away, and the fix (EXERCISE 02.2)".
    // Stuck? hint 02.2 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    // In double, f = E - O of two floats is exact and every later rounding is 2^-53: a ray from just
    // above a huge sphere keeps t to 1e-7 where float arithmetic lost it to 2e-3.
    const dvec3 f = dvec3(ray.origin) - dvec3(sphere.centre);
    const dvec3 V = dvec3(ray.dir);
    const double b = glm::dot(f, V);
    const dvec3 perp = f - b * V;  // from the centre to the ray's closest point
    const double r2 = double(sphere.radius) * double(sphere.radius);
    const double disc = r2 - glm::dot(perp, perp);
    if (disc <= 0)
        return std::nullopt;
    const double c = glm::dot(f, f) - r2;
    const double root = std::sqrt(disc);
    const double q = b >= 0 ? -b - root : -b + root;
    T near_t = static_cast<T>(c / q), far_t = static_cast<T>(q);
    if (near_t > far_t)
        std::swap(near_t, far_t);
    for (const T t : {near_t, far_t})
        if (range.surrounds(t))
            return t;
    return std::nullopt;
    // SOLUTION END
    // STUB return stub("02.2", std::nullopt);
}

template <class T>
std::optional<TriangleHit<T>> hit_triangle_slide(const BasicRay<T>& ray, const BasicTriangle<T>& tri,
                                                 BasicInterval<T> range)
{
    // EXERCISE 02.3: the slide's triangle test.
    // Return t strictly inside `range` where the ray meets the triangle, with the hit's barycentric
    // coordinates beta (the weight of tri.b) and gamma (of tri.c); edges and corners are inside, and
    // both faces count. Nothing for a ray parallel to the plane or a triangle without area, never a
    // NaN. ray.dir need not be unit length: t is then measured in its lengths.
    // Lesson: "The triangle, as the slide tests it (EXERCISE 02.3)".
    // Stuck? hint 02.3 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    const vec3_t<T> n = glm::cross(tri.b - tri.a, tri.b - tri.c);
    const T nv = glm::dot(n, ray.dir);
    if (nv == 0)
        return std::nullopt;
    const T t = glm::dot(n, tri.b - ray.origin) / nv;
    // Before the inside test: it is cheaper, and it rejects a t that overflowed to infinity.
    if (!range.surrounds(t))
        return std::nullopt;
    const vec3_t<T> p = ray.at(t);
    const T side_ab = glm::dot(glm::cross(tri.b - tri.a, p - tri.a), n);
    const T side_bc = glm::dot(glm::cross(tri.c - tri.b, p - tri.b), n);
    const T side_ca = glm::dot(glm::cross(tri.a - tri.c, p - tri.c), n);
    const bool same_sign = (side_ab >= 0 && side_bc >= 0 && side_ca >= 0) || (side_ab <= 0 && side_bc <= 0 && side_ca <= 0);
    const T sum = side_ab + side_bc + side_ca;
    // sum = 0 only when all three products underflow: no hit rather than 0 / 0.
    if (!same_sign || sum == 0)
        return std::nullopt;
    return TriangleHit<T>{t, side_ca / sum, side_ab / sum};
    // SOLUTION END
    // STUB return stub("02.3", std::nullopt);
}

template <class T>
std::optional<TriangleHit<T>> hit_triangle_moller_trumbore(const BasicRay<T>& ray, const BasicTriangle<T>& tri,
                                                           BasicInterval<T> range)
{
    // EXERCISE 02.4: Moller-Trumbore.
    // The same answers as 02.3 (t strictly inside `range`, beta and gamma, edges inside, both faces, any
    // non-zero ray.dir), found by solving for t, beta and gamma together and giving up as soon as one
    // of them shows a miss. No hit when the determinant is 0; a NaN must fail every test, never pass one.
    // Lesson: "Moller-Trumbore, "Shirley's better method" (EXERCISE 02.4)".
    // Stuck? hint 02.4 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    const vec3_t<T> e1 = tri.b - tri.a, e2 = tri.c - tri.a;
    const vec3_t<T> P = glm::cross(ray.dir, e2);
    const T det = glm::dot(e1, P);
    if (det == 0)
        return std::nullopt;
    const T inv_det = T(1) / det;
    const vec3_t<T> s = ray.origin - tri.a;
    const T beta = glm::dot(s, P) * inv_det;
    if (!(beta >= 0 && beta <= 1))
        return std::nullopt;
    const vec3_t<T> Q = glm::cross(s, e1);
    const T gamma = glm::dot(ray.dir, Q) * inv_det;
    if (!(gamma >= 0 && beta + gamma <= 1))
        return std::nullopt;
    const T t = glm::dot(e2, Q) * inv_det;
    if (!range.surrounds(t))
        return std::nullopt;
    return TriangleHit<T>{t, beta, gamma};
    // SOLUTION END
    // STUB return stub("02.4", std::nullopt);
}

template <class T>
std::optional<TriangleHit<T>> hit_triangle_watertight(const BasicRay<T>& ray, const BasicTriangle<T>& tri,
                                                      BasicInterval<T> range)
{
    // EXERCISE 02.5: the watertight test (advanced; Woop, Benthin and Wald, JCGT 2013).
    // The same answers as 02.3 (t strictly inside `range`, beta and gamma, edges inside, both faces, any
    // non-zero ray.dir), decided where the ray runs from the origin along +z, by three 2D edge functions
    // (the given cross_2d) that triangles sharing an edge compute from the same numbers, so that no ray
    // slips through a mesh. A triangle without area is never hit. An edge function that float rounds
    // to 0 is decided in double, and the grader checks t, beta and gamma to the bit (the contract).
    // Lesson: "Watertight (EXERCISE 02.5, advanced)".
    // Stuck? hint 02.5 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    const vec3_t<T> n = glm::cross(tri.b - tri.a, tri.c - tri.a);
    if (n.x == 0 && n.y == 0 && n.z == 0)
        return std::nullopt;

    const vec3_t<T> ad = glm::abs(ray.dir);
    const int kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (ray.dir[kz] < 0)
        std::swap(kx, ky);

    // Each vector's coordinates read in the order kx, ky, kz once. (glm's v[k] is a switch on k: with
    // k known only at run time, a branch per read, which the BVH of chapter 10 paid on every test.)
    const auto in_frame = [kx, ky, kz](const vec3_t<T>& v) {
        const T* c = glm::value_ptr(v);
        return vec3_t<T>(c[kx], c[ky], c[kz]);
    };
    const vec3_t<T> d = in_frame(ray.dir);
    const T Sx = d.x / d.z, Sy = d.y / d.z, Sz = T(1) / d.z;
    const vec3_t<T> A = in_frame(tri.a - ray.origin), B = in_frame(tri.b - ray.origin), C = in_frame(tri.c - ray.origin);
    const T Ax = A.x - Sx * A.z, Ay = A.y - Sy * A.z;
    const T Bx = B.x - Sx * B.z, By = B.y - Sy * B.z;
    const T Cx = C.x - Sx * C.z, Cy = C.y - Sy * C.z;

    T U = cross_2d(Cx, Cy, Bx, By), V = cross_2d(Ax, Ay, Cx, Cy), W = cross_2d(Bx, By, Ax, Ay);
    if (U == 0 || V == 0 || W == 0) {
        // A 0 may be a product difference that float rounded away; in double it is exact. (For
        // T = double this recomputes the same numbers: there is no wider type to fall back to.)
        U = static_cast<T>(cross_2d<double>(Cx, Cy, Bx, By));
        V = static_cast<T>(cross_2d<double>(Ax, Ay, Cx, Cy));
        W = static_cast<T>(cross_2d<double>(Bx, By, Ax, Ay));
    }
    if ((U < 0 || V < 0 || W < 0) && (U > 0 || V > 0 || W > 0))
        return std::nullopt;
    const T det = U + V + W;
    if (det == 0)
        return std::nullopt;
    const T t = (U * (Sz * A.z) + V * (Sz * B.z) + W * (Sz * C.z)) / det;
    if (!range.surrounds(t))
        return std::nullopt;
    return TriangleHit<T>{t, V / det, W / det};
    // SOLUTION END
    // STUB return stub("02.5", std::nullopt);
}

vec3 sphere_normal(const Sphere& sphere, const point3& p)
{
    // EXERCISE 02.6: the sphere's outward normal.
    // Return the outward unit normal of `sphere` at its surface point p: unit length even on a sphere
    // far from the origin, where p carries its coordinates' rounding.
    // Lesson: "Normals and shading (EXERCISE 02.6)".
    // Stuck? hint 02.6 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    return glm::normalize(p - sphere.centre);
    // SOLUTION END
    // STUB return stub("02.6", vec3(0.0f, 0.0f, 1.0f));
}

vec3 interpolated_normal(const CornerNormals& normals, const TriangleHit<float>& hit)
{
    // EXERCISE 02.6: the smooth-shading normal at a triangle hit.
    // Return the three corner normals weighted by the hit's barycentric coordinates (beta is the weight
    // of normals.b, gamma that of normals.c), made unit length: at a corner, that corner's normal (to a float step).
    // Lesson: "Normals and shading (EXERCISE 02.6)".
    // Stuck? hint 02.6 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    const float alpha = 1.0f - hit.beta - hit.gamma;
    return glm::normalize(alpha * normals.a + hit.beta * normals.b + hit.gamma * normals.c);
    // SOLUTION END
    // STUB return stub("02.6", normals.a);
}

// The five tests in float, the kit's precision, and in double, which the program measures against.
RT_CH02_INSTANTIATE(float)
RT_CH02_INSTANTIATE(double)

}  // namespace rt
