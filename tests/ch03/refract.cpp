// EXERCISE 03.2: the refracted direction by Snell's law, entering and leaving, and total internal
// reflection.
#include "common/random.hpp"
#include "tests/ch03/optics_reference.hpp"

#include <cmath>
#include <iomanip>
#include <initializer_list>

using namespace rt;
using namespace rt::grader;
using optics::query;
using optics::radians;

namespace {

// Two surfaces to refract at: a floor, and a tilted plane; each with a tangent in it.
struct Frame {
    vec3 n, s;
};

const Frame floor_frame{{0, 1, 0}, {1, 0, 0}};
const Frame tilted_frame{glm::normalize(vec3(0.3f, 0.8f, -0.5f)),
                         glm::normalize(glm::cross(glm::normalize(vec3(0.3f, 0.8f, -0.5f)), vec3(0, 0, 1)))};

// How far from unit length a refracted direction may be: v and n are a few float roundings off
// unit, and the formula scales their errors by eta (up to 2.5 here). Measured: 1.4e-6 at most over
// a million random rays, indices and sides.
constexpr float unit_tolerance = 2e-6f;

// The answer must be the reference's: the same decision, and a unit direction within `tolerance`.
void check_refraction(const vec3& v, const vec3& n, float ior, double tolerance)
{
    const std::optional<vec3> t = refract(v, n, ior);
    const optics::Refracted want = optics::refract_reference(v, n, ior);
    INFO(query(v, n, ior) << ": got " << optics::show(t) << ", expected " << optics::show(want)
         << " (sin(theta_t) = " << want.sin_t << ")");
    REQUIRE(t.has_value() == !want.total_internal_reflection);
    if (t) {
        CHECK(std::abs(glm::length(*t) - 1.0f) <= unit_tolerance);
        CHECK(optics::distance(*t, want.t) <= tolerance);
    }
}

}  // namespace

GRADED_TEST("refract: entering glass, water and diamond bends toward the normal as n1 sin(theta_i) = n2 sin(theta_t)", "03.2", 3)
{
    for (const Frame& f : {floor_frame, tilted_frame})
        for (const float ior : {1.333f, 1.5f, 2.4f})
            for (const double angle : {0.0, 10.0, 30.0, 45.0, 60.0, 75.0, 85.0}) {
                const vec3 v = optics::incident(f.n, f.s, radians(angle), false);
                check_refraction(v, f.n, ior, 2e-6);
                const std::optional<vec3> t = refract(v, f.n, ior);
                INFO(query(v, f.n, ior) << ": got " << optics::show(t) << ", which must go on into the object");
                CHECK(glm::dot(*t, f.n) < 0.0f);
            }
}

GRADED_TEST("refract: leaving glass bends away from the normal (the indices swap, the normal turns to face the ray)", "03.2", 3)
{
    for (const Frame& f : {floor_frame, tilted_frame})
        for (const float ior : {1.333f, 1.5f, 2.4f})
            for (const double angle : {0.0, 5.0, 12.0, 20.0, optics::critical_degrees(ior) - 2.0}) {
                const vec3 v = optics::incident(f.n, f.s, radians(angle), true);
                check_refraction(v, f.n, ior, 1e-5);
                const std::optional<vec3> t = refract(v, f.n, ior);
                INFO(query(v, f.n, ior) << ": got " << optics::show(t) << ", which must come out of the object");
                CHECK(glm::dot(*t, f.n) > 0.0f);
            }
}

GRADED_TEST("refract: beyond the critical angle no ray gets out (total internal reflection), just inside it one does", "03.2", 3)
{
    for (const float ior : {1.333f, 1.5f, 2.4f}) {
        const double critical = optics::critical_degrees(ior);
        for (const double angle : {critical - 0.5, critical + 0.5, 60.0, 89.0})
            check_refraction(optics::incident(floor_frame.n, floor_frame.s, radians(angle), true), floor_frame.n, ior,
                             1e-4);
        // Entering the denser medium there is no critical angle: even at 89.5 degrees a ray gets in.
        const vec3 skimming = optics::incident(floor_frame.n, floor_frame.s, radians(89.5), false);
        check_refraction(skimming, floor_frame.n, ior, 1e-5);
    }
}

GRADED_TEST("refract: into a bubble of air in water (ior 1 / 1.333) the critical angle is met entering", "03.2", 2)
{
    // The inside is now the less dense side: entering bends away from the normal and is totally
    // reflected beyond 48.6 degrees; leaving the bubble bends toward it and always gets out.
    const float bubble = 1.0f / 1.333f;
    for (const double angle : {0.0, 30.0, 45.0, 52.0, 70.0})
        for (const bool from_inside : {false, true})
            check_refraction(optics::incident(tilted_frame.n, tilted_frame.s, radians(angle), from_inside),
                             tilted_frame.n, bubble, 1e-5);
}

STABILITY_TEST("refract: exactly at the critical angle (48.61, 41.81, 24.62 degrees) and one float step either side, a grazing ray or none, never a NaN", "03.2", 3)
{
    // Leaving through a floor, n = (0, 1, 0), so v.n is exactly v.y = c, the cosine under test.
    // At the critical cosine and one float step either side, sin^2(theta_t) is 1 to within a few
    // rounding errors: either answer is right, but a direction must be unit length and skim the
    // surface on its far side. 0.01 degrees either way (1e-4 of sin^2 away from 1) must decide.
    const vec3 n{0, 1, 0};
    for (const float ior : {1.333f, 1.5f, 2.4f}) {
        const double ior_d = ior;
        const float critical_cos = static_cast<float>(std::sqrt(1.0 - 1.0 / (ior_d * ior_d)));
        for (const float c : {std::nextafter(critical_cos, 0.0f), critical_cos, std::nextafter(critical_cos, 2.0f)}) {
            const vec3 v{static_cast<float>(std::sqrt(1.0 - double(c) * c)), c, 0.0f};
            const std::optional<vec3> t = refract(v, n, ior);
            INFO(query(v, n, ior) << ", sin^2(theta_t) = " << ior_d * ior_d * (1.0 - double(c) * c)
                 << " from its cosine: got " << optics::show(t)
                 << ", expected none or a unit direction along the surface");
            if (t) {
                REQUIRE(std::isfinite(t->x + t->y + t->z));
                CHECK(std::abs(glm::length(*t) - 1.0f) <= unit_tolerance);
                CHECK(t->y >= 0.0f);
                CHECK(t->y <= 2e-3f);
            }
        }
        const double critical = optics::critical_degrees(ior);
        for (const double angle : {critical - 0.01, critical + 0.01})
            check_refraction(optics::incident(n, {1, 0, 0}, radians(angle), true), n, ior, 1e-3);
    }
}

STABILITY_TEST("refract: ior = 1 leaves every ray undeflected (to 1.35e-5), entering and leaving, 0 to 89.9 degrees", "03.2", 2)
{
    double worst = 0.0;
    for (const Frame& f : {floor_frame, tilted_frame})
        for (double angle = 0.0; angle <= 89.9; angle += 0.1)
            for (const bool from_inside : {false, true}) {
                const vec3 v = optics::incident(f.n, f.s, radians(angle), from_inside);
                const std::optional<vec3> t = refract(v, f.n, 1.0f);
                INFO(query(v, f.n, 1.0f) << ": got " << optics::show(t) << ", expected v itself");
                REQUIRE(t);
                worst = std::max(worst, static_cast<double>(glm::length(*t - v)));
                REQUIRE(glm::length(*t - v) <= 1.35e-5f);
            }
    INFO("the largest deflection was " << worst);
    CHECK(worst <= 1.35e-5);
}

STABILITY_TEST("refract: at ior 1 and 1 + 1e-6 a ray a few 1e-4 from grazing still gets through, as Snell's law says", "03.2", 2)
{
    // cos_i down to 1e-4 (0.0057 degrees from grazing): 1 - cos_i^2 is 1 in float there, so the
    // form 1 - eta^2 (1 - cos_i^2) says "total internal reflection" at ior = 1.
    for (const Frame& f : {floor_frame, tilted_frame})
        for (const float ior : {1.0f, 1.0f + 1e-6f})
            for (const double cos_i : {1e-4, 2e-4, 5e-4, 1e-3, 2e-3, 1e-2})
                for (const bool from_inside : {false, true}) {
                    const vec3 v = optics::incident(f.n, f.s, std::acos(cos_i), from_inside);
                    const std::optional<vec3> t = refract(v, f.n, ior);
                    const optics::Refracted want = optics::refract_reference(v, f.n, ior);
                    INFO(query(v, f.n, ior) << " (cos_i " << cos_i << "): got " << optics::show(t) << ", expected "
                         << optics::show(want));
                    REQUIRE(t.has_value() == !want.total_internal_reflection);
                    if (t) {
                        CHECK(std::abs(glm::length(*t) - 1.0f) <= unit_tolerance);
                        // Near grazing the direction is ill-conditioned in cos_i; at ior 1 it is v.
                        CHECK(optics::distance(*t, want.t) <= (ior == 1.0f ? 1.35e-5 : 2e-3));
                    }
                }
}

STABILITY_TEST("refract: unit length kept and Snell's law met in float, against double, for random rays, sides and indices", "03.2", 2)
{
    // Random unit v and n in every relation, indices from 1 to 2.5. The transmitted direction's
    // float error grows with the index and as 1 / cos(theta_t) (near the critical angle it is
    // ill-conditioned): measured, at most 4.8e-7 ior / cos(theta_t) where cos(theta_t) >= 0.05;
    // it is compared there, within twice that. The decision is checked where the exact sin^2(theta_t) is at
    // least 1e-4 from 1, and the length always.
    Rng rng(32, 0);
    const auto random_unit = [&] {
        return glm::normalize(vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() - 0.5f));
    };
    for (int k = 0; k < 100000; ++k) {
        const vec3 v = random_unit(), n = random_unit();
        const float ior = 1.0f + 1.5f * rng.next_float();
        const std::optional<vec3> t = refract(v, n, ior);
        const optics::Refracted want = optics::refract_reference(v, n, ior);
        const double sin2_t = want.sin_t * want.sin_t;
        INFO(query(v, n, ior) << ": got " << optics::show(t) << ", expected " << optics::show(want)
             << " (sin^2(theta_t) = " << sin2_t << ")");
        if (std::abs(sin2_t - 1.0) >= 1e-4)
            REQUIRE(t.has_value() == !want.total_internal_reflection);
        if (!t)
            continue;
        REQUIRE(std::isfinite(t->x + t->y + t->z));
        REQUIRE(std::abs(glm::length(*t) - 1.0f) <= unit_tolerance);
        const double cos_t = std::sqrt(std::max(0.0, 1.0 - sin2_t));
        if (cos_t >= 0.05)
            REQUIRE(optics::distance(*t, want.t) <= 1e-6 * ior / cos_t);
    }
}

STABILITY_TEST("refract: never a NaN: a grazing ray (v.n = 0) enters at the critical angle (at ior 1, exactly critical: no ray), head-on rays pass straight, v.n a hair beyond 1 either way is no trouble", "03.2", 2)
{
    const vec3 up{0, 1, 0};
    // v.n = 0 exactly (+0 or -0): it counts as arriving from outside, and enters at theta_t = theta_c.
    for (const vec3 v : {vec3(1, 0, 0), vec3(1, -0.0f, 0)})
        check_refraction(v, up, 1.5f, 1e-6);
    // ior = 1 at grazing incidence: cos^2(theta_t) is exactly 0 by any way of writing it, and the
    // contract says no ray at <= 0 (one input where that equality is exact, not a rounding away).
    {
        const std::optional<vec3> t = refract({1, 0, 0}, up, 1.0f);
        INFO(query({1, 0, 0}, up, 1.0f) << ": got " << optics::show(t)
             << ", expected none: cos^2(theta_t) = 0 exactly, and 0 is total internal reflection (<= 0)");
        CHECK(!t);
    }
    // Head-on from either side, and nearly so, at every index: straight through.
    Rng rng(33, 0);
    const vec3 v = glm::normalize(vec3(0.3f, -1.0f, 0.2f));
    for (const vec3 n : {-v, v, glm::normalize(-v + vec3(1e-4f, 0, 0)), glm::normalize(v + vec3(0, 0, 1e-6f))})
        for (const float ior : {1.333f, 1.5f, 2.4f})
            check_refraction(v, n, ior, 1e-5);
    // Float-normalised vectors are a few ulps off unit: v.v can be 1 + 1e-7, so with n = v the
    // cosine is a hair beyond 1 and 1 - cos^2 a hair below 0. Clamped, nothing happens.
    int found = 0;
    for (int k = 0; k < 1000 && found < 20; ++k) {
        const vec3 w = glm::normalize(vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() - 0.5f));
        if (glm::dot(w, w) <= 1.0f)
            continue;
        ++found;
        for (const vec3 n : {w, -w}) {
            const std::optional<vec3> t = refract(w, n, 1.5f);
            INFO(query(w, n, 1.5f) << " with v.n = " << glm::dot(w, n) << ": got " << optics::show(t)
                 << ", expected v itself");
            REQUIRE(t);
            REQUIRE(std::isfinite(t->x + t->y + t->z));
            CHECK(glm::length(*t - w) <= 1e-6f);
        }
    }
    CHECK(found > 0);
}

namespace {

// Leaving glass of index 2 through a floor (n = (0, 1, 0)), so v.n is exactly v.y = c: the float
// c whose square rounds to 0.75 puts cos^2(theta_t) = (1 - 2)(1 + 2) + 4 c^2 exactly at 0 (so does
// every order of the float products, 4 being a power of two), one float step smaller below 0, one
// step larger at 2^-22 above it.
struct TirBoundary {
    float below, at, above;  // the cosines
};

TirBoundary tir_boundary_at_ior_2()
{
    const float at = 0x1.bb67aep-1f;
    return {std::nextafter(at, 0.0f), at, std::nextafter(at, 1.0f)};
}

}  // namespace

GRADED_TEST("refract: leaving at ior 2 where cos^2(theta_t) is exactly 0 no ray gets out; one float step steeper one does, skimming the surface", "03.2", 2)
{
    const vec3 n{0, 1, 0};
    const TirBoundary c = tir_boundary_at_ior_2();
    REQUIRE(c.at * c.at == 0.75f);
    struct Case {
        float cos_i;
        bool through;
        const char* what;
    };
    for (const Case& k : {Case{c.below, false, "cos^2(theta_t) = -2^-21 in float: total internal reflection"},
                          Case{c.at, false, "cos^2(theta_t) = 0 exactly in float: total internal reflection (<= 0)"},
                          Case{c.above, true, "cos^2(theta_t) = 2^-22 in float: a ray gets out, cos_t = 2^-11"}}) {
        const vec3 v{static_cast<float>(std::sqrt(1.0 - double(k.cos_i) * k.cos_i)), k.cos_i, 0.0f};
        const std::optional<vec3> t = refract(v, n, 2.0f);
        INFO(query(v, n, 2.0f) << ", v.n = " << std::hexfloat << k.cos_i << std::defaultfloat << " (" << k.what
             << "): got " << optics::show(t) << ", expected "
             << (k.through ? "a unit direction along the surface, just outside it" : "none"));
        REQUIRE(t.has_value() == k.through);
        if (t) {
            REQUIRE(std::isfinite(t->x + t->y + t->z));
            CHECK(std::abs(glm::length(*t) - 1.0f) <= unit_tolerance);
            CHECK(t->y > 0.0f);
            CHECK(t->y <= 1e-3f);
        }
    }
}

STABILITY_TEST("refract: a grazing ray with v.n = -0 (the sign bit set) enters, as one with v.n = +0 does", "03.2", 1)
{
    // v = (-1, -0, -0) against n = (0, 1, 0): the three products are -0 and their sum is -0.
    const vec3 up{0, 1, 0};
    const vec3 v{-1.0f, -0.0f, -0.0f};
    const float vn = glm::dot(v, up);
    REQUIRE(vn == 0.0f);
    REQUIRE(std::signbit(vn));
    check_refraction(v, up, 1.5f, 1e-6);
    const std::optional<vec3> t = refract(v, up, 1.5f);
    INFO(query(v, up, 1.5f) << " with v.n = -0: got " << optics::show(t)
         << ", expected a ray into the glass at the critical angle (-0 is not > 0: it arrives from outside)");
    REQUIRE(t);
    CHECK(t->y < 0.0f);
}

STABILITY_TEST("refract: at ior 1 a ray whose cos^2(theta_t) is the least positive float (v.n = 1.25 * 2^-75) still gets through, either side", "03.2", 1)
{
    // cos^2(theta_t) = cos_i^2 at ior 1; with cos_i = 1.25 * 2^-75 that rounds to 2^-149, the least
    // positive float (a denormal): one float step above the "<= 0" of total internal reflection, so
    // a ray gets out, undeflected. Nothing here needs more than float's own range.
    const float c = std::ldexp(1.25f, -75);
    const vec3 up{0, 1, 0};
    for (const float side : {-1.0f, 1.0f}) {  // -1: entering (v.n < 0); +1: leaving (v.n > 0)
        const vec3 v{1.0f, side * c, 0.0f};
        const std::optional<vec3> t = refract(v, up, 1.0f);
        INFO(query(v, up, 1.0f) << ": v.n = " << std::setprecision(9) << glm::dot(v, up) << ", cos_i^2 = "
             << c * c << " (> 0); got " << optics::show(t) << ", expected v itself, to 1e-6");
        REQUIRE(t.has_value());
        CHECK(glm::length(*t - v) <= 1e-6f);
    }
}
