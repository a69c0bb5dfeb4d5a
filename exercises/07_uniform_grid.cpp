// Chapter 07, the uniform grid: your exercises.
//
// Each function below states what to compute (not how); its contract is documented in
// chapters/07_uniform_grid/07_uniform_grid.hpp and the lesson in that folder's README.md.
// Each stub compiles and returns a harmless value, so the chapter's program always runs: with
// the stubs, the grid finds nothing and the picture shows only the background.
// Check your work with:  cmake --build --preset grade --target check_07
// Stuck? Hints in tiers you open one at a time: chapters/07_uniform_grid/hints.md, or
// ./build/grade/hint 07.1 (tier 1, the idea), ./build/grade/hint 07.1 2 (the trap), ... 3 (the walk-through).
//
// This chapter uses chapter 02's objects (Objects::intersect, closer_than) and the slab test
// (common/bounds.hpp); the grid's build and its query loops are given (grid.hpp).
#include "07_uniform_grid/07_uniform_grid.hpp"
#include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

#include <algorithm>
#include <cmath>

namespace rt {

cell3 grid_resolution(const Bounds& box, int objects, float lambda, int max_per_axis)
{
    // EXERCISE 07.1: the cube-root rule.
    // Return the number of cells along each axis: cubic cells, about lambda of them per object,
    // spread over the axes the scene has room along; each count rounded to the nearest and kept
    // within 1 .. max_per_axis. An axis no wider than the final side gets one cell and takes no
    // part in choosing it. A count of 0 or less, an empty box, or a box of no extent: 1 x 1 x 1.
    // A floor spreads its cells over an area, a line over a length: the root must follow.
    // Lesson: "The grid's resolution (EXERCISE 07.1)".
    // DETAIL BEGIN: how, step by step (kept by an introductory course's handout, CONTRACTS=detailed)
    // An axis no wider than a cell gets one cell, and the side is chosen again over the others,
    // until none is.
    // DETAIL END
    // Stuck? hint 07.1 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("07.1", cell3{1, 1, 1});
}

cell3 cell_of(const GridShape& grid, const point3& p)
{
    // EXERCISE 07.2: the cell holding p, clamped into the grid.
    // Return the cell of `grid` that holds p: on each axis, how many whole cells p lies past the box's
    // min side. A point exactly on a boundary belongs to the cell above it; a point on the far face,
    // or outside the grid however far (even infinitely), to the nearest cell inside.
    // Lesson: "A point's cell, and an object's cells (EXERCISES 07.2 and 07.3)".
    // DETAIL BEGIN: how, step by step (kept by an introductory course's handout, CONTRACTS=detailed)
    // Clamp while the value is still a float: a point 1e30 away is no int.
    // DETAIL END
    // Stuck? hint 07.2 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("07.2", cell3{0, 0, 0});
}

CellRange cells_overlapping(const GridShape& grid, const Bounds& bounds)
{
    // EXERCISE 07.3: the cells a box overlaps.
    // Return the block of cells that hold some point of `bounds` as 07.2 places points, first and
    // last on each axis both included, clamped into the grid: a box larger than the grid gets every
    // cell. A box that ends exactly on a cell boundary is listed on both sides of it; one that
    // starts exactly on a boundary, in the cell above it only.
    // Lesson: "A point's cell, and an object's cells (EXERCISES 07.2 and 07.3)".
    // DETAIL BEGIN: how, step by step (kept by an introductory course's handout, CONTRACTS=detailed)
    // Your 07.2 already does the hard part.
    // DETAIL END
    // Stuck? hint 07.3 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("07.3", CellRange{{0, 0, 0}, {0, 0, 0}});
}

GridWalk start_walk(const GridShape& grid, const Ray& ray, Interval range)
{
    // EXERCISE 07.4: the walk's setup.
    // Return the walk of `ray` through `grid` over `range`, in the first cell it visits (where it
    // enters the box, or where the range starts inside it; a missed walk when it never meets the
    // box within the range), every GridWalk field set as the header says: per moving axis the step,
    // t_delta, t_first (in double) and t_max; t_enter; t_end, the nearer of the range's end and the
    // box's face as the walk's own boundaries place it; t_range. A 0 or -0 component never steps.
    // Lesson: "The walk (EXERCISES 07.4 and 07.5)" (its paragraphs The setup and Termination).
    // DETAIL BEGIN: how, step by step (kept by an introductory course's handout, CONTRACTS=detailed)
    // Going down an axis, the first boundary ahead is the cell's lower face.
    // DETAIL END
    // Stuck? hint 07.4 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("07.4", GridWalk{});
}

bool next_cell(GridWalk& walk)
{
    // EXERCISE 07.5: the next-voxel step.
    // Move `walk` into the neighbour the ray enters next, through the boundary it reaches first, and
    // return true; return false, the walk unchanged, when that boundary is at or beyond t_end. Every
    // field the step touches must stay consistent, and the next boundary's t comes from boundary_t,
    // never from a running sum. A walk whose t is NaN must stop too.
    // Lesson: "The walk (EXERCISES 07.4 and 07.5)" (the 3D DDA, Termination and Drift).
    // Stuck? hint 07.5 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("07.5", false);
}

bool closest_in_cell(const Grid& grid, const GridWalk& walk, const Ray& ray, Interval range, const Objects& objects,
                     ObjectHit& best)
{
    // EXERCISE 07.6: the cell query.
    // Keep in `best` the nearest hit of `ray`, among the objects listed in the walk's current cell,
    // that lies within the cell (no farther than walk.cell_exit()) and beats `best` (closer_than's
    // range). Return whether `best` changed; an empty cell changes nothing.
    // A hit beyond the cell is not wrong, only early: leave it, a later cell that lists it finds it.
    // Lesson: "The cell query (EXERCISE 07.6): a hit beyond the cell must not end the walk".
    // DETAIL BEGIN: how, step by step (kept by an introductory course's handout, CONTRACTS=detailed)
    // Test each object listed in the walk's current cell against `ray`, each in the range that
    // beats `best` (closer_than), and keep a hit only when its t is no farther than the cell's exit.
    // DETAIL END
    // Stuck? hint 07.6 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("07.6", false);
}

cell3 choose_grid_resolution(const Bounds& box, const std::vector<Bounds>& boxes)
{
    // EXERCISE 07.7 (open): the grid's shape for a scene.
    // Return the cells along each axis of the grid over `box` for the objects whose boxes are
    // `boxes`: each axis 1 to max_cells_per_axis, the grid's words (grid_words) within
    // grid_budget_words. Any method; the grader checks the grid's answers against brute force, then
    // counts its tests and cells per ray against the reference's.
    // Lesson: "The grid's shape for a scene (EXERCISE 07.7, open)".
    // Stuck? hint 07.7 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("07.7", cell3{0, 0, 0});
}

}  // namespace rt
