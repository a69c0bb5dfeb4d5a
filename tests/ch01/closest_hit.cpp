// EXERCISE 01.3: QueryScene, the nearest hit over the scene's discs.
#include "01_ray_casting/01_ray_casting.hpp"
#include "tests/grader/graded.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>

using namespace rt;
using rt::grader::show;

namespace {

// A disc of radius 1 on the z axis at depth z, facing the eye at the origin.
Disc disc_at(float z) { return Disc{{{0, 0, z}, {0, 0, 1}}, 1.0f, color(0.5f)}; }

const Ray down_z{{0, 0, 0}, {0, 0, -1}};

std::string describe(const DiscScene& scene)
{
    std::ostringstream s;
    s << "discs of radius 1 on the z axis at z =";
    for (const Disc& d : scene.discs)
        s << ' ' << d.plane.b.z;
    return s.str();
}

std::string show_hit(const std::optional<Hit>& hit)
{
    if (!hit)
        return "no hit";
    std::ostringstream s;
    s << "t = " << hit->t << " on disc " << hit->object << " at " << show(hit->p);
    return s.str();
}

}  // namespace

GRADED_TEST("the nearest of overlapping discs wins, whatever their order in the list", "01.3", 3)
{
    std::vector<float> depths{-2.0f, -5.0f, -9.0f};
    std::sort(depths.begin(), depths.end());
    do {
        DiscScene scene;
        for (const float z : depths)
            scene.discs.push_back(disc_at(z));
        const int nearest = static_cast<int>(std::find(depths.begin(), depths.end(), -2.0f) - depths.begin());
        const std::optional<Hit> hit = closest_hit(down_z, scene, Interval{});
        INFO(show(down_z) << " against " << describe(scene) << ": got " << show_hit(hit)
             << ", expected t = 2 on disc " << nearest);
        REQUIRE(hit);
        CHECK(hit->t == Approx(2.0f));
        CHECK(hit->object == nearest);
    } while (std::next_permutation(depths.begin(), depths.end()));
}

GRADED_TEST("a disc behind the eye does not hide the one in front", "01.3", 2)
{
    DiscScene scene;
    scene.discs = {disc_at(2.0f), disc_at(-4.0f)};
    const std::optional<Hit> hit = closest_hit(down_z, scene, Interval{});
    INFO(show(down_z) << " against " << describe(scene) << ": got " << show_hit(hit) << ", expected t = 4 on disc 1");
    REQUIRE(hit);
    CHECK(hit->t == Approx(4.0f));
    CHECK(hit->object == 1);
}

GRADED_TEST("a ray that misses every disc finds nothing, and one aimed at a disc finds it", "01.3", 2)
{
    DiscScene scene;
    CHECK_FALSE(closest_hit(down_z, scene, Interval{}));  // an empty scene
    scene.discs = {disc_at(-3.0f), disc_at(-6.0f)};
    {
        const Ray beside{{2.5f, 0, 0}, {0, 0, -1}};  // passes outside both radii
        const std::optional<Hit> miss = closest_hit(beside, scene, Interval{});
        INFO(show(beside) << " against " << describe(scene) << ": got " << show_hit(miss) << ", expected no hit");
        CHECK_FALSE(miss);
    }
    const Ray aimed{{0.5f, 0, 0}, {0, 0, -1}};
    const std::optional<Hit> hit = closest_hit(aimed, scene, Interval{});
    INFO(show(aimed) << " against " << describe(scene) << ": got " << show_hit(hit) << ", expected t = 3 on disc 0");
    REQUIRE(hit);
    CHECK(hit->object == 0);
}

GRADED_TEST("the range limits the search: range.max cuts off far discs, range.min near ones", "01.3", 2)
{
    DiscScene scene;
    scene.discs = {disc_at(-5.0f), disc_at(-2.0f)};
    struct Case {
        Interval range;
        int object;  // -1: no hit
    };
    for (const Case& c : {Case{{1e-4f, 3.0f}, 1}, Case{{1e-4f, 1.5f}, -1}, Case{{2.5f, infinity}, 0}}) {
        const std::optional<Hit> hit = closest_hit(down_z, scene, c.range);
        INFO(show(down_z) << " against " << describe(scene) << " in the range (" << c.range.min << ", "
             << c.range.max << "): got " << show_hit(hit) << ", expected "
             << (c.object < 0 ? std::string("no hit") : "disc " + std::to_string(c.object)));
        CHECK((hit ? hit->object : -1) == c.object);
    }
}

GRADED_TEST("the hit record gives the disc's index, the hit point and the disc's normal", "01.3", 1)
{
    DiscScene scene;
    scene.discs = {disc_at(-8.0f), Disc{{{0.2f, 0, -5}, glm::normalize(vec3(0, 1, 1))}, 2.0f, color(1.0f)}};
    const std::optional<Hit> hit = closest_hit(down_z, scene, Interval{});
    INFO(show(down_z) << " against a disc at z = -8 and a tilted one through (0.2, 0, -5): got " << show_hit(hit));
    REQUIRE(hit);
    CHECK(hit->object == 1);
    CHECK(glm::length(hit->p - vec3(0, 0, -5)) <= 1e-5f);
    CHECK(glm::length(hit->n - scene.discs[1].plane.n) <= 1e-6f);
}

GRADED_TEST("a disc exactly at range.min or range.max is not hit; one float step inside the range it is", "01.3", 2)
{
    // Discs at t = 2 and t = 5 exactly (straight down the z axis from the origin).
    DiscScene scene;
    scene.discs = {disc_at(-5.0f), disc_at(-2.0f)};
    const float before_2 = std::nextafter(2.0f, 0.0f), past_2 = std::nextafter(2.0f, 3.0f);
    const float before_5 = std::nextafter(5.0f, 0.0f), past_5 = std::nextafter(5.0f, 6.0f);
    struct Case {
        Interval range;
        int object;  // -1: no hit
    };
    for (const Case& c : {Case{{2.0f, 5.0f}, -1}, Case{{before_2, 5.0f}, 1}, Case{{2.0f, past_5}, 0},
                          Case{{past_2, before_5}, -1}, Case{{1e-4f, 2.0f}, -1}, Case{{1e-4f, past_2}, 1},
                          Case{{5.0f, infinity}, -1}, Case{{before_5, infinity}, 0}}) {
        const std::optional<Hit> hit = closest_hit(down_z, scene, c.range);
        INFO(show(down_z) << " against " << describe(scene) << " (hits at t = 5 and t = 2) in the open range ("
             << std::setprecision(9) << c.range.min << ", " << c.range.max << "): got " << show_hit(hit)
             << ", expected " << (c.object < 0 ? std::string("no hit") : "disc " + std::to_string(c.object)));
        CHECK((hit ? hit->object : -1) == c.object);
    }
}

GRADED_TEST("far from the origin, the nearer of two discs 0.05 apart wins, with t within 1e-6 of double", "01.3", 1)
{
    // Two parallel discs 3e4 from the origin, 0.05 apart, seen from a few units away; their order
    // in the list is the far one first, then the other way round.
    const vec3 n = glm::normalize(vec3(2, -1, 2));
    const point3 near_centre{12345.5f, -23456.25f, 34567.75f};
    const point3 far_centre = near_centre - 0.05f * n;
    const Ray ray{near_centre + 4.0f * n + vec3(0.25f, 0.5f, -0.25f), -n};
    const dvec3 dn(n), du(ray.origin), dv(ray.dir);
    const double expected = glm::dot(dn, dvec3(near_centre) - du) / glm::dot(dn, dv);
    for (const bool near_first : {false, true}) {
        DiscScene scene;
        const Disc near_disc{{near_centre, n}, 2.0f, color(0.5f)}, far_disc{{far_centre, n}, 2.0f, color(0.5f)};
        scene.discs = near_first ? std::vector<Disc>{near_disc, far_disc} : std::vector<Disc>{far_disc, near_disc};
        const int nearest = near_first ? 0 : 1;
        const std::optional<Hit> hit = closest_hit(ray, scene, Interval{});
        INFO(show(ray) << " against two discs of radius 2 with normal " << show(n) << " through " << show(near_centre)
             << " and " << show(far_centre) << " (listed " << (near_first ? "near one first" : "far one first")
             << "): got " << show_hit(hit) << ", expected t = " << std::setprecision(10) << expected << " on disc "
             << nearest);
        REQUIRE(hit);
        CHECK(hit->object == nearest);
        CHECK(rt::grader::rel_error(hit->t, expected) <= 1e-6);
    }
}
