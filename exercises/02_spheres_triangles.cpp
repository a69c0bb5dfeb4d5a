// Chapter 02, spheres and triangles: your exercises.
//
// Each function below says what to compute and gives a hint; its contract is documented in
// chapters/02_spheres_triangles/02_spheres_triangles.hpp and the lesson in that folder's
// README.md. Each stub compiles and returns a harmless value, so the chapter's program always runs.
// Check your work with:  cmake --build --preset grade --target check_02
//
// The intersection tests are templates: write T where you would write float (T(0), T(1) for
// constants, vec3_t<T> for a vector). The last lines of the file compile them for float and double.
#include "02_spheres_triangles/02_spheres_triangles.hpp"
#include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

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
    return stub("02.1", std::nullopt);
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
    return stub("02.2", std::nullopt);
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
    return stub("02.3", std::nullopt);
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
    return stub("02.4", std::nullopt);
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
    return stub("02.5", std::nullopt);
}

vec3 sphere_normal(const Sphere& sphere, const point3& p)
{
    // EXERCISE 02.6: the sphere's outward unit normal at p. (p - O) / r is unit in exact
    // arithmetic; in float p carries its coordinates' rounding (at 1e4 from the origin, steps of
    // 1e-3), so make it unit with glm::normalize instead.
    return stub("02.6", vec3(0.0f, 0.0f, 1.0f));
}

vec3 interpolated_normal(const CornerNormals& normals, const TriangleHit<float>& hit)
{
    // EXERCISE 02.6: the normal for smooth shading: (1 - beta - gamma) at a + beta at b +
    // gamma at c, where at a is normals.a and so on. A weighted sum of unit vectors is shorter than
    // 1 inside the triangle: make it unit again.
    return stub("02.6", normals.a);
}

// The five tests in float, the kit's precision, and in double, which the program measures against.
RT_CH02_INSTANTIATE(float)
RT_CH02_INSTANTIATE(double)

}  // namespace rt
