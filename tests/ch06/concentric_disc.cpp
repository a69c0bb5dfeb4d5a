// EXERCISE 06.1: Shirley and Chiu's concentric map from the unit square onto the unit disc.
#include "tests/ch06/describe.hpp"

#include <array>
#include <iomanip>
#include <vector>

using namespace rt;
using namespace rt::grader;

namespace {

// Float's rounding of the map: a, b, r and phi each carry half a unit in the last place of
// numbers up to 2, and cos and sin a few more; 2e-6 is ten times that.
constexpr double map_tolerance = 2e-6;

double distance(point2 got, glm::dvec2 want)
{
    return glm::length(glm::dvec2(got) - want);
}

// Checks that the map takes `square` to within map_tolerance of `want`; false when it does not.
bool check_maps_to(point2 square, glm::dvec2 want, const std::string& what)
{
    const point2 got = concentric_disc(square);
    INFO(what << ": concentric_disc" << show(square) << " gave " << show(got) << ", expected " << show(point2(want)));
    CHECK(distance(got, want) <= map_tolerance);
    return distance(got, want) <= map_tolerance;
}

}  // namespace

GRADED_TEST("the square's centre, the middles of its sides and its corners land on the disc's centre, axes and diagonals", "06.1", 2)
{
    const double h = std::sqrt(0.5);  // cos 45 degrees
    check_maps_to({0.5f, 0.5f}, {0, 0}, "the square's centre");
    check_maps_to({1.0f, 0.5f}, {1, 0}, "the middle of the right side");
    check_maps_to({0.5f, 1.0f}, {0, 1}, "the middle of the top side");
    check_maps_to({0.0f, 0.5f}, {-1, 0}, "the middle of the left side");
    check_maps_to({0.5f, 0.0f}, {0, -1}, "the middle of the bottom side");
    check_maps_to({1.0f, 1.0f}, {h, h}, "the corner (1, 1)");
    check_maps_to({0.0f, 1.0f}, {-h, h}, "the corner (0, 1)");
    check_maps_to({0.0f, 0.0f}, {-h, -h}, "the corner (0, 0)");
    check_maps_to({1.0f, 0.0f}, {h, -h}, "the corner (1, 0)");
}

GRADED_TEST("the middles of the square's sides and its corners land on the rim, not one float step outside the disc; the centre on exactly (0, 0)", "06.1", 1)
{
    // At these points a and b are exactly -1, 0 or 1, and r is exactly 1 (or 0 at the centre): the
    // point is on the rim up to cos and sin's own rounding (some 1e-15 of the distance in double),
    // never 1.0000001 away, which is outside the disc.
    const point2 rim[] = {{1.0f, 0.5f}, {0.0f, 0.5f}, {0.5f, 1.0f}, {0.5f, 0.0f},
                          {1.0f, 1.0f}, {0.0f, 1.0f}, {0.0f, 0.0f}, {1.0f, 0.0f}};
    for (const point2 square : rim) {
        const point2 got = concentric_disc(square);
        const double from_centre = glm::length(glm::dvec2(got));
        INFO("concentric_disc" << show(square) << " gave " << show(got) << ", " << std::setprecision(17) << from_centre
             << " from the centre; expected 1 (the rim) and not a float step (1.2e-7) past it: never outside the disc");
        CHECK(from_centre <= 1.0 + 1e-12);
        CHECK(from_centre >= 1.0 - map_tolerance);
    }
    const point2 centre = concentric_disc({0.5f, 0.5f});
    INFO("concentric_disc(0.5, 0.5), the square's centre, gave " << show(centre) << "; expected exactly (0, 0): r is 0 there");
    CHECK((centre.x == 0.0f && centre.y == 0.0f));
}

GRADED_TEST("each square ring around the centre becomes the circle of its half-side, walked at an even pace", "06.1", 2)
{
    // Walk the ring max(|a|, |b|) = m counter-clockwise from (m, 0): after a distance s along it,
    // the concentric map puts the point at angle 2 pi s / (8 m) on the circle of radius m.
    for (const double m : {0.2, 0.5, 0.9}) {
        const int steps = 48;
        for (int k = 0; k < steps; ++k) {
            const double s = 8.0 * m * k / steps;
            // The ring's sides, from (m, 0): up m, left 2m, down 2m, right 2m, up m.
            double a, b;
            if (s < m) { a = m; b = s; }
            else if (s < 3 * m) { a = m - (s - m); b = m; }
            else if (s < 5 * m) { a = -m; b = m - (s - 3 * m); }
            else if (s < 7 * m) { a = -m + (s - 5 * m); b = -m; }
            else { a = m; b = -m + (s - 7 * m); }
            const point2 square{static_cast<float>((a + 1.0) / 2.0), static_cast<float>((b + 1.0) / 2.0)};
            const double phi = 2.0 * pi * s / (8.0 * m);
            std::ostringstream what;
            what << "the point (a, b) = (" << a << ", " << b << ") of the square ring of half-side " << m << ", "
                 << s << " along it from (m, 0): on the circle of radius " << m << " at angle " << phi * 180.0 / pi
                 << " degrees";
            if (!check_maps_to(square, m * glm::dvec2(std::cos(phi), std::sin(phi)), what.str()))
                return;  // the first point off its circle says enough
        }
    }
}

GRADED_TEST("every point of the square lands in the unit disc, and the square's edges on its rim", "06.1", 2)
{
    Rng rng(6, 1);
    for (int k = 0; k < 20000; ++k) {
        const point2 square{rng.next_float(), rng.next_float()};
        const point2 got = concentric_disc(square);
        if (!(glm::length(glm::dvec2(got)) <= 1.0 + map_tolerance)) {
            INFO("concentric_disc" << show(square) << " gave " << show(got) << ", " << glm::length(glm::dvec2(got))
                 << " from the centre: outside the unit disc");
            CHECK(false);
            return;
        }
    }
    for (int k = 0; k <= 16; ++k) {
        const float f = k / 16.0f;
        for (const point2 edge : {point2{f, 0.0f}, point2{f, 1.0f}, point2{0.0f, f}, point2{1.0f, f}}) {
            const point2 got = concentric_disc(edge);
            INFO("concentric_disc" << show(edge) << ", a point of the square's edge, gave " << show(got) << ", "
                 << glm::length(glm::dvec2(got)) << " from the centre; expected 1 (the rim)");
            REQUIRE(std::abs(glm::length(glm::dvec2(got)) - 1.0) <= map_tolerance);
        }
    }
}

GRADED_TEST("area-preserving: every small patch of the square is stretched by the same factor, pi", "06.1", 2)
{
    // The disc's area over the square's is pi; an area-preserving map stretches every patch by
    // that, so the Jacobian |dp/ds.x x dp/ds.y| is pi everywhere. Central differences of step h
    // measure it; the map is smooth away from the square's diagonals, where its formula switches.
    const float h = 1.0f / 512.0f;  // exact in float; the differences' rounding is ~1e-4 of pi
    const int n = 40;
    int measured = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const float x = (i + 0.5f) / n, y = (j + 0.5f) / n;
            if (std::abs(std::abs(2 * x - 1) - std::abs(2 * y - 1)) < 8 * h)
                continue;  // too near a diagonal: the step would straddle the switch
            const glm::dvec2 dx = (glm::dvec2(concentric_disc({x + h, y})) - glm::dvec2(concentric_disc({x - h, y}))) / (2.0 * h);
            const glm::dvec2 dy = (glm::dvec2(concentric_disc({x, y + h})) - glm::dvec2(concentric_disc({x, y - h}))) / (2.0 * h);
            const double jacobian = std::abs(dx.x * dy.y - dx.y * dy.x);
            ++measured;
            INFO("around " << show(point2{x, y}) << " of the square, a small patch is stretched by " << jacobian
                 << " (the determinant of the map's derivatives, by central differences of step " << h
                 << "); expected pi = " << pi << " everywhere, which is what area-preserving means");
            REQUIRE(std::abs(jacobian - pi) <= 1e-3 * pi);
        }
    CHECK(measured > n * n / 2);
}

GRADED_TEST("seeded uniform numbers fill every ring and every wedge of the disc in proportion to its area", "06.1", 2)
{
    // 4 rings of equal area (radii sqrt(k / 4)) times 12 wedges of 30 degrees: 48 cells of equal
    // area, each of which must hold 1/48 of the points. 12 wedges rather than 8, so a map that is
    // uneven within each 45-degree octant cannot hide. Pearson's chi-squared with 47 degrees of
    // freedom has mean 47 and standard deviation 9.7; above 120 happens by chance with probability
    // about 3e-8 (Wilson-Hilferty), while a map that is not area-preserving scores in the hundreds or thousands.
    constexpr int rings = 4, wedges = 12, points = 48000;
    std::array<int, rings * wedges> cells{};
    Rng rng(6, 2);
    for (int k = 0; k < points; ++k) {
        const point2 p = concentric_disc({rng.next_float(), rng.next_float()});
        const double r2 = glm::dot(glm::dvec2(p), glm::dvec2(p));
        double angle = std::atan2(double(p.y), double(p.x));
        if (angle < 0.0)
            angle += 2.0 * pi;
        const int ring = std::min(rings - 1, static_cast<int>(r2 * rings));
        const int wedge = std::min(wedges - 1, static_cast<int>(angle / (2.0 * pi) * wedges));
        ++cells[ring * wedges + wedge];
    }
    const double expected = double(points) / cells.size();
    double chi2 = 0.0;
    std::ostringstream counts;
    for (int ring = 0; ring < rings; ++ring) {
        counts << "\n  ring " << ring + 1 << " (radius " << std::sqrt(ring / 4.0) << " to " << std::sqrt((ring + 1) / 4.0)
               << "):";
        for (int wedge = 0; wedge < wedges; ++wedge) {
            const int c = cells[ring * wedges + wedge];
            chi2 += (c - expected) * (c - expected) / expected;
            counts << ' ' << c;
        }
    }
    INFO(points << " points concentric_disc(u1, u2) of seeded uniform numbers, counted in 48 cells of equal area "
         "(each should hold about " << expected << "):" << counts.str() << "\nchi-squared " << chi2
         << ", expected about 47 and at most 120 for an area-preserving map");
    CHECK(chi2 <= 120.0);
}

STABILITY_TEST("near the centre and on the diagonals the map gives the exact point, never a NaN", "06.1", 1)
{
    const float tiny = 0x1p-24f;  // the smallest step of float just below 0.5
    const std::vector<point2> squares = {{0.5f + 2 * tiny, 0.5f},  {0.5f, 0.5f - tiny},   {0.5f - tiny, 0.5f + 2 * tiny},
                                         {0.9f, 0.9f},            {0.1f, 0.9f},          {0.3f, 0.3f},
                                         {0.5f + tiny, 0.5f + tiny}, {0.75f, 0.25f}};
    for (const point2 square : squares) {
        const point2 got = concentric_disc(square);
        const glm::dvec2 want = concentric_reference(square);
        INFO("concentric_disc" << show(square) << " gave " << show(got) << ", expected " << show(point2(want))
             << " (worked in double)");
        REQUIRE((std::isfinite(got.x) && std::isfinite(got.y)));
        CHECK(distance(got, want) <= map_tolerance);
    }
}
