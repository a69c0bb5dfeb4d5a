// EXERCISES 07.2 and 07.3: the cell of a point, and the cells a box overlaps.
#include "tests/ch07/describe.hpp"

#include "common/random.hpp"

using namespace rt;
using namespace rt::grader;

namespace {

// 4 x 2 x 5 cells of size 0.5 x 1 x 0.2 over the box from (-1, 0, 2) to (1, 2, 3).
const GridShape grid_4x2x5 = grid_shape({{-1, 0, 2}, {1, 2, 3}}, {4, 2, 5});

void check_cell(const point3& p, const cell3& expected, const char* why)
{
    const cell3 got = cell_of(grid_4x2x5, p);
    INFO("07.2 cell_of(" << show(grid_4x2x5) << ", " << show(p) << "): got " << show(got) << ", expected " << show(expected) << ": "
         << why);
    CHECK(got == expected);
}

void check_range(const Bounds& b, const cell3& first, const cell3& last, const char* why)
{
    const CellRange got = cells_overlapping(grid_4x2x5, b);
    INFO("07.3 cells_overlapping(" << show(grid_4x2x5) << ", " << show(b) << "): got " << show(got.first) << " to "
         << show(got.last) << ", expected " << show(first) << " to " << show(last) << ": " << why);
    CHECK(got.first == first);
    CHECK(got.last == last);
}

// The point on boundary i of an axis as the contract defines it: the least float whose quotient
// (p - min) / size, each operation in float, is at least i. The quotient never decreases as p
// grows, so stepping from min + i size (rounded to float, a few float steps away) finds it.
float point_on_boundary(float min, float size, int i)
{
    const auto quotient = [&](float p) { return (p - min) / size; };
    const float whole = static_cast<float>(i);
    float p = min + whole * size;
    while (quotient(p) >= whole)
        p = std::nextafter(p, -infinity);
    while (quotient(p) < whole)
        p = std::nextafter(p, infinity);
    return p;
}

}  // namespace

GRADED_TEST("cell_of: on grids whose division is inexact, the point where float's (p - min) / size reaches i is in cell i, the float below it in cell i - 1", "07.2", 2)
{
    // Grids like a scene's: min in [-10, 10], cells 0.01 to 3 wide, 2 to 64 of them. On about one
    // grid in six, min + i size rounded to float is not the point on boundary i (the contract's
    // "Precision"), so a cell that follows it, or a quotient formed another way, misses here.
    Rng rng(7, 72);
    for (int g = 0; g < 300; ++g) {
        point3 min, size;
        cell3 n, i;
        for (int a = 0; a < 3; ++a) {
            min[a] = -10.0f + 20.0f * rng.next_float();
            size[a] = 0.01f + 2.99f * rng.next_float();
            n[a] = 2 + static_cast<int>(rng.next_u32() % 63u);
            i[a] = 1 + static_cast<int>(rng.next_u32() % static_cast<std::uint32_t>(n[a] - 1));
        }
        const GridShape shape = grid_shape({min, min + vec3(n) * size}, n);
        point3 on, below;
        for (int a = 0; a < 3; ++a) {
            on[a] = point_on_boundary(shape.box.min[a], shape.cell_size[a], i[a]);
            below[a] = std::nextafter(on[a], -infinity);
        }
        const cell3 got_on = cell_of(shape, on), got_below = cell_of(shape, below);
        INFO("07.2 cell_of(" << show(shape) << ", " << show(on) << "), the point on boundaries " << show(i)
             << ": got " << show(got_on) << ", expected " << show(i) << "; and one float step below it, "
             << show(below) << ": got " << show(got_below) << ", expected " << show(i - cell3(1))
             << " (the contract's boundary: where float's (p - min) / cell_size reaches a whole number)");
        REQUIRE(got_on == i);
        REQUIRE(got_below == i - cell3(1));
    }
}

GRADED_TEST("cell_of: a point inside the grid lies in the cell floor((p - min) / size) says", "07.2", 3)
{
    check_cell({-0.9f, 0.5f, 2.1f}, {0, 0, 0}, "near the min corner");
    check_cell({0.3f, 1.5f, 2.75f}, {2, 1, 3}, "(1.3 / 0.5, 1.5 / 1, 0.75 / 0.2) = (2.6, 1.5, 3.75)");
    check_cell({0.9f, 1.9f, 2.95f}, {3, 1, 4}, "near the max corner");
}

GRADED_TEST("cell_of: a point on a boundary belongs to the cell above it; one on the far face to the last cell", "07.2", 3)
{
    check_cell({-0.5f, 1.0f, 2.0f}, {1, 1, 0}, "x = -0.5 and y = 1 are boundaries: the cells above them");
    check_cell({-1.0f, 0.0f, 2.0f}, {0, 0, 0}, "the min corner itself");
    check_cell({1.0f, 2.0f, 3.0f}, {3, 1, 4}, "the max corner: floor gives (4, 2, 5), one past the last cell");
}

STABILITY_TEST("cell_of: a point outside the grid, even very far or infinitely far, is clamped to the nearest cell", "07.2", 3)
{
    check_cell({-1.0000001f, -1e-7f, 1.9999999f}, {0, 0, 0}, "a hair outside the min corner (rounding)");
    check_cell({5.0f, -3.0f, 2.5f}, {3, 0, 2}, "outside in x and y");
    check_cell({1e30f, -1e30f, 1e30f}, {3, 0, 4}, "1e30 away: the float must be clamped before it becomes an int");
    check_cell({infinity, -infinity, 2.5f}, {3, 0, 2}, "infinitely far");
}

GRADED_TEST("cells_overlapping: a box spans the cells from its min corner's to its max corner's", "07.3", 3)
{
    check_range({{-0.9f, 0.1f, 2.1f}, {-0.6f, 0.9f, 2.15f}}, {0, 0, 0}, {0, 0, 0}, "inside one cell");
    check_range({{-0.9f, 0.1f, 2.1f}, {0.6f, 1.5f, 2.5f}}, {0, 0, 0}, {3, 1, 2}, "across several cells");
    check_range({{-5, -5, -5}, {5, 5, 5}}, {0, 0, 0}, {3, 1, 4}, "larger than the grid: every cell");
}

GRADED_TEST("cells_overlapping: a box that ends exactly on a boundary is listed on both sides of it", "07.3", 3)
{
    check_range({{-0.9f, 0.2f, 2.2f}, {-0.5f, 1.0f, 2.4f}}, {0, 0, 1}, {1, 1, 2},
                "it ends on x = -0.5, y = 1 and z = 2.4: the cells beyond those boundaries too; it starts on "
                "z = 2.2: from the cell above it only (z's cell 1), the cell below holds none of its points");
    check_range({{0.0f, 0.5f, 2.5f}, {0.0f, 0.5f, 2.5f}}, {2, 0, 2}, {2, 0, 2},
                "a point box on the boundary x = 0: the cell above it alone");
}

GRADED_TEST("cell_of: one ulp below a boundary is the cell below it, one ulp above the cell above; one ulp either side of the far face, the last cell", "07.2", 3)
{
    const float below_x = std::nextafter(-0.5f, -1.0f), above_x = std::nextafter(-0.5f, 0.0f);
    check_cell({below_x, 0.5f, 2.5f}, {0, 0, 2}, "x one ulp below the boundary x = -0.5: cell 0 along x");
    check_cell({above_x, 0.5f, 2.5f}, {1, 0, 2}, "x one ulp above the boundary x = -0.5: cell 1 along x");
    check_cell({0.0f, std::nextafter(1.0f, 0.0f), 2.5f}, {2, 0, 2}, "y one ulp below the boundary y = 1: cell 0 along y");
    check_cell({0.0f, std::nextafter(1.0f, 2.0f), 2.5f}, {2, 1, 2}, "y one ulp above the boundary y = 1: cell 1 along y");
    check_cell({std::nextafter(1.0f, 0.0f), std::nextafter(2.0f, 0.0f), 2.5f}, {3, 1, 2},
               "one ulp inside the far faces x = 1 and y = 2: the last cells");
    check_cell({std::nextafter(1.0f, 2.0f), std::nextafter(2.0f, 3.0f), 2.5f}, {3, 1, 2},
               "one ulp outside the far faces x = 1 and y = 2: still the last cells");
}

GRADED_TEST("cells_overlapping: a box ending one ulp before a boundary stays below it; one ulp past it, the cell beyond is listed too", "07.3", 3)
{
    check_range({{-0.9f, 0.2f, 2.5f}, {std::nextafter(-0.5f, -1.0f), std::nextafter(1.0f, 0.0f), 2.5f}}, {0, 0, 2},
                {0, 0, 2}, "it ends one ulp before x = -0.5 and y = 1: only the cells below them");
    check_range({{-0.9f, 0.2f, 2.5f}, {std::nextafter(-0.5f, 0.0f), std::nextafter(1.0f, 2.0f), 2.5f}}, {0, 0, 2},
                {1, 1, 2}, "it ends one ulp past x = -0.5 and y = 1: the cells beyond them too");
}
