// SOLUTION BEGIN
// Chapter 02, spheres and triangles: the reference solution.
//
// This file is also the source of exercises/02_spheres_triangles.cpp: the kit's cutter drops every
// block between SOLUTION BEGIN and SOLUTION END and keeps the STUB lines as code
// (`cmake --build <build> --target cut_exercises`; a test checks that the two agree).
// SOLUTION END
// STUB // Chapter 02, spheres and triangles: your exercises.
// STUB //
// STUB // Each function below says what to compute and gives a hint; its contract is documented in
// STUB // chapters/02_spheres_triangles/02_spheres_triangles.hpp and the lesson in that folder's
// STUB // README.md. Each stub compiles and returns a harmless value, so the chapter's program always runs.
// STUB // Check your work with:  cmake --build --preset grade --target check_02
// STUB //
// STUB // The intersection tests are templates: write T where you would write float (T(0), T(1) for
// STUB // constants, vec3_t<T> for a vector). The last lines of the file compile them for float and double.
#include "02_spheres_triangles/02_spheres_triangles.hpp"
// STUB #include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

#include <cmath>
#include <initializer_list>
#include <utility>

namespace rt {

template <class T>
std::optional<T> hit_sphere_slide(const BasicRay<T>& ray, const BasicSphere<T>& sphere, BasicInterval<T> range)
{
    // EXERCISE 02.1: the slide's geometric test. E is ray.origin, V is ray.dir (unit length), O is
    // sphere.centre and r is sphere.radius.
    // EO = O - E, e = EO.V (how far along the ray the centre lies), disc = r^2 - (|EO|^2 - e^2).
    // disc <= 0: no hit. Else d = sqrt(disc), and t = e - d is the near side. When e - d is not
    // inside the range (the ray starts inside the sphere), t = e + d, the far side, may be.
    // Hint: glm::dot(EO, EO) is |EO|^2; return t only when range.surrounds(t).
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
    // f = E - O and b = f.V. The ray passes the centre at distance |f - bV|, so
    // disc = r^2 - |f - bV|^2 (no hit when disc <= 0). With c = |f|^2 - r^2 the roots of
    // t^2 + 2bt + c = 0 are q and c/q, where q = -b - sign(b) sqrt(disc): -b and the square root
    // then have the same sign and add without cancelling. Try the nearer root first.
    // Compute in double (dvec3, double), even when T is float: see the lesson's "huge" sphere.
    // Hint: f = dvec3(ray.origin) - dvec3(sphere.centre) converts, then subtracts (dvec3(E - O) would
    // keep float's rounding of the difference); write sign(b) sqrt(disc) as
    // (b >= 0 ? sqrt(disc) : -sqrt(disc)); std::swap orders two values; return the root as T.
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
    // EXERCISE 02.3: the slide's triangle test. u is ray.origin, v is ray.dir; a, b, c the corners.
    // 1. n = (b - a) x (b - c). When n.v = 0 the ray runs parallel to the plane (or n = 0: the
    //    triangle has no area): no hit. Else t = n.(b - u) / n.v, kept only inside the range.
    // 2. p = u + vt is inside when the three products (b - a) x (p - a).n, (c - b) x (p - b).n and
    //    (a - c) x (p - c).n have the same sign; 0 counts as either sign (p on an edge).
    // 3. Each product is twice the area of the triangle p makes with one edge (times |n|), so each
    //    divided by their sum is the barycentric weight of the corner opposite that edge: beta, the
    //    weight of b, comes from the edge c-a; gamma, the weight of c, from the edge a-b.
    // Hint: glm::cross and glm::dot; ray.at(t) is p.
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
    // EXERCISE 02.4: Moller-Trumbore. Solve u + t v = a + beta e1 + gamma e2, with e1 = b - a and
    // e2 = c - a, by Cramer's rule:
    //   P = v x e2, det = e1.P (0: parallel or degenerate, no hit), s = u - a,
    //   beta = s.P / det   (outside [0, 1]: no hit),
    //   Q = s x e1, gamma = v.Q / det   (gamma < 0 or beta + gamma > 1: no hit),
    //   t = e2.Q / det   (kept only inside the range).
    // Hint: write the rejections as !(beta >= 0 && beta <= 1), so that a NaN is rejected too.
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
    // EXERCISE 02.5 (advanced): the watertight test (Woop, Benthin and Wald, JCGT 2013).
    // 0. A triangle with (b - a) x (c - a) exactly 0 has no area: no hit (pbrt-v4 does the same).
    // 1. kz: the axis along which |v| is largest; kx = (kz + 1) % 3, ky = (kx + 1) % 3, and swap
    //    kx and ky when v[kz] < 0 (so the triangle keeps its winding).
    // 2. The shear that turns v into +z: Sx = v[kx] / v[kz], Sy = v[ky] / v[kz], Sz = 1 / v[kz].
    // 3. Each corner relative to the origin, A = a - u (B, C likewise), sheared into 2D:
    //    Ax = A[kx] - Sx A[kz], Ay = A[ky] - Sy A[kz].
    // 4. The edge functions U = cross_2d(Cx, Cy, Bx, By), V = cross_2d(Ax, Ay, Cx, Cy),
    //    W = cross_2d(Bx, By, Ax, Ay). When one is exactly 0, compute all three again from the
    //    same numbers in double (products of floats are exact there). The ray passes through the
    //    triangle when U, V, W are all >= 0 or all <= 0, and det = U + V + W is not 0.
    // 5. t = (U Sz A[kz] + V Sz B[kz] + W Sz C[kz]) / det, kept only inside the range;
    //    beta = V / det and gamma = W / det.
    // Hint: a vector's component k is v[k].
    // SOLUTION BEGIN
    const vec3_t<T> n = glm::cross(tri.b - tri.a, tri.c - tri.a);
    if (n.x == 0 && n.y == 0 && n.z == 0)
        return std::nullopt;

    const vec3_t<T> ad = glm::abs(ray.dir);
    const int kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (ray.dir[kz] < 0)
        std::swap(kx, ky);

    const T Sx = ray.dir[kx] / ray.dir[kz], Sy = ray.dir[ky] / ray.dir[kz], Sz = T(1) / ray.dir[kz];
    const vec3_t<T> A = tri.a - ray.origin, B = tri.b - ray.origin, C = tri.c - ray.origin;
    const T Ax = A[kx] - Sx * A[kz], Ay = A[ky] - Sy * A[kz];
    const T Bx = B[kx] - Sx * B[kz], By = B[ky] - Sy * B[kz];
    const T Cx = C[kx] - Sx * C[kz], Cy = C[ky] - Sy * C[kz];

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
    const T t = (U * (Sz * A[kz]) + V * (Sz * B[kz]) + W * (Sz * C[kz])) / det;
    if (!range.surrounds(t))
        return std::nullopt;
    return TriangleHit<T>{t, V / det, W / det};
    // SOLUTION END
    // STUB return stub("02.5", std::nullopt);
}

vec3 sphere_normal(const Sphere& sphere, const point3& p)
{
    // EXERCISE 02.6: the sphere's outward unit normal at p. (p - O) / r is unit in exact
    // arithmetic; in float p carries its coordinates' rounding (at 1e4 from the origin, steps of
    // 1e-3), so make it unit with glm::normalize instead.
    // SOLUTION BEGIN
    return glm::normalize(p - sphere.centre);
    // SOLUTION END
    // STUB return stub("02.6", vec3(0.0f, 0.0f, 1.0f));
}

vec3 interpolated_normal(const CornerNormals& normals, const TriangleHit<float>& hit)
{
    // EXERCISE 02.6: the normal for smooth shading: (1 - beta - gamma) at a + beta at b +
    // gamma at c, where at a is normals.a and so on. A weighted sum of unit vectors is shorter than
    // 1 inside the triangle: make it unit again.
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
