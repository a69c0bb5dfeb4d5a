// EXERCISE 03.4: Schlick's approximation, with the cosine of the less dense side.
#include "tests/ch03/optics_reference.hpp"

#include <cmath>
#include <iomanip>
#include <initializer_list>

using namespace rt;
using namespace rt::grader;
using optics::radians;

namespace {

std::string schlick_query(float cos_i, float ior)
{
    return optics::call("fresnel_schlick", cos_i, ior);
}

// Schlick's curve of cos_i whatever the side: the classic bug, for the failure message.
double with_cos_i(float cos_i, float ior)
{
    const double r0 = (ior - 1.0) / (ior + 1.0);
    return r0 * r0 + (1.0 - r0 * r0) * std::pow(1.0 - std::abs(static_cast<double>(cos_i)), 5.0);
}

void check_schlick(float cos_i, float ior, double tolerance)
{
    const float R = fresnel_schlick(cos_i, ior);
    const double want = optics::schlick_reference(cos_i, ior);
    INFO(schlick_query(cos_i, ior) << ": got " << R << ", expected " << want
         << " (Schlick's curve of cos_i everywhere would give " << with_cos_i(cos_i, ior) << ")");
    REQUIRE(std::isfinite(R));
    CHECK(std::abs(R - want) <= tolerance);
}

}  // namespace

GRADED_TEST("fresnel_schlick: entering, R0 + (1 - R0)(1 - cos_i)^5: R0 head-on, 1 at grazing", "03.4", 2)
{
    for (const float ior : {1.333f, 1.5f, 2.4f})
        for (const float cos_i : {1.0f, 0.8f, 0.5f, 0.2f, 0.05f, 0.0f})
            check_schlick(cos_i, ior, 1e-6);
}

GRADED_TEST("fresnel_schlick: leaving the denser medium takes cos_t, not cos_i (the classic bug stays near R0 up to the critical angle)", "03.4", 3)
{
    for (const float ior : {1.333f, 1.5f, 2.4f}) {
        const double critical = optics::critical_degrees(ior);
        for (const double angle : {0.0, 10.0, critical - 8.0, critical - 3.0, critical - 1.0, critical - 0.2})
            check_schlick(-static_cast<float>(std::cos(radians(angle))), ior, 1e-4);
    }
}

GRADED_TEST("fresnel_schlick: beyond the critical angle exactly 1 (total internal reflection)", "03.4", 2)
{
    for (const float ior : {1.333f, 1.5f, 2.4f})
        for (const double angle : {optics::critical_degrees(ior) + 0.5, 60.0, 89.0, 90.0}) {
            const float cos_i = -static_cast<float>(std::cos(radians(angle)));
            const float R = fresnel_schlick(cos_i, ior);
            INFO(schlick_query(cos_i, ior) << ": got " << R << ", expected exactly 1 (Schlick's curve of cos_i would give "
                 << with_cos_i(cos_i, ior) << ")");
            CHECK(R == 1.0f);
        }
}

GRADED_TEST("fresnel_schlick: into a bubble of air in water (ior 1 / 1.333) the denser side is outside: cos_t entering, cos_i leaving", "03.4", 2)
{
    const float bubble = 1.0f / 1.333f;
    for (const double angle : {0.0, 20.0, 40.0, 47.0, 60.0})
        for (const float sign : {1.0f, -1.0f})
            check_schlick(sign * static_cast<float>(std::cos(radians(angle))), bubble, 1e-4);
}

STABILITY_TEST("fresnel_schlick: within 0.06 (water), 0.037 (glass), 0.075 (diamond) of the exact reflectance at every angle, both ways, never a NaN", "03.4", 2)
{
    // Schlick's worst error, measured with the right cosine, is the same entering and leaving:
    // 0.059, 0.036 and 0.074 (the chapter's --sweep measures them).
    struct Case {
        float ior;
        double bound;
    };
    for (const Case& c : {Case{1.333f, 0.0602}, Case{1.5f, 0.0367}, Case{2.4f, 0.0750}})
        for (int k = 0; k <= 9000; ++k)
            for (const float sign : {1.0f, -1.0f}) {
                const float cos_i = sign * static_cast<float>(std::cos(radians(0.01 * k)));
                const float R = fresnel_schlick(cos_i, c.ior);
                const double exact = optics::fresnel_reference(cos_i, c.ior);
                INFO(schlick_query(cos_i, c.ior) << ": got " << R << ", the exact reflectance is " << exact
                     << "; Schlick stays within " << c.bound);
                REQUIRE(std::isfinite(R));
                REQUIRE(std::abs(R - exact) <= c.bound);
            }
    for (const float cos_i : {0.0f, -0.0f, std::nextafter(1.0f, 2.0f), -std::nextafter(1.0f, 2.0f)}) {
        const float R = fresnel_schlick(cos_i, 1.5f);
        INFO(schlick_query(cos_i, 1.5f) << ": got " << R << ", expected 1 at grazing, R0 = 0.04 head-on");
        REQUIRE(std::isfinite(R));
        CHECK(std::abs(R - (cos_i == 0.0f ? 1.0f : 0.04f)) <= 1e-6f);
    }
}

GRADED_TEST("fresnel_schlick: leaving at ior 2 where sin^2(theta_t) is exactly 1, exactly 1; one float step steeper, in [0.99, 1]", "03.4", 1)
{
    // As for 03.3: c^2 rounds to 0.75 and sin^2(theta_t) = 4 (1 - c^2) is exactly 1 in float.
    const float at = 0x1.bb67aep-1f, below = std::nextafter(at, 0.0f), above = std::nextafter(at, 1.0f);
    for (const float c : {below, at}) {
        const float R = fresnel_schlick(-c, 2.0f);
        INFO(schlick_query(-c, 2.0f) << ", cos_i = " << std::hexfloat << -c << std::defaultfloat << ": got " << R
             << ", expected exactly 1 (sin^2(theta_t) " << (c == at ? "= 1" : "> 1") << " in float; Schlick's curve of "
             << "cos_i would give " << with_cos_i(-c, 2.0f) << ")");
        CHECK(R == 1.0f);
    }
    const float R = fresnel_schlick(-above, 2.0f);
    INFO(schlick_query(-above, 2.0f) << ", one float step inside the critical angle: got " << R << ", expected 0.99 to 1");
    REQUIRE(std::isfinite(R));
    CHECK(R >= 0.99f);
    CHECK(R <= 1.0f);
}

GRADED_TEST("fresnel_schlick: at ior 1 (no denser side, R0 = 0) a ray 0.02 to 0.03 degrees from grazing gets (1 - cos_i)^5, not total reflection", "03.4", 1)
{
    // At ior 1 neither side is denser: c = cos_i and R = (1 - cos_i)^5, 0.9983 and 0.9975 here,
    // not the 1 of total internal reflection (an eta a rounding above 1 takes the "denser side"
    // branch, where eta^2 (1 - cos_i^2) rounds to 1 this close to grazing).
    for (const float c : {3.5e-4f, 5e-4f})
        for (const float sign : {1.0f, -1.0f})
            check_schlick(sign * c, 1.0f, 1e-6);
}

GRADED_TEST("fresnel_schlick: leaving an index one float step above 1 (1 + 2^-23) beyond its critical angle (cos_i 2e-4 < 4.9e-4), exactly 1", "03.4", 1)
{
    // ior = 1 + 2^-23 is denser than outside, however little: its critical angle has cosine
    // sqrt(1 - 1 / ior^2) = 4.9e-4, and a ray leaving at cos_i = 2e-4 has sin^2(theta_t) = 1 + 2e-7
    // (in float, 1 + 1.2e-7 or more): total internal reflection, R = 1, not (1 - cos_i)^5 = 0.999.
    const float ior = std::nextafter(1.0f, 2.0f);
    const float R = fresnel_schlick(-2e-4f, ior);
    INFO(schlick_query(-2e-4f, ior) << " (ior = 1 + 2^-23): got " << R
         << ", expected exactly 1 (total internal reflection: eta = ior > 1, the denser side's rule)");
    CHECK(R == 1.0f);
}

STABILITY_TEST("fresnel_schlick: leaving at ior 2 just inside the critical angle, where cos_i^2 is exact in float, R within 5e-7 of the double answer", "03.4", 1)
{
    // cos_i with 12 significant bits: cos_i^2, 1 - cos_i^2 and sin^2(theta_t) = 4 (1 - cos_i^2) are
    // exact in float, so only c = cos_t = sqrt(1 - sin^2(theta_t)) and the polynomial round. c is
    // small here (0.05 to 0.09) and R moves fast with it: an error of one float step of 1 in
    // 1 - sin^2(theta_t) moves R by 8e-6 to 2.6e-5. Float's own answer is within 1.4e-7.
    for (const float c : {0x1.bb8p-1f, 0x1.bbcp-1f, 0x1.bcp-1f})
        check_schlick(-c, 2.0f, 5e-7);
}

GRADED_TEST("fresnel_schlick: at grazing incidence (cos_i = +0 or -0) exactly 1, never above 1", "03.4", 1)
{
    // c = 0 makes 1 - c exactly 1, (1 - c)^5 exactly 1, and R0 + (1 - R0) rounds to exactly 1 in
    // float for any R0 in [0, 1]: a reflectance is a share of the light, never more than all of it.
    for (const float ior : {1.333f, 1.5f, 2.4f, 1.0f / 1.333f})
        for (const float cos_i : {0.0f, -0.0f}) {
            const float R = fresnel_schlick(cos_i, ior);
            INFO(schlick_query(cos_i, ior) << ": got " << std::setprecision(9) << R << ", expected exactly 1 (grazing)");
            CHECK(R == 1.0f);
        }
}
