// The ray/box slab test (common/bounds.hpp) where slab tests break: zero direction components of
// either sign, origins on a face, rays lying in a face's plane or parallel to a slab, grazing rays
// that touch an edge, NaN and infinite rays; and the bounds of every kind of object
// (Objects::bounds), which every ray that hits the object must enter.
#include "02_spheres_triangles/objects.hpp"
#include "common/bounds.hpp"
#include "common/random.hpp"
#include "tests/grader/graded.hpp"

#include <limits>
#include <sstream>

using namespace rt;
using rt::grader::show;

namespace {

const Bounds unit{{0, 0, 0}, {1, 1, 1}};
const Interval all{0.0f, infinity};

std::string show_range(const std::optional<Interval>& r)
{
    if (!r)
        return "a miss";
    std::ostringstream s;
    s.precision(9);
    s << "t from " << r->min << " to " << r->max;
    return s.str();
}

void check_hit(const Ray& ray, Interval range, float t0, float t1, const char* why)
{
    const std::optional<Interval> got = hit_bounds(unit, ray, range);
    INFO("hit_bounds(the unit box, " << show(ray) << ", t in (" << range.min << ", " << range.max << ")): got "
         << show_range(got) << ", expected t from " << t0 << " to about " << t1 << ": " << why);
    REQUIRE(got);
    CHECK(got->min == t0);
    // t_far is widened by 1 + 2 gamma(3): a few units in the last place beyond the exact exit.
    CHECK(got->max >= t1);
    CHECK(got->max <= t1 * (1.0f + 1e-6f) + 1e-30f);
}

void check_miss(const Ray& ray, Interval range, const char* why)
{
    const std::optional<Interval> got = hit_bounds(unit, ray, range);
    INFO("hit_bounds(the unit box, " << show(ray) << ", t in (" << range.min << ", " << range.max << ")): got "
         << show_range(got) << ", expected a miss: " << why);
    CHECK(!got);
}

}  // namespace

TEST_CASE("slab test: rays through the box enter and leave where the faces are")
{
    check_hit({{-1, 0.5f, 0.5f}, {1, 0, 0}}, all, 1, 2, "straight through along x");
    check_hit({{0.5f, 0.5f, 0.5f}, {0, 0, 1}}, all, 0, 0.5f, "from the centre: entered at the range's start");
    const vec3 diagonal = glm::normalize(vec3(1, 1, 1));
    check_hit({{-1, -1, -1}, diagonal}, all, 1.0f / diagonal.x, 2.0f / diagonal.x, "the diagonal through both corners");
    check_hit({{-1, 0.5f, 0.5f}, {1, 0, 0}}, {1.25f, 1.5f}, 1.25f, 1.5f, "clipped to the range");
    check_miss({{-1, 0.5f, 0.5f}, {-1, 0, 0}}, all, "pointing away");
    check_miss({{-1, 0.5f, 0.5f}, {1, 0, 0}}, {0.0f, 0.5f}, "the range ends before the box");
    check_miss({{-1, 2, 0.5f}, {1, 0, 0}}, all, "passing above it");
}

TEST_CASE("slab test: zero and -0 direction components, inside or outside the slab, give the same answers")
{
    for (const float zero : {0.0f, -0.0f}) {
        check_hit({{-1, 0.5f, 0.5f}, {1, zero, zero}}, all, 1, 2, "parallel to the y and z slabs, inside them");
        check_miss({{-1, 1.5f, 0.5f}, {1, zero, 0}}, all, "parallel to the y slab, outside it");
        check_miss({{-1, -0.5f, 0.5f}, {1, zero, 0}}, all, "parallel to the y slab, below it");
        // In a face's plane (0 * infinity = NaN in the slab): the box is closed, so the ray is inside.
        check_hit({{-1, 1, 0.5f}, {1, zero, 0}}, all, 1, 2, "lying in the plane of the top face");
        check_hit({{-1, 0, 0.5f}, {1, zero, 0}}, all, 1, 2, "lying in the plane of the bottom face");
        check_hit({{-1, 1, 1}, {1, zero, zero}}, all, 1, 2, "along the box's top edge");
    }
}

TEST_CASE("slab test: origins exactly on a face, leaving or entering")
{
    check_hit({{0, 0.5f, 0.5f}, {1, 0, 0}}, all, 0, 1, "on the x = 0 face, going in");
    check_hit({{1, 0.5f, 0.5f}, {-1, 0, 0}}, all, 0, 1, "on the x = 1 face, going in");
    // Leaving through the face it stands on: it touches the box at t = 0 only.
    const std::optional<Interval> touch = hit_bounds(unit, {{1, 0.5f, 0.5f}, {1, 0, 0}}, all);
    INFO("from the x = 1 face going out: got " << show_range(touch) << ", expected t = 0 alone or a miss");
    CHECK((!touch || (touch->min == 0.0f && touch->max <= 1e-6f)));
}

TEST_CASE("slab test: a ray that only touches the box's edge is inside (the box is closed)")
{
    // The line x + y = 2 touches the unit box at its edge x = y = 1 alone: entry and exit are the
    // same t, and the widened t_far keeps it from rounding into a miss.
    const vec3 d = glm::normalize(vec3(1, -1, 0));
    for (int k = 0; k < 50; ++k) {
        const float z = 0.02f * static_cast<float>(k);
        const Ray ray{{-static_cast<float>(k), 2.0f + static_cast<float>(k), z}, d};
        const std::optional<Interval> got = hit_bounds(unit, ray, all);
        INFO(show(ray) << " touches the box's edge (1, 1, " << z << "): got " << show_range(got));
        REQUIRE(got);
        CHECK(got->max >= got->min);
        CHECK(got->min == got->max / slab_far_widening);
    }
}

TEST_CASE("slab test: NaN, infinite and zero rays, and an empty box, never hit")
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    check_miss({{nan, 0.5f, 0.5f}, {1, 0, 0}}, all, "a NaN origin");
    check_miss({{-1, 0.5f, 0.5f}, {nan, 0, 0}}, all, "a NaN direction");
    check_miss({{-1, 0.5f, 0.5f}, {infinity, 0, 0}}, all, "an infinite direction");
    check_miss({{-infinity, 0.5f, 0.5f}, {1, 0, 0}}, all, "an infinite origin");
    check_miss({{0.5f, 0.5f, 0.5f}, {0, 0, 0}}, all, "no direction, inside the box");
    check_miss({{-1, 0.5f, 0.5f}, {1, 0, 0}}, {nan, infinity}, "a NaN range");
    const std::optional<Interval> empty = hit_bounds(Bounds{}, {{-1, 0.5f, 0.5f}, {1, 0, 0}}, all);
    CHECK(!empty);
}

TEST_CASE("object bounds: every ray that hits a sphere, a triangle or a cone enters its box first")
{
    const std::vector<Sphere> spheres = {{{0.3f, -2, 1}, 0.7f}, {{1e4f, 0, 0}, 1e-3f}};
    const std::vector<Triangle> triangles = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{-3, 2, 5}, {4, 2.5f, -1}, {0.5f, 2, 2}}};
    const std::vector<Cone> cones = {{{0, 0, 0}, 1.0f, {0, 2, 0}, 0.2f},                     // along y
                                     {{1, 1, 1}, 0.5f, {1.0f, 1.0f, 1.0f + 1e-3f}, 0.5f},    // a short cylinder along z
                                     {{-1, 0, 2}, 0.3f, {2, 1, -1}, 0.0f}};                 // slanted, to a point
    Objects o;
    o.spheres = spheres.data();
    o.sphere_count = 2;
    o.triangles = triangles.data();
    o.triangle_count = 2;
    o.cones = cones.data();
    o.cone_count = 3;
    o.tests = {SphereTest::precise, TriangleTest::watertight};
    Rng rng(9, 9);
    for (int k = 0; k < o.size(); ++k) {
        const Bounds b = o.bounds(k);
        const vec3 e = b.extent() + vec3(1e-3f);
        int hits = 0, outside = 0;
        for (int r = 0; r < 20000; ++r) {
            const point3 target = b.min + e * vec3(rng.next_float(), rng.next_float(), rng.next_float());
            const vec3 d = glm::normalize(vec3(2 * rng.next_float() - 1, 2 * rng.next_float() - 1, 2 * rng.next_float() - 1));
            const Ray ray{target - 5.0f * glm::length(e) * d, d};
            ObjectHit h;
            if (!o.intersect(k, ray, all, h))
                continue;
            ++hits;
            // The box must be entered, around the hit: a flat box (a triangle in a plane) is entered
            // and left at one t, which rounds a few float steps away from the triangle's own t.
            const std::optional<Interval> in = hit_bounds(b, ray, all);
            const float slack = 1e-5f * h.t;
            outside += !in || h.t < in->min - slack || h.t > in->max + slack;
        }
        INFO("object " << k << " with " << show(b.min) << " to " << show(b.max) << ": " << outside << " of " << hits
             << " hits lie outside its box (or more than 1e-5 t from it)");
        CHECK(hits > 100);
        CHECK(outside == 0);
    }
}
