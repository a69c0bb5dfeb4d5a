// Chapter 04's bound on the watertight test's t (watertight_t_error, chapter 02's shape_tests.hpp),
// four lanes of a block at once (given). Why: the bounded test asks each hit for that bound, then
// for the plane's t in double, and asked lane by lane the bound alone took 11% of the wide tree's
// time on the pyramid (perf; chapters/benchmark/README.md, "Chapter 10's steps", step 12), mostly
// for lanes whose answer could not matter: behind the origin, beyond the best hit so far, or, for a
// shadow feeler, certainly inside its range. Four at once, in float, the bound tells those lanes apart;
// the others are asked one by one, exactly as before, so every answer stays the one-by-one loop's.
#pragma once

#include "02_spheres_triangles/shape_tests.hpp"
#include "10_hierarchies/four_triangles.hpp"
#include "10_hierarchies/lanes.hpp"

namespace rt {

// Each lane's bound on |t - true t|, at least the one-by-one test's (upper) and at most it (lower),
// and the lanes where that holds (known): elsewhere the bound says nothing and the lane is asked
// one by one.
struct FourBounds {
    float upper[4], lower[4];
    unsigned known = 0;
};

namespace lane_bounds_detail {

inline Float4 max3(Float4 a, Float4 b, Float4 c) { return greater_or_second(a, greater_or_second(b, c)); }
inline Float4 min4(Float4 a, Float4 b, Float4 c, Float4 d) { return less_or_second(less_or_second(a, b), less_or_second(c, d)); }

}  // namespace lane_bounds_detail

// The magnitudes are the one-by-one test's own: each corner minus the origin, sheared by the ray's
// frame, in float and in the same order, give the same floats in each lane (lanes.hpp); the frame
// may name x and y the other way round (ray_frame keeps the winding), which the bound does not see
// (an edge function changes sign, exactly). Only their combination differs: float here, double
// there. Its terms are all sums of products of magnitudes, 14 roundings of 2^-24 at most, so the
// float result times 1 + 2^-16 is at least double's (cast to float, one rounding more), and times
// 1 - 2^-16 at most it, wherever no step underflows or overflows. The lanes kept to known have the sheared magnitudes and heights
// above 2^-30 and the edge functions and det above 2^-60: the smallest product then stays above
// 2^-112 (float's least normal is 2^-126), and as |det| <= 3 max_e the bound itself stays above
// 2^-54. A lane whose edge function is 0 (the test retakes those in double) is not known.
inline FourBounds four_t_error_bounds(const FourTriangles& g, const RayFrame& f)
{
    using namespace lane_bounds_detail;
    const int axis[3] = {f.kx, f.ky, f.kz};
    const auto height = [&](int c) { return Float4::load(g.p[c][axis[2]]) - Float4(f.o[2]); };
    const Float4 z[3] = {height(0), height(1), height(2)};
    const auto sheared = [&](int c, int k, float S) {
        return (Float4::load(g.p[c][axis[k]]) - Float4(f.o[k])) - Float4(S) * z[c];
    };
    const Float4 x[3] = {sheared(0, 0, f.Sx), sheared(1, 0, f.Sx), sheared(2, 0, f.Sx)};
    const Float4 y[3] = {sheared(0, 1, f.Sy), sheared(1, 1, f.Sy), sheared(2, 1, f.Sy)};
    // The edge functions as 02.5 forms them: U from corners c and b, V from a and c, W from b and a.
    const Float4 U = x[2] * y[1] - y[2] * x[1];
    const Float4 V = x[0] * y[2] - y[0] * x[2];
    const Float4 W = x[1] * y[0] - y[1] * x[0];
    const Float4 det = U + V + W;
    const Float4 max_x = max3(abs(x[0]), abs(x[1]), abs(x[2]));
    const Float4 max_y = max3(abs(y[0]), abs(y[1]), abs(y[2]));
    const Float4 max_z = max3(abs(z[0]), abs(z[1]), abs(z[2]));
    const Float4 max_zt = abs(Float4(f.Sz)) * max_z;
    const Float4 max_e = max3(abs(U), abs(V), abs(W));
    const Float4 abs_det = abs(det);
    const Float4 bound = watertight_detail::t_error<float>(max_x, max_y, max_z, max_zt, max_e, abs_det);

    FourBounds b;
    (bound * Float4(1.0f + 0x1p-16f)).store(b.upper);
    (bound * Float4(1.0f - 0x1p-16f)).store(b.lower);
    // Lower limits keep every product normal; an overflow gives infinity, a bound that decides
    // nothing, except in det, which divides: max_e below 2^60 keeps det finite. NaN fails them all.
    const Mask4 known = (min4(max_x, max_y, max_z, max_zt) > Float4(0x1p-30f)) &
                        (min4(abs(U), abs(V), abs(W), abs_det) > Float4(0x1p-60f)) & (max_e < Float4(0x1p60f));
    b.known = bits(known);
    return b;
}

// What the bounded test's answer for a lane can be, told from its float t and its bound alone
// (chapter 02's bounded_answer): nothing where t lies more than the bound behind the origin;
// otherwise the float t itself, or a t within the bound of it (the plane's t in double, or double's
// own test) rounded to float. Those others come only where the bound is over 2^-20 of t (coarse_t)
// or t lies within it, so their rounding, and that of the sums below, is far below one bound; the
// float t itself needs no room, as t - 3 bound rounds to at most t. So with three bounds of room a
// lane whose interval lies outside a range is refused by it, and one whose interval lies inside it,
// beyond the bound, is hit in it.
struct LaneAnswer {
    float t, bound, lower;
    bool refused_by(Interval range) const
    {
        return t < -bound || t - 3.0f * bound >= range.max || t + 3.0f * bound <= range.min;
    }
    bool certainly_in(Interval range) const
    {
        return t > bound && t - 3.0f * bound > range.min && t + 3.0f * bound < range.max;
    }
    // Where t lies beyond the bound, bounded_answer answers with answer_beyond_bound, its t taken
    // again on the plane where the bound exceeds coarse_t of t: whether it does is certain when
    // both bounds lie on one side of coarse_t t (the same float product bounded_answer compares).
    bool beyond() const { return t > bound; }
    bool coarse() const { return lower > coarse_t * t; }
    bool fine() const { return bound <= coarse_t * t; }
};

}  // namespace rt
