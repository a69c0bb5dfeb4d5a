// EXERCISE 02.2: the precise sphere test (Ray Tracing Gems ch. 7), disc = r^2 - |f - bV|^2 and the
// stable pair of roots q, c/q. Its stability cases are the lesson's distant, tiny and huge spheres and the kit's
// goal: at distance 1e4, fewer than 0.01% wrong answers and t within 2e-6.
#include "tests/ch02/sphere_cases.hpp"

#include <cmath>

using namespace rt;
using namespace rt::grader;

namespace {

const spheres::SphereTestFn precise = &hit_sphere_precise<float>;
constexpr double u = 0x1p-24;  // float's unit roundoff

struct Bounds {
    double wrong_fraction;
    double rel_t_error;
};

void check_case(const std::string& what, const std::vector<extremes::SphereProbe<float>>& probes, Bounds bounds)
{
    std::vector<std::optional<float>> answers;
    const extremes::Score score = spheres::run_case(precise, probes, answers);
    INFO(describe(what, probes, answers, score) << "\n  allowed: " << 100.0 * bounds.wrong_fraction
         << "% wrong, relative t error " << bounds.rel_t_error);
    CHECK(score.answers == probes.size());
    CHECK(score.wrong_fraction() <= bounds.wrong_fraction);
    CHECK(score.max_rel_t_error <= bounds.rel_t_error);
}

}  // namespace

RT_SPHERE_BEHAVIOURS(hit_sphere_precise, "02.2")

STABILITY_TEST("hit_sphere_precise: at distance 1e4, under 0.01% wrong hit/miss answers and t within 2e-6", "02.2", 2)
{
    check_case("a unit sphere 1e4 away, rays aimed within 1.2 r of its centre",
               extremes::distant_spheres<float>(1e4f, 1.0f, 100000, 1), {1e-4, 2e-6});
}

STABILITY_TEST("hit_sphere_precise: from 1e2 to 1e6 away, only rays within rounding of the outline go wrong", "02.2", 2)
{
    // |f - bV| is the ray's distance from the centre, rounded like the coordinates: by a few D u.
    // Only rays whose distance lies that close to r can get the wrong answer, a fraction of about
    // 1.4 (3 D u) / r of rays spread over 1.2 r; 4 D u / r allows for it. t is worst for rays
    // that graze (a small disc has a large square root's slope), 1e-5 at any distance.
    for (const float distance : {1e2f, 1e3f, 1e4f, 1e5f, 1e6f}) {
        std::ostringstream what;
        what << "a unit sphere " << distance << " away, rays aimed within 1.2 r of its centre";
        check_case(what.str(), extremes::distant_spheres<float>(distance, 1.0f, 50000, 2), {4.0 * distance * u, 1e-5});
    }
}

STABILITY_TEST("hit_sphere_precise: tiny spheres (r = 1e-3, 1e-4 at distance 1) are hit as exactly", "02.2", 1)
{
    for (const float radius : {1e-3f, 1e-4f}) {
        std::ostringstream what;
        what << "a sphere of radius " << radius << " 1 away, rays aimed within 1.2 r of its centre";
        check_case(what.str(), extremes::distant_spheres<float>(1.0f, radius, 50000, 3), {4.0 * u / radius, 1e-5});
    }
}

STABILITY_TEST("hit_sphere_precise: a huge sphere (r = 1e4) seen from 1 above: no wrong answers and t within 1e-6", "02.2", 1)
{
    // In float arithmetic f = E - O rounds to steps of 2^-10 near 1e4, and c = |f|^2 - r^2 and
    // r^2 - |f - bV|^2 cancel to a few times 1e-3 of t for rays that graze the horizon. In double
    // (the contract) t comes out within a few float roundings: 1.2e-7 measured.
    check_case("a sphere of radius 1e4 from 1 above its surface, rays in every direction",
               extremes::huge_sphere<float>(50000, 4), {0.0, 1e-6});
}

STABILITY_TEST("hit_sphere_precise: a tangent ray 1000 away misses, one float step inside hits", "02.2", 1)
{
    spheres::tangent(precise, 1000.0f);
}

STABILITY_TEST("hit_sphere_precise: directions a few float steps off unit length still hit right 1e3 away", "02.2", 1)
{
    // The contract asks for a unit V, and glm::normalize gives one to within a few float steps.
    // The exact answer takes V as it is, so this checks that those steps cost no more than their
    // own size: the slide's e^2 would turn them into errors of D^2 |V - 1|.
    std::vector<extremes::SphereProbe<float>> probes = extremes::distant_spheres<float>(1e3f, 1.0f, 50000, 5);
    for (size_t k = 0; k < probes.size(); ++k)
        probes[k].ray.dir *= 1.0f + static_cast<float>(static_cast<int>(k % 9) - 4) * 0x1p-23f;
    check_case("a unit sphere 1e3 away, directions scaled by 1 + k 2^-23, k = -4..4", probes, {4.0 * 1e3 * u, 1e-5});
}

GRADED_TEST("hit_sphere_precise: a ray leaving from one float step inside the surface: t (about 1e-7) within 1e-6 of exact", "02.2", 2)
{
    // From one float step inside a sphere of radius 0.75, heading out (b = f.V between 0 and 1): the
    // exit is a float step or so away. q = -b - sqrt(disc) adds two numbers of one sign and c/q
    // gives the exit to double's precision; -b + sqrt(disc) subtracts two numbers within 1e-7 of
    // each other and keeps only the last digits of sqrt(disc)'s rounding: 2% to 19% wrong here.
    // The range starts at 0, for the exit is far nearer than the default range.min.
    const float r = 0.75f;
    const Sphere sphere{{0, 0, 0}, r};
    const point3 origin{std::nextafter(r, 0.0f), 0, 0};
    for (const vec3 dir : {vec3(0.6f, 0.8f, 0.0f), vec3(0.8f, 0.6f, 0.0f), vec3(0.28f, 0.96f, 0.0f)})
        spheres::check_against_exact(precise, Ray{origin, dir}, sphere, Interval{0.0f, infinity});
}

GRADED_TEST("hit_sphere_precise: with a range reaching behind the eye, the nearer root is the smaller t (e - d)", "02.2", 1)
{
    // 3 beyond a unit sphere's centre, heading away from it: the roots are t = -4 and t = -2, both
    // inside (-10, 10). The nearer root, as the slide's e - d, is -4; the farther one, -2, only when
    // -4 is outside the range. With b >= 0, c/q is the larger root and q the smaller.
    const Sphere sphere{{0, 0, 0}, 1.0f};
    const Ray ray{{0, 0, 3}, {0, 0, 1}};
    for (const auto& [range, expected] : {std::pair{Interval{-10.0f, 10.0f}, -4.0f}, std::pair{Interval{-3.0f, 10.0f}, -2.0f}}) {
        const std::optional<float> t = precise(ray, sphere, range);
        INFO(spheres::query(ray, sphere, range) << ": got " << show(t) << ", expected t = " << expected
             << " (the roots are -4 and -2; the smaller one inside the range comes first)");
        REQUIRE(t);
        CHECK(*t == expected);
    }
}
