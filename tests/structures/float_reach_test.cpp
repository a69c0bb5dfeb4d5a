// Scenes at the edges of what float holds, drawn as double draws them: a floor far wider than the
// eye is high, an eye far from the origin just above a floor, a ground tilted off the axes under a
// light, and meshes far finer than their distance from the origin. Each case asks the given query
// of chapter 04 (closest_hit, the feelers) and the reader, never a structure: the structures are
// held to brute force elsewhere (legal_scenes_test.cpp).
#include "04_shadow_feelers/radiance.hpp"
#include "common/random.hpp"
#include "tests/grader/graded.hpp"

#include <cmath>
#include <string>

using namespace rt;
using namespace rt::grader;

namespace {

// Rays from `eye` toward points of the floor y = 0 around the eye's foot, from `nearest` to `farthest`
// away (log-uniform, seeded): how many miss the floor, or hit it where it is not. Where the float test
// decides, t is as good as its own bound; where double decides, better.
struct FloorRays {
    int misses = 0, far_off = 0;
    std::string first;
};

FloorRays rays_at_floor(const LitScene& floor, const Triangle& tri, const point3& eye, float nearest, float farthest)
{
    FloorRays result;
    Rng rng(50, 1);
    const float octaves = std::log2(farthest / nearest);
    for (int k = 0; k < 2000; ++k) {
        const float r = nearest * std::exp2(octaves * rng.next_float());
        const float angle = 6.2831853f * rng.next_float();
        const point3 target(eye.x + r * std::cos(angle), 0, eye.z + r * std::sin(angle));
        const glm::dvec3 to = glm::dvec3(target) - glm::dvec3(eye);
        const Ray ray{eye, glm::normalize(vec3(to))};
        const std::optional<Hit> hit = closest_hit(ray, floor, Interval{0.0f, infinity});
        const double distance = glm::length(to);
        const double within = std::max(1e-4 * distance, double(watertight_t_error(ray, tri)));
        const bool wrong = !hit || std::abs(hit->t - distance) > within;
        result.misses += hit ? 0 : 1;
        result.far_off += hit && wrong ? 1 : 0;
        if (wrong && result.first.empty())
            result.first = show(ray) + " toward " + show(target) + ": " +
                           (hit ? "t = " + std::to_string(hit->t) : std::string("no hit")) + ", the floor is " +
                           std::to_string(distance) + " away";
    }
    return result;
}

LitScene one_triangle(const Triangle& tri)
{
    LitScene scene;
    scene.add_material({});
    scene.add_triangle(tri, 0);
    return scene;
}

// Every ray from `eye` toward the floor of `tri` (y = 0) hits it where it is.
void check_floor_drawn(const Triangle& tri, const point3& eye, float farthest)
{
    const FloorRays r = rays_at_floor(one_triangle(tri), tri, eye, 0.5f * eye.y, farthest);
    INFO("the eye at " << show(eye) << ": " << r.misses << " of 2000 rays toward the floor missed it, " << r.far_off
                       << " hit it far from where it is; the first: " << r.first);
    CHECK(r.misses == 0);
    CHECK(r.far_off == 0);
}

}  // namespace

TEST_CASE("a floor 1e9 across is drawn from 1e-3 above it, a ratio of 1e12", "[structures]")
{
    // The float test's t for a ray that meets the floor a hair from the eye can round to -0 or below;
    // double must still be asked there, since the floor is certainly in front.
    for (const float height : {1e-3f, 1e-2f, 1.0f})
        check_floor_drawn({{-1e9f, 0, 1e9f}, {1e9f, 0, 1e9f}, {0, 0, -1e9f}}, point3(0, height, 0), 1e8f);
}

TEST_CASE("a floor under an eye 4e6 from the origin and 1 above it is drawn", "[structures]")
{
    // The eye as given is exact: rounding of its coordinates (2^-23 of 4e6 is 0.5) cannot move it
    // across the floor, so nothing sized on those coordinates may refuse the floor's hits.
    for (const float height : {1.0f, 0.25f, 4.0f})
        check_floor_drawn({{-1e7f, 0, 1e7f}, {1e7f, 0, 1e7f}, {0, 0, -1e7f}}, point3(4e6f, height, 0), 5e5f);
}

TEST_CASE("a ground tilted off the axes, 1e4 to 1e6 across through the origin, casts no shadow on itself", "[structures]")
{
    // Its hit points' coordinates are far smaller than its corners' near the origin: a point summed
    // from the corners in float rounds by their float steps (0.01 at 1e5), far more than the offset
    // sized on the point moves it, and its feelers found the ground again.
    for (const float size : {1e4f, 1e5f, 1e6f}) {
        const vec3 n = glm::normalize(vec3(0.01f, 1.0f, 0.02f));
        // Three corners on the plane n.p = 0, around the origin.
        const auto on_plane = [&](float x, float z) { return point3(x, -(n.x * x + n.z * z) / n.y, z); };
        const Triangle tri{on_plane(-size, size), on_plane(size, size), on_plane(0, -size)};
        LitScene ground = one_triangle(tri);
        const point3 light = on_plane(3.0f, -2.0f) + 50.0f * n;
        Rng rng(51, 2);
        int hits = 0, shadowed = 0;
        std::string first;
        for (int k = 0; k < 4000; ++k) {
            // Eyes 1 to 1e3 above the ground near the origin, looking down at points within 1e3.
            const float height = std::exp2(10.0f * rng.next_float());
            const point3 eye = on_plane(200.0f * rng.next_float() - 100.0f, 200.0f * rng.next_float() - 100.0f) + height * n;
            const point3 target = on_plane(std::exp2(10.0f * rng.next_float()) - 1.0f, 40.0f * rng.next_float() - 20.0f);
            const Ray ray{eye, glm::normalize(target - eye)};
            const std::optional<Hit> hit = closest_hit(ray, ground, Interval{0.0f, infinity});
            if (!hit)
                continue;
            ++hits;
            if (light_blocked(ground, *hit, light, FeelerSettings{}) && shadowed++ == 0)
                first = "the feeler from " + show(hit->p) + " toward " + show(light) + " (" + show(ray) + ")";
        }
        INFO("a tilted ground " << size << " across: " << shadowed << " of " << hits
                                << " points found it in the way of the light; the first: " << first);
        CHECK(hits > 3000);
        CHECK(shadowed == 0);
    }
}
