// EXERCISES 07.4 and 07.5: the walk's setup and the next-voxel step, by hand-worked cases and
// against the oracle (describe.hpp) on seeded rays.
#include "common/random.hpp"
#include "tests/ch07/describe.hpp"

#include <limits>

using namespace rt;
using namespace rt::grader;

namespace {

// 4 x 2 x 2 cells of size 1 over the box from the origin to (4, 2, 2): strides (4, 2, 1).
const GridShape cube_cells = grid_shape({{0, 0, 0}, {4, 2, 2}}, {4, 2, 2});

// t_first and t_delta are doubles in GridWalk, and are compared as doubles: a setup computed in
// float rounds them to float, which the double-precision case below tells apart.
struct Expected {
    int p;
    int step_p[3];
    double t_first[3];
    double t_delta[3];
    float t_enter, t_end, t_range;
};

// The walk an Expected describes: no boundary crossed yet, t_max the t_first rounded once to float.
GridWalk walk_of(const Expected& e)
{
    GridWalk w;
    w.missed = false;
    w.p = e.p;
    for (int a = 0; a < 3; ++a) {
        w.step_p[a] = e.step_p[a];
        w.t_first[a] = e.t_first[a];
        w.t_delta[a] = e.t_delta[a];
        w.t_max[a] = static_cast<float>(e.t_first[a]);
    }
    w.t_enter = e.t_enter;
    w.t_end = e.t_end;
    w.t_range = e.t_range;
    return w;
}

// start_walk's walk against the expected one, field by field; t_first and t_delta within 1e-12 of
// their value (double's rounding, however the division is written; float's is some 1e-8).
void check_start(const Ray& ray, Interval range, const Expected& e, const char* why)
{
    const GridWalk w = start_walk(cube_cells, ray, range);
    const GridWalk expected = walk_of(e);
    const std::string differs = first_difference(w, expected, 1e-12);
    INFO("07.4 start_walk(" << show(cube_cells) << ", " << show(ray) << ", t in (" << range.min << ", " << range.max
         << ")): got " << show(w) << "; expected " << show(expected) << ": " << why
         << (differs.empty() ? "" : "; the first field that differs: " + differs));
    CHECK(differs.empty());
}

void check_missed(const Ray& ray, Interval range, const char* why)
{
    const GridWalk w = start_walk(cube_cells, ray, range);
    INFO("07.4 start_walk(" << show(cube_cells) << ", " << show(ray) << ", t in (" << range.min << ", " << range.max
         << ")): got " << show(w) << ", expected a missed walk: " << why);
    CHECK(w.missed);
}

constexpr float inf = infinity;
const Interval whole_ray{0.0f, infinity};

// The walk's cells against the oracle's, for one ray.
void check_walk(const GridShape& g, const Ray& ray, Interval range, const char* why)
{
    bool outside = false;
    const std::vector<int> walked = addresses(cells_walked(g, ray, range, outside));
    const std::vector<int> crossed = addresses(cells_crossed(g, ray, range));
    INFO("07.5 the walk along the " << show(ray) << ", t in (" << range.min << ", " << range.max << "), through " << show(g)
         << ": the walk visits " << show(walked) << (outside ? " and then steps outside the grid" : "")
         << "; the segment crosses " << show(crossed) << ": " << why);
    CHECK(!outside);
    CHECK(walked == crossed);
}

}  // namespace

GRADED_TEST("start_walk: a ray entering from outside starts in the entry cell, with the first boundary's t on its axis", "07.4", 3)
{
    check_start({{-1, 0.5f, 0.5f}, {1, 0, 0}}, whole_ray,
                {0, {4, 0, 0}, {2, inf, inf}, {1, inf, inf}, 1, 5, inf},
                "it enters cell (0, 0, 0) at t = 1, meets x = 1 at t = 2 and leaves the box at x = 4, t = 5");
    check_start({{4.5f, 1.5f, 1.5f}, {-1, 0, 0}}, whole_ray,
                {15, {-4, 0, 0}, {1.5f, inf, inf}, {1, inf, inf}, 0.5f, 4.5f, inf},
                "going down x it enters cell (3, 1, 1) at x = 4, meets x = 3 at t = 1.5 and leaves at x = 0, t = 4.5");
}

GRADED_TEST("start_walk: a ray starting inside steps on every axis it moves along; t_end is the first face it reaches", "07.4", 3)
{
    check_start({{0.25f, 0.25f, 1.5f}, {0.5f, 1, 0}}, whole_ray,
                {1, {4, 2, 0}, {1.5f, 0.75f, inf}, {2, 1, inf}, 0, 1.75f, inf},
                "from cell (0, 0, 1): x = 1 at t = 1.5, y = 1 at t = 0.75; it leaves through y = 2 at t = 1.75, "
                "before x = 4 at t = 7.5");
    check_start({{3.5f, 1.75f, 0.5f}, {-1, -0.5f, 1}}, whole_ray,
                {14, {-4, -2, 1}, {0.5f, 1.5f, 0.5f}, {1, 2, 1}, 0, 1.5f, inf},
                "from cell (3, 1, 0) down x and y and up z: it leaves through z = 2 at t = 1.5");
}

GRADED_TEST("start_walk: a range that ends inside the box ends the walk there; one before the box misses it", "07.4", 3)
{
    check_start({{-1, 0.5f, 0.5f}, {1, 0, 0}}, {0.0f, 2.5f},
                {0, {4, 0, 0}, {2, inf, inf}, {1, inf, inf}, 1, 2.5f, 2.5f}, "the range ends at t = 2.5, in cell (1, 0, 0)");
    check_start({{-1, 0.5f, 0.5f}, {1, 0, 0}}, {3.5f, infinity},
                {8, {4, 0, 0}, {4, inf, inf}, {1, inf, inf}, 3.5f, 5, inf}, "the range starts at t = 3.5, in cell (2, 0, 0)");
    check_missed({{-1, 0.5f, 0.5f}, {1, 0, 0}}, {0.0f, 0.5f}, "the range ends before the box");
    check_missed({{-1, 0.5f, 0.5f}, {-1, 0, 0}}, whole_ray, "the ray points away from the box");
    check_missed({{-1, 5, 0.5f}, {1, 0, 0}}, whole_ray, "the ray passes above the box");
}

STABILITY_TEST("start_walk: a zero or -0 direction component never steps that axis; a NaN, infinite or zero ray misses", "07.4", 3)
{
    check_start({{-1, 0.5f, 0.5f}, {1, -0.0f, 0}}, whole_ray,
                {0, {4, 0, 0}, {2, inf, inf}, {1, inf, inf}, 1, 5, inf}, "-0 along y is 0: y is never crossed");
    check_start({{0.5f, 0.5f, 1.5f}, {0, 0, -1}}, whole_ray,
                {1, {0, 0, -1}, {inf, inf, 0.5f}, {inf, inf, 1}, 0, 1.5f, inf}, "straight down z from cell (0, 0, 1)");
    const float nan = std::numeric_limits<float>::quiet_NaN();
    check_missed({{nan, 0.5f, 0.5f}, {1, 0, 0}}, whole_ray, "a NaN origin");
    check_missed({{-1, 0.5f, 0.5f}, {1, nan, 0}}, whole_ray, "a NaN direction");
    check_missed({{-1, 0.5f, 0.5f}, {infinity, 0, 0}}, whole_ray, "an infinite direction");
    check_missed({{-infinity, 0.5f, 0.5f}, {1, 0, 0}}, whole_ray, "an infinitely distant origin");
    check_missed({{1, 0.5f, 0.5f}, {0, 0, 0}}, whole_ray, "no direction at all");
}

GRADED_TEST("start_walk: the least float above 0 (a denormal, 1.4e-45) is no zero: that axis steps with its sign, its first boundary some 3.5e44 away", "07.4", 2)
{
    // The contract tests dir[a] != 0: no threshold. A component of 1.4e-45 (the least float above 0)
    // moves the ray across y = 1 at t = 0.5 / 1.4e-45, about 3.5e44: in double that is a number,
    // rounded to float it is infinity, so t_max[1] is infinity and x decides t_end.
    const float tiny = std::numeric_limits<float>::denorm_min();
    const double d = tiny;
    check_start({{0.5f, 0.5f, 0.5f}, {1, tiny, 0}}, whole_ray,
                {0, {4, 2, 0}, {0.5, 0.5 / d, inf}, {1, 1 / d, inf}, 0, 3.5f, inf},
                "from cell (0, 0, 0), y going up by 1.4e-45: step_p[1] = +2, t_first[1] = (1 - 0.5) / 1.4e-45, "
                "t_delta[1] = 1 / 1.4e-45; x reaches the face x = 4 first, at t = 3.5");
    check_start({{0.5f, 1.5f, 0.5f}, {1, -tiny, 0}}, whole_ray,
                {2, {4, -2, 0}, {0.5, 0.5 / d, inf}, {1, 1 / d, inf}, 0, 3.5f, inf},
                "from cell (0, 1, 0), y going down by 1.4e-45: step_p[1] = -2, t_first[1] = (1 - 1.5) / -1.4e-45");
}

STABILITY_TEST("start_walk: an origin on a boundary going down starts in the cell above and leaves it at once", "07.4", 3)
{
    check_start({{2, 0.5f, 0.5f}, {-1, 0, 0}}, whole_ray,
                {8, {-4, 0, 0}, {0, inf, inf}, {1, inf, inf}, 0, 2, inf},
                "x = 2 is cell 2's lower boundary: the ray crosses it at t = 0 into cell 1");
    check_start({{4, 2, 2}, {-1, -1, -1}}, whole_ray,
                {15, {-4, -2, -1}, {1, 1, 1}, {1, 1, 1}, 0, 2, inf},
                "from the box's max corner: the last cell (3, 1, 1), whose lower faces it crosses at t = 1; it leaves "
                "the box through y = 0 and z = 0 at t = 2");
}

GRADED_TEST("start_walk: t_first and t_delta are kept in double: along (0.3, 0.4, 0) they are double's quotients, not float's", "07.4", 3)
{
    // 0.3 and 0.4 are no floats, and neither are 1 / 0.3f or 0.9f / 0.3f: a setup that divides in
    // float stores float's rounding of each (off by about 1e-8 of it), a double one double's.
    const double ox = 0.1f, oy = 0.25f, dx = 0.3f, dy = 0.4f;
    Expected e{0, {4, 2, 0}, {(1.0 - ox) / dx, (1.0 - oy) / dy, inf}, {1.0 / dx, 1.0 / dy, inf}, 0, 0, inf};
    // t_end: the box's faces as the walk's own boundaries place them, x = 4 three boundaries on and
    // y = 2 one boundary on, rounded once (boundary_t).
    e.t_end = std::min(static_cast<float>(e.t_first[0] + 3.0 * e.t_delta[0]),
                       static_cast<float>(e.t_first[1] + 1.0 * e.t_delta[1]));
    check_start({{0.1f, 0.25f, 0.5f}, {0.3f, 0.4f, 0}}, whole_ray, e,
                "from cell (0, 0, 0) up x and y: t_delta = 1 / 0.3 and 1 / 0.4, t_first = (1 - 0.1) / 0.3 and "
                "(1 - 0.25) / 0.4, each divided in double (float's quotient is off by some 1e-8 of it)");
}

GRADED_TEST("start_walk: a range that ends exactly where the ray enters the box walks that one cell, one ulp earlier misses; t_end is the least of range.max and the face", "07.4", 3)
{
    // The ray from (-1, 0.5, 0.5) along +x enters the box at t = 1 and reaches its face x = 4 at t = 5.
    const Ray ray{{-1, 0.5f, 0.5f}, {1, 0, 0}};
    check_start(ray, {0.0f, 1.0f}, {0, {4, 0, 0}, {2, inf, inf}, {1, inf, inf}, 1, 1, 1},
                "the range [0, 1] meets the box at t = 1 alone: the walk starts and ends in cell (0, 0, 0)");
    check_missed(ray, {0.0f, std::nextafter(1.0f, 0.0f)}, "the range ends one ulp before the ray enters the box");
    check_start(ray, {0.0f, 5.0f}, {0, {4, 0, 0}, {2, inf, inf}, {1, inf, inf}, 1, 5, 5},
                "range.max is exactly the face's t, 5: t_end = 5");
    const float above = std::nextafter(5.0f, 6.0f), below = std::nextafter(5.0f, 4.0f);
    check_start(ray, {0.0f, above}, {0, {4, 0, 0}, {2, inf, inf}, {1, inf, inf}, 1, 5, above},
                "range.max is one ulp past the face's t: t_end is the face's t, 5");
    check_start(ray, {0.0f, below}, {0, {4, 0, 0}, {2, inf, inf}, {1, inf, inf}, 1, below, below},
                "range.max is one ulp before the face's t: t_end is range.max");
}

GRADED_TEST("next_cell: steps along the axis whose boundary comes first, and stops at t_end", "07.5", 4)
{
    // The walk start_walk makes for the ray from (0.25, 0.25, 1.5) along (0.5, 1, 0) (07.4's case).
    GridWalk w;
    w.missed = false;
    w.p = 1;
    w.step_p[0] = 4;
    w.step_p[1] = 2;
    w.t_first[0] = w.t_max[0] = 1.5f;
    w.t_first[1] = w.t_max[1] = 0.75f;
    w.t_delta[0] = 2;
    w.t_delta[1] = 1;
    w.t_end = 1.75f;
    w.t_range = infinity;
    INFO("07.5 next_cell from " << show(w));
    REQUIRE(next_cell(w));
    INFO("after the first step: " << show(w) << "; expected y crossed at t = 0.75 into p = 3, t_max[1] = 1.75");
    CHECK(w.p == 3);
    CHECK(w.t_enter == 0.75f);
    CHECK(w.steps[1] == 1);
    CHECK(w.t_max[1] == 1.75f);
    REQUIRE(next_cell(w));
    INFO("after the second step: " << show(w) << "; expected x crossed at t = 1.5 into p = 7, t_max[0] = 3.5");
    CHECK(w.p == 7);
    CHECK(w.t_enter == 1.5f);
    CHECK(w.steps[0] == 1);
    CHECK(w.t_max[0] == 3.5f);
    INFO("the third step: the next boundary is y = 2 at t = 1.75 = t_end, the box's face: the walk must end");
    CHECK(!next_cell(w));
}

GRADED_TEST("next_cell: the walk visits exactly the cells the segment crosses, in order (seeded rays, three grids)", "07.5", 5)
{
    const GridShape grids[] = {
        grid_shape({{-1, -2, -3}, {2, 2, 2}}, {3, 4, 5}),
        grid_shape({{0, 0, 0}, {1, 1, 1}}, {1, 1, 1}),
        grid_shape({{10, 0, -0.5f}, {17, 0.25f, 0.7f}}, {7, 1, 3}),
    };
    Rng rng(7, 1);
    const auto u = [&] { return rng.next_float(); };
    for (const GridShape& g : grids) {
        const vec3 e = g.box.extent();
        for (int k = 0; k < 3000; ++k) {
            // An origin in or around the box, sometimes snapped onto a cell boundary; a direction
            // with components sometimes zero (or -0); sometimes a range that ends in the box.
            point3 o = g.box.min - 0.5f * e + 2.0f * e * vec3(u(), u(), u());
            vec3 d(2 * u() - 1, 2 * u() - 1, 2 * u() - 1);
            for (int a = 0; a < 3; ++a) {
                if (u() < 0.2f)
                    o[a] = g.box.min[a] + static_cast<float>(static_cast<int>(u() * (g.n[a] + 1))) * g.cell_size[a];
                if (u() < 0.2f)
                    d[a] = u() < 0.5f ? 0.0f : -0.0f;
            }
            if (d == vec3(0.0f))
                continue;
            const Interval range{0.0f, u() < 0.25f ? glm::length(e) * u() : infinity};
            check_walk(g, {o, glm::normalize(d)}, range, "a seeded ray");
        }
    }
}

STABILITY_TEST("next_cell: rays along grid edges, through cell corners and along the box's faces visit the crossed cells", "07.5", 4)
{
    const GridShape g = grid_shape({{0, 0, 0}, {4, 4, 4}}, {4, 4, 4});
    check_walk(g, {{-1, 1, 2}, {1, 0, 0}}, whole_ray, "along the edge y = 1, z = 2: the cells above both planes");
    check_walk(g, {{0, 0, 0}, glm::normalize(vec3(1, 1, 1))}, whole_ray, "the diagonal through every cell corner");
    check_walk(g, {{4, 4, 4}, glm::normalize(vec3(-1, -1, -1))}, whole_ray, "the diagonal back from the max corner");
    check_walk(g, {{-1, 4, 4}, {1, 0, 0}}, whole_ray, "along the box's far edge (y = z = 4): the last cells");
    check_walk(g, {{2, 2, -3}, {0, 0, 1}}, whole_ray, "straight up z through a vertex of four cells");
    check_walk(g, {{0.5f, 0.5f, 0.5f}, glm::normalize(vec3(1, 2, -0.0f))}, whole_ray, "with a -0 component");
    check_walk(g, {{2, 1, 1}, {-1, 0, 0}}, whole_ray, "from a boundary, going down x");
}

STABILITY_TEST("next_cell: after 10^4 and 10^5 steps the walk is in the right cell, its boundaries within 1e-3 cells after 10^4 steps, 1e-2 after 10^5", "07.5", 4)
{
    // 200000 cells of 0.1 along x: t_delta = 0.1 is not a float, so t_max += t_delta drifts.
    const GridShape g = grid_shape({{0, 0, 0}, {20000, 1, 1}}, {200000, 1, 1});
    const Ray ray{{0.05f, 0.5f, 0.5f}, {1, 0, 0}};
    GridWalk w = start_walk(g, ray, whole_ray);
    REQUIRE(!w.missed);
    const double size = static_cast<double>(g.cell_size.x);
    for (int step = 1; step <= 100000; ++step) {
        REQUIRE(next_cell(w));
        if (step == 10000 || step == 100000) {
            // The oracle: the boundary at box.min + step * size, reached at t = that - 0.05.
            const double t_exact = static_cast<double>(step) * size - 0.05;
            const double drift = std::abs(static_cast<double>(w.t_enter) - t_exact) / size;
            INFO("07.5 after " << step << " steps: " << show(w) << "; expected p = " << step << " and t_enter = "
                 << t_exact << ": off by " << drift << " cells");
            CHECK(w.p == step);
            CHECK(drift < 1e-3 * (step / 10000));
        }
    }
}

namespace {

// One call of next_cell on a walk built by hand, against the walk it must leave and what it must
// return; the message names the first field that differs.
void check_step(const GridWalk& before, bool expected_return, const GridWalk& expected, const char* why)
{
    GridWalk w = before;
    const bool got = next_cell(w);
    const std::string differs = first_difference(w, expected);
    INFO("07.5 next_cell from " << show(before) << ": returned " << std::boolalpha << got << " and left "
         << show(w) << "; expected " << expected_return << " and " << show(expected) << ": " << why
         << (differs.empty() ? "" : "; the first field that differs: " + differs));
    CHECK(got == expected_return);
    CHECK(differs.empty());
}

// A walk along x alone, in cell 0 of a row of cells of size 1, the next boundary at t = 2.
GridWalk along_x(float t_end)
{
    GridWalk w;
    w.missed = false;
    w.p = 0;
    w.step_p[0] = 4;
    w.t_first[0] = 2;
    w.t_delta[0] = 1;
    w.t_max[0] = 2;
    w.t_enter = 1;
    w.t_end = t_end;
    w.t_range = infinity;
    return w;
}

}  // namespace

GRADED_TEST("next_cell: a step changes only t_enter, p, that axis's count of boundaries and its t_max; three axes, one going down", "07.5", 3)
{
    // From cell (0, 1, 0) of 4 x 2 x 2 (p = 2): up x (+4), down y (-2), up z (+1); the next
    // boundaries at t = 0.5, 0.75 and 1.25, one every 1, 2 and 1.5; the walk ends at t = 2.
    GridWalk w;
    w.missed = false;
    w.p = 2;
    const int step_p[3] = {4, -2, 1};
    const double first[3] = {0.5, 0.75, 1.25}, delta[3] = {1, 2, 1.5};
    for (int a = 0; a < 3; ++a) {
        w.step_p[a] = step_p[a];
        w.t_first[a] = first[a];
        w.t_delta[a] = delta[a];
        w.t_max[a] = static_cast<float>(first[a]);
    }
    w.t_end = 2;
    w.t_range = infinity;
    struct Step {
        int axis;
        float t_enter;
        int p;
        const char* why;
    };
    const Step steps[] = {{0, 0.5f, 6, "x's boundary at t = 0.5 comes first: into p = 2 + 4 = 6, x's next at 1.5"},
                          {1, 0.75f, 4, "then y's at 0.75, going down: p = 6 - 2 = 4, y's next at 2.75"},
                          {2, 1.25f, 5, "then z's at 1.25: p = 4 + 1 = 5, z's next at 2.75"},
                          {0, 1.5f, 9, "then x's second at 1.5: p = 5 + 4 = 9, steps (2, 1, 1), x's next at 2.5"}};
    for (const Step& s : steps) {
        GridWalk expected = w;
        expected.t_enter = s.t_enter;
        expected.p = s.p;
        ++expected.steps[s.axis];
        expected.t_max[s.axis] = static_cast<float>(first[s.axis] + expected.steps[s.axis] * delta[s.axis]);
        check_step(w, true, expected, s.why);
        w = expected;  // on from the right walk, so one wrong step fails once
    }
    check_step(w, false, w, "the next boundary, x's at t = 2.5, is beyond t_end = 2: the walk is over, unchanged");
}

GRADED_TEST("next_cell: the walk steps when the next boundary is one ulp below t_end, and stops, unchanged, when it is at t_end or one ulp beyond", "07.5", 3)
{
    const GridWalk on = along_x(2.0f);
    check_step(on, false, on, "the next boundary is at t = 2 = t_end: not below it, so the walk is over");
    const GridWalk ends_before = along_x(std::nextafter(2.0f, 1.0f));
    check_step(ends_before, false, ends_before, "the next boundary (t = 2) is one ulp beyond t_end: the walk is over");
    const GridWalk ends_after = along_x(std::nextafter(2.0f, 3.0f));
    GridWalk stepped = ends_after;
    stepped.p = 4;
    stepped.t_enter = 2;
    stepped.steps[0] = 1;
    stepped.t_max[0] = 3;
    check_step(ends_after, true, stepped, "the next boundary (t = 2) is one ulp below t_end: the ray enters p = 4 at t = 2");
}

STABILITY_TEST("next_cell: a walk whose t_end or t_max is NaN stops at once, unchanged (NaN is not below t_end); with numbers the same walk steps", "07.5", 3)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const GridWalk nan_end = along_x(nan);
    check_step(nan_end, false, nan_end, "t_end is NaN: no boundary is below it");
    GridWalk nan_max = along_x(5.0f);
    for (int a = 0; a < 3; ++a) {
        nan_max.step_p[a] = a == 0 ? 4 : a == 1 ? 2 : 1;
        nan_max.t_first[a] = nan;
        nan_max.t_delta[a] = 1;
        nan_max.t_max[a] = nan;
    }
    check_step(nan_max, false, nan_max, "every t_max is NaN: the next boundary is not below t_end = 5");
    // The same walk along x with a number for t_end steps: it is the NaN that stops it.
    GridWalk stepped = along_x(5.0f);
    stepped.p = 4;
    stepped.t_enter = 2;
    stepped.steps[0] = 1;
    stepped.t_max[0] = 3;
    check_step(along_x(5.0f), true, stepped, "t_end = 5, a number: x's boundary at t = 2 is below it, into p = 4");
}
