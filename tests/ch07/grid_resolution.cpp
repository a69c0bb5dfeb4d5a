// EXERCISE 07.1: the grid's resolution by the cube-root rule.
#include "tests/ch07/describe.hpp"

using namespace rt;
using namespace rt::grader;

namespace {

void check(const Bounds& box, int objects, float lambda, const cell3& expected, const char* why)
{
    const cell3 got = grid_resolution(box, objects, lambda);
    INFO("07.1 grid_resolution(" << show(box) << ", " << objects << " objects, lambda " << lambda << "): got " << show(got)
         << ", expected " << show(expected) << ": " << why);
    CHECK(got == expected);
}

Bounds box(const point3& lo, const point3& hi) { return {lo, hi}; }

}  // namespace

GRADED_TEST("grid_resolution: a cube gets the cube root of lambda N cells along each axis", "07.1", 3)
{
    check(box({0, 0, 0}, {1, 1, 1}), 1000, 1.0f, {10, 10, 10}, "1000 cells of side 0.1");
    check(box({-2, -2, -2}, {2, 2, 2}), 1000, 8.0f, {20, 20, 20}, "8000 cells of side 0.2: lambda multiplies the cells");
    check(box({5, 5, 5}, {6, 6, 6}), 125, 1.0f, {5, 5, 5}, "the box's position does not matter");
}

GRADED_TEST("grid_resolution: a long box gets cubic cells, more of them along its long axis", "07.1", 3)
{
    // V = 8 x 1 x 1 = 8, 64 cells: side cbrt(8 / 64) = 0.5.
    check(box({0, 0, 0}, {8, 1, 1}), 64, 1.0f, {16, 2, 2}, "cells of side 0.5: 16 x 2 x 2 = 64");
    check(box({0, 0, 0}, {1, 4, 2}), 8, 1.0f, {1, 4, 2}, "cells of side 1");
    check(box({0, 0, 0}, {1, 4, 2}), 64, 1.0f, {2, 8, 4}, "V = 8 and 64 cells: side cbrt(8 / 64) = 0.5");
    // Rounded to the nearest count: 10 / cbrt(1000 / 1200) = 10.6 -> 11.
    check(box({0, 0, 0}, {10, 10, 10}), 1200, 1.0f, {11, 11, 11}, "10.6 cells per axis round to 11");
}

GRADED_TEST("grid_resolution: a flat scene spreads its cells over its area; an axis thinner than a cell gets one", "07.1", 3)
{
    check(box({0, 0, 0}, {4, 0, 4}), 16, 1.0f, {4, 1, 4}, "a floor: 16 cells over its 4 x 4 area, side 1");
    check(box({0, 0, 0}, {4, 0.01f, 4}), 16, 1.0f, {4, 1, 4},
          "a floor 0.01 thick is thinner than a cell: it counts as flat, 16 cells over the area");
    check(box({0, 0, 0}, {0, 0, 6}), 3, 2.0f, {1, 1, 6}, "a line: 6 cells along its length");
    // Above, the area (or length) equals lambda N, so the cell side is 1 whatever root is taken.
    // Here it is not: a square root for a floor, none for a line.
    check(box({0, 0, 0}, {4, 0, 4}), 64, 1.0f, {8, 1, 8}, "a floor with 64 objects: side sqrt(16 / 64) = 0.5");
    check(box({0, 0, 0}, {4, 0.01f, 4}), 64, 1.0f, {8, 1, 8},
          "a thin floor with 64 objects: flat, so side sqrt(16 / 64) = 0.5, not a cube root");
    check(box({0, 0, 0}, {0, 0, 6}), 12, 1.0f, {1, 1, 12}, "a line with 12 objects: side 6 / 12 = 0.5");
}

GRADED_TEST("grid_resolution: at least 1 and at most max_cells_per_axis cells per axis; no objects, 1 x 1 x 1", "07.1", 3)
{
    check(box({0, 0, 0}, {1, 1, 1}), 0, 4.0f, {1, 1, 1}, "no objects: one cell");
    check(box({0, 0, 0}, {1, 1, 1}), 1, 0.001f, {1, 1, 1}, "fewer cells than one: one cell");
    check(box({0, 0, 0}, {1, 1, 1}), 100000000, 1000.0f, {max_cells_per_axis, max_cells_per_axis, max_cells_per_axis},
          "1e11 cells asked: max_cells_per_axis along each axis");
    check(box({0, 0, 0}, {0, 0, 0}), 5, 1.0f, {1, 1, 1}, "a box of no extent at all: one cell");
    // Inputs the grid's build never passes, but a caller could: a box with nothing in it (Bounds{},
    // min = +infinity, max = -infinity, whose extent is no number of cells), and a count below 0.
    check(Bounds{}, 5, 1.0f, {1, 1, 1}, "an empty box (Bounds{}, nothing inside) though 5 objects are counted: one cell");
    check(box({0, 0, 0}, {1, 1, 1}), -3, 1.0f, {1, 1, 1}, "a negative count: one cell");
    const cell3 wide = grid_resolution(box({0, 0, 0}, {1, 1, 1}), 100000000, 1000.0f, 2048);
    INFO("07.1 grid_resolution with max_per_axis = 2048 (the hashed grid's limit), 1e11 cells asked: got " << show(wide));
    CHECK(wide == cell3(2048, 2048, 2048));
}

GRADED_TEST("grid_resolution: at the count's boundary, 1 object gets its lambda cells; 0 objects one cell, whatever the box", "07.1", 2)
{
    // One object is a scene like any other: lambda 8 asks for 8 cells, side cbrt(1 / 8) = 0.5.
    check(box({0, 0, 0}, {1, 1, 1}), 1, 8.0f, {2, 2, 2}, "1 object and lambda 8: 8 cells of side 0.5");
    check(box({0, 0, 0}, {4, 0, 4}), 1, 16.0f, {4, 1, 4}, "a floor, 1 object and lambda 16: 16 cells of side 1");
    // No objects is one cell before any division: a box 1e-20 across has a volume of 1e-60, which
    // float rounds to 0, and 0 / (lambda 0) is no number of cells.
    check(box({0, 0, 0}, {1e-20f, 1e-20f, 1e-20f}), 0, 1.0f, {1, 1, 1},
          "no objects in a box 1e-20 across (its volume, 1e-60, is 0 in float): one cell");
}

GRADED_TEST("grid_resolution: an infinite extent (an unbounded plane's box) makes cells of infinite side: one cell, a flat axis beside it included", "07.1", 2)
{
    // V = infinity: s = infinity, and every axis, infinite or not, is no wider than a cell. A flat
    // axis (extent 0) is left out from the start: it must not multiply the infinite volume by 0.
    const float inf = infinity;
    check(box({0, 0, 0}, {inf, 1, 0}), 8, 1.0f, {1, 1, 1}, "x infinite, y 1, z flat (0): one cell");
    check(box({0, 0, 0}, {0, inf, 1}), 8, 1.0f, {1, 1, 1}, "x flat (0), y infinite, z 1: one cell");
    check(box({0, 0, 0}, {1, 0, inf}), 8, 1.0f, {1, 1, 1}, "x 1, y flat (0), z infinite: one cell");
    check(box({0, 0, 0}, {2, 0, 2}), 16, 1.0f, {4, 1, 4}, "a finite floor 2 x 2 beside them keeps its 16 cells of side 0.5");
}

GRADED_TEST("grid_resolution: axes are dropped until none is thinner than a cell, however many rounds that takes", "07.1", 3)
{
    // Extents 10 x 1 x 0.5 and 8 cells: the cube root gives s = cbrt(5 / 8) = 0.85, so z (0.5) is
    // thinner than a cell. Over x and y, s = sqrt(10 / 8) = 1.12: now y (1) is thinner too. Over x
    // alone, s = 10 / 8 = 1.25: 8 x 1 x 1. Stopping after one round gives 10 / 1.12 = 8.9 -> 9 x 1 x 1.
    check(box({0, 0, 0}, {10, 1, 0.5f}), 8, 1.0f, {8, 1, 1},
          "z is dropped in the first round, y only in the second, when s has grown to 1.12: s = 10 / 8 = 1.25");
    check(box({0, 0, 0}, {0.5f, 10, 1}), 4, 2.0f, {1, 8, 1}, "the same box turned: its long axis y gets the 8 cells");
}

GRADED_TEST("grid_resolution: an axis exactly one cell thick (extent = s), or one ulp either side, gets one cell", "07.1", 3)
{
    // 8 x 1 x 8 with 64 cells: s = cbrt(64 / 64) = 1, so y's extent is exactly s. Dropping it leaves
    // s = sqrt(64 / 64) = 1 (at extent = s the two roots agree): 8 x 1 x 8 either way.
    check(box({0, 0, 0}, {8, 1, 8}), 64, 1.0f, {8, 1, 8}, "y's extent 1 equals the cell's side 1: one cell");
    check(box({0, 0, 0}, {8, std::nextafter(1.0f, 0.0f), 8}), 64, 1.0f, {8, 1, 8},
          "y's extent is one ulp below the cell's side: one cell");
    check(box({0, 0, 0}, {8, std::nextafter(1.0f, 2.0f), 8}), 64, 1.0f, {8, 1, 8},
          "y's extent is one ulp above the cell's side: round(1.0000001) = 1 cell");
}

GRADED_TEST("grid_resolution: n_i is extent_i / s rounded to the nearest, down as well as up", "07.1", 3)
{
    // 10 / cbrt(1000 / 800) = 9.28: 9, not 10.
    check(box({0, 0, 0}, {10, 10, 10}), 800, 1.0f, {9, 9, 9}, "9.28 cells per axis round to 9");
    // 8 / cbrt(8 x 2 x 2 / 40) = 8 / 0.93 = 8.6 -> 9 along x, 2.15 -> 2 along y and z.
    check(box({0, 0, 0}, {8, 2, 2}), 40, 1.0f, {9, 2, 2}, "8.6 cells along x round to 9, 2.15 along y and z to 2");
}

GRADED_TEST("grid_resolution: exactly max_per_axis cells is allowed, one more is clamped, and a count past any int clamps too", "07.1", 3)
{
    const auto check_max = [](const Bounds& b, int objects, float lambda, int max, const cell3& expected, const char* why) {
        const cell3 got = grid_resolution(b, objects, lambda, max);
        INFO("07.1 grid_resolution(" << show(b) << ", " << objects << " objects, lambda " << lambda << ", max_per_axis "
             << max << "): got " << show(got) << ", expected " << show(expected) << ": " << why);
        CHECK(got == expected);
    };
    check_max(box({0, 0, 0}, {1, 1, 1}), 125, 1.0f, 5, {5, 5, 5}, "5 cells per axis asked, at most 5: 5");
    check_max(box({0, 0, 0}, {1, 1, 1}), 216, 1.0f, 5, {5, 5, 5}, "6 cells per axis asked, at most 5: 5");
    check_max(box({0, 0, 0}, {1, 1, 1}), 125, 1.0f, 6, {5, 5, 5}, "5 cells per axis asked, at most 6: 5");
    // 1e33 cells: 1e11 per axis, past any int: clamped while still a float, not converted first.
    check(box({0, 0, 0}, {1, 1, 1}), 100000000, 1e25f, {max_cells_per_axis, max_cells_per_axis, max_cells_per_axis},
          "1e33 cells asked, 1e11 per axis (no int holds it): max_cells_per_axis along each axis");
}
