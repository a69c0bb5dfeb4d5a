// The open cone or cylinder of NFF's `c` (shapes.hpp, Cone): where a ray meets its side, the side's
// normal, and the side's point nearest a hit point.
//
// The side is every point at height h in [0, H] along the unit axis k from the base, at distance
// r(h) = r_b + s h from the axis (s the slope, (r_apex - r_b) / H). The caps are not part of it: a
// ray along a cylinder's axis sees nothing. Like the chapter's sphere tests, hit_cone returns only
// a t strictly inside the range: never a NaN or an infinity, no hit for a tangent ray (a double
// root), the far wall for a ray that starts inside.
#pragma once

#include "02_spheres_triangles/shapes.hpp"
#include "common/interval.hpp"
#include "common/ray.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace rt {

namespace cone_detail {

// The cone in double: base, unit axis k, height H, base radius r_b and slope s.
struct Frame {
    dpoint3 base;
    dvec3 k;
    double H;
    double r_b;
    double s;
};

inline Frame frame(const Cone& cone)
{
    const dvec3 axis = dvec3(cone.apex) - dvec3(cone.base);
    const double H = glm::length(axis);
    return {dpoint3(cone.base), axis / H, H, double(cone.base_radius),
            (double(cone.apex_radius) - double(cone.base_radius)) / H};
}

// A unit vector perpendicular to the unit vector k, with no division by zero for any k (Duff et
// al., "Building an Orthonormal Basis, Revisited", JCGT 2017).
inline dvec3 perpendicular(const dvec3& k)
{
    const double sign = std::copysign(1.0, k.z);
    const double a = -1.0 / (sign + k.z);
    return {1.0 + sign * k.x * k.x * a, sign * k.x * k.y * a, -sign * k.x};
}

// The unit direction of p_perp, p's offset from the axis; on the axis, where every direction is as
// good, a fixed perpendicular.
inline dvec3 radial(const dvec3& k, const dvec3& p_perp)
{
    const double length = glm::length(p_perp);
    return length > 0.0 ? p_perp / length : perpendicular(k);
}

inline bool finite(const vec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The gradient of |x_perp| - (r_b + s h) at the point f from the base: the radial direction,
// tilted against the slope. At a pointed tip the side has no normal: the axis out of the tip
// stands in for it. (On a cylinder's axis, which is not on the side, this only keeps it unit.)
inline dvec3 normal_at(const Frame& frame, const dvec3& f)
{
    const dvec3 p_perp = f - glm::dot(f, frame.k) * frame.k;
    const double distance = glm::length(p_perp);
    if (!(distance > 0.0))
        return frame.s > 0.0 ? -frame.k : frame.k;
    return glm::normalize(p_perp / distance - frame.s * frame.k);
}

// The side's point on the radial line of p at p's height clamped to [0, H].
inline dpoint3 side_point(const Frame& frame, const dpoint3& p)
{
    const dvec3 f = p - frame.base;
    const double h_p = glm::dot(f, frame.k);
    const double h = std::clamp(h_p, 0.0, frame.H);
    return frame.base + h * frame.k + (frame.r_b + frame.s * h) * radial(frame.k, f - h_p * frame.k);
}

}  // namespace cone_detail

// The nearest t strictly inside range where the ray meets the side with 0 <= h <= H. Any non-zero
// ray.dir (t in lengths of it); a NaN or infinite ray has no hit.
inline std::optional<float> hit_cone(const Ray& ray, const Cone& cone, Interval range)
{
    // A NaN or infinity would reach the tests below only as NaN (inf - inf), which fails them;
    // rejected here so the contract does not hang on that chain.
    if (!cone_detail::finite(ray.origin) || !cone_detail::finite(ray.dir))
        return std::nullopt;

    // In double: c below subtracts two numbers of size D^2 for a cone at distance D and cancels to
    // size r^2, exactly like the slide's sphere (this chapter's lesson, "Why the slide's sphere fails far away"). *Measured* with these
    // steps in float, rays aimed within 1.5 r of a cone: 0.04%, 3.1% and 44% wrong hit/miss answers
    // at D = 1e2, 1e3, 1e4. Double keeps about eight digits of c at 1e4, none wrong.
    const auto [base, k, H, r_b, s] = cone_detail::frame(cone);
    const dvec3 f = dvec3(ray.origin) - base;
    const dvec3 V = dvec3(ray.dir);

    // f and V split along the axis and across it: at t the point is at height h = f.k + t V.k and
    // at offset f_perp + t V_perp from the axis.
    const double f_k = glm::dot(f, k);
    const double V_k = glm::dot(V, k);
    const dvec3 f_perp = f - f_k * k;
    const dvec3 V_perp = V - V_k * k;

    // The side, |f_perp + t V_perp|^2 = (r_b + s h)^2, as a t^2 + 2 b t + c = 0: the implicit form
    // of pbrt-v3's Cone::Intersect (a pointed cone on the z axis there), for any axis and radii.
    const double r0 = r_b + s * f_k;
    const double r1 = s * V_k;
    const double a = glm::dot(V_perp, V_perp) - r1 * r1;
    const double b = glm::dot(f_perp, V_perp) - r0 * r1;
    const double c = glm::dot(f_perp, f_perp) - r0 * r0;

    double roots[2];
    int count = 0;
    if (a == 0.0) {
        // The ray parallel to a slant line (or to a cylinder's axis): 2 b t + c = 0 has one root,
        // none when b = 0 too.
        if (b == 0.0)
            return std::nullopt;
        roots[count++] = -c / (2.0 * b);
    } else {
        // No real root, or a double root (a tangent ray): a miss, as for the sphere.
        const double disc = b * b - a * c;
        if (!(disc > 0.0))
            return std::nullopt;
        // Stable roots (Press et al., Numerical Recipes, sec. 5.6): q adds numbers of one sign, so
        // neither q / a nor c / q comes from a cancelling difference.
        const double q = -(b + std::copysign(std::sqrt(disc), b));
        roots[count++] = std::min(q / a, c / q);
        roots[count++] = std::max(q / a, c / q);
    }

    // Only roots between the discs: this also drops the mirror nappe beyond a pointed tip. The
    // range is tested on the float returned (a root beyond float's range rounds to infinity).
    for (int i = 0; i < count; ++i) {
        const double h = f_k + roots[i] * V_k;
        const float t = static_cast<float>(roots[i]);
        if (0.0 <= h && h <= H && range.surrounds(t))
            return t;
    }
    return std::nullopt;
}

// The unit normal at a point p on the side, pointing away from the axis.
inline vec3 cone_normal(const Cone& cone, const point3& p)
{
    const cone_detail::Frame frame = cone_detail::frame(cone);
    return vec3(cone_detail::normal_at(frame, dvec3(p) - frame.base));
}

// The point of the side on p's radial line at p's height clamped to [0, H]: a hit point ray.at(t)
// moved onto the surface within float rounding (the sphere's reprojection, pbrt-v4's
// `Sphere::BasicIntersect`). Computed in double and rounded to float once, at the end.
inline point3 cone_surface_point(const Cone& cone, const point3& p)
{
    const cone_detail::Frame frame = cone_detail::frame(cone);
    return point3(cone_detail::side_point(frame, dpoint3(p)));
}

// A hit on the side as a new ray leaves it: cone_surface_point's point, and the normal there taken
// from the same double point before it is rounded. Why not cone_normal(cone, cone_surface_point(..)):
// that rounds the point to float and widens it back, a round trip GCC 12.2 at -O3 dropped in some
// translation units and kept in others, so chapter 04's program and chapter 07's gave one hit two
// normals a unit in the last place apart (chapter 04's lesson, "One brute force").
inline OnSurface cone_surface(const Cone& cone, const point3& p)
{
    const cone_detail::Frame frame = cone_detail::frame(cone);
    const dpoint3 q = cone_detail::side_point(frame, dpoint3(p));
    return {point3(q), vec3(cone_detail::normal_at(frame, q - frame.base))};
}

}  // namespace rt
