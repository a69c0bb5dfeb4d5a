// SOLUTION BEGIN
// Chapter 07, the uniform grid: the reference solution.
//
// This file is also the source of exercises/07_uniform_grid.cpp: the kit's cutter drops every
// block between SOLUTION BEGIN and SOLUTION END and keeps the STUB lines as code
// (`cmake --build <build> --target cut_exercises`; a test checks that the two agree).
// SOLUTION END
// STUB // Chapter 07, the uniform grid: your exercises.
// STUB //
// STUB // Each function below says what to compute and gives a hint; its contract is documented in
// STUB // chapters/07_uniform_grid/07_uniform_grid.hpp and the lesson in that folder's README.md.
// STUB // Each stub compiles and returns a harmless value, so the chapter's program always runs: with
// STUB // the stubs, the grid finds nothing and the picture shows only the background.
// STUB // Check your work with:  cmake --build --preset grade --target check_07
// STUB //
// STUB // This chapter uses chapter 02's objects (Objects::intersect, closer_than) and the slab test
// STUB // (common/bounds.hpp); the grid's build and its query loops are given (grid.hpp).
#include "07_uniform_grid/07_uniform_grid.hpp"
// STUB #include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

#include <algorithm>
#include <cmath>

namespace rt {

cell3 grid_resolution(const Bounds& box, int objects, float lambda, int max_per_axis)
{
    // EXERCISE 07.1: the cube-root rule.
    // 1. No objects, or an empty box: 1 x 1 x 1.
    // 2. Start with every axis of extent > 0 as one of the grid's dims (3 for a solid, 2 for a
    //    floor, 1 for a line); V is the product of their extents.
    // 3. Cells of side s with V / s^dims = lambda N: s = (V / (lambda N))^(1 / dims).
    // 4. An axis with extent <= s is thinner than a cell: drop it from the dims (it gets 1 cell)
    //    and go back to 3 with the others. When none is dropped, n_i = round(extent_i / s),
    //    clamped to 1 .. max_per_axis.
    // Hint: std::pow(x, 1.0f / dims); compute in float, the box is float; clamp a float before
    // converting it to int.
    // SOLUTION BEGIN
    if (objects <= 0 || box.empty())
        return {1, 1, 1};
    const vec3 e = box.extent();
    bool dim[3] = {e.x > 0.0f, e.y > 0.0f, e.z > 0.0f};
    for (;;) {
        int dims = 0;
        float volume = 1.0f;
        for (int a = 0; a < 3; ++a)
            if (dim[a]) {
                ++dims;
                volume *= e[a];
            }
        if (dims == 0)
            return {1, 1, 1};
        const float side = std::pow(volume / (lambda * static_cast<float>(objects)), 1.0f / static_cast<float>(dims));
        bool dropped = false;
        for (int a = 0; a < 3; ++a)
            if (dim[a] && e[a] <= side) {
                dim[a] = false;  // thinner than a cell
                dropped = true;
            }
        if (dropped)
            continue;
        cell3 n(1);
        for (int a = 0; a < 3; ++a)
            if (dim[a])
                n[a] = static_cast<int>(std::clamp(std::round(e[a] / side), 1.0f, static_cast<float>(max_per_axis)));
        return n;
    }
    // SOLUTION END
    // STUB return stub("07.1", cell3{1, 1, 1});
}

cell3 cell_of(const GridShape& grid, const point3& p)
{
    // EXERCISE 07.2: the cell holding p, clamped into the grid.
    // For each axis a: floor((p[a] - grid.box.min[a]) / grid.cell_size[a]), clamped to
    // 0 .. grid.n[a] - 1.
    // Hint: clamp the float before converting it to int: a point far outside gives a value no int
    // can hold.
    // SOLUTION BEGIN
    cell3 c;
    for (int a = 0; a < 3; ++a) {
        const float i = std::floor((p[a] - grid.box.min[a]) / grid.cell_size[a]);
        c[a] = static_cast<int>(std::clamp(i, 0.0f, static_cast<float>(grid.n[a] - 1)));
    }
    return c;
    // SOLUTION END
    // STUB return stub("07.2", cell3{0, 0, 0});
}

CellRange cells_overlapping(const GridShape& grid, const Bounds& bounds)
{
    // EXERCISE 07.3: the cells the box overlaps: from the cell of its min corner to the cell of its
    // max corner, on each axis (both included).
    // Hint: two calls of cell_of (07.2).
    // SOLUTION BEGIN
    return {cell_of(grid, bounds.min), cell_of(grid, bounds.max)};
    // SOLUTION END
    // STUB return stub("07.3", CellRange{{0, 0, 0}, {0, 0, 0}});
}

GridWalk start_walk(const GridShape& grid, const Ray& ray, Interval range)
{
    // EXERCISE 07.4: the walk's setup.
    // 1. inside = hit_bounds(grid.box, ray, range); none: return a GridWalk{} (missed).
    // 2. walk.missed = false; the first cell c = cell_of(grid, ray.at(inside->min)), p its address;
    //    t_enter = inside->min; t_range = range.max; t_end = range.max for now.
    // 3. For each axis a with ray.dir[a] != 0:
    //      going up (dir > 0): step_p = +strides()[a], boundary = box.min + (c[a] + 1) s, m = n - 1 - c[a];
    //      going down:         step_p = -strides()[a], boundary = box.min + c[a] s,       m = c[a];
    //      t_delta = s / |dir[a]|, t_first = (boundary - origin[a]) / dir[a], both in double,
    //      t_max = t_first rounded to float, and t_end = min(t_end, boundary_t(walk, a, m)).
    // Hint: s is grid.cell_size[a]; static_cast<double>(x) before dividing; leave the other axes as
    // GridWalk{} has them (infinity, 0).
    // SOLUTION BEGIN
    GridWalk walk;
    const std::optional<Interval> inside = hit_bounds(grid.box, ray, range);
    if (!inside)
        return walk;
    walk.missed = false;
    const cell3 c = cell_of(grid, ray.at(inside->min));
    walk.p = grid.address(c);
    walk.t_enter = inside->min;
    walk.t_range = range.max;
    walk.t_end = range.max;
    const cell3 stride = grid.strides();
    for (int a = 0; a < 3; ++a) {
        const float d = ray.dir[a];
        if (d == 0.0f)
            continue;  // -0 too: never crosses a boundary of this axis
        const float s = grid.cell_size[a];
        const bool up = d > 0.0f;
        const float boundary = grid.box.min[a] + static_cast<float>(up ? c[a] + 1 : c[a]) * s;
        walk.step_p[a] = up ? stride[a] : -stride[a];
        walk.t_delta[a] = static_cast<double>(s) / std::abs(static_cast<double>(d));
        walk.t_first[a] = (static_cast<double>(boundary) - ray.origin[a]) / d;
        walk.t_max[a] = static_cast<float>(walk.t_first[a]);
        const int to_face = up ? grid.n[a] - 1 - c[a] : c[a];
        walk.t_end = std::min(walk.t_end, boundary_t(walk, a, to_face));
    }
    return walk;
    // SOLUTION END
    // STUB return stub("07.4", GridWalk{});
}

bool next_cell(GridWalk& walk)
{
    // EXERCISE 07.5: the next-voxel step.
    // 1. a = the axis with the least t_max.
    // 2. t_max[a] >= t_end: the ray leaves the box (or its range ends) before the next boundary;
    //    return false.
    // 3. t_enter = t_max[a]; p += step_p[a]; ++steps[a]; t_max[a] = boundary_t(walk, a, steps[a]).
    // Hint: written as !(t_max[a] < t_end), the test also stops a walk whose t is NaN.
    // SOLUTION BEGIN
    int a = walk.t_max[0] < walk.t_max[1] ? 0 : 1;
    if (walk.t_max[2] < walk.t_max[a])
        a = 2;
    if (!(walk.t_max[a] < walk.t_end))
        return false;
    walk.t_enter = walk.t_max[a];
    walk.p += walk.step_p[a];
    ++walk.steps[a];
    walk.t_max[a] = boundary_t(walk, a, walk.steps[a]);
    return true;
    // SOLUTION END
    // STUB return stub("07.5", false);
}

bool closest_in_cell(const Grid& grid, const GridWalk& walk, const Ray& ray, Interval range, const Objects& objects,
                     ObjectHit& best)
{
    // EXERCISE 07.6: the cell query.
    // For each object k = grid.object_index[i], i from grid.cell_start[walk.p] up to (not including)
    // grid.cell_start[walk.p + 1]: when objects.intersect(k, ray, closer_than(range, best, k), hit)
    // and hit.t <= walk.cell_exit(), best = hit. Return whether best changed.
    // Hint: a hit beyond cell_exit() is not wrong, only early: leave it, a later cell finds it again.
    // SOLUTION BEGIN
    bool found = false;
    const float exit = walk.cell_exit();
    for (std::uint32_t i = grid.cell_start[walk.p]; i < grid.cell_start[walk.p + 1]; ++i) {
        const int k = static_cast<int>(grid.object_index[i]);
        ObjectHit hit;
        if (objects.intersect(k, ray, closer_than(range, best, k), hit) && hit.t <= exit) {
            best = hit;
            found = true;
        }
    }
    return found;
    // SOLUTION END
    // STUB return stub("07.6", false);
}

}  // namespace rt
