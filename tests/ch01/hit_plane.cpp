// EXERCISE 01.2: ray/plane, t = n.(b - u) / n.v.
#include "01_ray_casting/01_ray_casting.hpp"
#include "common/random.hpp"
#include "tests/grader/graded.hpp"

#include <cfenv>
#include <cmath>
#include <iomanip>
#include <limits>

using namespace rt;
using rt::grader::show;

namespace {

const Plane floor_plane{{5, 0, -2}, {0, 1, 0}};

// t in double from the same float inputs: the reference for the float answer.
double reference_t(const Ray& ray, const Plane& plane)
{
    const dvec3 n(plane.n), b(plane.b), u(ray.origin), v(ray.dir);
    return glm::dot(n, b - u) / glm::dot(n, v);
}

std::string describe(const Ray& ray, const Plane& plane, Interval range)
{
    std::ostringstream s;
    s << show(ray) << " against the plane through " << show(plane.b) << " with normal " << show(plane.n)
      << ", range (" << range.min << ", " << range.max << ")";
    return s.str();
}

}  // namespace

GRADED_TEST("a ray straight down hits the floor at the eye's height, from either side's normal", "01.2", 2)
{
    const Ray ray{{0, 3, 0}, {0, -1, 0}};
    for (const vec3 n : {vec3(0, 1, 0), vec3(0, -1, 0)}) {
        const Plane plane{floor_plane.b, n};
        const std::optional<float> t = hit_plane(ray, plane, Interval{});
        INFO(describe(ray, plane, Interval{}) << ": got t = " << show(t) << ", expected 3");
        REQUIRE(t);
        CHECK(*t == Approx(3.0f).epsilon(1e-6));
    }
}

GRADED_TEST("an oblique ray hits where t = n.(b - u) / n.v says, and the point lies on the plane", "01.2", 2)
{
    const Ray ray{{1, 2, 3}, glm::normalize(vec3(1, -2, -2))};
    const Plane plane{{0, 0, 0}, glm::normalize(vec3(0, 1, 0.5f))};
    const double expected = reference_t(ray, plane);
    const std::optional<float> t = hit_plane(ray, plane, Interval{});
    INFO(describe(ray, plane, Interval{}) << ": got t = " << show(t) << ", expected " << expected);
    REQUIRE(t);
    CHECK(rt::grader::rel_error(*t, expected) <= 1e-6);
    CHECK(std::abs(glm::dot(plane.n, ray.at(*t) - plane.b)) <= 1e-5f);
}

GRADED_TEST("a ray parallel to the plane misses, and one tilted slightly toward it hits far away", "01.2", 2)
{
    // A parallel ray is turned away before any division: n.(b - u) / 0 would raise the division-by-zero
    // flag (or, for a ray in the plane, 0 / 0 the invalid flag) even when the range then rejects the
    // infinity or NaN it gives.
    for (const Ray& parallel : {Ray{{0, 1, 0}, {1, 0, 0}}, Ray{{0, 0, 0}, {1, 0, 0}}}) {
        std::feclearexcept(FE_ALL_EXCEPT);
        const std::optional<float> none = hit_plane(parallel, floor_plane, Interval{});
        const bool divided_by_zero = std::fetestexcept(FE_DIVBYZERO), invalid = std::fetestexcept(FE_INVALID);
        INFO(describe(parallel, floor_plane, Interval{}) << ": got t = " << show(none) << ", expected no hit"
             << (divided_by_zero ? "; it divided by n.v = 0 (a division by zero) instead of testing n.v = 0 first" : "")
             << (invalid ? "; it computed 0 / 0 (an invalid operation) instead of testing n.v = 0 first" : ""));
        CHECK_FALSE(none);
        CHECK_FALSE(divided_by_zero);
        CHECK_FALSE(invalid);
    }

    const Ray tilted{{0, 1, 0}, glm::normalize(vec3(1, -1e-3f, 0))};
    const double expected = reference_t(tilted, floor_plane);
    const std::optional<float> t = hit_plane(tilted, floor_plane, Interval{});
    INFO(describe(tilted, floor_plane, Interval{}) << ": got t = " << show(t) << ", expected " << expected);
    REQUIRE(t);
    CHECK(rt::grader::rel_error(*t, expected) <= 1e-6);
}

GRADED_TEST("only hits strictly inside the range count: not behind the eye, not beyond range.max", "01.2", 2)
{
    const Ray down{{0, 3, 0}, {0, -1, 0}};  // meets the floor at t = 3
    const Ray up{{0, 3, 0}, {0, 1, 0}};     // the floor is behind it, at t = -3
    struct Case {
        Ray ray;
        Interval range;
        bool hits;
    };
    for (const Case& c : {Case{down, {1e-4f, infinity}, true}, Case{down, {2.9f, 3.1f}, true},
                          Case{down, {1e-4f, 2.0f}, false}, Case{down, {3.5f, infinity}, false},
                          Case{up, {1e-4f, infinity}, false}}) {
        const std::optional<float> t = hit_plane(c.ray, floor_plane, c.range);
        INFO(describe(c.ray, floor_plane, c.range) << ": got t = " << show(t) << ", expected "
             << (c.hits ? "t = 3" : "no hit"));
        CHECK(t.has_value() == c.hits);
        if (t && c.hits)
            CHECK(*t == Approx(3.0f));
    }
}

STABILITY_TEST("nearly parallel rays hit where a double-precision computation says", "01.2", 2)
{
    for (double angle = 1e-1; angle >= 1e-7; angle /= 10) {
        const Ray ray{{0, 1, 0}, glm::normalize(vec3(float(std::cos(angle)), float(-std::sin(angle)), 0.0f))};
        const double expected = reference_t(ray, floor_plane);
        const std::optional<float> t = hit_plane(ray, floor_plane, Interval{});
        INFO(describe(ray, floor_plane, Interval{}) << " (" << angle << " radians above parallel): got t = "
             << show(t) << ", expected " << expected);
        REQUIRE(t);
        CHECK(rt::grader::rel_error(*t, expected) <= 1e-6);
    }
}

STABILITY_TEST("grazing rays give a finite t or no hit, never a NaN or an infinity", "01.2", 2)
{
    // dir.y = -1e-30 puts the hit at 1e30, still a float; -1e-45 (the smallest subnormal) puts it
    // beyond the largest float; a ray starting on the plane meets it at t = 0, outside the range.
    {
        const Ray far{{0, 1, 0}, {1, -1e-30f, 0}};
        const std::optional<float> t_far = hit_plane(far, floor_plane, Interval{});
        INFO(describe(far, floor_plane, Interval{}) << ": got t = " << show(t_far) << ", expected about 1e30");
        REQUIRE(t_far);
        CHECK(rt::grader::rel_error(*t_far, 1e30) <= 1e-6);
    }

    {
        // The smallest grazing slope of all: n.v is the smallest subnormal, 1.4e-45, and so is
        // n.(b - u), from an eye that far above the floor (the normal facing down): t = 1. It is not
        // parallel (n.v is not 0), and a test against anything but 0 misses it.
        const float tiny = std::numeric_limits<float>::denorm_min();
        const Ray lowest{{0, tiny, 0}, {1, -tiny, 0}};
        const Plane facing_down{floor_plane.b, {0, -1, 0}};
        const std::optional<float> t_one = hit_plane(lowest, facing_down, Interval{});
        INFO(describe(lowest, facing_down, Interval{}) << " (n.v and n.(b - u) both the smallest subnormal, "
             << tiny << "): got t = " << show(t_one) << ", expected t = 1");
        REQUIRE(t_one);
        CHECK(*t_one == 1.0f);
    }

    for (const Ray& ray : {Ray{{0, 1, 0}, {1, -1e-45f, 0}}, Ray{{0, 0, 0}, glm::normalize(vec3(1, -1, 0))},
                           Ray{{0, 0, 0}, {1, 0, 0}}}) {
        const std::optional<float> t = hit_plane(ray, floor_plane, Interval{});
        INFO(describe(ray, floor_plane, Interval{}) << ": got t = " << show(t) << ", expected no hit");
        CHECK_FALSE(t);
    }
}

STABILITY_TEST("a plane behind the eye is never hit, and the same plane ahead always is", "01.2", 2)
{
    // 2000 directions over the sphere, from an eye 1 above the floor.
    Rng rng(7, 0);
    for (int k = 0; k < 2000; ++k) {
        const float z = 2.0f * rng.next_float() - 1.0f, phi = 6.2831853f * rng.next_float();
        const float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const Ray ray{{0, 1, 0}, {s * std::cos(phi), z, s * std::sin(phi)}};
        if (ray.dir.y == 0.0f)
            continue;
        const std::optional<float> t = hit_plane(ray, floor_plane, Interval{});
        INFO(describe(ray, floor_plane, Interval{}) << ": got t = " << show(t) << ", expected "
             << (ray.dir.y < 0 ? "a hit at 1 / |dir.y|" : "no hit: the floor is behind"));
        REQUIRE(t.has_value() == (ray.dir.y < 0.0f));
        if (t)
            CHECK(rt::grader::rel_error(*t, reference_t(ray, floor_plane)) <= 1e-6);
    }
}

GRADED_TEST("a hit exactly at range.min or range.max does not count; one float step inside the range it does", "01.2", 2)
{
    // Straight down from 3 above the floor: t = n.(b - u) / n.v = -3 / -1 = 3 exactly.
    const Ray down{{0, 3, 0}, {0, -1, 0}};
    const float below = std::nextafter(3.0f, 0.0f), above = std::nextafter(3.0f, 4.0f);
    struct Case {
        Interval range;
        bool hits;
        const char* why;
    };
    for (const Case& c : {Case{{3.0f, infinity}, false, "t = 3 is range.min itself: the range is open"},
                          Case{{below, infinity}, true, "range.min is one float step below t = 3"},
                          Case{{above, infinity}, false, "range.min is one float step beyond t = 3"},
                          Case{{1e-4f, 3.0f}, false, "t = 3 is range.max itself: the range is open"},
                          Case{{1e-4f, above}, true, "range.max is one float step beyond t = 3"},
                          Case{{1e-4f, below}, false, "range.max is one float step below t = 3"}}) {
        const std::optional<float> t = hit_plane(down, floor_plane, c.range);
        INFO(describe(down, floor_plane, c.range) << " (" << c.why << "): got t = " << show(t) << ", expected "
             << (c.hits ? "t = 3" : "no hit"));
        CHECK(t.has_value() == c.hits);
        if (t && c.hits)
            CHECK(*t == 3.0f);
    }
}

GRADED_TEST("planes and rays 1e4 to 1e5 from the origin: t within 1e-6 of double, as n.(b - u) / n.v keeps it", "01.2", 2)
{
    // b - u of two nearby points is exact in float (or nearly), so n.(b - u) keeps float's precision
    // however far the scene lies from the origin. n.b - n.u, the same number written as the plane's
    // offset minus the eye's, subtracts two dot products near |b| and cancels: at 3e4 from the origin
    // each is rounded by about 3e4 x 6e-8 = 2e-3, a relative error of 1e-4 to 1e-3 for a plane a few
    // units away.
    const Plane planes[] = {{{12345.5f, -23456.25f, 34567.75f}, glm::normalize(vec3(2, -1, 2))},
                            {{-40000.0f, 10000.0f, 80000.0f}, glm::normalize(vec3(-3, 4, 12))},
                            {{-9876.5f, 54321.0f, -4096.25f}, glm::normalize(vec3(1, 1, -1))}};
    for (const Plane& plane : planes)
        for (const float distance : {0.5f, 1.0f, 3.0f, 7.0f, 20.0f}) {
            const Ray ray{plane.b + distance * plane.n + vec3(3.25f, -1.5f, 2.0f),
                          glm::normalize(vec3(-0.3f, 0.2f, 0.0f) - plane.n)};
            const double expected = reference_t(ray, plane);
            const std::optional<float> t = hit_plane(ray, plane, Interval{});
            INFO(describe(ray, plane, Interval{}) << ": got t = " << show(t) << ", expected " << std::setprecision(10)
                 << expected << " (relative error " << (t ? rt::grader::rel_error(*t, expected) : 0.0)
                 << ", allowed 1e-6: take b - u first, then the dot product)");
            REQUIRE(t);
            CHECK(rt::grader::rel_error(*t, expected) <= 1e-6);
        }
}

STABILITY_TEST("a NaN or an infinity in the ray gives no hit, never a NaN t; a ray with n.v = -0 is parallel", "01.2", 1)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const Ray& ray : {Ray{{nan, 3, 0}, {0, -1, 0}}, Ray{{0, nan, 0}, {0, -1, 0}}, Ray{{0, 3, 0}, {nan, nan, nan}},
                           Ray{{0, infinity, 0}, {0, -1, 0}}, Ray{{0, 3, 0}, {0, -infinity, 0}},
                           Ray{{0, 1, 0}, {-1, -0.0f, -0.0f}}, Ray{{0, 0, 0}, {-1, -0.0f, -0.0f}}}) {
        const std::optional<float> t = hit_plane(ray, floor_plane, Interval{});
        INFO(describe(ray, floor_plane, Interval{}) << ": got t = " << show(t) << ", expected no hit");
        CHECK_FALSE(t);
    }
    const Ray sound{{0, 3, 0}, {0, -1, 0}};
    INFO(describe(sound, floor_plane, Interval{}) << ": expected a hit at t = 3");
    CHECK(hit_plane(sound, floor_plane, Interval{}));
}
