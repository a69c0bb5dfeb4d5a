// An axis-aligned box (the bounds of an object, a grid cell, a tree node) and the ray/box slab
// test every accelerator of chapters 07-10 enters its boxes with.
//
// The slab test (Kay and Kajiya 1986): the ray is inside the box where it is inside all three
// slabs min_i <= p_i <= max_i, each one the t interval between its two planes,
// t = (min_i - o_i) / d_i and t = (max_i - o_i) / d_i. It is made robust as Ize ("Robust BVH Ray
// Traversal", JCGT 2013) and pbrt-v4 (`Bounds3::IntersectP`) make it:
//   - t_far of each slab is multiplied by 1 + 2 gamma(3), gamma(n) = n u / (1 - n u) with
//     u = 2^-24: the computed t_far can be up to that factor too small (two roundings and a
//     division), and a box whose t_near and t_far are equal in exact arithmetic would otherwise be
//     missed by a grazing ray: thin holes in a mesh;
//   - a zero direction component (+0 or -0, made +0) gives 1 / d_i = +infinity: the slab's two t
//     are both +infinity or both -infinity when the origin lies outside that slab (a miss), and
//     -inf and +inf when it lies inside (no limit), with IEEE arithmetic doing the work (Williams
//     et al., "An Efficient and Robust Ray-Box Intersection Algorithm", 2005);
//   - an origin exactly on a face with d_i = 0 makes 0 * inf = NaN; the comparisons below are
//     written so that a NaN leaves the interval unchanged: a ray that runs in the face's plane is
//     inside that slab (the box is closed);
//   - a ray with a NaN or infinite origin or direction, or none at all (0, 0, 0), never enters a
//     box (valid_ray).
#pragma once

#include "common/interval.hpp"
#include "common/ray.hpp"
#include "common/vec.hpp"

#include <glm/common.hpp>

#include <cmath>
#include <optional>

namespace rt {

struct Bounds {
    point3 min{infinity};   // empty: min > max on every axis
    point3 max{-infinity};

    bool empty() const { return !(min.x <= max.x && min.y <= max.y && min.z <= max.z); }
    vec3 extent() const { return empty() ? vec3(0.0f) : max - min; }
    point3 centre() const { return 0.5f * (min + max); }

    void grow(const point3& p)
    {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void grow(const Bounds& b)
    {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }

    // Half the surface area: what the surface area heuristic (chapter 10) weighs a box by.
    float half_area() const
    {
        const vec3 e = extent();
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
};

// The box one float step larger on every side: bounds computed in float (a sphere's c + r) may
// round inward by half a step, which would let a ray hit the object but miss its box.
inline Bounds widened_one_ulp(const Bounds& b)
{
    Bounds w;
    for (int i = 0; i < 3; ++i) {
        w.min[i] = next_down(b.min[i]);
        w.max[i] = next_up(b.max[i]);
    }
    return w;
}

// A ray an accelerator can follow: finite, with a direction. The others hit nothing.
inline bool valid_ray(const Ray& ray)
{
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(ray.origin[i]) || !std::isfinite(ray.dir[i]))
            return false;
    return ray.dir != vec3(0.0f);
}

// 1 + 2 gamma(3), gamma(n) = n u / (1 - n u), u = 2^-24 (float's unit roundoff): Ize 2013.
constexpr float gamma_3 = 3.0f * 0x1p-24f / (1.0f - 3.0f * 0x1p-24f);
constexpr float slab_far_widening = 1.0f + 2.0f * gamma_3;

// What the slab test needs of a ray, computed once per ray: 1 / d_i, +infinity for a zero
// component (a -0 made +0 first, -0 + 0 being +0 in IEEE arithmetic, so that a ray along no axis
// i always counts as going up it), and which of each slab's two planes the ray meets first, by the
// sign of 1 / d_i. Chosen by the sign, a slab whose t is NaN
// (0 * infinity: an origin on a face, d_i = 0) leaves the interval alone whichever plane it is.
struct RaySlabs {
    point3 origin;
    vec3 inv_dir;
    bool down[3];  // 1 / d_i < 0: the ray meets the max plane of slab i first

    explicit RaySlabs(const Ray& ray) : origin(ray.origin), inv_dir(1.0f / (ray.dir + vec3(0.0f)))
    {
        for (int i = 0; i < 3; ++i)
            down[i] = inv_dir[i] < 0.0f;
    }
};

// The part of `range` where the ray is inside the box, or nothing when the ray misses it (or only
// touches it at an end of an open range). The ray must be finite: the accelerators check that
// once per query (valid_ray); hit_bounds below checks it for you.
inline std::optional<Interval> slab_interval(const Bounds& box, const RaySlabs& ray, Interval range)
{
    float t0 = range.min, t1 = range.max;
    for (int i = 0; i < 3; ++i) {
        // The near plane chosen by the ray's sign, not by comparing the two t: a choice the same for
        // every box, where a comparison is a branch taken either way box after box.
        const float near_plane = ray.down[i] ? box.max[i] : box.min[i];
        const float far_plane = ray.down[i] ? box.min[i] : box.max[i];
        const float t_near = (near_plane - ray.origin[i]) * ray.inv_dir[i];
        const float t_far = (far_plane - ray.origin[i]) * ray.inv_dir[i] * slab_far_widening;
        // Written so that a NaN (0 * inf: an origin on the face, d_i = 0) leaves t0 and t1 alone.
        t0 = t_near > t0 ? t_near : t0;
        t1 = t_far < t1 ? t_far : t1;
    }
    // One test after all three slabs, not one per slab: t0 only grows and t1 only shrinks, so the
    // answer is the same, and a branch the processor cannot predict is taken once, not three times.
    if (t0 > t1)
        return std::nullopt;
    return Interval{t0, t1};
}

inline std::optional<Interval> hit_bounds(const Bounds& box, const Ray& ray, Interval range)
{
    if (!valid_ray(ray) || box.empty() || !(range.min <= range.max))
        return std::nullopt;
    return slab_interval(box, RaySlabs(ray), range);
}

}  // namespace rt
