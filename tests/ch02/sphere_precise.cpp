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
