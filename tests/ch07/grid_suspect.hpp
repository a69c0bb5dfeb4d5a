// Chapter 07's diagnosis of one ray the grid answers differently from brute force (suspect.hpp):
// the grid's exercises run again on that ray, each held to its own contract, in the order the
// query uses them:
//  - the lists (07.3, with 07.2 at the corners): every object the ray hits within its range is
//    given the block of cells its grown box overlaps, as 07.2 places the box's corners;
//  - the walk's setup (07.4, with 07.2 at the entry point): missed as the slab test says, standing
//    in the cell holding the entry point, every field as its contract says (t_first and t_delta
//    within 1e-12 of double's quotients, the rest bit for bit);
//  - the walk, cell by cell: the cell's query (07.6) answers as brute force over that cell's list
//    does, restricted to the cell's part of the ray (up to cell_exit()), against the best so far,
//    and each step (07.5) goes through the face reached first, into the neighbour, with
//    boundary_t's next boundary, or stops, unchanged, at t_end.
// Chapters 08-10 reuse the walk's checks (check_start, check_step) and the cell's reference.
#pragma once

#include "07_uniform_grid/grid.hpp"
#include "tests/ch07/describe.hpp"
#include "tests/ch07/suspect.hpp"

#include <cmath>
#include <optional>
#include <sstream>
#include <string>

namespace rt::grader::suspect {

inline std::string show_range(Interval r)
{
    std::ostringstream s;
    s.precision(9);
    s << "(" << r.min << ", " << r.max << ")";
    return s.str();
}

inline std::string show_t(float t)
{
    std::ostringstream s;
    s.precision(9);
    s << t;
    return s.str();
}

// 07.2's promise: the cell holding p, cells half-open from the grid's own box.min and cell_size,
// clamped into the grid while still a float.
inline cell3 cell_promised(const GridShape& g, const point3& p)
{
    cell3 c;
    for (int a = 0; a < 3; ++a) {
        const float i = std::floor((p[a] - g.box.min[a]) / g.cell_size[a]);
        c[a] = static_cast<int>(std::clamp(i, 0.0f, static_cast<float>(g.n[a] - 1)));
    }
    return c;
}

// 07.2 on one point: false (and the finding) when it breaks its promise.
inline bool check_cell_of(Diagnosis& d, const GridShape& g, const point3& p, const char* which)
{
    d.check("07.2", "cell_of");
    const cell3 got = cell_of(g, p), want = cell_promised(g, p);
    if (got == want)
        return true;
    d.fail("07.2", "cell_of", std::string("for ") + which + " " + show(p) + " in " + show(g) + " it returned cell " +
                                  show(got) + "; its contract promises " + show(want) +
                                  " (cells half-open, a point outside in the nearest cell inside)");
    return false;
}

// 07.4's promise for `ray` over `range` in `g`, standing in cell c (the cell its own 07.2 gives
// the entry point). t_end is taken from the walk's own t_first and t_delta (`own`), as the
// contract says: boundary_t's value for the face.
inline GridWalk start_promised(const GridShape& g, const Ray& ray, Interval range, const cell3& c, const Interval& inside,
                               const GridWalk& own)
{
    GridWalk w;
    w.missed = false;
    w.p = g.address(c);
    w.t_enter = inside.min;
    w.t_range = range.max;
    w.t_end = range.max;
    const cell3 stride = g.strides();
    for (int a = 0; a < 3; ++a) {
        const float dir = ray.dir[a];
        if (dir == 0.0f)
            continue;
        const float s = g.cell_size[a];
        const bool up = dir > 0.0f;
        const float boundary = g.box.min[a] + static_cast<float>(up ? c[a] + 1 : c[a]) * s;
        w.step_p[a] = up ? stride[a] : -stride[a];
        w.t_delta[a] = static_cast<double>(s) / std::abs(static_cast<double>(dir));
        w.t_first[a] = (static_cast<double>(boundary) - ray.origin[a]) / dir;
        w.t_max[a] = static_cast<float>(own.t_first[a]);
        const int to_face = up ? g.n[a] - 1 - c[a] : c[a];
        w.t_end = std::min(w.t_end, boundary_t(own, a, to_face));
    }
    return w;
}

// 07.4 (with 07.2 at the entry point) on the ray: the walk it starts, or nullopt when it breaks
// its promise (or misses, as it should: then `missed` is set).
inline std::optional<GridWalk> check_start(Diagnosis& d, const GridShape& g, const Ray& ray, Interval range, bool& missed)
{
    missed = false;
    const std::optional<Interval> inside = hit_bounds(g.box, ray, range);
    if (inside && !check_cell_of(d, g, ray.at(inside->min), "the entry point"))
        return std::nullopt;
    d.check("07.4", "start_walk");
    const GridWalk got = start_walk(g, ray, range);
    if (!inside) {
        missed = true;
        if (!got.missed)
            d.fail("07.4", "start_walk", "it started a walk at p = " + std::to_string(got.p) + "; its contract promises a missed walk: the ray meets " + show(g.box) + " nowhere in " + show_range(range));
        return std::nullopt;
    }
    const GridWalk want = start_promised(g, ray, range, cell_of(g, ray.at(inside->min)), *inside, got);
    const std::string differs = first_difference(got, want, 1e-12);
    if (!differs.empty()) {
        d.fail("07.4", "start_walk", "on " + show(g) + ", t in " + show_range(range) + ", " + differs +
                                         " (t_first and t_delta within 1e-12 of double's quotients, the rest bit for bit)");
        return std::nullopt;
    }
    return got;
}

// 07.5 on one step from `before` (a walk that kept every promise so far): the walk it leaves, and
// whether it stepped; nullopt when it broke its promise.
inline std::optional<std::pair<GridWalk, bool>> check_step(Diagnosis& d, const GridWalk& before)
{
    d.check("07.5", "next_cell");
    GridWalk got = before;
    const bool stepped = next_cell(got);
    const float next = std::min({before.t_max[0], before.t_max[1], before.t_max[2]});
    std::ostringstream at;
    at.precision(9);
    at << "from p = " << before.p << " (t_max (" << before.t_max[0] << ", " << before.t_max[1] << ", " << before.t_max[2]
       << "), t_end " << before.t_end << ")";
    if (!(next < before.t_end)) {
        const std::string differs = first_difference(got, before);
        if (stepped || !differs.empty())
            d.fail("07.5", "next_cell", at.str() + " it " + (stepped ? "stepped to p = " + std::to_string(got.p) : "changed " + differs) +
                                            "; its contract promises false, the walk unchanged: the next face is not before t_end");
        if (d.failed())
            return std::nullopt;
        return std::make_pair(got, false);
    }
    std::string first_differs;
    for (int a = 0; a < 3; ++a) {
        if (!(before.t_max[a] == next) || before.step_p[a] == 0)
            continue;
        GridWalk want = before;
        want.t_enter = next;
        want.p += want.step_p[a];
        ++want.steps[a];
        want.t_max[a] = boundary_t(want, a, want.steps[a]);
        const std::string differs = first_difference(got, want);
        if (stepped && differs.empty())
            return std::make_pair(got, true);
        if (first_differs.empty())
            first_differs = stepped ? "stepped, but " + differs : std::string("returned false");
    }
    d.fail("07.5", "next_cell", at.str() + " it " + first_differs + "; its contract promises the step through the face reached first (t = " + show_t(next) +
                                    "), t_max of that axis boundary_t's next boundary");
    return std::nullopt;
}

// The cell query's promise (07.6, and 08.3, 09.5 on their lists): of the objects `list` names,
// the nearest hit within `range` that beats `best` and lies no farther than `exit`. Returns
// whether best changed.
template <class List>
bool cell_query_promised(const List& list, const Ray& ray, Interval range, float exit, const Objects& objects, ObjectHit& best)
{
    bool found = false;
    for (const std::uint32_t object : list) {
        const int k = static_cast<int>(object);
        ObjectHit hit;
        if (objects.intersect(k, ray, closer_than(range, best, k), hit) && hit.t <= exit) {
            best = hit;
            found = true;
        }
    }
    return found;
}

// A cell query's answer against its promise, in words ("" when they agree).
inline std::string cell_differs(bool got, const ObjectHit& got_best, bool want, const ObjectHit& want_best, const GridWalk& w,
                                const ObjectHit& before, size_t listed)
{
    if (got == want && (!want || (got_best.object == want_best.object && got_best.t == want_best.t)))
        return "";
    std::ostringstream s;
    s.precision(9);
    s << "in cell p = " << w.p << " (" << listed << " objects listed, the ray in it from t = " << w.t_enter << " to its exit "
      << w.cell_exit() << "), the best so far " << show(before) << ", it returned " << (got ? "true, " + show(got_best) : "false")
      << "; its contract promises " << (want ? "true, " + show(want_best) : "false (no listed object hit within the cell beats the best)");
    return s.str();
}

// The objects `ray` hits within `range`, by brute force.
inline std::vector<int> objects_hit(const Ray& ray, Interval range, const Objects& objects)
{
    std::vector<int> hit;
    for (int k = 0; k < objects.size(); ++k) {
        ObjectHit h;
        if (objects.intersect(k, ray, range, h))
            hit.push_back(k);
    }
    return hit;
}

// 07.3 (with 07.2 at the corners) for the objects the ray hits: false when one breaks its promise.
inline bool check_lists(Diagnosis& d, const GridShape& g, const Ray& ray, Interval range, const Objects& objects,
                        const Margins& margins)
{
    for (const int k : objects_hit(ray, range, objects)) {
        const Bounds box = grown(objects.bounds(k), vec3(margins.of(objects.bounds(k))) + grid_rounding(g));
        d.check("07.3", "cells_overlapping");
        const CellRange got = cells_overlapping(g, box);
        const cell3 first = cell_promised(g, box.min), last = cell_promised(g, box.max);
        if (got.first == first && got.last == last)
            continue;
        if (!check_cell_of(d, g, box.min, "the min corner of an object's box,") || !check_cell_of(d, g, box.max, "the max corner of an object's box,"))
            return false;
        d.fail("07.3", "cells_overlapping", "for object " + std::to_string(k) + " (hit by the ray), " + show(box) + " (its box grown by the grid's margin) in " + show(g) +
                                                ", it returned cells " + show(got.first) + " to " + show(got.last) + "; its contract promises " +
                                                show(first) + " to " + show(last) + " (the cells holding its corners, a box ending on a boundary in the cell beyond)");
        return false;
    }
    return true;
}

// Chapter 07's diagnosis of a grid whose build failed (it asked for too many cells): 07.1 on the
// box and count the build gives it.
inline std::string diagnose_grid_build(const Objects& objects, float lambda)
{
    Diagnosis d;
    d.exercised = "07.1-07.3 (the build)";
    d.subject = "the build's box and count";
    d.check("07.1", "grid_resolution");
    const Bounds box = resolution_box(bounds_of_all(objects));
    const cell3 got = grid_resolution(box, objects.size(), lambda);
    // 07.1's promise as a bound: a cut axis is wider than s and gets round(extent / s) cells, at most
    // 1.5 extent / s, so the cut axes hold at most 1.5^3 lambda N cells, the others 1 each.
    const double cells = static_cast<double>(got.x) * got.y * got.z;
    const double most = 3.375 * static_cast<double>(lambda) * objects.size() + 1.0;
    if (!(cells <= most)) {
        std::ostringstream s;
        s.precision(9);
        s << "for " << show(box) << ", " << objects.size() << " objects at lambda " << lambda << " it returned " << show(got)
          << " cells, " << cells << " in all; its contract promises about lambda N = " << lambda * objects.size()
          << " (each axis wider than s rounds extent / s, so never more than " << most << ")";
        d.fail("07.1", "grid_resolution", s.str());
    }
    return d.text();
}

// Chapter 07's diagnosis of `ray` over `range` through the grid `grid` built over `objects`.
inline std::string diagnose_grid(const UniformGrid& grid, const Ray& ray, Interval range, const Objects& objects)
{
    Diagnosis d;
    d.exercised = "07.1-07.6 (07.1 the resolution, 07.2-07.3 the lists, 07.4-07.5 the walk, 07.6 the cell's query)";
    const Grid& g = grid.grid();
    const GridShape& shape = g.shape;
    if (!check_lists(d, shape, ray, range, objects, margins_of(objects)))
        return d.text();
    bool missed = false;
    std::optional<GridWalk> w = check_start(d, shape, ray, range, missed);
    if (!w)
        return d.text();
    ObjectHit best;
    for (int steps = 0; steps < (1 << 16); ++steps) {
        if (w->p < 0 || w->p >= shape.cell_count())
            break;  // check_step has failed before
        d.check("07.6", "closest_in_cell");
        const std::vector<std::uint32_t> list(g.object_index.begin() + g.cell_start[w->p], g.object_index.begin() + g.cell_start[w->p + 1]);
        ObjectHit got_best = best, want_best = best;
        const bool got = closest_in_cell(g, *w, ray, range, objects, got_best);
        const bool want = cell_query_promised(list, ray, range, w->cell_exit(), objects, want_best);
        const std::string differs = cell_differs(got, got_best, want, want_best, *w, best, list.size());
        if (!differs.empty()) {
            d.fail("07.6", "closest_in_cell", differs);
            break;
        }
        if (want)
            break;  // the query ends at the first cell that keeps a hit
        const auto step = check_step(d, *w);
        if (!step || !step->second)
            break;
        w = step->first;
    }
    return d.text();
}

}  // namespace rt::grader::suspect
