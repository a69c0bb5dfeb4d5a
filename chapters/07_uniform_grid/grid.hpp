// The uniform grid as an accelerator (given): built from EXERCISES 07.1-07.3, queried with
// 07.4-07.6, and plugged into the scene's queries (scene_query.hpp) in place of brute force.
//
// The build, in two passes over the objects (a counting sort, so the cell lists are two flat
// arrays and not a vector per cell): count each cell's objects, turn the counts into offsets
// (cell_start), then write each object's number into every cell it overlaps. Objects go in by
// increasing number, so every cell lists them in that order.
#pragma once

#include "02_spheres_triangles/scene_query.hpp"
#include "07_uniform_grid/07_uniform_grid.hpp"
#include "common/error.hpp"
#include "common/notice.hpp"
#include "common/stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <numeric>
#include <string>
#include <utility>

namespace rt {

// Why each object's box grows by a margin: a hit's t carries its test's rounding, so the point
// o + t d it stands for can lie a little outside the object's own box, and the walk's cell
// boundaries and the slab test's t are rounded too. Brute force reports such a hit; a structure must
// meet the object's box (or a cell listing it) at that t as well.
//
// How much: each of those roundings is a relative error of u = 2^-24 of the magnitudes it combines
// (Goldberg's model, as pbrt's error bounds count it: Pharr, Jakob and Humphreys, "Physically Based
// Rendering", 3rd ed., sec. 3.9, 4th ed., sec. 6.8), and the magnitudes are distances from the ray's
// origin o to the point p and the coordinates of p and of the box: a t measures |p - o|, never the
// scene's size.
//  - the sphere test (02.2) works in double and rounds t to float once: 1 float step of t, 2u |p - o|;
//  - the watertight test (02.5) gives t as a weighted mean of the corners' heights along the ray,
//    each carrying a few roundings (shape_tests.hpp, after pbrt sec. 3.9.6): about 9u of the
//    corners' distance from o, at most |p - o| plus the triangle's own size;
//  - the slab test's near t, (plane - o) / d, three roundings: 3u |p - o| (its far t is widened
//    already: Ize, "Robust BVH Ray Traversal", 2013, bounds.hpp);
//  - the box itself (its corners rounded from a centre and radius, then grown), the walk's first
//    point o + t d and a grid's cell numbers ((p - min) / s): a few u of the coordinates, |p| and
//    |o| (the grid's own part, u of its extent, is grid_rounding's).
// Together about 16 of them, so the margin is 2^-20 (|p| + D): |p| the object's own largest coordinate
// magnitude, D the farthest a covered ray's origin lies from the object's points on any axis (which
// bounds |p - o|, and |o| by |p| + D). D is the width of the box around the object and the rays'
// reach (Margins, below): the bulk of the scene and 4 of its widths around it, where surfaces and an
// eye that frames the scene lie. Where the origin lies outside the reach, no margin is promised: such
// a ray gets brute force's answer (Margins::covers), unless it passes the reach farther off than its
// hits there could round. An eye 1e6 times the scene's size away rounds a hit's t by a good part of
// the scene, and sorting objects apart along its rays sorts nothing. Why not the scene's box for D,
// as once: one far object (a sphere 1e4 away from a cluster 0.01 across, a floor 1e6 across under it)
// then widens every margin near the origin past the cluster's objects, and no cell or node can sort
// them apart; and an eye outside that box was covered only by the slack in the 16.
constexpr float margin_roundings = 0x1p-20f;  // 16 u

// Why 8: the reach is built around the box of the scene's bulk, its objects but the 8 farthest on each
// side of each axis (or 1 in 100 of them, when that is fewer), so that a few far objects (a sphere 1e4
// away, a huge floor) do not decide it. A part of the scene made of many objects (a stadium around a
// teapot, where the eye stands) stays in the bulk: rays start there.
constexpr int reach_outliers = 8;

// Why 4 widths: rays start on the scene's surfaces, inside the bulk's box, or at an eye that frames
// the bulk; a view of the bulk at a field of view of 15 degrees or more stands within 4 of its widths.
// An eye farther out costs brute force's tests for its rays, never a wrong answer; a larger reach
// costs every object a wider margin.
constexpr float reach_widths = 4.0f;

// Why 1 << 25 cells (32 Mi, 128 MB of offsets): a dense grid pays for every cell, empty or not;
// past this the build would take seconds and most of the machine's memory for one scene. A lambda
// that asks for more is refused: the number is the user's.
constexpr long long max_grid_cells = 1LL << 25;

// Why 2^26 references (256 MB of object numbers): the most a grid of this chapter's scenes lists
// (a few per object, a few hundred for long thin ones) for scenes of up to millions of objects; past
// it a build takes seconds and gigabytes.
constexpr long long max_grid_references = 1LL << 26;

// Whether a grid of `shape` holding `references` earns its keep over `objects` objects: a ray
// crosses about (n_x + n_y + n_z) / 3 of its cells (chapter 10's hierarchy of grids weighs its
// children the same way), each listing references / cells objects on average, and brute force
// tests every object once. A grid whose walk would test more than that is sorting nothing apart:
// objects as large as the scene (a thousand spheres at one point, or each around all the others)
// are listed in every cell, the references grow as objects times cells (4e8 for 10,000 such spheres
// at chapter 07's density), and a ray pays for the whole list in every cell it crosses.
// Below grid_pays_floor tests a ray, brute force is cheap whatever a grid does: a scene of a few
// objects keeps the grid it asks for.
constexpr double grid_pays_floor = 64.0;

inline bool grid_pays(const GridShape& shape, long long references, long long objects)
{
    const double crossed = (shape.n.x + shape.n.y + shape.n.z) / 3.0;
    const double tests = crossed * static_cast<double>(references) / static_cast<double>(shape.cell_count());
    return references <= max_grid_references && tests <= std::max(grid_pays_floor, static_cast<double>(objects));
}

// Why 2^-20 of the largest extent: an axis that thin is a flat scene's thickness (its objects' boxes
// widened by a float step each way), not room for cells.
constexpr float flat_thickness = 0x1p-20f;

// The box the cube-root rule (07.1) is given: the scene's, with an axis thinner than flat_thickness
// made exactly flat, and scaled by a power of two (exact in float) so that its largest side lies in
// [0.5, 1). The rule depends only on the box's proportions, but it multiplies the sides into a
// volume in float: a flat scene at the coordinate 0 (a thickness of two denormals) or a scene 1e-15
// across would underflow to a volume of 0 and ask for cells of size 0, one 1e13 across overflow.
inline Bounds resolution_box(const Bounds& box)
{
    if (box.empty())
        return box;
    const vec3 e = box.extent();
    const float largest = std::max({e.x, e.y, e.z});
    if (!(largest > 0.0f) || !std::isfinite(largest))
        return box;
    int exponent = 0;
    std::frexp(largest, &exponent);
    const float scale = std::ldexp(1.0f, -exponent);
    Bounds b{point3(0.0f), e * scale};
    for (int a = 0; a < 3; ++a)
        if (e[a] <= flat_thickness * largest)
            b.max[a] = 0.0f;
    return b;
}

// What the grid's build reports (--stats, the trade tables).
struct GridStats {
    int objects = 0;
    cell3 resolution{1};
    float lambda = 0.0f;  // the lambda built with: the one asked for, or lower (plan_grid)
    long long cells = 0;
    long long references = 0;
    long long empty_cells = 0;
    std::size_t bytes = 0;
    double build_seconds = 0.0;
};

// The largest coordinate magnitude of a box's corners (0 for an empty box).
inline float magnitude(const Bounds& b)
{
    if (b.empty())
        return 0.0f;
    const vec3 m = glm::max(glm::abs(b.min), glm::abs(b.max));
    return std::max({m.x, m.y, m.z});
}

inline Bounds grown(const Bounds& b, const vec3& margin)
{
    return {b.min - margin, b.max + margin};
}

inline Bounds grown(const Bounds& b, float margin)
{
    return grown(b, vec3(margin));
}

// Whether box `b` lies within box `in`.
inline bool inside(const Bounds& b, const Bounds& in)
{
    return b.min.x >= in.min.x && b.min.y >= in.min.y && b.min.z >= in.min.z && b.max.x <= in.max.x &&
           b.max.y <= in.max.y && b.max.z <= in.max.z;
}

// The margins of a scene's objects (margin_roundings above), and the rays they cover. An object inside
// `reach` (the scene's bulk, reach_widths of its width around it) grows by 2^-20 (its own magnitude +
// the width of the box around it and the reach): every ray that starts in the reach is covered. An
// object outside it (a far sphere, a huge floor: a few at most) grows by the same with `wide` (the
// whole scene's box, reach_widths of its width around it) for the reach, so a ray that starts in the
// wide box is covered for those objects; it is covered for the bulk's too when it passes the reach
// farther from them than the rounding its hits there would carry (covers). Every structure of chapters
// 07-10 grows its objects' boxes by these, and answers a ray they do not cover with brute force
// (MarginedAccelerator, below). The default reaches everywhere: the margins of a grid built by hand
// (the tests') are never asked.
struct Margins {
    Bounds reach{point3(-infinity), point3(infinity)};
    Bounds wide{point3(-infinity), point3(infinity)};

    float of(const Bounds& object) const
    {
        Bounds both = object;
        both.grow(inside(object, reach) ? reach : wide);
        const vec3 e = both.extent();
        return margin_roundings * (magnitude(object) + std::max({e.x, e.y, e.z}));
    }

    // Whether the margins cover `ray` over `range`: it starts in the reach, or in the wide box on a
    // line that stays off the reach's box by more than a bulk object's margin for this origin would be
    // (the margin of the reach grown to the origin; worked out in double, so its own rounding is
    // nothing beside it). False for a NaN origin.
    bool covers(const Ray& ray, Interval range) const
    {
        if (contains(reach, ray.origin))
            return true;
        if (!contains(wide, ray.origin))
            return false;
        Bounds with_origin = reach;
        with_origin.grow(ray.origin);
        const vec3 e = with_origin.extent();
        const double off = 2.0 * margin_roundings * (magnitude(reach) + std::max({e.x, e.y, e.z}));
        double near = range.min, far = range.max;
        for (int a = 0; a < 3; ++a) {
            const double o = ray.origin[a], d = ray.dir[a];
            const double lo = reach.min[a] - off, hi = reach.max[a] + off;
            if (d == 0.0) {
                if (o < lo || o > hi)
                    return true;  // parallel to the slab, outside it: the line never meets the reach
                continue;
            }
            const double t0 = (lo - o) / d, t1 = (hi - o) / d;
            near = std::max(near, std::min(t0, t1));
            far = std::min(far, std::max(t0, t1));
        }
        return near > far;
    }

    static bool contains(const Bounds& b, const point3& p)
    {
        return p.x >= b.min.x && p.x <= b.max.x && p.y >= b.min.y && p.y <= b.max.y && p.z >= b.min.z &&
               p.z <= b.max.z;
    }
};

// The box of the scene's bulk, from its objects' boxes: on each axis from the (q + 1)-th least of
// their minima to the (q + 1)-th greatest of their maxima, q the lesser of reach_outliers and 1 in 100
// of them (empty for none).
inline Bounds bulk_of(const std::vector<Bounds>& boxes)
{
    Bounds bulk;
    if (boxes.empty())
        return bulk;
    const std::size_t q = std::min(boxes.size() / 100, static_cast<std::size_t>(reach_outliers));
    // The q + 1 least minima and greatest maxima on each axis, in one pass: an array of at most
    // reach_outliers + 1, sorted, that most boxes pass with one comparison each, where six
    // nth_elements over copies of every coordinate cost the BVH's build more (chapters/benchmark/
    // README.md, "Chapter 10's steps", step 16).
    struct Least {
        float v[reach_outliers + 1];
        std::size_t n = 0;
        void offer(float x, std::size_t keep)
        {
            if (n == keep && !(x < v[n - 1]))
                return;
            std::size_t i = n < keep ? n++ : n - 1;
            for (; i > 0 && x < v[i - 1]; --i)
                v[i] = v[i - 1];
            v[i] = x;
        }
    };
    Least low[3], high[3];  // high: the maxima negated
    for (const Bounds& b : boxes)
        for (int a = 0; a < 3; ++a) {
            low[a].offer(b.min[a], q + 1);
            high[a].offer(-b.max[a], q + 1);
        }
    for (int a = 0; a < 3; ++a) {
        bulk.min[a] = low[a].v[q];
        bulk.max[a] = -high[a].v[q];
    }
    return bulk;
}

// A box grown by reach_widths of its largest width on every side.
inline Bounds reach_around(const Bounds& b)
{
    const vec3 e = b.extent();
    return grown(b, reach_widths * std::max({e.x, e.y, e.z}));
}

// The margins of the structures over objects whose boxes are `boxes` (objects.bounds(k), as they
// are, not grown): the reach around their bulk, the wide box around them all.
inline Margins margins_of(const std::vector<Bounds>& boxes)
{
    Bounds all;
    for (const Bounds& b : boxes)
        all.grow(b);
    const Bounds bulk = bulk_of(boxes);
    if (bulk.empty())
        return {Bounds{point3(0.0f), point3(0.0f)}, Bounds{point3(0.0f), point3(0.0f)}};
    return {reach_around(bulk), reach_around(all)};
}

// The margins of `objects`' structures.
inline Margins margins_of(const Objects& objects)
{
    std::vector<Bounds> boxes(static_cast<std::size_t>(objects.size()));
    for (int k = 0; k < objects.size(); ++k)
        boxes[static_cast<std::size_t>(k)] = objects.bounds(k);
    return margins_of(boxes);
}

// The seam every structure of chapters 07-10 answers through: a ray its margins cover (Margins::covers)
// gets the structure's own answer, any other ray brute force's, so no structure can forget the rays
// its margins promise nothing for. A structure sets margins_ at its build and gives closest_covered
// and any_covered. The check is not virtual, so that it inlines into every query.
class MarginedAccelerator : public Accelerator {
public:
    bool closest(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const final
    {
        return margins_.covers(ray, range) ? closest_covered(ray, range, objects, hit)
                                           : brute_force().closest(ray, range, objects, hit);
    }

    bool any(const Ray& ray, Interval range, const Objects& objects) const final
    {
        return margins_.covers(ray, range) ? any_covered(ray, range, objects) : brute_force().any(ray, range, objects);
    }

    const Margins& margins() const { return margins_; }

protected:
    MarginedAccelerator() = default;  // margins that reach everywhere: the tests' grids built by hand
    explicit MarginedAccelerator(const Margins& margins) : margins_(margins) {}

    virtual bool closest_covered(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const = 0;
    virtual bool any_covered(const Ray& ray, Interval range, const Objects& objects) const = 0;

    Margins margins_;
};

// The rounding of a grid's own cell decisions on each axis, to add to each object's margin where it
// is listed: 07.2's boundary i is where float's (p - min) / s reaches i, and the walk's boundary
// min + i s is taken in double; (p - min), its quotient by s, and s itself (an extent over n) each
// round by u, at most u of the grid's extent along that axis in space each: 3u, within 4u = 2^-22.
inline vec3 grid_rounding(const GridShape& shape)
{
    return 0x1p-22f * shape.box.extent();
}

// The cells each object's box, grown by its margin and the grid's own rounding, overlaps (07.3), and
// how many references they make in all: counted in 64 bits before anything is allocated.
inline long long object_cell_ranges(const GridShape& shape, const Objects& objects, const std::vector<std::uint32_t>& ids,
                                    const Margins& margins, std::vector<CellRange>& ranges)
{
    ranges.resize(ids.size());
    long long references = 0;
    for (std::size_t i = 0; i < ids.size(); ++i) {
        const Bounds box = objects.bounds(static_cast<int>(ids[i]));
        ranges[i] = cells_overlapping(shape, grown(box, vec3(margins.of(box)) + grid_rounding(shape)));
        const cell3 span = ranges[i].last - ranges[i].first + cell3(1);
        references += static_cast<long long>(std::max(span.x, 0)) * std::max(span.y, 0) * std::max(span.z, 0);
    }
    return references;
}

// The resolution `n` (07.1's for `box`, count objects, lambda) with the cells an axis held at
// max_per_axis could not take spread over the other axes: the cube-root rule gives every axis cells of
// one side s, and an axis far longer than the others (a sphere 1e4 away from a cluster 0.01 across)
// reaches the limit with cells far wider than s, leaving the others a few cells each: the cluster
// then lies in a few cells, and a ray through it tests more than brute force. The other axes get the
// rule's answer for the box without the held axes, lambda / (their cells) per object, so the grid
// still holds about lambda count cells, and no more than it holds already at 2^31 (an int address).
inline cell3 spread_past_limit(const Bounds& box, cell3 n, int count, float lambda, int max_per_axis)
{
    Bounds rest = box;
    double held = 1.0;
    for (int a = 0; a < 3; ++a)
        if (n[a] >= max_per_axis) {
            rest.max[a] = rest.min[a];
            held *= n[a];
        }
    if (held == 1.0 || held * 2.0 > static_cast<double>(lambda) * count)
        return n;
    const cell3 m = grid_resolution(resolution_box(rest), count, static_cast<float>(lambda / held), max_per_axis);
    cell3 spread = n;
    for (int a = 0; a < 3; ++a)
        if (n[a] < max_per_axis)
            spread[a] = std::max(n[a], m[a]);
    const double cells = static_cast<double>(spread.x) * spread.y * spread.z;
    return cells < 2147483648.0 ? spread : n;
}

// A grid's shape chosen for the objects `ids` in `box` (their union, not yet grown), lambda cells
// per object, with each object's cells: the shape the cube-root rule (07.1) gives, or, when that
// grid would not pay (grid_pays), the one of the densest lower lambda that does. A scene that asks
// for this is the scene's doing, not the user's: the build says so and goes on (say_lambda_lowered).
struct GridPlan {
    GridShape shape;
    std::vector<CellRange> ranges;
    long long references = 0;
    float lambda = 0.0f;             // the lambda built with
    long long asked_references = 0;  // at the lambda asked for, when it was lowered (else 0)
    cell3 asked_resolution{1};
};

inline GridPlan plan_grid(const Bounds& box, const Objects& objects, const std::vector<std::uint32_t>& ids, float lambda,
                          const Margins& margins, int max_per_axis)
{
    const int count = static_cast<int>(ids.size());
    GridPlan plan;
    plan.lambda = lambda;
    // Cells no finer than the margin at the box's own coordinates (the largest its objects get, and
    // the one the grid's box grows by): a cell smaller than the rounding the margin covers sorts
    // nothing apart, and each object would be listed in the (margin / cell)^3 cells around it. Only a
    // scene far from the origin for its size meets this (300 spheres 100 across at 1e7).
    const float margin = count > 0 ? margins.of(box) : 0.0f;
    const vec3 extent = box.extent();
    const float widest = std::max({extent.x, extent.y, extent.z});
    if (margin > 0.0f && widest / margin < static_cast<float>(max_per_axis))
        max_per_axis = std::max(1, static_cast<int>(widest / margin));
    for (;;) {
        const cell3 n = spread_past_limit(box, grid_resolution(resolution_box(box), count, plan.lambda, max_per_axis),
                                          count, plan.lambda, max_per_axis);
        plan.shape = grid_shape(count > 0 ? grown(box, margin) : Bounds{point3(0.0f), point3(1.0f)}, n);
        plan.references = object_cell_ranges(plan.shape, objects, ids, margins, plan.ranges);
        if (n == cell3(1) || grid_pays(plan.shape, plan.references, count))
            return plan;
        if (plan.asked_references == 0) {
            plan.asked_references = plan.references;
            plan.asked_resolution = n;
        }
        plan.lambda *= 0.5f;  // each try costs one pass over the objects: a few dozen at most
    }
}

// Lists the objects `ids` (in increasing number) in the cells of grid.shape given by `ranges` (one
// per object, from object_cell_ranges): a counting sort into grid.cell_start and grid.object_index.
// Chapter 10's hierarchy of grids lists a cell's objects in its child grid the same way.
inline void list_objects(Grid& grid, const std::vector<std::uint32_t>& ids, const std::vector<CellRange>& ranges)
{
    const GridShape& shape = grid.shape;
    const int cell_count = shape.cell_count();
    const auto for_each_cell = [&](const CellRange& r, auto&& visit) {
        for (int i = r.first.x; i <= r.last.x; ++i)
            for (int j = r.first.y; j <= r.last.y; ++j)
                for (int l = r.first.z; l <= r.last.z; ++l) {
                    const int p = shape.address({i, j, l});
                    if (p >= 0 && p < cell_count)  // a student's 07.3 may step outside the grid
                        visit(p);
                }
    };
    // Pass 1: how many objects each cell lists, as offsets.
    grid.cell_start.assign(static_cast<std::size_t>(cell_count) + 1, 0);
    for (const CellRange& r : ranges)
        for_each_cell(r, [&](int p) { ++grid.cell_start[p + 1]; });
    for (int p = 0; p < cell_count; ++p)
        grid.cell_start[p + 1] += grid.cell_start[p];
    // Pass 2: the object numbers, in increasing order within each cell.
    grid.object_index.resize(grid.cell_start[cell_count]);
    std::vector<std::uint32_t> fill(grid.cell_start.begin(), grid.cell_start.end() - 1);
    for (std::size_t i = 0; i < ids.size(); ++i)
        for_each_cell(ranges[i], [&](int p) { grid.object_index[fill[p]++] = ids[i]; });
}

// The notice (common/notice.hpp) a build gives when the scene made it lower lambda.
inline void say_lambda_lowered(const char* structure, const GridPlan& plan, float asked, int objects)
{
    if (plan.asked_references == 0)
        return;
    char line[640];
    std::snprintf(line, sizeof line,
                  "%s: at lambda %g (%d x %d x %d cells) its %d objects would be listed %lld times, %.0f each: their boxes "
                  "overlap too much for cells to sort them apart, and a ray would test more objects than brute force; "
                  "built at lambda %g instead (%d x %d x %d cells)",
                  structure, static_cast<double>(asked), plan.asked_resolution.x, plan.asked_resolution.y,
                  plan.asked_resolution.z, objects, plan.asked_references,
                  static_cast<double>(plan.asked_references) / std::max(1, objects), static_cast<double>(plan.lambda),
                  plan.shape.n.x, plan.shape.n.y, plan.shape.n.z);
    notice(line);
}

// The box around every object.
inline Bounds bounds_of_all(const Objects& objects)
{
    Bounds scene;
    for (int k = 0; k < objects.size(); ++k)
        scene.grow(objects.bounds(k));
    return scene;
}

// The plan (plan_grid) of a grid over every object of the scene's box `scene` with the objects'
// margins, up to max_per_axis cells an axis; a lambda lowered is said as a notice in the name of `structure`.
inline GridPlan plan_over_all(const Objects& objects, const Bounds& scene, const Margins& margins, float lambda,
                              int max_per_axis, const char* structure)
{
    const int count = objects.size();
    std::vector<std::uint32_t> all(static_cast<std::size_t>(count));
    std::iota(all.begin(), all.end(), 0u);
    const GridPlan plan = plan_grid(scene, objects, all, lambda, margins, max_per_axis);
    say_lambda_lowered(structure, plan, lambda, count);
    return plan;
}

// A built grid's statistics (GridStats), for `objects` objects built at `lambda` (0: 07.7's shape).
inline void grid_stats(const Grid& grid, int objects, float lambda, const Timer& timer, GridStats& stats)
{
    const int cell_count = grid.shape.cell_count();
    stats.objects = objects;
    stats.resolution = grid.shape.n;
    stats.lambda = lambda;
    stats.cells = cell_count;
    stats.references = static_cast<long long>(grid.object_index.size());
    stats.empty_cells = 0;
    for (int p = 0; p < cell_count; ++p)
        stats.empty_cells += grid.cell_start[p] == grid.cell_start[p + 1];
    stats.bytes = (grid.cell_start.size() + grid.object_index.size()) * sizeof(std::uint32_t);
    stats.build_seconds = timer.seconds();
}

// Builds the grid over every object, lambda cells per object (lowered where it would not pay), each
// object's box grown by its margin (`margins`, margins_of(objects)).
// Throws InputError when the resolution asked for would pass max_grid_cells.
inline Grid build_grid(const Objects& objects, const Margins& margins, float lambda, GridStats* stats = nullptr)
{
    const Timer timer;
    const int count = objects.size();
    const Bounds scene = bounds_of_all(objects);
    Grid grid;
    const cell3 n = grid_resolution(resolution_box(scene), count, lambda);
    const long long cells = static_cast<long long>(n.x) * n.y * n.z;
    if (cells > max_grid_cells)
        throw InputError("a grid of " + std::to_string(n.x) + " x " + std::to_string(n.y) + " x " + std::to_string(n.z) +
                         " cells (lambda " + std::to_string(lambda) + ", " + std::to_string(count) +
                         " objects) passes the limit of " + std::to_string(max_grid_cells) +
                         " cells: choose a smaller lambda");
    const GridPlan plan = plan_over_all(objects, scene, margins, lambda, max_cells_per_axis, "the grid");
    grid.shape = plan.shape;
    std::vector<std::uint32_t> all(static_cast<std::size_t>(count));
    std::iota(all.begin(), all.end(), 0u);
    list_objects(grid, all, plan.ranges);
    if (stats)
        grid_stats(grid, count, plan.lambda, timer, *stats);
    return grid;
}

// What EXERCISE 07.7 is given for a scene: the grid's box (the objects' union grown by its margin,
// as plan_grid grows it) and each object's box as the build lists it (grown by its margin and the
// grid's rounding, object_cell_ranges' boxes), so that grid_words counts exactly what the build
// stores.
struct ResolutionQuestion {
    Bounds box;
    std::vector<Bounds> boxes;
};

inline ResolutionQuestion resolution_question(const Objects& objects, const Margins& margins)
{
    const Bounds scene = bounds_of_all(objects);
    ResolutionQuestion q;
    q.box = objects.size() > 0 ? grown(scene, margins.of(scene)) : Bounds{point3(0.0f), point3(1.0f)};
    const vec3 rounding = grid_rounding(grid_shape(q.box, cell3(1)));
    q.boxes.resize(static_cast<std::size_t>(objects.size()));
    for (int k = 0; k < objects.size(); ++k) {
        const Bounds b = objects.bounds(k);
        q.boxes[static_cast<std::size_t>(k)] = grown(b, vec3(margins.of(b)) + rounding);
    }
    return q;
}

// Builds the grid over every object at the resolution your 07.7 chooses (choose_grid_resolution),
// each object listed where its box as 07.7 saw it lies. Throws InputError, naming what is wrong
// (grid_resolution_problem), for a resolution outside the rules or over the budget.
inline Grid build_chosen_grid(const Objects& objects, const Margins& margins, GridStats* stats = nullptr)
{
    const Timer timer;
    const ResolutionQuestion q = resolution_question(objects, margins);
    const cell3 n = choose_grid_resolution(q.box, q.boxes);
    const std::string problem = grid_resolution_problem(q.box, q.boxes, n);
    if (!problem.empty())
        throw InputError("your 07.7 (choose_grid_resolution) for " + std::to_string(objects.size()) + " objects: " + problem);
    Grid grid;
    grid.shape = grid_shape(q.box, n);
    std::vector<CellRange> ranges(q.boxes.size());
    for (std::size_t k = 0; k < q.boxes.size(); ++k)
        ranges[k] = cells_overlapping(grid.shape, q.boxes[k]);
    std::vector<std::uint32_t> all(q.boxes.size());
    std::iota(all.begin(), all.end(), 0u);
    list_objects(grid, all, ranges);
    if (stats)
        grid_stats(grid, objects.size(), 0.0f, timer, *stats);
    return grid;
}

// Whether a walk that is over (its next boundary not below t_end) ended short of the grid: neither at
// the end of the query's range nor in a cell on the face it leaves through. That happens where the
// cells are finer than the float steps of t (a scene 1e-6 across seen from 10 away, found by
// accel_fuzz): the next boundaries all round to t_end, and the walk stops with cells still ahead,
// crossed at t_end in float. Their objects can only be hit at t_end, so the query asks brute force
// for that one ray rather than answer without them.
inline bool walk_cut_short(const GridShape& grid, const GridWalk& walk)
{
    const float next = std::min({walk.t_max[0], walk.t_max[1], walk.t_max[2]});
    if (next < walk.t_end || !(walk.t_end < walk.t_range))
        return false;
    const cell3 stride = grid.strides();
    for (int a = 0; a < 3; ++a) {
        if (walk.step_p[a] == 0 || walk.t_max[a] != walk.t_end)
            continue;
        const int i = (walk.p / stride[a]) % grid.n[a];
        if (i == (walk.step_p[a] > 0 ? grid.n[a] - 1 : 0))
            return false;  // in the face's cell: the walk ended where the ray leaves
    }
    return true;
}

// The walk every grid of chapters 07-10 shares (Amanatides and Woo's loop): from a started walk
// (07.4), each cell in order along the ray, counted, then asked with `visit`, which returns true to
// stop the walk there; `next` steps to the following cell (07.5's next_cell, or a structure's own
// step that keeps something along, such as chapter 09's residue). Returns whether a visit stopped
// it, with `walk` left at that cell; false for a missed walk or one that ran to its end.
template <class Visit, class Next>
bool walk_cells(GridWalk& walk, Visit&& visit, Next&& next)
{
    if (walk.missed)
        return false;
    do {
        count(Counter::cells_visited);
        if (visit(walk))
            return true;
    } while (next(walk));
    return false;
}

template <class Visit>
bool walk_cells(GridWalk& walk, Visit&& visit)
{
    return walk_cells(walk, visit, next_cell);
}

// A grid's closest hit, the slides' walk: the cells in order, each asked with its cell query
// (query(walk, best): 07.6, 08.3 or 09.5); the first cell that keeps a hit ends it, since every
// later cell lies farther on. A walk cut short (walk_cut_short) asks brute force for that one ray.
template <class CellQuery, class Next>
bool grid_closest(const GridShape& shape, GridWalk& walk, const Ray& ray, Interval range, const Objects& objects,
                  ObjectHit& hit, CellQuery&& query, Next&& next)
{
    if (walk.missed)
        return false;
    ObjectHit best;
    const bool found = walk_cells(walk, [&](const GridWalk& w) { return query(w, best); }, next);
    if (walk_cut_short(shape, walk))
        return brute_force().closest(ray, range, objects, hit);
    if (found)
        hit = best;
    return found;
}

// A grid's any hit: the cells in order, each asked whether any of its objects is hit anywhere in
// the range (any_in(walk)); the first that is ends it.
template <class AnyInCell, class Next>
bool grid_any(const GridShape& shape, GridWalk& walk, const Ray& ray, Interval range, const Objects& objects,
              AnyInCell&& any_in, Next&& next)
{
    if (walk.missed)
        return false;
    return walk_cells(walk, any_in, next) || (walk_cut_short(shape, walk) && brute_force().any(ray, range, objects));
}

// Each object a grid's cell p lists, in the cell's order, handed to f(k).
template <class F>
void for_each_listed(const Grid& grid, int p, F&& f)
{
    for (std::uint32_t i = grid.cell_start[p]; i < grid.cell_start[p + 1]; ++i)
        f(static_cast<int>(grid.object_index[i]));
}

// A cell's closest hit by 07.6's rules over the objects for_each_object hands to its function (a
// grid's cell, a hashed table's), each asked with ask(k, range, hit) in the range that beats `best`
// and kept when no farther than the cell's `exit`. Returns whether `best` changed. The given grids
// that ask otherwise than 07.6 does (08.4's ray cache, 09.6's open table) walk their cells with it.
template <class ForEachObject, class Ask>
bool closest_in_listed(ForEachObject&& for_each_object, float exit, Interval range, ObjectHit& best, Ask&& ask)
{
    bool changed = false;
    for_each_object([&](int k) {
        ObjectHit h;
        if (ask(k, closer_than(range, best, k), h) && h.t <= exit)
            best = h, changed = true;
    });
    return changed;
}

// Whether any object a grid's cell p lists is hit, each asked with test(k): the any-hit cell of
// every grid that lists its objects in two flat arrays.
template <class Test>
bool any_listed(const Grid& grid, int p, Test&& test)
{
    for (std::uint32_t i = grid.cell_start[p]; i < grid.cell_start[p + 1]; ++i)
        if (test(static_cast<int>(grid.object_index[i])))
            return true;
    return false;
}

// The grid's --stats lines (the lesson's "The program" lists them).
inline void report_grid(std::ostream& out, const GridStats& s)
{
    out << "grid_resolution=" << s.resolution.x << 'x' << s.resolution.y << 'x' << s.resolution.z << '\n'
        << "grid_lambda=" << s.lambda << '\n'
        << "grid_cells=" << s.cells << '\n'
        << "grid_empty_cells=" << s.empty_cells << '\n'
        << "grid_references=" << s.references << '\n'
        << "references_per_object=" << (s.objects > 0 ? static_cast<double>(s.references) / s.objects : 0.0) << '\n'
        << "grid_bytes=" << s.bytes << '\n'
        << "bytes=" << s.bytes << '\n'
        << "build_seconds=" << s.build_seconds << '\n';
}

// UniformGrid's tag for a grid at 07.7's resolution instead of 07.1's at a lambda.
struct ChosenResolution {};

class UniformGrid final : public MarginedAccelerator {
public:
    UniformGrid(const Objects& objects, float lambda)
        : MarginedAccelerator(margins_of(objects)), grid_(build_grid(objects, margins_, lambda, &stats_))
    {
    }
    // A grid built by other means (the tests build small ones by hand): its margins reach everywhere.
    explicit UniformGrid(Grid grid) : grid_(std::move(grid)) {}
    // The grid at the resolution your 07.7 chooses (build_chosen_grid).
    UniformGrid(const Objects& objects, ChosenResolution)
        : MarginedAccelerator(margins_of(objects)), grid_(build_chosen_grid(objects, margins_, &stats_))
    {
    }

    std::size_t bytes() const override { return stats_.bytes; }
    void report(std::ostream& out) const override { report_grid(out, stats_); }

    const Grid& grid() const { return grid_; }
    const GridStats& stats() const { return stats_; }

private:
    bool closest_covered(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const override
    {
        GridWalk walk = start_walk(grid_.shape, ray, range);
        const auto query = [&](const GridWalk& w, ObjectHit& best) {
            return closest_in_cell(grid_, w, ray, range, objects, best);
        };
        return grid_closest(grid_.shape, walk, ray, range, objects, hit, query, next_cell);
    }

    bool any_covered(const Ray& ray, Interval range, const Objects& objects) const override
    {
        GridWalk walk = start_walk(grid_.shape, ray, range);
        ObjectHit hit;
        const auto any_in = [&](const GridWalk& w) {
            return any_listed(grid_, w.p, [&](int k) { return objects.intersect(k, ray, range, hit); });
        };
        return grid_any(grid_.shape, walk, ray, range, objects, any_in, next_cell);
    }

    GridStats stats_;
    Grid grid_;
};

}  // namespace rt
