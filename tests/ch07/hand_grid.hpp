// The small grid chapter 07's and 08's cell-query tests build by hand: three cells of size 1 along
// x over the box from (0, 0, 0) to (3, 1, 1), and the ray from (-1, 0.5, 0.5) along +x, which
// enters cell 0 at t = 1, cell 1 at t = 2, cell 2 at t = 3, and leaves the box at t = 4.
#pragma once

#include "tests/ch07/describe.hpp"

namespace rt::grader::hand_grid {

const Ray ray{{-1, 0.5f, 0.5f}, {1, 0, 0}};
const Interval all{0.0f, infinity};

// Objects 0-2 are spheres on the ray; 3-5 are one triangle thrice, across the ray in the plane
// x = 1 (cell 0's far boundary), so all three are hit at exactly t = 2.
const std::vector<Sphere> spheres = {
    {{2.5f, 0.5f, 0.5f}, 0.2f},   // 0: hit at x = 2.3, t = 3.3 (in cell 2)
    {{0.95f, 0.5f, 0.5f}, 0.2f},  // 1: hit at x = 0.75, t = 1.75 (in cell 0)
    {{0.5f, 0.5f, 0.5f}, 0.2f},   // 2: hit at x = 0.3, t = 1.3 (in cell 0)
};
const Triangle across{{1, -1, -1}, {1, 3, -1}, {1, -1, 3}};
const std::vector<Triangle> triangles = {across, across, across};

inline Objects objects() { return objects_over(spheres, triangles); }

// The same with object 6, a triangle in x = 3.001: hit at t = 4.001, past the box's face x = 3
// (t = 4), where rounding can put a hit on that face. Only the walk's last cell, which reaches to
// the range's end, keeps it.
const std::vector<Triangle> triangles_with_one_past_the_box = {
    across, across, across, Triangle{{3.001f, -1, -1}, {3.001f, 3, -1}, {3.001f, -1, 3}}};

inline Objects objects_with_one_past_the_box() { return objects_over(spheres, triangles_with_one_past_the_box); }

// The grid with `lists[c]` in cell c.
inline Grid grid_of(const std::vector<std::vector<std::uint32_t>>& lists)
{
    Grid g;
    g.shape = grid_shape({{0, 0, 0}, {3, 1, 1}}, {3, 1, 1});
    g.cell_start = {0};
    for (const auto& list : lists) {
        g.object_index.insert(g.object_index.end(), list.begin(), list.end());
        g.cell_start.push_back(static_cast<std::uint32_t>(g.object_index.size()));
    }
    return g;
}

// The walk in cell c, as start_walk and next_cell leave it there.
inline GridWalk walk_in(int c, float range_max = infinity)
{
    GridWalk w;
    w.missed = false;
    w.p = c;
    w.step_p[0] = 1;
    w.t_first[0] = 2.0f;
    w.t_delta[0] = 1.0f;
    w.steps[0] = c;
    w.t_max[0] = 2.0f + static_cast<float>(c);
    w.t_enter = 1.0f + static_cast<float>(c);
    w.t_end = std::min(4.0f, range_max);
    w.t_range = range_max;
    return w;
}

}  // namespace rt::grader::hand_grid
