// The scene's objects as one numbered list, the seam every query goes through: spheres are
// objects 0 .. S-1, triangles S .. S+T-1, cones after them (the order every chapter's scene
// already numbers its hits in). An accelerator (chapters 07-10) never sees a sphere or a triangle:
// it holds object numbers and asks this list two things, the object's bounds and whether a ray
// hits it; shading asks it a third, where the hit lies and which way the surface faces there. So a
// new kind of shape is one case in each of `intersect`, `bounds`, `normal_at` and `surface`; outside
// this file only the triangles' smooth shading names a kind (the README's "Adding a shape").
//
// The list is a view of the scene's own arrays (no copy), with the choice of tests a query asks
// for: chapter 02's program picks among its sphere and triangle tests, chapter 04 on uses the
// precise sphere and the watertight triangle, and the classic NFF rules see some triangles from
// their front only.
#pragma once

#include "02_spheres_triangles/shape_tests.hpp"
#include "common/bounds.hpp"

#include <glm/common.hpp>

#include <array>
#include <cmath>
#include <vector>

namespace rt {

// Where a hit lies: a hit point moved onto the surface it hit, for a ray that leaves it (chapter 04 on): ray.at(t)
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
// test's slab (shape_tests.hpp) are sized on: a few float steps of the point's own
// coordinates. pbrt-v4 instead carries the float sum's larger error with the point and offsets by
// it (sec. 6.8.6); a point that is accurate needs no such offset.

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
// gamma, which carry the test's own rounding, a few float steps of the corners: on a floor much
// larger than the eye's distance from it, the point slides along the ray and the feelers' shadows
// move with it (chapter 04's lesson, "The right picture at every scale"). The plane's t in double
// is off by 2^-50 or so of the distances it combines, whatever the triangle's size.
inline point3 triangle_surface_point(const Triangle& tri, const Ray& ray)
{
    const dvec3 a(tri.a), o(ray.origin), d(ray.dir);
    const dvec3 n = glm::cross(dvec3(tri.b) - a, dvec3(tri.c) - a);
    const double t = glm::dot(n, a - o) / glm::dot(n, d);
    return point3(o + t * d);
}

// What a query learns of the object it hits: t, which object, and for a triangle where on it
// (the barycentric weights that chapter 02's normals and chapter 04's surface point need).
struct ObjectHit {
    float t = infinity;
    int object = -1;
    float beta = 0.0f, gamma = 0.0f;
};

// The kinds of object, in the order the list numbers them. The numbering itself (spheres, then
// triangles, then cones) is written once, in object_ref and first_of below: everything else asks
// them.
enum class ObjectKind { sphere, triangle, cone };
constexpr int object_kinds = 3;

// An object by its kind and its place among that kind's: spheres[index], triangles[index] or
// cones[index] of the scene.
struct ObjectRef {
    ObjectKind kind;
    int index;
};

// Which object number `object` is, in a list of `spheres` spheres and `triangles` triangles.
inline ObjectRef object_ref(int object, int spheres, int triangles)
{
    if (object < spheres)
        return {ObjectKind::sphere, object};
    if (object - spheres < triangles)
        return {ObjectKind::triangle, object - spheres};
    return {ObjectKind::cone, object - spheres - triangles};
}

// The number of the first object of `kind`, so that object first_of(kind) + i is that kind's i-th.
inline int first_of(ObjectKind kind, int spheres, int triangles)
{
    return kind == ObjectKind::sphere ? 0 : kind == ObjectKind::triangle ? spheres : spheres + triangles;
}

// The same for a scene with the three arrays (ShapeScene, LitScene).
template <class Scene>
ObjectRef object_ref(const Scene& scene, int object)
{
    return object_ref(object, static_cast<int>(scene.spheres.size()), static_cast<int>(scene.triangles.size()));
}

// What a scene keeps beside each kind's array, index for index (a colour, a material): one list
// per kind, so a new kind needs no new member in any scene.
template <class T>
struct PerKind {
    std::array<std::vector<T>, object_kinds> of;

    std::vector<T>& operator[](ObjectKind kind) { return of[static_cast<int>(kind)]; }
    const std::vector<T>& operator[](ObjectKind kind) const { return of[static_cast<int>(kind)]; }
    // What it keeps for the object `r` names.
    const T& operator[](const ObjectRef& r) const { return (*this)[r.kind][r.index]; }
};

// Why 1e-6: above the few float roundings (each 6e-8 of 1) in normalising the axis and squaring it.
constexpr float cone_reach_margin = 1e-6f;

struct Objects {
    const Sphere* spheres = nullptr;
    int sphere_count = 0;
    const Triangle* triangles = nullptr;
    int triangle_count = 0;
    const Cone* cones = nullptr;
    int cone_count = 0;
    ShapeTests tests{};
    const std::vector<bool>* one_sided = nullptr;  // per triangle: seen from its front only (or none)

    int size() const { return sphere_count + triangle_count + cone_count; }
    ObjectRef ref(int k) const { return object_ref(k, sphere_count, triangle_count); }
    int first(ObjectKind kind) const { return first_of(kind, sphere_count, triangle_count); }

    // One counted intersection test of object k: true, with `hit` filled in, when the ray hits it
    // with t strictly inside `range` (and, for a one-sided triangle, from its front).
    bool intersect(int k, const Ray& ray, Interval range, ObjectHit& hit) const
    {
        const ObjectRef o = ref(k);
        switch (o.kind) {
        case ObjectKind::sphere: {
            const std::optional<float> t = hit_sphere(ray, spheres[o.index], range, tests.sphere);
            if (!t)
                return false;
            hit = {*t, k, 0.0f, 0.0f};
            return true;
        }
        case ObjectKind::triangle: {
            const Triangle& tri = triangles[o.index];
            TriangleHit<float> h;
            if (!hit_triangle(ray, tri, range, tests.triangle, h))
                return false;
            if (one_sided && (*one_sided)[o.index] && glm::dot(face_normal(tri), ray.dir) > 0.0f)
                return false;  // its back
            hit = {h.t, k, h.beta, h.gamma};
            return true;
        }
        case ObjectKind::cone:
            break;
        }
        const std::optional<float> t = hit_cone_counted(ray, cones[o.index], range);
        if (!t)
            return false;
        hit = {*t, k, 0.0f, 0.0f};
        return true;
    }

    // A box that holds all of object k, one float step generous (widened_one_ulp).
    Bounds bounds(int k) const
    {
        Bounds b;
        const ObjectRef o = ref(k);
        if (o.kind == ObjectKind::sphere) {
            const vec3 r(spheres[o.index].radius);
            b.grow(spheres[o.index].centre - r);
            b.grow(spheres[o.index].centre + r);
        } else if (o.kind == ObjectKind::triangle) {
            const Triangle& t = triangles[o.index];
            b.grow(t.a);
            b.grow(t.b);
            b.grow(t.c);
        } else {
            // Each end disc of radius r across the unit axis a reaches r sqrt(1 - a_i^2) along axis i.
            // 1 - a_i^2 carries a few 1e-7 of rounding, which the square root magnifies near 0
            // (an axis almost along i): cone_reach_margin, added first, keeps the box outside.
            const Cone& c = cones[o.index];
            const vec3 a = glm::normalize(c.apex - c.base);
            const vec3 reach = glm::sqrt(glm::clamp(vec3(1.0f + cone_reach_margin) - a * a, vec3(0.0f), vec3(1.0f)));
            b.grow(c.base - c.base_radius * reach);
            b.grow(c.base + c.base_radius * reach);
            b.grow(c.apex - c.apex_radius * reach);
            b.grow(c.apex + c.apex_radius * reach);
        }
        return widened_one_ulp(b);
    }

    // The unit outward normal of object k at p, a point found on it at ray.at(t) (chapter 02's
    // shading): a sphere's from its centre, a triangle's face normal, a cone's from its axis.
    vec3 normal_at(int k, const point3& p) const
    {
        const ObjectRef o = ref(k);
        switch (o.kind) {
        case ObjectKind::sphere:
            return sphere_normal(spheres[o.index], p);
        case ObjectKind::triangle:
            return face_normal(triangles[o.index]);
        case ObjectKind::cone:
            break;
        }
        return cone_normal(cones[o.index], p);
    }

    // The hit as a new ray leaves it (chapter 04 on): its point moved onto the surface within float
    // rounding (above) and the outward normal there, a triangle's its face normal.
    OnSurface surface(const Ray& ray, const ObjectHit& hit) const
    {
        const ObjectRef o = ref(hit.object);
        switch (o.kind) {
        case ObjectKind::sphere: {
            const Sphere& sphere = spheres[o.index];
            const point3 p = sphere_surface_point(sphere, ray.at(hit.t));
            return {p, sphere_normal(sphere, p)};
        }
        case ObjectKind::triangle: {
            const Triangle& tri = triangles[o.index];
            return {triangle_surface_point(tri, ray), face_normal(tri)};
        }
        case ObjectKind::cone:
            break;
        }
        return cone_surface(cones[o.index], ray.at(hit.t));
    }
};

// The objects of any of the chapters' scenes (ShapeScene, LitScene: each has the three arrays).
template <class Scene>
Objects objects_of(const Scene& scene, ShapeTests tests, const std::vector<bool>* one_sided = nullptr)
{
    return {scene.spheres.data(),   static_cast<int>(scene.spheres.size()),
            scene.triangles.data(), static_cast<int>(scene.triangles.size()),
            scene.cones.data(),     static_cast<int>(scene.cones.size()),
            tests,                  one_sided};
}

}  // namespace rt
