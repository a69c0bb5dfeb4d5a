// EXERCISE 03.1: the mirror direction, r = v - 2 (v.n) n, as the slide derives it.
#include "common/random.hpp"
#include "tests/ch03/optics_reference.hpp"

#include <cmath>

using namespace rt;
using namespace rt::grader;

namespace {

// The slide's decomposition in double, from the same float inputs.
dvec3 mirror_reference(const vec3& v, const vec3& n)
{
    const dvec3 V(v), N(n);
    const dvec3 v_n = glm::dot(V, N) * N, v_s = V - v_n;
    return v_s - v_n;
}

std::string reflect_query(const vec3& v, const vec3& n)
{
    return "reflect(v = " + show(v) + ", n = " + show(n) + ")";
}

void check_against_reference(const vec3& v, const vec3& n, double tolerance)
{
    const vec3 r = reflect(v, n);
    const dvec3 want = mirror_reference(v, n);
    INFO(reflect_query(v, n) << ": got " << show(r) << ", expected " << show(vec3(want)) << " (v_s kept, v_n reversed)");
    REQUIRE(optics::distance(r, want) <= tolerance);
}

}  // namespace

GRADED_TEST("reflect: keeps the part of v along the surface and reverses the part along the normal", "03.1", 3)
{
    const vec3 up{0, 1, 0};
    // 45 degrees onto a floor: down-and-forward becomes up-and-forward.
    {
        const vec3 v = glm::normalize(vec3(1, -1, 0));
        const vec3 r = reflect(v, up);
        INFO(reflect_query(v, up) << ": got " << show(r) << ", expected " << show(glm::normalize(vec3(1, 1, 0))));
        CHECK(glm::length(r - glm::normalize(vec3(1, 1, 0))) <= 1e-6f);
    }
    // Oblique rays on tilted surfaces, against the slide's v_s - v_n in double.
    const vec3 tilted = glm::normalize(vec3(0.3f, 0.8f, -0.5f));
    for (const vec3 v : {glm::normalize(vec3(0.2f, -0.9f, 0.4f)), glm::normalize(vec3(-1, -0.1f, 2)),
                         glm::normalize(vec3(3, 1, -2))})
        for (const vec3 n : {up, tilted, glm::normalize(vec3(-1, 0.5f, 2))})
            check_against_reference(v, n, 1e-6);
}

GRADED_TEST("reflect: the normal's sign does not matter, the angle to the normal is kept, twice gives v back", "03.1", 2)
{
    const vec3 v = glm::normalize(vec3(0.4f, -0.7f, -0.6f));
    const vec3 n = glm::normalize(vec3(-0.2f, 1.0f, 0.3f));
    const vec3 r = reflect(v, n), r_flipped = reflect(v, -n), back = reflect(r, n);
    INFO(reflect_query(v, n) << " = " << show(r) << "; with -n: " << show(r_flipped) << "; reflected again: " << show(back)
         << "; r.n = " << glm::dot(r, n) << ", expected -v.n = " << -glm::dot(v, n));
    CHECK(glm::length(r - r_flipped) <= 1e-6f);
    CHECK(std::abs(glm::dot(r, n) + glm::dot(v, n)) <= 1e-6f);
    CHECK(glm::length(back - v) <= 1e-6f);
}

STABILITY_TEST("reflect: unit length kept and never a NaN, grazing (r = v), head-on (r = -v) and random", "03.1", 2)
{
    // v.n = 0 exactly: nothing to reverse, r is v to the bit.
    const vec3 grazing{0.6f, 0.0f, 0.8f}, up{0, 1, 0};
    {
        const vec3 r = reflect(grazing, up);
        INFO(reflect_query(grazing, up) << ": got " << show(r) << ", expected v itself");
        CHECK(r == grazing);
    }
    // Head-on, n along -v and along v: straight back.
    const vec3 v = glm::normalize(vec3(1, -2, 3));
    for (const vec3 n : {-v, v}) {
        const vec3 r = reflect(v, n);
        INFO(reflect_query(v, n) << ": got " << show(r) << ", expected -v = " << show(-v));
        CHECK(glm::length(r + v) <= 1e-6f);
    }
    // Random unit v and n (float-normalised, so a few ulps off unit): |r| stays within 1e-6 of 1
    // and within 1e-6 of the double answer. Grazing and nearly head-on pairs come up too.
    Rng rng(31, 0);
    for (int k = 0; k < 100000; ++k) {
        const vec3 a = glm::normalize(vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() - 0.5f));
        const vec3 b = glm::normalize(vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() - 0.5f));
        const vec3 r = reflect(a, b);
        INFO(reflect_query(a, b) << ": got " << show(r) << " of length " << glm::length(r));
        REQUIRE(std::isfinite(r.x + r.y + r.z));
        REQUIRE(std::abs(glm::length(r) - 1.0f) <= 1e-6f);
        check_against_reference(a, b, 1e-6);
    }
}

GRADED_TEST("reflect: off a mirror facing along an axis, exactly that coordinate of v changes sign, to the bit", "03.1", 1)
{
    // With n a unit axis, v.n is one coordinate of v, 2 (v.n) n is exact, and v - 2 (v.n) n turns
    // that coordinate around without a rounding: head-on, -v itself; obliquely, the other two kept.
    const vec3 vs[] = {vec3(0, 0, -1), glm::normalize(vec3(1, -2, 3)), glm::normalize(vec3(-0.3f, 0.7f, -0.2f)),
                       vec3(0.6f, -0.8f, 0.0f)};
    for (const vec3& v : vs)
        for (int axis = 0; axis < 3; ++axis)
            for (const float sign : {1.0f, -1.0f}) {
                vec3 n(0.0f);
                n[axis] = sign;
                if (v[axis] == 0.0f)
                    continue;
                vec3 want = v;
                want[axis] = -v[axis];
                const vec3 r = reflect(v, n);
                INFO(reflect_query(v, n) << ": got " << show(r) << ", expected exactly " << show(want)
                                 << " (only the coordinate along n reversed, no rounding: each step is exact)");
                CHECK(r == want);
            }
}
