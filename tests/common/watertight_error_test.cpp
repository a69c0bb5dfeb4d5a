// The watertight test's own bound on t (chapter 02's shape_tests.hpp), where it is needed most:
// a ray leaving the plane of a nearly collinear triangle. The true t is then exactly 0, so every t
// the watertight test (EXERCISE 02.5) reports is all rounding and must lie within the bound, or
// chapter 04's bounded test lets the ray find its own surface again, at a point outside the
// triangle's box where no structure of chapters 07-10 looks for it.
#include "02_spheres_triangles/02_spheres_triangles.hpp"
#include "02_spheres_triangles/shape_tests.hpp"
#include "common/random.hpp"
#include "tests/grader/graded.hpp"

#include <cmath>
#include <sstream>

using namespace rt;
using rt::grader::show;

TEST_CASE("every t the watertight test finds from the plane of a nearly collinear triangle lies within its bound")
{
    // Slivers a, a + e + s p, a + 2 e (p across e, s from 1 down to 2^-23 of it) 2^-20 to 2^19
    // across, in a plane z = c, x = c or y = c; the ray from a point of that plane near the sliver's
    // middle, in any direction. Before the bound followed 02.5's fallback to double, 11 of these
    // rays' 271,500 hits got a bound of 0: it divided by the float edge functions' sum, cancelled
    // to 0, where 02.5 recomputes them in double and hits at the t of its rounding.
    Rng rng(27, 4);
    const auto u = [&] { return 2.0f * rng.next_float() - 1.0f; };
    int hits = 0, beyond = 0;
    std::string first;
    for (int k = 0; k < 2'000'000; ++k) {
        const float scale = std::ldexp(1.0f, static_cast<int>(rng.next_u32() % 40) - 20);
        const float s = std::ldexp(1.0f, -static_cast<int>(rng.next_u32() % 24));
        const float c = 4.0f * scale * u();
        const point3 a(4.0f * scale * u() + scale * u(), 4.0f * scale * u() + scale * u(), c);
        const vec3 e(scale * u(), scale * u(), 0.0f), p(-e.y, e.x, 0.0f);
        point3 b = a + e + s * u() * p, d = a + 2.0f * e + s * u() * p, o = a + (1.0f + u()) * e + s * u() * p;
        b.z = d.z = o.z = c;
        const vec3 dir = glm::normalize(vec3(u(), u(), u()));
        // The plane is z = c, x = c or y = c by turns.
        const auto turn = [k](const vec3& v) { return k % 3 == 0 ? v : k % 3 == 1 ? vec3(v.z, v.x, v.y) : vec3(v.y, v.z, v.x); };
        const Triangle tri{turn(a), turn(b), turn(d)};
        const Ray ray{turn(o), turn(dir)};
        const std::optional<TriangleHit<float>> hit = hit_triangle_watertight(ray, tri, Interval{-infinity, infinity});
        if (!hit)
            continue;
        ++hits;
        const float bound = watertight_t_error(ray, tri);
        if (std::abs(hit->t) <= bound)
            continue;
        if (beyond++ == 0) {
            std::ostringstream s9;
            s9.precision(9);
            s9 << "the triangle " << show(tri.a) << ", " << show(tri.b) << ", " << show(tri.c) << " and the " << show(ray)
               << ": t " << hit->t << " (the true t is 0), bound " << bound;
            first = s9.str();
        }
    }
    INFO(beyond << " of " << hits << " hits lie beyond the bound; the first: " << first);
    CHECK(hits > 100'000);
    CHECK(beyond == 0);
}
