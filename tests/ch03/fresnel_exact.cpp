// EXERCISE 03.3: the exact reflectance of a clear dielectric interface (Fresnel's equations).
#include "tests/ch03/optics_reference.hpp"

#include <cmath>
#include <iomanip>
#include <initializer_list>

using namespace rt;
using namespace rt::grader;
using optics::radians;

namespace {

std::string exact_query(float cos_i, float ior)
{
    return optics::call("fresnel_dielectric", cos_i, ior);
}

void check_reflectance(float cos_i, float ior, double tolerance)
{
    const float R = fresnel_dielectric(cos_i, ior);
    const double want = optics::fresnel_reference(cos_i, ior);
    INFO(exact_query(cos_i, ior) << ": got " << R << ", expected " << want);
    REQUIRE(std::isfinite(R));
    CHECK(std::abs(R - want) <= tolerance);
}

}  // namespace

GRADED_TEST("fresnel_dielectric: head-on, R0 = ((n1 - n2) / (n1 + n2))^2 from either side: 0.04 for glass", "03.3", 2)
{
    for (const float ior : {1.333f, 1.5f, 2.4f})
        for (const float cos_i : {1.0f, -1.0f})
            check_reflectance(cos_i, ior, 1e-6);
    const float glass = fresnel_dielectric(1.0f, 1.5f);
    INFO(exact_query(1.0f, 1.5f) << ": got " << glass << ", expected 0.04");
    CHECK(std::abs(glass - 0.04f) <= 1e-6f);
}

GRADED_TEST("fresnel_dielectric: Fresnel's equations at every angle, entering and leaving, against double precision", "03.3", 3)
{
    // Within 0.5 degrees of the critical angle R climbs to 1 with an infinite slope, and the
    // float cosine's rounding moves it further than 1e-5; the stability case looks there.
    for (const float ior : {1.333f, 1.5f, 2.4f})
        for (double angle = 0.0; angle <= 89.0; angle += 1.0)
            for (const bool leaving : {false, true}) {
                if (leaving && std::abs(angle - optics::critical_degrees(ior)) < 0.5)
                    continue;
                const float cos_i = static_cast<float>((leaving ? -1.0 : 1.0) * std::cos(radians(angle)));
                check_reflectance(cos_i, ior, 1e-5);
            }
}

GRADED_TEST("fresnel_dielectric: total internal reflection reflects everything (exactly 1), grazing incidence nearly so", "03.3", 2)
{
    for (const float ior : {1.333f, 1.5f, 2.4f}) {
        for (const double angle : {optics::critical_degrees(ior) + 0.5, 60.0, 80.0, 90.0}) {
            const float cos_i = -static_cast<float>(std::cos(radians(angle)));
            const float R = fresnel_dielectric(cos_i, ior);
            INFO(exact_query(cos_i, ior) << ": got " << R << ", expected exactly 1 (beyond the critical angle "
                 << optics::critical_degrees(ior) << ")");
            CHECK(R == 1.0f);
        }
        // Entering at grazing incidence: R -> 1 as cos_i -> 0.
        for (const float cos_i : {0.0f, 1e-3f, 0.02f})
            check_reflectance(cos_i, ior, 1e-4);
    }
}

GRADED_TEST("fresnel_dielectric: the same reflectance both ways along a path (entering at theta_i, leaving at theta_t)", "03.3", 2)
{
    // Reciprocity: light that enters at theta_i and goes on at theta_t reflects as much as light
    // that comes back the same way, leaving at theta_t.
    for (const float ior : {1.333f, 1.5f, 2.4f})
        for (const double angle : {5.0, 30.0, 50.0, 70.0, 85.0}) {
            const double theta_t = std::asin(std::sin(radians(angle)) / ior);
            const float in = static_cast<float>(std::cos(radians(angle))), out = -static_cast<float>(std::cos(theta_t));
            const float R_in = fresnel_dielectric(in, ior), R_out = fresnel_dielectric(out, ior);
            INFO(exact_query(in, ior) << " = " << R_in << "; " << exact_query(out, ior) << " = " << R_out
                 << "; expected both " << optics::fresnel_reference(in, ior));
            CHECK(std::abs(R_in - R_out) <= 2e-5f);
            CHECK(std::abs(R_in - optics::fresnel_reference(in, ior)) <= 1e-5);
        }
}

STABILITY_TEST("fresnel_dielectric: at the critical angle and one float step either side, in [0.99, 1]; 0.01 degrees beyond, exactly 1", "03.3", 2)
{
    for (const float ior : {1.333f, 1.5f, 2.4f}) {
        const double ior_d = ior;
        const float critical_cos = static_cast<float>(std::sqrt(1.0 - 1.0 / (ior_d * ior_d)));
        for (const float c : {std::nextafter(critical_cos, 0.0f), critical_cos, std::nextafter(critical_cos, 2.0f)}) {
            const float R = fresnel_dielectric(-c, ior);
            INFO(exact_query(-c, ior) << ": got " << R << ", expected 0.99 to 1 at the critical angle "
                 << optics::critical_degrees(ior));
            REQUIRE(std::isfinite(R));
            CHECK(R >= 0.99f);
            CHECK(R <= 1.0f);
        }
        const double critical = optics::critical_degrees(ior);
        const float beyond = -static_cast<float>(std::cos(radians(critical + 0.01)));
        const float R_beyond = fresnel_dielectric(beyond, ior);
        INFO(exact_query(beyond, ior) << ": got " << R_beyond << ", expected exactly 1");
        CHECK(R_beyond == 1.0f);
        check_reflectance(-static_cast<float>(std::cos(radians(critical - 0.01))), ior, 2e-3);
    }
}

STABILITY_TEST("fresnel_dielectric: never a NaN: ior = 1 reflects nothing, grazing or cos_i a hair beyond 1 either way stays in [0, 1]", "03.3", 2)
{
    // ior = 1 is no interface at all: nothing reflects, except at exactly grazing incidence, where
    // both fractions would be 0 / 0 (the contract then says 1: sin^2(theta_t) = 1).
    for (double angle = 0.0; angle <= 84.0; angle += 1.0)
        for (const float sign : {1.0f, -1.0f}) {
            const float cos_i = sign * static_cast<float>(std::cos(radians(angle)));
            const float R = fresnel_dielectric(cos_i, 1.0f);
            INFO(exact_query(cos_i, 1.0f) << ": got " << R << ", expected 0");
            CHECK(std::abs(R) <= 1e-6f);
        }
    for (const float cos_i : {0.0f, -0.0f, 1e-30f, -1e-30f})
        for (const float ior : {1.0f, 1.5f}) {
            const float R = fresnel_dielectric(cos_i, ior);
            INFO(exact_query(cos_i, ior) << ": got " << R << ", expected 1 (grazing)");
            REQUIRE(std::isfinite(R));
            CHECK(std::abs(R - 1.0f) <= 1e-6f);
        }
    // A cosine from float-normalised vectors can be 1 + 1e-7: R0 still.
    for (const float cos_i : {std::nextafter(1.0f, 2.0f), -std::nextafter(1.0f, 2.0f)}) {
        const float R = fresnel_dielectric(cos_i, 1.5f);
        INFO(exact_query(cos_i, 1.5f) << ": got " << R << ", expected R0 = 0.04");
        REQUIRE(std::isfinite(R));
        CHECK(std::abs(R - 0.04f) <= 1e-6f);
    }
}

GRADED_TEST("fresnel_dielectric: leaving at ior 2 where sin^2(theta_t) is exactly 1, exactly 1; one float step steeper, in [0.99, 1]", "03.3", 1)
{
    // c = 0x1.bb67aep-1: c^2 rounds to 0.75, so sin^2(theta_t) = 4 (1 - c^2) = 1 exactly in float,
    // the edge of total internal reflection; one float step below it, beyond the edge.
    const float at = 0x1.bb67aep-1f, below = std::nextafter(at, 0.0f), above = std::nextafter(at, 1.0f);
    for (const float c : {below, at}) {
        const float R = fresnel_dielectric(-c, 2.0f);
        INFO(exact_query(-c, 2.0f) << ", cos_i = " << std::hexfloat << -c << std::defaultfloat << ": got " << R
             << ", expected exactly 1 (sin^2(theta_t) " << (c == at ? "= 1" : "> 1") << " in float)");
        CHECK(R == 1.0f);
    }
    const float R = fresnel_dielectric(-above, 2.0f);
    INFO(exact_query(-above, 2.0f) << ", one float step inside the critical angle: got " << R << ", expected 0.99 to 1");
    REQUIRE(std::isfinite(R));
    CHECK(R >= 0.99f);
    CHECK(R <= 1.0f);
}

GRADED_TEST("fresnel_dielectric: 0.02 to 0.03 degrees from grazing (cos_i 3.5e-4, 5e-4) glass (ior 1.5) reflects nearly all, ior 1 almost nothing, not everything", "03.3", 1)
{
    // ior = 1 is no interface: sin^2(theta_t) = 1 - cos_i^2 stays below 1 (in float too, for these
    // cosines), so this is no total internal reflection, and R is near 0 (within 0.01: the float
    // form 1 - cos_i^2 is coarse this close to grazing). eta = n1 / n2 is exactly 1 here; an eta a
    // rounding above 1 pushes sin^2(theta_t) to 1 and answers "everything".
    for (const float c : {3.5e-4f, 5e-4f})
        for (const float sign : {1.0f, -1.0f}) {
            const float R = fresnel_dielectric(sign * c, 1.0f);
            INFO(exact_query(sign * c, 1.0f) << ": got " << R << ", expected about 0 (at most 0.01): ior 1 is no interface");
            REQUIRE(std::isfinite(R));
            CHECK(R >= 0.0f);
            CHECK(R <= 0.01f);
            // Glass at the same angle: nearly everything reflects (R = 0.998 and 0.997).
            const float R_glass = fresnel_dielectric(sign * c, 1.5f);
            INFO(exact_query(sign * c, 1.5f) << ": got " << R_glass << ", expected at least 0.99 (near grazing)");
            CHECK(R_glass >= 0.99f);
            CHECK(R_glass <= 1.0f);
        }
}

GRADED_TEST("fresnel_dielectric: leaving at ior 2 one float step inside the edge (sin^2(theta_t) = 1 - 3e-7), R is below 1 (about 0.997): no total reflection", "03.3", 1)
{
    // c = 0x1.bb67b0p-1, one float step steeper than 0x1.bb67aep-1 (where sin^2(theta_t) is exactly
    // 1): exactly, sin^2(theta_t) = 4 (1 - c^2) = 1 - 3.05e-7, and in float 4 (1 - c^2) = 1 - 2.4e-7,
    // so cos(theta_t) is about 5e-4 and R = 0.9969 (0.9972 in float). "Exactly 1" belongs to total
    // internal reflection only; 1 - cos_i^2 computed a rounding too large tips this ray over the edge.
    const float c = 0x1.bb67b0p-1f;
    const float R = fresnel_dielectric(-c, 2.0f);
    INFO(exact_query(-c, 2.0f) << ", cos_i = " << std::hexfloat << -c << std::defaultfloat << ": got " << R
         << ", expected about 0.997 (at least 0.99, at most 0.999): sin^2(theta_t) is below 1 there");
    REQUIRE(std::isfinite(R));
    CHECK(R >= 0.99f);
    CHECK(R <= 0.999f);
}

STABILITY_TEST("fresnel_dielectric: leaving at ior 2 just inside the critical angle, where cos_i^2 is exact in float, R within 5e-7 of the double answer", "03.3", 1)
{
    // cos_i with 12 significant bits: cos_i^2, 1 - cos_i^2 and 4 (1 - cos_i^2) are exact in float,
    // so sin^2(theta_t) is exact and only cos_t = sqrt(1 - sin^2(theta_t)) and the two fractions
    // round. cos_t is small here (0.05 to 0.09), and R moves fast with it: an error of one float
    // step of 1 in 1 - sin^2(theta_t) moves R by 2e-6 to 7e-6. Float's own answer is within 1e-7.
    for (const float c : {0x1.bb8p-1f, 0x1.bbcp-1f, 0x1.bcp-1f})
        check_reflectance(-c, 2.0f, 5e-7);
}

GRADED_TEST("fresnel_dielectric: at grazing incidence from outside (cos_i = +0 or -0) exactly 1, never above 1", "03.3", 1)
{
    // cos_i = 0: r_perp = (0 - cos_t) / (0 + cos_t) = -1 and r_par = (0 - eta cos_t) / (0 + eta cos_t)
    // = -1 exactly, so R = (1 + 1) / 2 = 1 exactly: all the light, and not a rounding more.
    for (const float ior : {1.333f, 1.5f, 2.4f, 1.0f})
        for (const float cos_i : {0.0f, -0.0f}) {
            const float R = fresnel_dielectric(cos_i, ior);
            INFO(exact_query(cos_i, ior) << ": got " << std::setprecision(9) << R << ", expected exactly 1 (grazing)");
            CHECK(R == 1.0f);
        }
}
