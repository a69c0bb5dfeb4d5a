// Chapter 10's diagnosis of one ray the hierarchy of grids answers differently from brute force
// (tests/ch07/suspect.hpp): the hierarchy's walk (10.5) asked again grid by grid on that ray, each
// call held to its contract: chapter 07's walk of grid g over the part asked, a cell without a grid
// of its own asked as 07.6 asks it, a cell with one by that grid's walk over the part of the ray
// inside the cell (from where the ray enters it to its cell_exit()), the first cell that keeps a
// hit ending the walk. The call that breaks it is named at the deepest level where it differs.
#pragma once

#include "10_hierarchies/hgrid.hpp"
#include "tests/ch07/grid_suspect.hpp"

namespace rt::grader::suspect {

// 10.5's promise for grid g over `part` (chapter 07's solutions for the walk and the cell).
inline bool hgrid_promised(const HGrid& h, int g, const Ray& ray, Interval part, Interval range, const Objects& objects, ObjectHit& best)
{
    const GridNode& node = h.grids[static_cast<size_t>(g)];
    GridWalk w = start_walk(node.grid.shape, ray, part);
    if (w.missed)
        return false;
    do {
        const int child = node.child[static_cast<size_t>(w.p)];
        const bool kept = child < 0 ? closest_in_cell(node.grid, w, ray, range, objects, best)
                                    : hgrid_promised(h, child, ray, Interval{w.t_enter, w.cell_exit()}, range, objects, best);
        if (kept)
            return true;
    } while (next_cell(w));
    return false;
}

// The deepest call of 10.5 under grid g whose answer breaks its promise, in words ("" when none).
inline std::string hgrid_differs(const HGrid& h, int g, int level, const Ray& ray, Interval part, Interval range, const Objects& objects,
                                 const ObjectHit& before)
{
    ObjectHit got_best = before, want_best = before;
    const bool got = hgrid_closest(h, g, ray, part, range, objects, got_best);
    const bool want = hgrid_promised(h, g, ray, part, range, objects, want_best);
    if (got == want && (!want || (got_best.object == want_best.object && got_best.t == want_best.t)))
        return "";
    // Is a child's call the one that differs? Walk grid g as promised and ask each child grid met.
    const GridNode& node = h.grids[static_cast<size_t>(g)];
    GridWalk w = start_walk(node.grid.shape, ray, part);
    ObjectHit best = before;
    if (!w.missed)
        do {
            const int child = node.child[static_cast<size_t>(w.p)];
            if (child >= 0) {
                const std::string deeper = hgrid_differs(h, child, level + 1, ray, Interval{w.t_enter, w.cell_exit()}, range, objects, best);
                if (!deeper.empty())
                    return deeper;
            }
            const bool kept = child < 0 ? closest_in_cell(node.grid, w, ray, range, objects, best)
                                        : hgrid_promised(h, child, ray, Interval{w.t_enter, w.cell_exit()}, range, objects, best);
            if (kept)
                break;
        } while (next_cell(w));
    std::ostringstream s;
    s << "hgrid_closest(grid " << g << " at level " << level << ", part " << show_range(part) << ", best so far " << show(before) << ") returned "
      << (got ? "true, " + show(got_best) : "false") << "; its contract promises " << (want ? "true, " + show(want_best) : "false")
      << " (its cells in the ray's order, a cell's grid walked over the ray's part inside that cell only, the first cell that keeps a hit ending the walk)";
    return s.str();
}

inline std::string diagnose_hgrid(const HGrid& h, const Ray& ray, Interval range, const Objects& objects)
{
    Diagnosis d;
    d.exercised = "10.5 (with chapter 07's grid, walk and cell query)";
    d.check("10.5", "hgrid_closest");
    if (h.grids.empty())
        return d.text();
    const std::string differs = hgrid_differs(h, 0, 0, ray, range, range, objects, ObjectHit{});
    if (!differs.empty())
        d.fail("10.5", "hgrid_closest", differs);
    return d.text();
}

}  // namespace rt::grader::suspect
