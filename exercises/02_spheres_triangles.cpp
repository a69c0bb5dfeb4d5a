// Chapter 02, spheres and triangles: your exercises.
//
// Each function below states what to compute (not how); its contract is documented in
// chapters/02_spheres_triangles/02_spheres_triangles.hpp and the lesson in that folder's
// README.md. Each stub compiles and returns a harmless value, so the chapter's program always runs.
// Check your work with:  cmake --build --preset grade --target check_02
// Stuck? Hints in tiers you open one at a time: chapters/02_spheres_triangles/hints.md, or
// ./build/grade/hint 02.1 (tier 1, the idea), ./build/grade/hint 02.1 2 (the trap), ... 3 (the walk-through).
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
    // EXERCISE 02.1: the slide's geometric sphere test.
    // Return the nearest t strictly inside `range` where the ray meets the sphere, or nothing. A tangent
    // ray misses; a ray that starts inside (the case the slide leaves out) hits the far side. The
    // slide's E, V, O and r are the ray's origin and unit direction, the sphere's centre and radius.
    // Write T wherever you would write float. Lesson: "The sphere, as the slide tests it (EXERCISE 02.1)".
    // Stuck? hint 02.1 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("02.1", std::nullopt);
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
    return stub("02.2", std::nullopt);
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
    return stub("02.3", std::nullopt);
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
    return stub("02.4", std::nullopt);
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
    return stub("02.5", std::nullopt);
}

vec3 sphere_normal(const Sphere& sphere, const point3& p)
{
    // EXERCISE 02.6: the sphere's outward normal.
    // Return the outward unit normal of `sphere` at its surface point p: unit length even on a sphere
    // far from the origin, where p carries its coordinates' rounding.
    // Lesson: "Normals and shading (EXERCISE 02.6)".
    // Stuck? hint 02.6 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("02.6", vec3(0.0f, 0.0f, 1.0f));
}

vec3 interpolated_normal(const CornerNormals& normals, const TriangleHit<float>& hit)
{
    // EXERCISE 02.6: the smooth-shading normal at a triangle hit.
    // Return the three corner normals weighted by the hit's barycentric coordinates (beta is the weight
    // of normals.b, gamma that of normals.c), made unit length: at a corner, that corner's normal (to a float step).
    // Lesson: "Normals and shading (EXERCISE 02.6)".
    // Stuck? hint 02.6 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("02.6", normals.a);
}

// The five tests in float, the kit's precision, and in double, which the program measures against.
RT_CH02_INSTANTIATE(float)
RT_CH02_INSTANTIATE(double)

}  // namespace rt
