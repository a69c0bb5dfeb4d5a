// EXERCISE 05.2: a point of the unit square to a point of a disc light, preserving area.
//
// Any area-preserving map passes (the concentric map, the polar map with r = sqrt(u.x)): the cases
// check where the points land and how they spread, not which point each u gives.
#include "tests/ch05/describe.hpp"

#include <cmath>
#include <vector>

using namespace rt;
using namespace rt::grader;

namespace {

// A disc of radius 0.8 tilted toward the scene, away from the origin, and one facing straight down.
const AreaLight tilted_disc = disc_light({1.5f, 4.0f, -2.0f}, glm::normalize(vec3(-0.3f, -0.9f, 0.3f)), 0.8f, color(1.0f));
const AreaLight ceiling_disc = disc_light({0.0f, 3.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.5f, color(1.0f));

constexpr int draws = 40000;
// A share p of `draws` points has the binomial standard error sqrt(p (1 - p) / draws); 5 of them
// makes a false failure about one in a million per bin (and the seeded draws never change).
constexpr double bin_z_allowed = 5.0;

double standard_error(double p)
{
    return std::sqrt(p * (1.0 - p) / draws);
}

// Where the points of `draws` uniform u land: in the disc's frame, radius as a fraction of its own.
struct Landing {
    double x, y, r;
};

std::vector<Landing> landings(const AreaLight& light, std::uint64_t seed)
{
    std::vector<Landing> out;
    Rng rng(seed, 0);
    for (int k = 0; k < draws; ++k) {
        const sample2 u{rng.next_float(), rng.next_float()};
        const OnLight on = on_light(light, point_on_disc(light, u));
        out.push_back({on.x, on.y, std::hypot(on.x, on.y)});
    }
    return out;
}

}  // namespace

GRADED_TEST("point_on_disc: every point lies on the disc, in its plane and within its radius, and the points reach its rim", "05.2", 2)
{
    Rng rng(53, 0);
    std::vector<sample2> us = {{0.0f, 0.0f}, {0.5f, 0.5f}, {one_minus_epsilon, 0.0f}, {0.0f, one_minus_epsilon},
                               {one_minus_epsilon, one_minus_epsilon}, {0.5f, 0.0f}, {0.25f, 0.9f}};
    for (int k = 0; k < 2000; ++k)
        us.push_back({rng.next_float(), rng.next_float()});
    for (const AreaLight& light : {tilted_disc, ceiling_disc}) {
        double outer = 0.0;
        for (const sample2 u : us) {
            const point3 got = point_on_disc(light, u);
            const OnLight on = on_light(light, got);
            const double r = std::hypot(on.x, on.y);
            INFO(show(light) << ", " << show(u) << ": got " << show(got) << ", " << r << " radii from the centre and "
                 << on.off_plane << " off the disc's plane; expected at most 1 radius and 0 off the plane "
                 << "(centre + x axis_u + y axis_v with x^2 + y^2 <= 1)");
            REQUIRE(std::isfinite(r));
            REQUIRE(r <= 1.0 + 1e-5);
            REQUIRE(std::abs(on.off_plane) <= 1e-5);
            outer = std::max(outer, r);
        }
        INFO(show(light) << ": of " << us.size() << " points u, the farthest landed " << outer
             << " radii from the centre; expected beyond 0.99: the whole disc, not a smaller one");
        CHECK(outer >= 0.99);
    }
}

GRADED_TEST("point_on_disc: area-preserving, the share of points within r sqrt(k/8) of the centre is k/8", "05.2", 3)
{
    // A ring of the disc from radius sqrt((k-1)/8) to sqrt(k/8) has 1/8 of its area: uniform points
    // put 1/8 of themselves there. r = u.x would put a quarter of them in the first two rings'
    // half-radius, r = u.x^2 even more.
    for (const AreaLight& light : {tilted_disc, ceiling_disc}) {
        const std::vector<Landing> points = landings(light, 54);
        std::vector<int> rings(8, 0);
        for (const Landing& p : points)
            ++rings[std::min(7, static_cast<int>(p.r * p.r * 8.0))];
        for (int k = 0; k < 8; ++k) {
            const double share = static_cast<double>(rings[k]) / draws;
            INFO(show(light) << ": of " << draws << " uniform u, a share " << share << " landed between "
                 << std::sqrt(k / 8.0) << " and " << std::sqrt((k + 1) / 8.0) << " radii from the centre, "
                 << "an eighth of the disc's area; expected 0.125 within " << bin_z_allowed * standard_error(0.125)
                 << " (5 standard errors). Shares per ring: " << rings[0] << ' ' << rings[1] << ' ' << rings[2] << ' '
                 << rings[3] << ' ' << rings[4] << ' ' << rings[5] << ' ' << rings[6] << ' ' << rings[7]);
            CHECK(std::abs(share - 0.125) <= bin_z_allowed * standard_error(0.125));
        }
    }
}

GRADED_TEST("point_on_disc: the angle is uniform too, each of 8 sectors gets an eighth of the points", "05.2", 2)
{
    constexpr double pi = 3.14159265358979323846;
    for (const AreaLight& light : {tilted_disc, ceiling_disc}) {
        const std::vector<Landing> points = landings(light, 55);
        std::vector<int> sectors(8, 0);
        for (const Landing& p : points) {
            const double turn = (std::atan2(p.y, p.x) + pi) / (2.0 * pi);  // 0 .. 1 around the disc
            ++sectors[std::min(7, static_cast<int>(turn * 8.0))];
        }
        for (int k = 0; k < 8; ++k) {
            const double share = static_cast<double>(sectors[k]) / draws;
            INFO(show(light) << ": of " << draws << " uniform u, a share " << share << " landed in the sector from "
                 << -180 + 45 * k << " to " << -135 + 45 * k << " degrees around axis_u; expected 0.125 within "
                 << bin_z_allowed * standard_error(0.125));
            CHECK(std::abs(share - 0.125) <= bin_z_allowed * standard_error(0.125));
        }
    }
}

GRADED_TEST("point_on_disc: u a hair apart land a hair apart, across the square's middle lines and diagonals too", "05.2", 2)
{
    // Both area-preserving maps are continuous inside the square: a step of 2^-20 in u moves the
    // point at most about 1e-3 radii (the polar map's sqrt near u.x = 0; the concentric map's far
    // less). A map that sends a middle line to the centre (a = 0 or b = 0 taken for a = b = 0), or
    // turns a quarter over (its angle running the other way), jumps there: rings and sectors, whose
    // shares count areas, never see it.
    constexpr float step = 0x1p-20f;
    constexpr double allowed = 0.01;
    std::vector<float> coords = {0.0f, 0.5f, std::nextafter(0.5f, 0.0f), 0.25f, 0.75f, 0.9f, 0.1f, 1.0f - 2 * step};
    Rng rng(57, 0);
    for (int k = 0; k < 12; ++k)
        coords.push_back(rng.next_float() * (1.0f - 2 * step));
    for (const AreaLight& light : {tilted_disc, ceiling_disc}) {
        double farthest = 0.0;  // a map that sends every u to one point is continuous, but no map of the disc
        for (const float x : coords)
            for (const float y : coords)
                for (const sample2 u : {sample2(x, y), sample2(x, x), sample2(x, 1.0f - 2 * step - x)})
                    for (const sample2 v : {sample2(u.x + step, u.y), sample2(u.x, u.y + step)}) {
                        const OnLight a = on_light(light, point_on_disc(light, u)), b = on_light(light, point_on_disc(light, v));
                        farthest = std::max(farthest, std::hypot(a.x, a.y));
                        const double apart = std::hypot(a.x - b.x, a.y - b.y);
                        INFO(show(light) << ": " << show(u) << " landed at (" << a.x << ", " << a.y << ") and " << show(v)
                             << ", 2^-20 away, at (" << b.x << ", " << b.y << ") radii: " << apart
                             << " apart; expected at most " << allowed);
                        REQUIRE(apart <= allowed);
                    }
        INFO(show(light) << ": the farthest of these points landed " << farthest << " radii from the centre; expected them "
             << "spread over the disc, some beyond 0.9");
        REQUIRE(farthest > 0.9);
    }
}

STABILITY_TEST("point_on_disc: never a NaN, at the square's centre (0/0 in the concentric map), corners and edges; its far corner on the rim", "05.2", 1)
{
    const float below_half = std::nextafter(0.5f, 0.0f), above_half = std::nextafter(0.5f, 1.0f);
    for (const sample2 u : {sample2(0.5f, 0.5f), sample2(below_half, 0.5f), sample2(0.5f, above_half),
                            sample2(below_half, above_half), sample2(0.0f, 0.0f), sample2(one_minus_epsilon),
                            sample2(0.0f, 0.5f), sample2(0.5f, one_minus_epsilon), sample2(1e-30f, 0.5f)}) {
        const point3 got = point_on_disc(tilted_disc, u);
        const OnLight on = on_light(tilted_disc, got);
        INFO(show(tilted_disc) << ", " << show(u) << ": got " << show(got) << "; expected a point of the disc, finite");
        REQUIRE((std::isfinite(got.x) && std::isfinite(got.y) && std::isfinite(got.z)));
        REQUIRE(std::hypot(on.x, on.y) <= 1.0 + 1e-5);
    }
    // The square's far corner lands on the rim, under either area-preserving map.
    const OnLight corner = on_light(tilted_disc, point_on_disc(tilted_disc, sample2(one_minus_epsilon)));
    INFO(show(tilted_disc) << ": the square's far corner u = (one_minus_epsilon, one_minus_epsilon) landed "
         << std::hypot(corner.x, corner.y) << " radii from the centre; expected the rim, 1");
    CHECK(std::abs(std::hypot(corner.x, corner.y) - 1.0) <= 1e-5);
}

GRADED_TEST("point_on_disc: uniform points on the disc, each of 4 rings by 16 sectors (64 cells of equal area) gets 1/64 of them", "05.2", 2)
{
    // Uniform over the whole disc, not only ring by ring and sector by sector: the cells between
    // radii sqrt((i-1)/4) and sqrt(i/4) and angles 22.5 degrees apart all have the area pi / 64. A
    // map whose angles crowd toward the axes inside each quarter (phi = (pi / 4) (a b) for a / b)
    // keeps the 8 sectors even but not their halves.
    constexpr double pi = 3.14159265358979323846;
    constexpr int cells_draws = 100000;
    const double p = 1.0 / 64.0, allowed = bin_z_allowed * std::sqrt(p * (1.0 - p) / cells_draws);
    for (const AreaLight& light : {tilted_disc, ceiling_disc}) {
        Rng rng(56, 0);
        std::vector<int> cells(64, 0);
        for (int k = 0; k < cells_draws; ++k) {
            const sample2 u{rng.next_float(), rng.next_float()};
            const OnLight on = on_light(light, point_on_disc(light, u));
            const double r2 = on.x * on.x + on.y * on.y;
            const double turn = (std::atan2(on.y, on.x) + pi) / (2.0 * pi);
            const int ring = std::min(3, static_cast<int>(r2 * 4.0)), sector = std::min(15, static_cast<int>(turn * 16.0));
            ++cells[ring * 16 + sector];
        }
        for (int c = 0; c < 64; ++c) {
            const double share = static_cast<double>(cells[c]) / cells_draws;
            INFO(show(light) << ": of " << cells_draws << " uniform u, a share " << share << " landed between "
                 << std::sqrt((c / 16) / 4.0) << " and " << std::sqrt((c / 16 + 1) / 4.0) << " radii from the centre and "
                 << -180 + 22.5 * (c % 16) << " to " << -157.5 + 22.5 * (c % 16) << " degrees around axis_u, a 64th of "
                 << "the disc's area; expected " << p << " within " << allowed << " (5 standard errors)");
            CHECK(std::abs(share - p) <= allowed);
        }
    }
}
