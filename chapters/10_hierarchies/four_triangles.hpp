// A leaf's triangles four to a block (given), for the four-triangle test of EXERCISE 10.6.
//
// Why: with four boxes tested for the price of one (wide_bvh.hpp), the triangle test, one triangle
// at a time, is most of what is left of a query. Embree stores a leaf's triangles four to a block,
// corner by corner and axis by axis, and tests the four with one pass of SIMD instructions (Wald et
// al., "Embree", 2014). This file is the kit's block, and the ray's frame worked out once per query;
// the test of a block is yours (10.6). Step 6 of the lesson's "Where a query's time goes"; the
// measurements are in chapters/benchmark/README.md, "Chapter 10's steps".
#pragma once

#include "02_spheres_triangles/objects.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstdint>
#include <utility>

namespace rt {

// The watertight test's frame for one ray (02.5's first steps), worked out once per query instead of
// once per triangle: kz the axis the ray runs along most, kx and ky the other two (swapped when the
// ray runs down kz, so the triangle keeps its winding), the shear, and the origin in that order.
struct RayFrame {
    int kx, ky, kz;
    float Sx, Sy, Sz;
    float o[3];
};

inline RayFrame ray_frame(const Ray& ray)
{
    // std::fabs, which clears the sign bit, not glm::abs, whose `x >= 0 ? x : -x` GCC compiles to
    // a branch per axis that a query's new direction mispredicts.
    const vec3 ad(std::fabs(ray.dir.x), std::fabs(ray.dir.y), std::fabs(ray.dir.z));
    const int kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (ray.dir[kz] < 0)
        std::swap(kx, ky);
    const float* d = glm::value_ptr(ray.dir);
    const float* o = glm::value_ptr(ray.origin);
    return {kx, ky, kz, d[kx] / d[kz], d[ky] / d[kz], 1.0f / d[kz], {o[kx], o[ky], o[kz]}};
}

// Four triangles of a leaf, corner by corner and axis by axis: p[c][a][i] is coordinate a of corner c
// (a, b, c) of the triangle in lane i. 172 bytes for four, copied from the scene at the build; a
// block of fewer than four leaves its other lanes at 0, out of with_area.
struct FourTriangles {
    float p[3][3][4];
    std::int32_t object[4];   // each lane's object number
    std::uint32_t with_area;  // bit i: lane i holds a triangle with area (02.5 never hits one without)
    // Where every corner of the block's triangles lies on one plane of an axis (a floor, a wall):
    // that axis (-1: none) and the plane's coordinate. The wide tree then passes the block over for
    // a bounded query whose ray leaves that plane (wide_bvh.hpp, WideQuery::leaves_plane).
    std::int32_t flat_axis = -1;
    float flat_at = 0.0f;

    // Lane i's triangle, the scene's own floats: what the wide tree asks of a lane hit (chapter 04's
    // bound on t, which face the ray meets) without reading the scene's arrays again.
    Triangle triangle(int i) const
    {
        return {{p[0][0][i], p[0][1][i], p[0][2][i]}, {p[1][0][i], p[1][1][i], p[1][2][i]}, {p[2][0][i], p[2][1][i], p[2][2][i]}};
    }
};

// What the test of a block finds (10.6): the lanes hit, and for each lane hit its t, and the edge
// functions V and W and det = U + V + W, of which 02.5's beta = V / det and gamma = W / det (worked
// out by the caller for the one hit it keeps). `tested` is false only for 10.6's stub
// (FourHits::not_tested()): the wide tree then asks the block's triangles one by one, as before
// step 6, so a program runs and answers right, at step 5's speed, until 10.6 is written.
struct FourHits {
    unsigned hit = 0;  // bit i: lane i hit
    float t[4], V[4], W[4], det[4];
    bool tested = true;
    static FourHits not_tested()
    {
        FourHits h;
        h.tested = false;
        return h;
    }
};

// The four triangles of the leaf objects `object[0 .. n)` (n <= 4; all triangles), copied from the
// scene: what the wide tree stores for each leaf of triangles.
inline FourTriangles four_triangles(const Objects& objects, const std::uint32_t* object, std::uint32_t n)
{
    FourTriangles g{};
    for (std::uint32_t i = 0; i < n; ++i) {
        const int k = static_cast<int>(object[i]);
        const Triangle& tri = objects.triangles[objects.ref(k).index];
        const vec3 corner[3] = {tri.a, tri.b, tri.c};
        for (int c = 0; c < 3; ++c)
            for (int a = 0; a < 3; ++a)
                g.p[c][a][i] = corner[c][a];
        g.object[i] = k;
        // 02.5's own first check, on the same floats: a triangle whose normal is 0 is never hit.
        const vec3 normal = glm::cross(tri.b - tri.a, tri.c - tri.a);
        if (!(normal.x == 0 && normal.y == 0 && normal.z == 0))
            g.with_area |= 1u << i;
    }
    for (int a = 0; a < 3 && g.flat_axis < 0; ++a) {
        bool flat = true;
        for (std::uint32_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c)
                flat = flat && g.p[c][a][i] == g.p[0][a][0];
        if (flat) {
            g.flat_axis = a;
            g.flat_at = g.p[0][a][0];
        }
    }
    return g;
}

}  // namespace rt
