// EXERCISE 06.3: the thin-lens ray: from a point of the lens, drawn from the pixel's stream,
// through the point where the pixel's pinhole ray meets the plane of sharp focus.
#include "tests/ch06/describe.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <vector>

using namespace rt;
using namespace rt::grader;

namespace {

bool same_bits(const vec3& a, const vec3& b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// The first two numbers `rng` will give, as the lens sample s, without touching rng.
point2 next_two(const Rng& rng)
{
    Rng copy = rng;
    const float x = copy.next_float();
    return {x, copy.next_float()};
}

// Whether `rng` has drawn exactly `drawn` numbers since it was `before`.
bool drew(const Rng& before, const Rng& after, int drawn)
{
    Rng b = before, a = after;
    for (int k = 0; k < drawn; ++k)
        b.next_u32();
    return b.next_u32() == a.next_u32() && b.next_u32() == a.next_u32();
}

// The lens point of a ray, in the lens's own coordinates (along u and v from the eye), and how far
// off the lens's plane it lies (along w).
struct OnLens {
    glm::dvec2 uv;
    double off_plane;
};

OnLens on_lens(const Camera& cam, const Ray& ray)
{
    const dvec3 d = to_double(ray.origin) - to_double(cam.eye);
    return {{glm::dot(d, to_double(cam.u)), glm::dot(d, to_double(cam.v))}, glm::dot(d, to_double(cam.w))};
}

}  // namespace

GRADED_TEST("with an aperture of 0 the ray is primary_ray's, bit for bit, and nothing is drawn from the stream", "06.3", 3)
{
    Rng cases(6, 4);
    for (int k = 0; k < 50; ++k) {
        LensCase c = random_lens_case(cases);
        c.lens.aperture_radius = 0.0f;
        Rng rng(7, static_cast<std::uint64_t>(k));
        const Rng before = rng;
        const Ray got = thin_lens_ray(c.cam, c.lens, c.x, c.y, rng);
        const Ray want = primary_ray(c.cam, c.x, c.y);
        INFO(show(c) << " (a pinhole): got " << show(got) << ", expected primary_ray's " << show(want)
             << " exactly, and the stream untouched");
        REQUIRE(same_bits(got.origin, want.origin));
        REQUIRE(same_bits(got.dir, want.dir));
        REQUIRE(drew(before, rng, 0));
    }
}

GRADED_TEST("a ray leaves eye + R (d.x u + d.y v), d = concentric_disc of the stream's next two numbers, toward focal_point", "06.3", 4)
{
    // Measured against your own concentric_disc (06.1) and focal_point (06.2): this case checks how
    // the ray is put together, so a mistake in either costs points there.
    Rng cases(6, 5);
    for (int k = 0; k < 100; ++k) {
        const LensCase c = random_lens_case(cases);
        const Camera& cam = c.cam;
        Rng rng(8, static_cast<std::uint64_t>(k));
        const Rng before = rng;
        const point2 s = next_two(rng);
        const point2 d = concentric_disc(s);
        const Ray got = thin_lens_ray(cam, c.lens, c.x, c.y, rng);
        const point3 lens_point = cam.eye + c.lens.aperture_radius * (d.x * cam.u + d.y * cam.v);
        const point3 focus = focal_point(cam, c.lens, primary_ray(cam, c.x, c.y));
        const vec3 want_dir = glm::normalize(focus - lens_point);
        INFO(show(c) << ", the stream's next two numbers s = " << show(s) << ", concentric_disc(s) = " << show(d)
             << ": got " << show(got) << "; expected the ray from the lens point " << show(lens_point)
             << " toward the focal point " << show(focus) << ", along " << show(want_dir)
             << ", with exactly two numbers drawn"
             << (focus == lens_point ? " (your focal_point gave the lens point itself, so there is no direction to "
                                       "it: EXERCISE 06.2 first)"
                                     : ""));
        REQUIRE(glm::length(got.origin - lens_point) <= 1e-6f * (glm::length(cam.eye) + c.lens.aperture_radius));
        REQUIRE(std::abs(glm::length(got.dir) - 1.0f) <= 1e-6f);
        REQUIRE(glm::length(got.dir - want_dir) <= 1e-5f);
        REQUIRE(drew(before, rng, 2));
    }
}

GRADED_TEST("the rays of one pixel all cross at one point of the plane of focus, where its pinhole ray meets it", "06.3", 3)
{
    Rng cases(6, 6);
    for (int k = 0; k < 40; ++k) {
        const LensCase c = random_lens_case(cases);
        const dvec3 want = focal_point_reference(c.cam, c.lens.focus_distance, primary_ray(c.cam, c.x, c.y).dir);
        Rng rng(9, static_cast<std::uint64_t>(k));
        for (int sample = 0; sample < 32; ++sample) {
            const Ray ray = thin_lens_ray(c.cam, c.lens, c.x, c.y, rng);
            const dvec3 got = at_depth(c.cam, ray, c.lens.focus_distance);
            // The lens point's and the direction's rounding, carried over the distance to the plane.
            const double tolerance =
                4e-6 * (glm::length(to_double(c.cam.eye)) + glm::length(want - to_double(c.cam.eye)));
            INFO(show(c) << ", sample " << sample << ": " << show(ray) << " crosses the plane of focus at "
                 << show(vec3(got)) << ", " << glm::length(got - want) << " from where the pinhole ray does, "
                 << show(vec3(want)) << ": every ray of a pixel must pass through that point, so the plane of focus "
                 "stays sharp");
            REQUIRE(glm::length(got - want) <= tolerance);
        }
    }
}

GRADED_TEST("at depth d the rays of one pixel spread over the circle of confusion, radius R abs(d - F) / F around the pinhole ray", "06.3", 2)
{
    // By similar triangles: a ray from lens point L (|L| <= R) through the focal point P at depth F
    // is at depth d at P d / F + L (1 - d / F), so the pixel's rays cover a disc of radius
    // R |1 - d / F| there, uniformly when the lens points are uniform: the mean squared distance
    // from the centre is then half the squared radius (within 5%: 4000 samples estimate it to 0.9%).
    const Camera cam = make_camera(CameraSpec{{0.5f, 1.0f, 4.0f}, {0.0f, 0.6f, -2.0f}, {0, 1, 0}, 45.0f, 32, 24});
    const ThinLens lens{0.25f, 6.0f};
    const float x = 21.3f, y = 5.7f;
    const Ray pinhole = primary_ray(cam, x, y);
    for (const double depth : {2.0, 12.0, 30.0}) {
        const double radius = lens.aperture_radius * std::abs(depth - lens.focus_distance) / lens.focus_distance;
        const dvec3 centre = at_depth(cam, pinhole, depth);
        Rng rng(10, 0);
        double farthest = 0.0, mean_square = 0.0;
        const int samples = 4000;
        for (int k = 0; k < samples; ++k) {
            const double r = glm::length(at_depth(cam, thin_lens_ray(cam, lens, x, y, rng), depth) - centre);
            farthest = std::max(farthest, r);
            mean_square += r * r / samples;
        }
        INFO(show(cam) << ", " << show(lens) << ", pixel position (" << x << ", " << y << "), " << samples
             << " rays: at depth " << depth << " they lie up to " << farthest << " from the pinhole ray's point, with a "
             "mean squared distance of " << mean_square << "; expected a disc of radius R |d - F| / F = " << radius
             << " (the circle of confusion), filled evenly: at most " << radius << ", and a mean square of "
             << radius * radius / 2);
        CHECK(farthest <= radius * (1.0 + 1e-4));
        CHECK(farthest >= radius * 0.97);
        CHECK(std::abs(mean_square - radius * radius / 2) <= 0.05 * radius * radius / 2);
    }
}

GRADED_TEST("successive rays draw fresh lens points from the stream given, spread evenly over the aperture", "06.3", 2)
{
    // The same pixel, 4000 times from one stream: the lens points must fill the disc of radius R
    // evenly (a quarter in each quadrant of u and v, mean squared distance R^2 / 2), and two
    // pixels' streams must give them different lens points.
    const Camera cam = make_camera(CameraSpec{{3, 1, 2}, {0, 0.5f, -4}, {0, 1, 0}, 50.0f, 40, 30});
    const ThinLens lens{0.4f, 5.0f};
    const int samples = 4000;
    Rng rng = pixel_rng(1, 12, 7, cam.nx);
    std::array<int, 4> quadrants{};
    double farthest = 0.0, mean_square = 0.0;
    for (int k = 0; k < samples; ++k) {
        const OnLens p = on_lens(cam, thin_lens_ray(cam, lens, 12, 7, rng));
        farthest = std::max(farthest, glm::length(p.uv));
        mean_square += glm::dot(p.uv, p.uv) / samples;
        ++quadrants[(p.uv.x >= 0 ? 0 : 1) + (p.uv.y >= 0 ? 0 : 2)];
    }
    const double r2 = double(lens.aperture_radius) * lens.aperture_radius;
    INFO(show(cam) << ", " << show(lens) << ", pixel (12, 7), " << samples << " rays from its stream: the lens points "
         "lie up to " << farthest << " from the eye, with a mean squared distance of " << mean_square
         << ", and fall in the quadrants of u and v " << quadrants[0] << ", " << quadrants[1] << ", " << quadrants[2]
         << ", " << quadrants[3] << "; expected at most R = " << lens.aperture_radius << ", a mean square of R^2 / 2 = "
         << r2 / 2 << " (within 5%) and about " << samples / 4 << " in each quadrant (within 140)");
    CHECK(farthest <= lens.aperture_radius * (1.0 + 1e-5));
    CHECK(std::abs(mean_square - r2 / 2) <= 0.05 * r2 / 2);
    int worst_quadrant = 0;
    for (const int q : quadrants)
        worst_quadrant = std::max(worst_quadrant, std::abs(q - samples / 4));
    CHECK(worst_quadrant <= 140);  // 5 standard deviations of a binomial count

    Rng first = pixel_rng(1, 0, 0, cam.nx), second = pixel_rng(1, 1, 0, cam.nx);
    const OnLens a = on_lens(cam, thin_lens_ray(cam, lens, 0, 0, first));
    const OnLens b = on_lens(cam, thin_lens_ray(cam, lens, 1, 0, second));
    INFO("pixels (0, 0) and (1, 0), each with its own stream, got the lens points " << show(point2(a.uv)) << " and "
         << show(point2(b.uv)) << ": they must differ, or every pixel blurs the same way and the picture shows it");
    CHECK(a.uv != b.uv);
}

STABILITY_TEST("tiny scenes and cameras far from the origin keep every ray unit, finite and through the focal point", "06.3", 2)
{
    struct Case {
        const char* what;
        CameraSpec spec;
        ThinLens lens;
    };
    const std::vector<Case> cases = {
        {"a scene 1e-4 across", {{1e-4f, 2e-4f, 3e-4f}, {0, 0, -5e-4f}, {0, 1, 0}, 50.0f, 16, 12}, {2e-6f, 7e-4f}},
        {"an eye 2.3e5 from the origin", {{1e5f, -2e5f, 3e4f}, {1e5f + 3, -2e5f + 1, 3e4f - 4}, {0, 1, 0}, 50.0f, 16, 12}, {0.5f, 20.0f}},
        {"a huge lens focused 1e6 away", {{0, 1, 0}, {0, 1, -1}, {0, 1, 0}, 50.0f, 16, 12}, {1e3f, 1e6f}},
        {"a lens of radius 1e-30", {{0, 1, 0}, {0, 1, -1}, {0, 1, 0}, 50.0f, 16, 12}, {1e-30f, 3.0f}},
    };
    for (const Case& c : cases) {
        const Camera cam = make_camera(c.spec);
        Rng rng(11, 0);
        for (int k = 0; k < 200; ++k) {
            const float x = 15.0f * rng.next_float(), y = 11.0f * rng.next_float();
            const Ray ray = thin_lens_ray(cam, c.lens, x, y, rng);
            const dvec3 want = focal_point_reference(cam, c.lens.focus_distance, primary_ray(cam, x, y).dir);
            const dvec3 got = at_depth(cam, ray, c.lens.focus_distance);
            // Float's rounding of the eye's coordinates, of the lens offset and of the distance to
            // the plane, each carried to the plane: 4e-6 of their sum is a few dozen units in the last place.
            const double tolerance = 4e-6 * (glm::length(to_double(cam.eye)) + c.lens.aperture_radius +
                                             glm::length(want - to_double(cam.eye)));
            INFO(c.what << ": " << show(cam) << ", " << show(c.lens) << ", pixel position (" << x << ", " << y << "): "
                 << show(ray) << " crosses the plane of focus at " << show(vec3(got)) << ", expected "
                 << show(vec3(want)) << ", a unit and finite direction");
            REQUIRE((finite(ray.origin) && finite(ray.dir)));
            REQUIRE(std::abs(glm::length(ray.dir) - 1.0f) <= 1e-6f);
            REQUIRE(glm::length(got - want) <= tolerance);
        }
    }
}

GRADED_TEST("an aperture of -0 is the pinhole too; one the least bit above 0 is a lens: two numbers drawn, the ray from its lens point through the focal point", "06.3", 1)
{
    // "aperture_radius = 0" is the test: -0 compares equal to 0, and a radius of 1e-30 (or the
    // least float) is not 0, however small the lens. A threshold (R < 1e-6 taken as a pinhole)
    // draws nothing where the contract draws two numbers, and shifts every later pixel's samples.
    Rng cases(6, 9);
    for (int k = 0; k < 20; ++k) {
        LensCase c = random_lens_case(cases);
        for (const float radius : {-0.0f, 1e-30f, std::numeric_limits<float>::denorm_min()}) {
            c.lens.aperture_radius = radius;
            Rng rng(9, static_cast<std::uint64_t>(k));
            const Rng before = rng;
            const Ray got = thin_lens_ray(c.cam, c.lens, c.x, c.y, rng);
            const Ray pinhole = primary_ray(c.cam, c.x, c.y);
            const bool lens = radius != 0.0f;
            const point3 focus = focal_point(c.cam, c.lens, pinhole);
            const vec3 want_dir = lens ? glm::normalize(focus - c.cam.eye) : pinhole.dir;
            INFO("thin_lens_ray with " << show(c) << ": got " << show(got) << " after drawing "
                 << (drew(before, rng, 0) ? "0" : drew(before, rng, 2) ? "2" : "neither 0 nor 2") << " numbers; expected "
                 << (lens ? "a lens (R is not 0): two numbers drawn, the ray from the eye (R d is below float's reach) "
                            "toward the focal point " + show(focus) + ", along " + show(want_dir)
                          : "the pinhole (R = -0 equals 0): primary_ray's " + show(pinhole) + " bit for bit, nothing drawn"));
            if (lens) {
                REQUIRE(drew(before, rng, 2));
                REQUIRE(glm::length(got.origin - c.cam.eye) <= 1e-6f * glm::length(c.cam.eye));
                REQUIRE(glm::length(got.dir - want_dir) <= 1e-5f);
            } else {
                REQUIRE(drew(before, rng, 0));
                REQUIRE(same_bits(got.origin, pinhole.origin));
                REQUIRE(same_bits(got.dir, pinhole.dir));
            }
        }
    }
}
