// Chapter 07's tests in words, and their oracle: every cell a ray's segment crosses, found by a
// slab test against each cell's own box in double precision and sorted by t, to hold the walk
// (EXERCISES 07.4 and 07.5) against.
#pragma once

#include "07_uniform_grid/grid.hpp"
#include "tests/grader/graded.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace rt::grader {

inline std::string show(const cell3& c)
{
    std::ostringstream s;
    s << '(' << c.x << ", " << c.y << ", " << c.z << ')';
    return s.str();
}

inline std::string show(const Bounds& b) { return "the box from " + show(b.min) + " to " + show(b.max); }

inline std::string show(const GridShape& g)
{
    return "the grid of " + show(g.n) + " cells over " + show(g.box);
}

inline std::string show(const GridWalk& w)
{
    std::ostringstream s;
    s.precision(9);
    if (w.missed)
        return "a missed walk";
    s << "the walk at p = " << w.p << ", step_p = (" << w.step_p[0] << ", " << w.step_p[1] << ", " << w.step_p[2]
      << "), t_first = (" << w.t_first[0] << ", " << w.t_first[1] << ", " << w.t_first[2] << "), t_delta = ("
      << w.t_delta[0] << ", " << w.t_delta[1] << ", " << w.t_delta[2] << "), steps = (" << w.steps[0] << ", "
      << w.steps[1] << ", " << w.steps[2] << "), t_max = (" << w.t_max[0] << ", " << w.t_max[1] << ", " << w.t_max[2]
      << "), t_enter = " << w.t_enter << ", t_end = " << w.t_end << ", t_range = " << w.t_range;
    return s.str();
}

// The first field in which two walks differ, in words ("t_max[1]: got 1.75, expected 2.75"), or ""
// when they agree in every field (a NaN agrees with a NaN): so a failing case names what differs.
// t_first and t_delta, doubles, may differ by `relative` of the expected value (0: not at all).
inline std::string first_difference(const GridWalk& got, const GridWalk& expected, double relative = 0.0)
{
    std::ostringstream s;
    s.precision(17);
    const auto differ = [](double a, double b) { return !(a == b || (std::isnan(a) && std::isnan(b))); };
    const auto differ_by = [&](double a, double b) {
        return differ(a, b) && !(std::isfinite(b) && std::abs(a - b) <= relative * std::abs(b));
    };
    const auto field = [&](const char* name, int axis, double a, double b) {
        if (axis >= 0)
            s << name << '[' << axis << "]: got " << a << ", expected " << b;
        else
            s << name << ": got " << a << ", expected " << b;
        return s.str();
    };
    if (got.missed != expected.missed)
        return field("missed", -1, got.missed, expected.missed);
    if (got.p != expected.p)
        return field("p", -1, got.p, expected.p);
    for (int a = 0; a < 3; ++a) {
        if (got.step_p[a] != expected.step_p[a])
            return field("step_p", a, got.step_p[a], expected.step_p[a]);
        if (got.steps[a] != expected.steps[a])
            return field("steps", a, got.steps[a], expected.steps[a]);
        if (differ_by(got.t_first[a], expected.t_first[a]))
            return field("t_first", a, got.t_first[a], expected.t_first[a]);
        if (differ_by(got.t_delta[a], expected.t_delta[a]))
            return field("t_delta", a, got.t_delta[a], expected.t_delta[a]);
        if (differ(got.t_max[a], expected.t_max[a]))
            return field("t_max", a, got.t_max[a], expected.t_max[a]);
    }
    if (differ(got.t_enter, expected.t_enter))
        return field("t_enter", -1, got.t_enter, expected.t_enter);
    if (differ(got.t_end, expected.t_end))
        return field("t_end", -1, got.t_end, expected.t_end);
    if (differ(got.t_range, expected.t_range))
        return field("t_range", -1, got.t_range, expected.t_range);
    return "";
}

inline std::string show(const std::vector<int>& cells)
{
    std::ostringstream s;
    s << '[';
    for (size_t k = 0; k < cells.size() && k < 24; ++k)
        s << (k ? ", " : "") << cells[k];
    if (cells.size() > 24)
        s << ", ... (" << cells.size() << " cells)";
    s << ']';
    return s.str();
}

inline std::string show(const ObjectHit& h)
{
    if (h.object < 0)
        return "no hit";
    std::ostringstream s;
    s.precision(9);
    s << "object " << h.object << " at t = " << h.t;
    return s.str();
}

// The objects of these arrays, which must outlive the view, tested as the lit chapters test them
// (the precise sphere, the watertight triangle): the hand-built cases of chapters 07-10.
inline Objects objects_over(const std::vector<Sphere>& spheres, const std::vector<Triangle>& triangles)
{
    Objects o;
    o.spheres = spheres.data();
    o.sphere_count = static_cast<int>(spheres.size());
    o.triangles = triangles.data();
    o.triangle_count = static_cast<int>(triangles.size());
    o.tests = {SphereTest::precise, TriangleTest::watertight};
    return o;
}

// A cell the segment crosses: its address and the t where the ray enters and leaves it.
struct CrossedCell {
    int p;
    double t_in, t_out;
};

// Cells shorter than this along the ray (in cells) are where the ray passes within rounding of an
// edge or a corner: which of the cells there a float walk visits is rounding's choice.
constexpr double negligible_cells = 1e-4;

// The oracle: the cells whose half-open boxes [lo, hi) the segment [range.min, range.max] of the ray
// spends more than negligible_cells inside, sorted by t. A ray lying in a boundary plane (a zero
// component) belongs to the cell above that plane, as cell_of's floor says, except on the box's
// far face, which belongs to the last cell.
inline std::vector<CrossedCell> cells_crossed(const GridShape& g, const Ray& ray, Interval range)
{
    std::vector<CrossedCell> crossed;
    const dvec3 o(ray.origin), d(ray.dir);
    double min_size = g.cell_size.x;
    for (int a = 1; a < 3; ++a)
        min_size = std::min(min_size, static_cast<double>(g.cell_size[a]));
    const double speed = glm::length(d);
    for (int i = 0; i < g.n.x; ++i)
        for (int j = 0; j < g.n.y; ++j)
            for (int k = 0; k < g.n.z; ++k) {
                const cell3 c(i, j, k);
                double t0 = range.min, t1 = range.max;
                bool inside = true;
                for (int a = 0; a < 3 && inside; ++a) {
                    const double lo = static_cast<double>(g.box.min[a]) + c[a] * static_cast<double>(g.cell_size[a]);
                    const double hi = c[a] + 1 == g.n[a]
                                          ? static_cast<double>(g.box.max[a])
                                          : static_cast<double>(g.box.min[a]) + (c[a] + 1) * static_cast<double>(g.cell_size[a]);
                    if (d[a] == 0.0) {
                        inside = lo <= o[a] && (o[a] < hi || (c[a] + 1 == g.n[a] && o[a] == hi));
                        continue;
                    }
                    double ta = (lo - o[a]) / d[a], tb = (hi - o[a]) / d[a];
                    if (ta > tb)
                        std::swap(ta, tb);
                    t0 = std::max(t0, ta);
                    t1 = std::min(t1, tb);
                }
                if (inside && (t1 - t0) * speed > negligible_cells * min_size)
                    crossed.push_back({g.address(c), t0, t1});
            }
    std::sort(crossed.begin(), crossed.end(), [](const CrossedCell& a, const CrossedCell& b) { return a.t_in < b.t_in; });
    return crossed;
}

inline std::vector<int> addresses(const std::vector<CrossedCell>& cells)
{
    std::vector<int> p;
    for (const CrossedCell& c : cells)
        p.push_back(c.p);
    return p;
}

// What the walk visits (start_walk, then next_cell until it returns false), as crossed cells,
// leaving out those it crosses for less than negligible_cells; at most `limit` steps, so a walk
// that never ends fails instead of hanging. `outside` is set when an address leaves the grid.
inline std::vector<CrossedCell> cells_walked(const GridShape& g, const Ray& ray, Interval range, bool& outside,
                                             int limit = 1 << 20)
{
    std::vector<CrossedCell> walked;
    outside = false;
    GridWalk w = start_walk(g, ray, range);
    if (w.missed)
        return walked;
    double min_size = g.cell_size.x;
    for (int a = 1; a < 3; ++a)
        min_size = std::min(min_size, static_cast<double>(g.cell_size[a]));
    const double speed = glm::length(dvec3(ray.dir));
    for (int steps = 0; steps < limit; ++steps) {
        if (w.p < 0 || w.p >= g.cell_count()) {
            outside = true;
            return walked;
        }
        const double t_in = std::max(static_cast<double>(w.t_enter), static_cast<double>(range.min));
        // Where the ray leaves the cell: the next boundary, or the walk's end in the last cell.
        const float leave = std::min({w.t_max[0], w.t_max[1], w.t_max[2], w.t_end});
        const double t_out = std::min(static_cast<double>(leave), static_cast<double>(range.max));
        if ((t_out - t_in) * speed > negligible_cells * min_size)
            walked.push_back({w.p, t_in, t_out});
        if (!next_cell(w))
            return walked;
    }
    return walked;
}

}  // namespace rt::grader
