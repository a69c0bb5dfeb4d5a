// EXERCISE 04.2: the any-hit shadow feeler: anything strictly between the origin and the light?
#include "02_spheres_triangles/mesh_scene.hpp"
#include "tests/ch04/describe.hpp"

#include <cmath>
#include <optional>
#include <sstream>
#include <tuple>

using namespace rt;
using namespace rt::grader;

namespace {

struct Case {
    LitScene scene;
    point3 origin;
    point3 light;
    float t_min;
    bool blocked;
    const char* why;
};

void check(const Case& c)
{
    const bool got = occluded(c.scene, c.origin, c.light, c.t_min);
    INFO("occluded: the feeler from " << show(c.origin) << " to the light at " << show(c.light) << " with t_min = " << c.t_min
         << " in " << show(c.scene) << ": got " << show(got) << ", expected " << show(c.blocked) << ": " << c.why);
    CHECK(got == c.blocked);
}

const point3 ground{0, 0, 0};
const point3 overhead{0, 10, 0};

std::uint64_t intersection_tests()
{
    return total_count(Counter::intersection_tests);
}

}  // namespace

GRADED_TEST("occluded: a sphere or a triangle between the point and the light blocks it; nothing between, it is seen", "04.2", 3)
{
    check({scene_of({{{0, 5, 0}, 1}}, {}), ground, overhead, 0.0f, true, "the sphere lies across the feeler"});
    check({scene_of({}, square_facing_up({0, 5, 0}, 2)), ground, overhead, 0.0f, true, "the square lies across the feeler"});
    check({scene_of({{{0.5f, 3, -0.5f}, 2}}, square_facing_up({4, 5, 0}, 1)), ground, {4, 8, 1}, 0.0f, true,
           "the sphere lies across the slanted feeler"});
    check({scene_of({{{3, 5, 0}, 1}}, square_facing_up({-4, 5, 0}, 2)), ground, overhead, 0.0f, false,
           "both objects lie beside the feeler"});
    check({scene_of({}, {}), ground, overhead, 0.0f, false, "there is nothing in the scene"});
}

GRADED_TEST("occluded: an occluder beyond the light or behind the point does not block it; one just before the light does", "04.2", 3)
{
    check({scene_of({{{0, 15, 0}, 1}}, {}), ground, overhead, 0.0f, false, "the sphere lies beyond the light"});
    check({scene_of({}, square_facing_up({0, 12, 0}, 5)), ground, overhead, 0.0f, false, "the square lies beyond the light"});
    check({scene_of({{{0, -5, 0}, 1}}, square_facing_up({0, -1, 0}, 5)), ground, overhead, 0.0f, false,
           "both lie behind the point"});
    check({scene_of({{{0, 9, 0}, 0.5f}}, {}), ground, overhead, 0.0f, true, "the sphere spans y = 8.5 to 9.5, before the light at 10"});
    check({scene_of({}, square_facing_up({0, 9.5f, 0}, 5)), ground, overhead, 0.0f, true, "the square at y = 9.5 lies before the light"});
}

GRADED_TEST("occluded: stops at the first occluder of any kind (1 test when all block, 11 when only the 11th of 21 does), tests all when none does", "04.2", 3)
{
    // Twenty spheres, and twenty squares, all across the feeler: any one of them answers.
    std::vector<Sphere> spheres;
    std::vector<Triangle> triangles;
    for (int k = 0; k < 20; ++k) {
        spheres.push_back({{0, 0.4f + 0.45f * static_cast<float>(k), 0}, 0.2f});
        triangles.push_back({{-3, 0.5f + 0.45f * static_cast<float>(k), 3}, {3, 0.5f + 0.45f * static_cast<float>(k), 3},
                             {0, 0.5f + 0.45f * static_cast<float>(k), -3}});
    }
    for (const LitScene& scene : {scene_of(spheres, {}), scene_of({}, triangles)}) {
        reset_counters();
        const bool got = occluded(scene, ground, overhead, 0.0f);
        const std::uint64_t tests = intersection_tests();
        INFO("the feeler from " << show(ground) << " to the light at " << show(overhead) << " through " << show(scene)
             << ", every one of them across it: got " << show(got) << " after " << tests
             << " intersection tests (counted by hit_sphere and hit_triangle), expected blocked after 1");
        CHECK(got);
        CHECK(tests == 1);
    }
    const std::vector<Sphere> spheres_across = spheres;
    // Moved aside, none blocks, and each must be asked.
    for (Sphere& s : spheres)
        s.centre.x = 5.0f;
    reset_counters();
    const LitScene aside = scene_of(spheres, {});
    const bool got = occluded(aside, ground, overhead, 0.0f);
    INFO("the feeler from " << show(ground) << " to " << show(overhead) << " beside 20 spheres: got " << show(got)
         << " after " << intersection_tests() << " intersection tests, expected not blocked after 20");
    CHECK_FALSE(got);
    CHECK(intersection_tests() == 20);

    // Only the middle one of 21 spheres across: found after 11 tests, whichever end the search
    // starts from (the first try misses here, unlike above).
    std::vector<Sphere> one_across(21, Sphere{{5, 0, 0}, 0.2f});
    for (int k = 0; k < 21; ++k)
        one_across[k].centre.y = 0.4f + 0.45f * static_cast<float>(k);
    one_across[10].centre.x = 0.0f;
    reset_counters();
    const bool middle = occluded(scene_of(one_across, {}), ground, overhead, 0.0f);
    INFO("the feeler from " << show(ground) << " to " << show(overhead) << " past 21 spheres, only the 11th across it: got "
         << show(middle) << " after " << intersection_tests() << " intersection tests, expected blocked after 11");
    CHECK(middle);
    CHECK(intersection_tests() == 11);

    // Spheres and triangles together, all across: the first occluder of either kind ends the search,
    // so one test, not one per kind.
    reset_counters();
    const bool mixed = occluded(scene_of(spheres_across, triangles), ground, overhead, 0.0f);
    INFO("the feeler from " << show(ground) << " to " << show(overhead)
         << " through 20 spheres and 20 triangles, all across it: got " << show(mixed) << " after "
         << intersection_tests() << " intersection tests, expected blocked after 1");
    CHECK(mixed);
    CHECK(intersection_tests() == 1);
}

GRADED_TEST("occluded: a cylinder or a cone from a scene file between the point and the light blocks it", "04.2", 2)
{
    // Lying across the feeler: a cylinder along x at height 5, and a cone standing on the ground
    // beside the point with the feeler slanting through its wall.
    const Cone cylinder{{-2, 5, 0}, 0.5f, {2, 5, 0}, 0.5f};
    const Cone cone{{1, 0, 0}, 1.5f, {1, 4, 0}, 0.0f};
    check({scene_of({}, {}, {cylinder}), ground, overhead, 0.0f, true, "the cylinder lies across the feeler"});
    check({scene_of({}, {}, {cone}), ground, {4, 3, 0}, 0.0f, true, "the point lies inside the cone, and the feeler leaves through its wall"});
    // An open cylinder around the feeler has no caps: the feeler runs up its inside, unblocked.
    const Cone chimney{{0, 2, 0}, 1.0f, {0, 8, 0}, 1.0f};
    check({scene_of({}, {}, {chimney}), ground, overhead, 0.0f, false,
           "the feeler runs up the axis of an open cylinder, which has no caps"});
}

GRADED_TEST("occluded: t_min is honoured, a surface nearer than t_min to the origin does not block", "04.2", 2)
{
    const LitScene scene = scene_of({}, square_facing_up({0, 0.001f, 0}, 1));
    check({scene, ground, overhead, 0.01f, false, "the square is 0.001 away, nearer than t_min = 0.01"});
    check({scene, ground, overhead, 0.0f, true, "the square is 0.001 away, farther than t_min = 0"});
    check({scene, ground, overhead, 0.0005f, true, "the square is 0.001 away, farther than t_min = 0.0005"});
}

STABILITY_TEST("occluded: a surface through the light itself does not block it; the same surface 1% nearer does", "04.2", 2)
{
    // A lamp resting on a surface: the feeler stops shadow_epsilon short of the light.
    check({scene_of({}, square_facing_up(overhead, 3)), ground, overhead, 0.0f, false, "the square passes through the light"});
    check({scene_of({{{0, 11, 0}, 1}}, {}), ground, overhead, 0.0f, false, "the sphere's surface passes through the light"});
    check({scene_of({}, square_facing_up({0, 9.9f, 0}, 3)), ground, overhead, 0.0f, true, "the square lies 1% before the light"});
    check({scene_of({{{0, 10.9f, 0}, 1}}, {}), ground, overhead, 0.0f, true, "the sphere reaches 1% before the light"});
    // Far from the origin, where float steps are 1/16: the same answers.
    const point3 far_ground{1e6f, 0, -1e6f}, far_light{1e6f, 1e4f, -1e6f};
    check({scene_of({{{1e6f, 5e3f, -1e6f}, 100}}, {}), far_ground, far_light, 0.0f, true, "a sphere halfway, 1e6 from the origin"});
    check({scene_of({}, square_facing_up(far_light, 500)), far_ground, far_light, 0.0f, false,
           "a square through the light, 1e6 from the origin"});
    check({scene_of({{{1e6f, 2e4f, -1e6f}, 100}}, {}), far_ground, far_light, 0.0f, false, "a sphere beyond the light, 1e6 from the origin"});
}

STABILITY_TEST("occluded: a light inside a closed object is hidden from every point outside and seen from inside", "04.2", 2)
{
    const point3 light{0.2f, 5.1f, -0.3f};
    check({scene_of({{{0, 5, 0}, 1}}, {}), ground, light, 0.0f, true, "the light is inside the sphere, the point outside"});
    check({scene_of({{{0, 5, 0}, 1}}, {}), {0.5f, 4.6f, 0.2f}, light, 0.0f, false, "light and point are both inside the sphere"});
    // Inside a closed mesh of 320 triangles: from every direction, no feeler slips between them.
    const IndexedMesh mesh = icosphere({0, 5, 0}, 1.0f, 2);
    std::vector<Triangle> triangles;
    for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f)
        triangles.push_back(triangle_of(mesh, f));
    const LitScene closed = scene_of({}, triangles);
    int slipped = 0;
    point3 first{0.0f};
    for (const point3& corner : mesh.vertices) {  // aimed through the mesh's own vertices, its weakest spots
        const point3 outside = light + 4.0f * (corner - light);
        if (!occluded(closed, outside, light, 0.0f) && slipped++ == 0)
            first = outside;
    }
    INFO("the light at " << show(light) << " inside a closed icosphere of 320 triangles (centre (0, 5, 0), radius 1), "
         "feelers from outside aimed through each of its " << mesh.vertices.size() << " vertices: " << slipped
         << " were not blocked (the first from " << show(first) << "), expected every one blocked");
    CHECK(slipped == 0);
}

namespace {

// A triangle across the feeler that runs up the y axis from the origin, in the plane y = height,
// 2 `size` wide: its corners put the feeler at weights 1/4, 1/4, 1/2 of it, so the watertight test's
// t is the height itself, bit for bit (every sum it forms is the height times a power of two).
Triangle across_y_axis(float height, float size)
{
    return {{-size, height, -size}, {size, height, -size}, {0, height, size}};
}

// The t at which the given watertight test meets `tri` from the origin straight up: the occluder's
// true place on the feeler, as occluded's own tests see it.
float t_straight_up(const Triangle& tri)
{
    const std::optional<TriangleHit<float>> h =
        hit_triangle_watertight(Ray{{0, 0, 0}, {0, 1, 0}}, tri, Interval{0.0f, infinity});
    return h ? h->t : -1.0f;
}

}  // namespace

GRADED_TEST("occluded: on feelers 2^-10 to 2^20 long, an occluder exactly at d (1 - shadow_epsilon) or past it does not block, one a float step nearer does", "04.2", 2)
{
    // Powers of two, so that d (1 - shadow_epsilon), d - d shadow_epsilon and the same in double
    // all round to one float: the end of the range is the same however the product is written.
    for (const float d : {0x1p-10f, 1.0f, 8.0f, 0x1p20f}) {
        const point3 light{0, d, 0};
        const float end = d * (1.0f - shadow_epsilon);
        const struct {
            float height;
            bool blocked;
            const char* where;
        } occluders[] = {
            {std::nextafter(end, 0.0f), true, "one float step before the end of the range, d (1 - shadow_epsilon)"},
            {end, false, "exactly at the end of the range, d (1 - shadow_epsilon): the range is open"},
            {std::nextafter(end, infinity), false, "one float step past the end of the range"},
            {d, false, "exactly at the light"},
            {std::nextafter(d, infinity), false, "one float step past the light"},
            {0.5f * d, true, "halfway to the light"},
        };
        for (const auto& o : occluders) {
            const Triangle tri = across_y_axis(o.height, d);
            const float t = t_straight_up(tri);
            std::ostringstream why;
            why.precision(9);
            why << "the feeler is " << d << " long, its range ends at " << end << ", and the triangle lies at t = " << t
                << ", " << o.where;
            check({scene_of({}, {tri}), ground, light, 0.0f, o.blocked, why.str().c_str()});
        }
    }
}

GRADED_TEST("occluded: an occluder exactly at t_min does not block, one a float step farther does", "04.2", 1)
{
    const point3 light{0, 8, 0};
    for (const float t_min : {0.5f, 0.0625f, 3.0f}) {
        for (const auto& [height, blocked, where] :
             {std::tuple<float, bool, const char*>{t_min, false, "exactly at t_min: the range is open"},
              {std::nextafter(t_min, infinity), true, "one float step past t_min"},
              {std::nextafter(t_min, 0.0f), false, "one float step before t_min"}}) {
            const Triangle tri = across_y_axis(height, 8.0f);
            std::ostringstream why;
            why.precision(9);
            why << "t_min = " << t_min << " and the triangle lies at t = " << t_straight_up(tri) << ", " << where;
            check({scene_of({}, {tri}), ground, light, t_min, blocked, why.str().c_str()});
        }
    }
}
