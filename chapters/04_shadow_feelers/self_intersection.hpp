// Self-intersection measured: how often a ray leaving a hit point re-finds its own surface, and how
// often it jumps past a real occluder, for each way of starting it (Offset), on one scene scaled
// from 1e-4 to 1e6. The program's table (--sweep) prints these rates; the stability tests assert
// the kit's goal on them (zero re-hits at every scale, an occluder 0.25 S above the
// surface still found).
//
// The scene at scale S, every length multiplied by S (so its coordinates grow with it, as a scene
// modelled in millimetres or kilometres does): a surface of radius S/2 centred at S (1, 2, -3),
// either an icosphere of 320 triangles or a true sphere, inside a spherical shell of radius 3S/4,
// the occluder 0.25 S above the surface. Beside them, the case where Wachter and Binder's offset
// meets its limit: a floor through y = 0, a square 20 S across centred on the origin, under a plane
// at y = S/4. Hit points come from rays shot at the surface from 3 S away (or farther), with their
// points computed from the surface (radiance.hpp) or, to show why, from ray.at(t); from each,
// one feeler leaves on the front side (toward a light outside) or on the back side (into the
// object, as a refracted ray would), in a direction uniform over that hemisphere, grazing ones
// included.
//
// Cases are seeded, so a run repeats exactly.
#pragma once

#include "01_ray_casting/01_ray_casting.hpp"
#include "02_spheres_triangles/extremes.hpp"
#include "04_shadow_feelers/radiance.hpp"

#include <array>
#include <cassert>
#include <cstdint>
#include <vector>

namespace rt::self_intersection {

// The scales S measured: every power of ten from 1e-4 to 1e6.
constexpr std::array<float, 11> scales = {1e-4f, 1e-3f, 1e-2f, 1e-1f, 1.0f, 1e1f, 1e2f, 1e3f, 1e4f, 1e5f, 1e6f};

enum class Surface { triangles, sphere, floor };
enum class Side { front, back };

struct ScaledScene {
    float scale;
    point3 centre;
    IndexedMesh mesh;  // the surface as triangles
    Sphere sphere;     // the surface as a sphere
    Sphere shell;      // the occluder around either
    IndexedMesh floor; // a floor through y = 0, 20 S square, centred on the origin
    Plane ceiling;     // the occluder above it, y = S / 4
};

inline ScaledScene scaled_scene(float scale)
{
    const point3 centre = scale * point3(1.0f, 2.0f, -3.0f);
    IndexedMesh floor;
    floor.vertices = {scale * point3(-10, 0, 10), scale * point3(10, 0, 10), scale * point3(10, 0, -10),
                      scale * point3(-10, 0, -10)};
    floor.faces = {{0, 1, 2}, {0, 2, 3}};
    return {scale, centre, icosphere(centre, 0.5f * scale, 2), {centre, 0.5f * scale}, {centre, 0.75f * scale},
            floor, Plane{{0.0f, 0.25f * scale, 0.0f}, {0.0f, 1.0f, 0.0f}}};
}

// A hit point on the surface: p as closest_hit computes it, the geometric normal, and the triangle
// it lies on (on the icosphere or the floor; -1 on the sphere).
struct SurfacePoint {
    point3 p;
    vec3 n;
    Surface surface;
    int face;
};

// Where the hit point comes from: the surface (the kit's way), or ray.at(t), to measure why not.
enum class PointFrom { surface, ray };

// A unit vector uniform over the hemisphere around the unit vector `axis`.
inline vec3 random_in_hemisphere(Rng& rng, const vec3& axis)
{
    const vec3 d = extremes::random_unit_vector(rng);
    return glm::dot(d, axis) < 0.0f ? -d : d;
}

inline std::vector<SurfacePoint> surface_points(const ScaledScene& scene, Surface surface, int count,
                                                std::uint64_t seed, PointFrom from = PointFrom::surface,
                                                float eye_distance = 3.0f)
{
    std::vector<SurfacePoint> points;
    Rng rng(seed, 40);
    // Aimed rays miss only within rounding of an edge, rarely; a hit test that misses them all (a
    // stub, a mistake) must end the search rather than loop, and its caller sees fewer points.
    const long long most_tries = 4LL * count + 64;
    for (long long tries = 0; static_cast<int>(points.size()) < count && tries < most_tries; ++tries) {
        if (surface == Surface::sphere) {
            const vec3 outward = extremes::random_unit_vector(rng);
            const point3 target = scene.centre + scene.sphere.radius * outward;
            const Ray ray = extremes::ray_towards<float>(target + eye_distance * scene.scale * random_in_hemisphere(rng, outward), target);
            const std::optional<float> t = hit_sphere_precise(ray, scene.sphere, Interval{0.0f, infinity});
            if (!t)
                continue;
            const point3 p = from == PointFrom::surface ? sphere_surface_point(scene.sphere, ray.at(*t)) : ray.at(*t);
            points.push_back({p, sphere_normal(scene.sphere, p), surface, -1});
            continue;
        }
        const IndexedMesh& mesh = surface == Surface::floor ? scene.floor : scene.mesh;
        const int faces = static_cast<int>(mesh.faces.size());
        const int f = std::min(faces - 1, static_cast<int>(rng.next_float() * static_cast<float>(faces)));
        const Triangle tri = triangle_of(mesh, f);
        float beta = rng.next_float(), gamma = rng.next_float();
        if (beta + gamma > 1.0f) {  // fold the square onto the triangle: uniform over it
            beta = 1.0f - beta;
            gamma = 1.0f - gamma;
        }
        const point3 target = tri.a + beta * (tri.b - tri.a) + gamma * (tri.c - tri.a);
        const vec3 n = face_normal(tri);
        const Ray ray = extremes::ray_towards<float>(target + eye_distance * scene.scale * random_in_hemisphere(rng, n), target);
        const std::optional<TriangleHit<float>> hit = hit_triangle_watertight(ray, tri, Interval{0.0f, infinity});
        if (!hit)
            continue;  // a target within rounding of an edge, on the other side of it
        points.push_back({from == PointFrom::surface ? triangle_surface_point(tri, *hit) : ray.at(hit->t), n, surface, f});
    }
    return points;
}

struct Score {
    std::uint64_t feelers = 0;
    std::uint64_t rehits = 0;          // feelers that found their own surface again
    std::uint64_t occluder_tests = 0;  // front-side feelers, each of which must find the occluder
    std::uint64_t missed = 0;          // ... and did not: they started beyond it, or t_min skipped it
    size_t first_rehit = npos, first_missed = npos;  // which feeler, for a test's failure message
    static constexpr size_t npos = static_cast<size_t>(-1);

    double rehit_rate() const { return feelers ? static_cast<double>(rehits) / static_cast<double>(feelers) : 0.0; }
    double missed_rate() const
    {
        return occluder_tests ? static_cast<double>(missed) / static_cast<double>(occluder_tests) : 0.0;
    }
};

// One feeler of the measurement: the point it leaves, and the ray and range it is sent with.
struct Feeler {
    SurfacePoint from;
    Ray ray;
    Interval range;
};

// The feeler that leaves `point` on `side`, started as `offset` says, its direction drawn from rng.
inline Feeler feeler_from(const SurfacePoint& point, Side side, Offset offset, Rng& rng)
{
    const vec3 d = random_in_hemisphere(rng, side == Side::front ? point.n : -point.n);
    const RayStart start = ray_start(point.p, point.n, d, offset);
    return {point, Ray{start.origin, d}, Interval{start.t_min, infinity}};
}

// Which triangle test the feeler meets its own surface with: chapter 02's watertight test as it is
// (the offsets' own measure), or refusing hits within its rounding of t = 0 (the kit's, lit_tests).
enum class Test { watertight, bounded };

inline bool hits_triangle(const Feeler& f, const Triangle& tri, Test test)
{
    return test == Test::bounded ? hit_triangle(f.ray, tri, f.range, TriangleTest::watertight_bounded).has_value()
                                 : hit_triangle_watertight(f.ray, tri, f.range).has_value();
}

inline bool rehits(const ScaledScene& scene, const Feeler& f, Test test = Test::watertight)
{
    switch (f.from.surface) {
    case Surface::sphere:
        return hit_sphere_precise(f.ray, scene.sphere, f.range).has_value();
    case Surface::triangles:
        return hits_triangle(f, triangle_of(scene.mesh, f.from.face), test);
    case Surface::floor:
        return hits_triangle(f, triangle_of(scene.floor, f.from.face), test);
    }
    return false;  // not reached: the switch names every surface
}

// A front-side feeler must meet the occluder 0.25 S above the surface: the shell around the
// icosphere or sphere, the plane above the floor (chapter 01's hit_plane).
inline bool finds_occluder(const ScaledScene& scene, const Feeler& f)
{
    if (f.from.surface == Surface::floor)
        return hit_plane(f.ray, scene.ceiling, f.range).has_value();
    return hit_sphere_precise(f.ray, scene.shell, f.range).has_value();
}

// On the sphere only front-side feelers are measured: one into the sphere meets its far side for
// real, which a re-hit could not be told from when it grazes.
inline Score measure(const ScaledScene& scene, const std::vector<SurfacePoint>& points, Offset offset, Side side,
                     std::uint64_t seed, Test test = Test::watertight)
{
    Score s;
    Rng rng(seed, 41);
    for (size_t k = 0; k < points.size(); ++k) {
        assert(side == Side::front || points[k].surface != Surface::sphere);
        const Feeler f = feeler_from(points[k], side, offset, rng);
        ++s.feelers;
        if (rehits(scene, f, test) && s.rehits++ == 0)
            s.first_rehit = k;
        if (side == Side::front) {
            ++s.occluder_tests;
            if (!finds_occluder(scene, f) && s.missed++ == 0)
                s.first_missed = k;
        }
    }
    return s;
}

// The feeler of measure()'s k-th point, again: for a test's failure message.
inline Feeler replay(const std::vector<SurfacePoint>& points, size_t k, Offset offset, Side side, std::uint64_t seed)
{
    Rng rng(seed, 41);
    Feeler f{};
    for (size_t j = 0; j <= k; ++j)
        f = feeler_from(points[j], side, offset, rng);
    return f;
}

}  // namespace rt::self_intersection
