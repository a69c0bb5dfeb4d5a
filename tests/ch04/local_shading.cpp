// EXERCISE 04.1: local shading of one light, light * (k_d max(0, n.l) + k_s max(0, n.h)^p).
#include "tests/ch04/describe.hpp"

#include <cmath>
#include <limits>

using namespace rt;
using namespace rt::grader;

namespace {

const vec3 up{0, 1, 0};

// The direction at `degrees` from +y toward +x (or -x for negative angles), in the xy plane.
vec3 tilted(double degrees)
{
    const double a = degrees * pi / 180.0;
    return {static_cast<float>(std::sin(a)), static_cast<float>(std::cos(a)), 0.0f};
}

// The expected answer in double, from the formula.
color reference(const PhongMaterial& m, const vec3& n, const vec3& v, const vec3& l, const color& light)
{
    const double cos_l = glm::dot(dvec3(n), dvec3(l));
    if (cos_l <= 0)
        return color(0.0f);
    const dvec3 h = dvec3(l) + dvec3(v);
    const double cos_h = glm::dot(h, h) > 0 ? glm::dot(dvec3(n), glm::normalize(h)) : 0.0;
    const double spec = cos_h > 0 ? std::pow(cos_h, static_cast<double>(m.shininess)) : 0.0;
    return color(dvec3(light) * (dvec3(m.diffuse) * cos_l + dvec3(m.specular) * spec));
}

std::string query(const PhongMaterial& m, const vec3& n, const vec3& v, const vec3& l, const color& light)
{
    return show(m) + ", normal " + show(n) + ", toward the eye " + show(v) + ", toward the light " + show(l) +
           ", light arriving " + show(light);
}

// Checks one call against the formula.
void check(const PhongMaterial& m, const vec3& n, const vec3& v, const vec3& l, const color& light)
{
    const color got = local_shading(m, n, v, l, light);
    const color want = reference(m, n, v, l, light);
    INFO(query(m, n, v, l, light) << ": got " << show(got) << ", expected " << show(want));
    CHECK(same_colour(got, want));
}

}  // namespace

GRADED_TEST("local_shading: Lambert's cosine, k_d I straight above and k_d I cos(theta) at a slant", "04.1", 3)
{
    const PhongMaterial matte{{0.5f, 0.25f, 1.0f}, color(0.0f), 1.0f};
    const color light{2.0f, 3.0f, 0.5f};
    for (const double degrees : {0.0, 30.0, 60.0, -75.0, 89.0})
        check(matte, up, tilted(-40.0), tilted(degrees), light);
}

GRADED_TEST("local_shading: the highlight is k_s I where n bisects light and eye, and falls off as (n.h)^p", "04.1", 3)
{
    const PhongMaterial shiny{color(0.0f), {0.5f, 0.6f, 0.7f}, 20.0f};
    const color light(1.5f);
    // Mirror directions: h = n, so the highlight is k_s I exactly.
    {
        const color got = local_shading(shiny, up, tilted(-35.0), tilted(35.0), light);
        INFO(query(shiny, up, tilted(-35.0), tilted(35.0), light) << ": got " << show(got)
             << ", expected the full highlight k_s I = " << show(light * shiny.specular));
        CHECK(glm::length(got - light * shiny.specular) <= 1e-5f);
    }
    for (const double eye : {-50.0, -20.0, 10.0, 70.0})
        check(shiny, up, tilted(eye), tilted(35.0), light);
    // Diffuse and specular add up.
    const PhongMaterial plastic{{0.4f, 0.1f, 0.1f}, color(0.5f), 8.0f};
    check(plastic, glm::normalize(vec3(0.2f, 1.0f, -0.3f)), tilted(-10.0), glm::normalize(vec3(0.5f, 1.0f, 0.5f)), light);
}

GRADED_TEST("local_shading: a light behind the surface gives nothing, not even a highlight; one above it does", "04.1", 2)
{
    const PhongMaterial plastic{{0.6f, 0.5f, 0.4f}, color(0.8f), 2.0f};
    const color light(1.0f);
    // Behind (n.l < 0) with the eye placed so that n.h > 0, and exactly in the plane (n.l = 0).
    for (const vec3& l : {tilted(100.0), vec3(1, 0, 0)}) {
        const vec3 v = tilted(-10.0);
        const color got = local_shading(plastic, up, v, l, light);
        INFO(query(plastic, up, v, l, light) << ": got " << show(got) << ", expected black: the light is not above the surface");
        CHECK(got == color(0.0f));
    }
    check(plastic, up, tilted(-10.0), tilted(80.0), light);
}

GRADED_TEST("local_shading: a halfway vector below the surface (the eye below it) gives no highlight, and no NaN", "04.1", 1)
{
    // shade() turns n toward the eye, so it never asks this, but nothing in the contract forbids it:
    // with the light above and the eye below, h = l + v can point below the surface, n.h < 0, and
    // (n.h)^p is positive for an even p and NaN for p = 2.5 unless max(0, n.h) comes first.
    for (const float p : {20.0f, 2.5f}) {
        const PhongMaterial plastic{{0.6f, 0.5f, 0.4f}, color(0.8f), p};
        const vec3 l = tilted(60.0), v = tilted(-150.0);
        const color got = local_shading(plastic, up, v, l, color(1.0f));
        const color want = reference(plastic, up, v, l, color(1.0f));
        INFO(query(plastic, up, v, l, color(1.0f)) << ": n.h = " << glm::dot(up, glm::normalize(l + v)) << ", got "
             << show(got) << ", expected " << show(want) << " (the diffuse term alone)");
        CHECK(same_colour(got, want));
    }
}

STABILITY_TEST("local_shading: never a NaN, with the light straight opposite the eye or grazing, p from 0.5 to 1000", "04.1", 1)
{
    // l = -v leaves no halfway vector (normalising 0 gives a NaN): the highlight is 0 there.
    for (const float p : {0.5f, 1.0f, 1000.0f}) {
        const PhongMaterial plastic{{0.6f, 0.5f, 0.4f}, color(0.8f), p};
        for (const vec3& l : {tilted(30.0), tilted(89.9999), glm::normalize(vec3(1.0f, 1e-7f, 0.0f))}) {
            const vec3 v = -l;
            const color got = local_shading(plastic, up, v, l, color(1.0f));
            const color want = reference(plastic, up, v, l, color(1.0f));
            INFO(query(plastic, up, v, l, color(1.0f)) << ": got " << show(got) << ", expected " << show(want)
                 << " (the diffuse term alone, finite)");
            REQUIRE((std::isfinite(got.x) && std::isfinite(got.y) && std::isfinite(got.z)));
            REQUIRE((same_colour(got, want) && got.x > 0.0f));
        }
        check(plastic, up, tilted(-89.999), tilted(89.999), color(1.0f));
    }
}

GRADED_TEST("local_shading: n.l exactly 0 gives black; a light the least bit above the surface (n.l = 1e-30, or the least float) keeps its highlight", "04.1", 1)
{
    // The contract's test is n.l <= 0, nothing else: a threshold such as n.l > 1e-4 drops the
    // highlight of a grazing light, which is bright when the eye looks along its mirror direction.
    const PhongMaterial plastic{{0.6f, 0.5f, 0.4f}, color(0.8f), 2.0f};
    const vec3 v = tilted(-10.0);
    for (const float above : {0.0f, -0.0f, 1e-30f, std::numeric_limits<float>::denorm_min(), -1e-30f}) {
        const vec3 l{1.0f, above, 0.0f};  // unit: 1 + 1e-60 is 1 in float
        const color got = local_shading(plastic, up, v, l, color(1.0f));
        const color want = reference(plastic, up, v, l, color(1.0f));
        INFO("local_shading with " << query(plastic, up, v, l, color(1.0f)) << ": n.l = " << glm::dot(up, l) << ", got " << show(got) << ", expected "
             << show(want) << (glm::dot(up, l) > 0.0f ? " (the light is above the surface: its highlight counts)"
                                                      : " (black: the light is not above the surface)"));
        CHECK(same_colour(got, want));
        CHECK((glm::dot(up, l) > 0.0f) == (got.x > 0.0f));
    }
}

GRADED_TEST("local_shading: a light the least bit off straight opposite the eye keeps its halfway vector and highlight, however short l + v is", "04.1", 1)
{
    // Only l exactly opposite v has no halfway vector. Here l + v = (0, 0, d) with d = 2^-74.5
    // (rounded to float): its squared length is the least float, 2^-149, and not 0, so
    // h = normalize(l + v) = (0, 0, 1) and n.h = 0.6. A threshold on |l + v| (a "too short to
    // normalise" test) drops this highlight.
    const PhongMaterial plastic{{0.6f, 0.5f, 0.4f}, color(0.8f), 2.0f};
    const vec3 n{0.0f, 0.8f, 0.6f};
    const float d = static_cast<float>(std::ldexp(std::sqrt(2.0), -75));
    const vec3 l{0.6f, 0.8f, 0.0f}, v{-0.6f, -0.8f, d};
    const vec3 halfway = l + v;
    const color got = local_shading(plastic, n, v, l, color(1.0f));
    const color want = reference(plastic, n, v, l, color(1.0f));
    const color diffuse_alone = plastic.diffuse * glm::dot(n, l);
    INFO(query(plastic, n, v, l, color(1.0f)) << ": l + v = " << show(halfway) << ", its squared length "
         << glm::dot(halfway, halfway) << " (not 0: l is not exactly opposite v), so the halfway vector is (0, 0, 1) and n.h = 0.6; got "
         << show(got) << ", expected " << show(want) << " (the diffuse term alone would be " << show(diffuse_alone) << ")");
    REQUIRE(glm::dot(halfway, halfway) > 0.0f);
    CHECK(same_colour(got, want));
}

GRADED_TEST("local_shading: a halfway vector the least bit above the surface (n.h = the least float) keeps its highlight; at n.h = 0 or below, none", "04.1", 1)
{
    // max(0, n.h)^p is positive for every n.h > 0: with p = 0.5 the least float, 2^-149, gives
    // 2^-74.5, seen here in a light of 1e20. The normal is (1, 0, 0), the light grazes it at
    // n.l = 2^-149, the eye lies in the surface (or the least bit below it), and l + v has length 1,
    // so n.h is l_x + v_x exactly. No diffuse colour, so what comes back is the highlight alone.
    const PhongMaterial gloss{color(0.0f), {0.5f, 0.6f, 0.7f}, 0.5f};
    const vec3 n{1.0f, 0.0f, 0.0f};
    const float least = std::numeric_limits<float>::denorm_min();
    const vec3 l{least, 1.0f, 0.0f};
    const color light(1e20f);
    for (const float eye_x : {0.0f, -least, -2.0f * least}) {
        const vec3 v{eye_x, -0.5f, 0.866025388f};
        const color got = local_shading(gloss, n, v, l, light);
        const color want = reference(gloss, n, v, l, light);
        const bool above = l.x + eye_x > 0.0f;
        INFO(query(gloss, n, v, l, light) << ": n.h = " << l.x + eye_x << ", got " << show(got) << ", expected " << show(want)
             << (above ? " (the halfway vector is above the surface: k_s (n.h)^0.5 times the light)"
                       : " (black: the halfway vector is not above the surface)"));
        CHECK(same_colour(got, want));
        CHECK(above == (got.x > 0.0f));
    }
}

GRADED_TEST("local_shading: a shininess of 0 gives k_s wherever the halfway vector is above the surface, and no highlight exactly along it (n.h = 0)", "04.1", 1)
{
    // pow(n.h, 0) is 1 for every n.h, 0 included: only the test n.h > 0 keeps the highlight off a
    // halfway vector that lies in the surface. The normal is (1, 0, 0), the light grazes it at
    // n.l = 2^-149 (no diffuse colour), and l + v has length 1, so n.h is l_x + v_x exactly.
    const PhongMaterial matte_gloss{color(0.0f), {0.5f, 0.6f, 0.7f}, 0.0f};
    const vec3 n{1.0f, 0.0f, 0.0f};
    const float least = std::numeric_limits<float>::denorm_min();
    const vec3 l{least, 1.0f, 0.0f};
    for (const float eye_x : {0.0f, -least}) {
        const vec3 v{eye_x, -0.5f, 0.866025388f};
        const color got = local_shading(matte_gloss, n, v, l, color(1.0f));
        const bool above = l.x + eye_x > 0.0f;
        const color want = above ? matte_gloss.specular : color(0.0f);
        INFO(query(matte_gloss, n, v, l, color(1.0f)) << ": n.h = " << l.x + eye_x << ", got " << show(got) << ", expected "
             << show(want) << (above ? " (k_s: (n.h)^0 is 1 above the surface)" : " (black: n.h = 0 is not above the surface)"));
        CHECK(same_colour(got, want));
    }
}
