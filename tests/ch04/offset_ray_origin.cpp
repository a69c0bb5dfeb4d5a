// EXERCISE 04.3: Wachter and Binder's robust offset of a ray's origin (Ray Tracing Gems ch. 6).
// Its stability cases are the kit's goal: no re-hit at any scale from 1e-4 to 1e6, and an
// occluder 0.25 S above the surface still found.
#include "tests/ch04/describe.hpp"

#include <cmath>
#include <cstdint>

using namespace rt;
using namespace rt::grader;

namespace {

std::string query(const point3& p, const vec3& n, const vec3& dir)
{
    return "offset_ray_origin(p = " + show(p) + ", n = " + show(n) + ", dir = " + show(dir) + ")";
}

// The signed distance of q from the plane through the triangle, in double from its float corners:
// positive on the side its face normal points to.
double plane_distance(const Triangle& tri, const point3& q)
{
    const dvec3 a(tri.a), n = glm::normalize(glm::cross(dvec3(tri.b) - a, dvec3(tri.c) - a));
    return glm::dot(n, dvec3(q) - a);
}

// The expected coordinate i: the rule of the contract, computed here bit by bit.
float expected_coordinate(float p, float n)
{
    if (std::abs(p) < offset_origin)
        return p + offset_float_scale * n;
    const auto ulps = static_cast<std::int32_t>(offset_int_scale * n);
    std::int32_t bits;
    std::memcpy(&bits, &p, sizeof bits);
    bits += p < 0.0f ? -ulps : ulps;
    float moved;
    std::memcpy(&moved, &bits, sizeof bits);
    return moved;
}

void check_exact(const point3& p, const vec3& n, const vec3& dir)
{
    const point3 got = offset_ray_origin(p, n, dir);
    const vec3 out = glm::dot(n, dir) < 0.0f ? -n : n;
    for (int i = 0; i < 3; ++i) {
        const float want = expected_coordinate(p[i], out[i]);
        INFO(query(p, n, dir) << ": coordinate " << i << " of " << show_bits(p[i]) << " with n_i = " << out[i]
             << " (n turned to dir's side) became " << show_bits(got[i]) << ", expected " << show_bits(want)
             << (std::abs(p[i]) < offset_origin ? ": p_i + n_i / 65536, since |p_i| < 1/32"
                                                : ": int(256 n_i) units in the last place, with p_i's sign"));
        REQUIRE(bits_of(got[i]) == bits_of(want));
    }
}

// Feelers from `points` at scale S, offset robustly: none may re-hit, none may miss the occluder.
void check_no_rehits(const std::string& what, self_intersection::Surface surface, self_intersection::Side side, int count,
                     const std::vector<float>& scales = {self_intersection::scales.begin(), self_intersection::scales.end()})
{
    using namespace self_intersection;
    for (const float scale : scales) {
        const ScaledScene scene = scaled_scene(scale);
        const std::vector<SurfacePoint> points = surface_points(scene, surface, count, 7);
        INFO(what << " at scale S = " << scale << ": rays aimed at the surface found " << points.size() << " of "
             << count << " points on it; expected all (the hit test of 02.4 or 02.5 misses them)");
        REQUIRE(static_cast<int>(points.size()) == count);
        const Score score = measure(scene, points, Offset::robust, side, 8);
        std::ostringstream first;
        if (score.first_rehit != Score::npos)
            first << "\n  the first to re-hit: " << show(replay(points, score.first_rehit, Offset::robust, side, 8));
        if (score.first_missed != Score::npos)
            first << "\n  the first to miss the occluder: "
                  << show(replay(points, score.first_missed, Offset::robust, side, 8));
        std::ostringstream occluder;
        if (score.occluder_tests > 0)
            occluder << " and " << score.missed << " of " << score.occluder_tests << " missed the occluder 0.25 S above it";
        INFO(what << " at scale S = " << scale << ": "
             << score.rehits << " of " << score.feelers << " feelers re-hit their own surface" << occluder.str()
             << "; expected none" << first.str());
        REQUIRE((score.rehits == 0 && score.missed == 0));
    }
}

}  // namespace

GRADED_TEST("offset_ray_origin: the origin moves off the surface, to the side the ray leaves toward", "04.3", 3)
{
    const point3 p{1.5f, -2.25f, 3.0f};
    for (const vec3& n : {vec3(0, 1, 0), vec3(-1, 0, 0), glm::normalize(vec3(1, 2, 2)), glm::normalize(vec3(-0.3f, 0.1f, -1))}) {
        for (const float side : {1.0f, -1.0f}) {
            // n tilted by less than 90 degrees (the added vector is shorter than 1), then maybe reversed.
            const vec3 dir = side * glm::normalize(n + vec3(0.3f, -0.2f, 0.1f));
            const point3 got = offset_ray_origin(p, n, dir);
            const float moved = glm::dot(got - p, n);
            INFO(query(p, n, dir) << " returned " << show(got) << ": it moved " << moved << " along n, expected a small move "
                 << (side > 0 ? "along n (dir leaves on n's side)" : "against n (dir leaves on the other side)"));
            REQUIRE(moved * side > 0.0f);
            REQUIRE(glm::length(got - p) < 1e-3f);
        }
    }
}

GRADED_TEST("offset_ray_origin: each coordinate moves by int(256 n_i) units in the last place, with the float's sign", "04.3", 3)
{
    const vec3 n = glm::normalize(vec3(0.3f, -0.8f, 0.52f));
    for (const point3& p : {point3(3.0f, -7.5f, 0.25f), point3(-1234.5f, 0.0625f, -0.04f), point3(1e6f, -1e6f, 2e5f)})
        for (const vec3& dir : {n, -n, vec3(0, -1, 0)})
            check_exact(p, n, dir);
}

GRADED_TEST("offset_ray_origin: coordinates smaller than 1/32 move by n_i / 65536 instead", "04.3", 2)
{
    const vec3 n = glm::normalize(vec3(-0.6f, 0.7f, 0.4f));
    for (const point3& p : {point3(0.01f, -0.02f, 5.0f), point3(0.03f, 0.0f, -0.001f), point3(1e-30f, -0.0312f, 0.5f)})
        for (const vec3& dir : {n, -n})
            check_exact(p, n, dir);
}

STABILITY_TEST("offset_ray_origin: no feeler re-finds its triangle at scales 1e-4 to 1e6, and the occluder 0.25 S above is found", "04.3", 3)
{
    check_no_rehits("feelers toward a light outside an icosphere of 320 triangles (radius S/2, centre S (1, 2, -3))", self_intersection::Surface::triangles,
                    self_intersection::Side::front, 20000);
}

STABILITY_TEST("offset_ray_origin: feelers leaving on the back side, into the object, never re-find their triangle", "04.3", 2)
{
    check_no_rehits("feelers into an icosphere of 320 triangles (radius S/2, centre S (1, 2, -3)), as refracted rays leave", self_intersection::Surface::triangles,
                    self_intersection::Side::back, 20000);
}

STABILITY_TEST("offset_ray_origin: no feeler re-finds its sphere at scales 1e-4 to 1e6, and the shell 0.25 S above is found", "04.3", 2)
{
    check_no_rehits("feelers toward a light outside a sphere (radius S/2, centre S (1, 2, -3))", self_intersection::Surface::sphere,
                    self_intersection::Side::front, 20000);
}

STABILITY_TEST("offset_ray_origin: on a floor through y = 0, 20 S across, no feeler re-hits up to S = 10, up or down", "04.3", 1)
{
    // y = 0 takes the fixed n / 65536 step at every scale, while the triangle test's rounding grows
    // with the floor's size: beyond S = 10 the step is too small (README, "Where the robust offset
    // stops"). Up to there it must hold, both ways.
    for (const self_intersection::Side side : {self_intersection::Side::front, self_intersection::Side::back})
        check_no_rehits(side == self_intersection::Side::front ? "feelers up from a floor through y = 0 (20 S square)"
                                                               : "feelers down from a floor through y = 0 (20 S square)",
                        self_intersection::Surface::floor, side, 20000, {1e-4f, 1e-3f, 1e-2f, 1e-1f, 1.0f, 1e1f});
}

STABILITY_TEST("offset_ray_origin: points with coordinates exactly 0 move off the surface, and no feeler re-hits", "04.3", 1)
{
    // A triangle in the plane x + 2y + 3z = 0 with its centroid at the origin, so its normal has
    // three non-zero components; and the floor y = 0. At the origin every coordinate is 0 and takes
    // the n_i / 65536 branch (integer steps from 0 would give denormals: no move at all).
    const Triangle tilted{{2, -1, 0}, {-1, -1, 1}, {-1, 2, -1}};
    const Triangle floor{{-1, 0, 1}, {1, 0, 1}, {0, 0, -2}};
    Rng rng(21, 0);
    for (const Triangle& tri : {tilted, floor}) {
        const vec3 n = glm::normalize(glm::cross(tri.b - tri.a, tri.c - tri.a));
        for (const point3& p : {point3(0, 0, 0), point3(-0.0f, 0, -0.0f)}) {
            for (int k = 0; k < 200; ++k) {
                const vec3 dir = self_intersection::random_in_hemisphere(rng, k % 2 ? n : -n);
                const point3 origin = offset_ray_origin(p, n, dir);
                const double distance = plane_distance(tri, origin);
                const std::optional<TriangleHit<float>> rehit =
                    hit_triangle_watertight(Ray{origin, dir}, tri, Interval{0.0f, infinity});
                INFO(query(p, n, dir) << " on " << show(tri) << " returned " << show(origin) << ", " << distance
                     << " from the plane; expected at least 1e-5 on dir's side, and no re-hit; the feeler from there "
                     << (rehit ? "re-hit it at t = " + std::to_string(rehit->t) : std::string("did not re-hit it")));
                REQUIRE(distance * (k % 2 ? 1.0 : -1.0) >= 1e-5);
                REQUIRE_FALSE(rehit);
            }
        }
    }
}

STABILITY_TEST("offset_ray_origin: at 1e5, where 100000 + 0.00001 == 100000 in float, the origin still leaves the surface", "04.3", 1)
{
    // A fixed 1e-5 along the normal is lost in the rounding there (INFO below shows it); 256 units
    // in the last place (1/128 each at 1e5) are not.
    const Triangle tri{{1e5f, 1e5f, -1e5f}, {1.0001e5f, 1.00003e5f, -1e5f}, {1e5f, 1.00002e5f, -0.99995e5f}};
    const vec3 n = glm::normalize(glm::cross(tri.b - tri.a, tri.c - tri.a));
    const point3 p = triangle_surface_point(tri, TriangleHit<float>{0.0f, 0.3f, 0.3f});
    INFO("at 1e5: p + 1e-5 n == p in float is " << (p + 1e-5f * n == p ? "true" : "false"));
    Rng rng(22, 0);
    for (int k = 0; k < 500; ++k) {
        const vec3 dir = self_intersection::random_in_hemisphere(rng, k % 2 ? n : -n);
        const point3 origin = offset_ray_origin(p, n, dir);
        const double distance = plane_distance(tri, origin);
        const std::optional<TriangleHit<float>> rehit = hit_triangle_watertight(Ray{origin, dir}, tri, Interval{0.0f, infinity});
        INFO(query(p, n, dir) << " on " << show(tri) << " returned " << show(origin) << ", " << distance
             << " from the plane; expected a move to dir's side, and no re-hit; the feeler from there "
             << (rehit ? "re-hit it at t = " + std::to_string(rehit->t) : std::string("did not re-hit it")));
        REQUIRE(origin != p);
        REQUIRE(distance * (k % 2 ? 1.0 : -1.0) > 0.0);
        REQUIRE_FALSE(rehit);
    }
}

GRADED_TEST("offset_ray_origin: a coordinate of exactly 1/32 or -1/32 takes the ulp step, a float nearer 0 the n_i / 65536 step, a float farther the ulp step", "04.3", 2)
{
    // "Below 1/32" is strict: 1/32 itself is moved in its own ulps. Both signs of p_i, both ways
    // along n, and p_i just below a power of two, where 256 ulps cross into the next exponent (the
    // bit pattern's integer addition steps across it; p + 256 ulp(p) does not).
    const float edge = offset_origin;
    const vec3 n = glm::normalize(vec3(0.6f, -0.48f, 0.64f));
    for (const float x : {edge, std::nextafter(edge, 0.0f), std::nextafter(edge, 1.0f)})
        for (const float sign : {1.0f, -1.0f})
            for (const vec3& dir : {n, -n}) {
                const float px = sign * x;
                check_exact(point3(px, px, px), n, dir);
                check_exact(point3(px, -px, std::nextafter(2.0f, 0.0f)), n, dir);
            }
}

GRADED_TEST("offset_ray_origin: n is turned only when n.dir < 0: a dir along the surface (n.dir = 0) keeps n, the least negative n.dir turns it", "04.3", 1)
{
    const point3 p{1.5f, -2.25f, 3.0f};
    // n.dir exactly 0 (dir in the surface's plane), and the smallest negative and positive n.dir.
    const vec3 n{0, 1, 0};
    for (const vec3& dir : {vec3(1, 0, 0), vec3(0.6f, 0.0f, -0.8f), vec3(1.0f, -1e-30f, 0.0f), vec3(1.0f, 1e-30f, 0.0f)}) {
        INFO("n.dir = " << glm::dot(n, dir) << (glm::dot(n, dir) < 0.0f ? ": n is turned to -n" : ": n stays as it is"));
        check_exact(p, n, dir);
    }
}
