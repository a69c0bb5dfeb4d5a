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

struct Expected {
    int p;
    int step_p[3];
    float t_first[3];
    float t_delta[3];
    float t_enter, t_end, t_range;
};

bool same(float a, float b) { return a == b || (std::isnan(a) && std::isnan(b)); }

void check_start(const Ray& ray, Interval range, const Expected& e, const char* why)
{
    const GridWalk w = start_walk(cube_cells, ray, range);
    INFO("start_walk(" << show(cube_cells) << ", " << show(ray) << ", t in (" << range.min << ", " << range.max
         << ")): got " << show(w) << "; expected p = " << e.p << ", step_p = (" << e.step_p[0] << ", " << e.step_p[1]
         << ", " << e.step_p[2] << "), t_first = (" << e.t_first[0] << ", " << e.t_first[1] << ", " << e.t_first[2]
         << "), t_delta = (" << e.t_delta[0] << ", " << e.t_delta[1] << ", " << e.t_delta[2] << "), t_enter = "
         << e.t_enter << ", t_end = " << e.t_end << ", t_range = " << e.t_range << ": " << why);
    REQUIRE(!w.missed);
    CHECK(w.p == e.p);
    for (int a = 0; a < 3; ++a) {
        CHECK(w.step_p[a] == e.step_p[a]);
        CHECK(same(w.t_first[a], e.t_first[a]));
        CHECK(same(w.t_max[a], e.t_first[a]));
        CHECK(same(w.t_delta[a], e.t_delta[a]));
        CHECK(w.steps[a] == 0);
    }
    CHECK(w.t_enter == e.t_enter);
    CHECK(w.t_end == e.t_end);
    CHECK(w.t_range == e.t_range);
}

void check_missed(const Ray& ray, Interval range, const char* why)
{
    const GridWalk w = start_walk(cube_cells, ray, range);
    INFO("start_walk(" << show(cube_cells) << ", " << show(ray) << ", t in (" << range.min << ", " << range.max
         << ")): got " << show(w) << ", expected a missed walk: " << why);
    CHECK(w.missed);
}

constexpr float inf = infinity;
const Interval all{0.0f, infinity};

// The walk's cells against the oracle's, for one ray.
void check_walk(const GridShape& g, const Ray& ray, Interval range, const char* why)
{
    bool outside = false;
    const std::vector<int> walked = addresses(cells_walked(g, ray, range, outside));
    const std::vector<int> crossed = addresses(cells_crossed(g, ray, range));
    INFO(show(ray) << ", t in (" << range.min << ", " << range.max << "), through " << show(g)
         << ": the walk visits " << show(walked) << (outside ? " and then steps outside the grid" : "")
         << "; the segment crosses " << show(crossed) << ": " << why);
    CHECK(!outside);
    CHECK(walked == crossed);
}

}  // namespace

GRADED_TEST("start_walk: a ray entering from outside starts in the entry cell, with the first boundary's t on its axis", "07.4", 3)
{
    check_start({{-1, 0.5f, 0.5f}, {1, 0, 0}}, all,
                {0, {4, 0, 0}, {2, inf, inf}, {1, inf, inf}, 1, 5, inf},
                "it enters cell (0, 0, 0) at t = 1, meets x = 1 at t = 2 and leaves the box at x = 4, t = 5");
    check_start({{4.5f, 1.5f, 1.5f}, {-1, 0, 0}}, all,
                {15, {-4, 0, 0}, {1.5f, inf, inf}, {1, inf, inf}, 0.5f, 4.5f, inf},
                "going down x it enters cell (3, 1, 1) at x = 4, meets x = 3 at t = 1.5 and leaves at x = 0, t = 4.5");
}

GRADED_TEST("start_walk: a ray starting inside steps on every axis it moves along; t_end is the first face it reaches", "07.4", 3)
{
    check_start({{0.25f, 0.25f, 1.5f}, {0.5f, 1, 0}}, all,
                {1, {4, 2, 0}, {1.5f, 0.75f, inf}, {2, 1, inf}, 0, 1.75f, inf},
                "from cell (0, 0, 1): x = 1 at t = 1.5, y = 1 at t = 0.75; it leaves through y = 2 at t = 1.75, "
                "before x = 4 at t = 7.5");
    check_start({{3.5f, 1.75f, 0.5f}, {-1, -0.5f, 1}}, all,
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
    check_missed({{-1, 0.5f, 0.5f}, {-1, 0, 0}}, all, "the ray points away from the box");
    check_missed({{-1, 5, 0.5f}, {1, 0, 0}}, all, "the ray passes above the box");
}

STABILITY_TEST("start_walk: a zero or -0 direction component never steps that axis; a NaN, infinite or zero ray misses", "07.4", 3)
{
    check_start({{-1, 0.5f, 0.5f}, {1, -0.0f, 0}}, all,
                {0, {4, 0, 0}, {2, inf, inf}, {1, inf, inf}, 1, 5, inf}, "-0 along y is 0: y is never crossed");
    check_start({{0.5f, 0.5f, 1.5f}, {0, 0, -1}}, all,
                {1, {0, 0, -1}, {inf, inf, 0.5f}, {inf, inf, 1}, 0, 1.5f, inf}, "straight down z from cell (0, 0, 1)");
    const float nan = std::numeric_limits<float>::quiet_NaN();
    check_missed({{nan, 0.5f, 0.5f}, {1, 0, 0}}, all, "a NaN origin");
    check_missed({{-1, 0.5f, 0.5f}, {1, nan, 0}}, all, "a NaN direction");
    check_missed({{-1, 0.5f, 0.5f}, {infinity, 0, 0}}, all, "an infinite direction");
    check_missed({{-infinity, 0.5f, 0.5f}, {1, 0, 0}}, all, "an infinitely distant origin");
    check_missed({{1, 0.5f, 0.5f}, {0, 0, 0}}, all, "no direction at all");
}

STABILITY_TEST("start_walk: an origin on a boundary going down starts in the cell above and leaves it at once", "07.4", 3)
{
    check_start({{2, 0.5f, 0.5f}, {-1, 0, 0}}, all,
                {8, {-4, 0, 0}, {0, inf, inf}, {1, inf, inf}, 0, 2, inf},
                "x = 2 is cell 2's lower boundary: the ray crosses it at t = 0 into cell 1");
    check_start({{4, 2, 2}, {-1, -1, -1}}, all,
                {15, {-4, -2, -1}, {1, 1, 1}, {1, 1, 1}, 0, 2, inf},
                "from the box's max corner: the last cell (3, 1, 1), whose lower faces it crosses at t = 1; it leaves "
                "the box through y = 0 and z = 0 at t = 2");
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
    INFO("from " << show(w));
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
    check_walk(g, {{-1, 1, 2}, {1, 0, 0}}, all, "along the edge y = 1, z = 2: the cells above both planes");
    check_walk(g, {{0, 0, 0}, glm::normalize(vec3(1, 1, 1))}, all, "the diagonal through every cell corner");
    check_walk(g, {{4, 4, 4}, glm::normalize(vec3(-1, -1, -1))}, all, "the diagonal back from the max corner");
    check_walk(g, {{-1, 4, 4}, {1, 0, 0}}, all, "along the box's far edge (y = z = 4): the last cells");
    check_walk(g, {{2, 2, -3}, {0, 0, 1}}, all, "straight up z through a vertex of four cells");
    check_walk(g, {{0.5f, 0.5f, 0.5f}, glm::normalize(vec3(1, 2, -0.0f))}, all, "with a -0 component");
    check_walk(g, {{2, 1, 1}, {-1, 0, 0}}, all, "from a boundary, going down x");
}

STABILITY_TEST("next_cell: after 10^4 and 10^5 steps the walk is in the right cell, its boundaries within 1e-3 cells after 10^4 steps, 1e-2 after 10^5", "07.5", 4)
{
    // 200000 cells of 0.1 along x: t_delta = 0.1 is not a float, so t_max += t_delta drifts.
    const GridShape g = grid_shape({{0, 0, 0}, {20000, 1, 1}}, {200000, 1, 1});
    const Ray ray{{0.05f, 0.5f, 0.5f}, {1, 0, 0}};
    GridWalk w = start_walk(g, ray, all);
    REQUIRE(!w.missed);
    const double size = static_cast<double>(g.cell_size.x);
    for (int step = 1; step <= 100000; ++step) {
        REQUIRE(next_cell(w));
        if (step == 10000 || step == 100000) {
            // The oracle: the boundary at box.min + step * size, reached at t = that - 0.05.
            const double t_exact = static_cast<double>(step) * size - 0.05;
            const double drift = std::abs(static_cast<double>(w.t_enter) - t_exact) / size;
            INFO("after " << step << " steps: " << show(w) << "; expected p = " << step << " and t_enter = "
                 << t_exact << ": off by " << drift << " cells");
            CHECK(w.p == step);
            CHECK(drift < 1e-3 * (step / 10000));
        }
    }
}
