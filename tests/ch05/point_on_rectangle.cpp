// EXERCISE 05.1: a point of the unit square to a point of a rectangle light.
#include "tests/ch05/describe.hpp"

using namespace rt;
using namespace rt::grader;

namespace {

// A tilted rectangle, 3 by 1, away from the origin, and an axis-aligned one.
const AreaLight tilted_rectangle = rectangle_light({2.0f, 5.0f, -1.0f}, {1.2f, 0.0f, 0.9f}, {0.0f, 0.5f, 0.0f}, color(1.0f));
const AreaLight ceiling_rectangle = rectangle_light({0.0f, 3.0f, 0.0f}, {0.5f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.25f}, color(1.0f));

// Points equal within float rounding of coordinates of size `scale`.
bool same_point(const point3& got, const point3& want, float scale)
{
    return glm::length(got - want) <= 1e-6f * scale;
}

void check(const AreaLight& light, sample2 u, const point3& want, const char* what)
{
    const point3 got = point_on_rectangle(light, u);
    INFO(show(light) << ", " << show(u) << ": got " << show(got) << ", expected " << what << " " << show(want)
         << " = centre + (2 u.x - 1) axis_u + (2 u.y - 1) axis_v");
    CHECK(same_point(got, want, 10.0f));
}

// Requires point_on_rectangle(light, u) at (2 u.x - 1, 2 u.y - 1) in half-axes and on the light's
// plane, within 1e-5 (off the plane, 1e-5 times `size`, the light's scale); returns the point.
point3 require_at_half_axes(const AreaLight& light, sample2 u, double size)
{
    const point3 got = point_on_rectangle(light, u);
    const OnLight on = on_light(light, got);
    INFO(show(light) << ", " << show(u) << ": got " << show(got) << ", at (" << on.x << ", " << on.y
         << ") in half-axes and " << on.off_plane << " off the light's plane; expected (" << 2 * u.x - 1 << ", "
         << 2 * u.y - 1 << ") and 0");
    REQUIRE(std::abs(on.x - (2.0 * u.x - 1.0)) <= 1e-5);
    REQUIRE(std::abs(on.y - (2.0 * u.y - 1.0)) <= 1e-5);
    REQUIRE(std::abs(on.off_plane) <= 1e-5 * size);
    return got;
}

}  // namespace

GRADED_TEST("point_on_rectangle: (0, 0) is the corner centre - axis_u - axis_v, (1/2, 1/2) the centre, u.x runs along axis_u", "05.1", 2)
{
    for (const AreaLight& light : {tilted_rectangle, ceiling_rectangle}) {
        const point3 c = light.centre;
        const vec3 a = light.axis_u, b = light.axis_v;
        check(light, {0.0f, 0.0f}, c - a - b, "the corner");
        check(light, {0.5f, 0.5f}, c, "the centre");
        check(light, {1.0f, 0.0f}, c + a - b, "the corner along axis_u");
        check(light, {0.0f, 1.0f}, c - a + b, "the corner along axis_v");
        check(light, {0.75f, 0.25f}, c + 0.5f * a - 0.5f * b, "halfway from the centre to the edges");
    }
}

GRADED_TEST("point_on_rectangle: any u lands at (2 u.x - 1, 2 u.y - 1) in half-axes, on the light; midpoints go to midpoints", "05.1", 2)
{
    // An affine map: equal areas of the square go to equal areas of the rectangle.
    Rng rng(51, 0);
    for (int k = 0; k < 1000; ++k) {
        const sample2 u{rng.next_float(), rng.next_float()}, w{rng.next_float(), rng.next_float()};
        const point3 got = require_at_half_axes(tilted_rectangle, u, 1.0);
        const point3 mid = point_on_rectangle(tilted_rectangle, 0.5f * (u + w));
        const point3 want = 0.5f * (got + point_on_rectangle(tilted_rectangle, w));
        INFO(show(tilted_rectangle) << ": the point of the midpoint of " << show(u) << " and " << show(w) << " is " << show(mid)
             << ", expected the midpoint of their points, " << show(want));
        REQUIRE(same_point(mid, want, 10.0f));
    }
}

STABILITY_TEST("point_on_rectangle: lights 1e-4 and 1e5 across keep every point on them, within float rounding", "05.1", 1)
{
    Rng rng(52, 0);
    for (const float size : {1e-4f, 1e5f}) {
        const AreaLight light =
            rectangle_light(size * point3(0.3f, 2.0f, -0.7f), size * vec3(0.6f, 0.0f, 0.8f), size * vec3(0.0f, 0.25f, 0.0f), color(1.0f));
        for (int k = 0; k < 1000; ++k) {
            const sample2 u = k == 0 ? sample2(one_minus_epsilon) : sample2(rng.next_float(), rng.next_float());
            require_at_half_axes(light, u, size);
        }
    }
}

GRADED_TEST("point_on_rectangle: a u with one coordinate 1/2 lies exactly on the light's centre line, no rounding across it", "05.1", 1)
{
    // Centre z 0.1 and axis_v (0, 0, 0.3): from the corner, 0.1 - 0.3 + 0.3 rounds to 0.099999994.
    const AreaLight upright = rectangle_light({0.7f, 2.0f, 0.1f}, {0.35f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.3f}, color(1.0f));
    for (const float along : {0.0f, 0.125f, 0.3f, 0.75f, 1.0f}) {
        const point3 on_u_line = point_on_rectangle(upright, {along, 0.5f});
        const point3 on_v_line = point_on_rectangle(upright, {0.5f, along});
        INFO(show(upright) << ": u = (" << along << ", 1/2) gave " << show(on_u_line) << ", u = (1/2, " << along
             << ") gave " << show(on_v_line) << "; expected z exactly " << upright.centre.z << " and x exactly "
             << upright.centre.x << " (on a centre line (2 u - 1) is exactly 0: nothing to round)");
        CHECK(on_u_line.z == upright.centre.z);
        CHECK(on_v_line.x == upright.centre.x);
        CHECK(on_u_line.y == upright.centre.y);
        // And at the right place along the line (within rounding), so that the centre alone is no answer.
        const float s = 2.0f * along - 1.0f;
        CHECK(same_point(on_u_line, upright.centre + s * upright.axis_u, 10.0f));
        CHECK(same_point(on_v_line, upright.centre + s * upright.axis_v, 10.0f));
    }
}
