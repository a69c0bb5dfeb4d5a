// EXERCISE 01.3: QueryScene, the nearest hit over the scene's discs.
#include "01_ray_casting/01_ray_casting.hpp"
#include "tests/grader/graded.hpp"

#include <algorithm>

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
