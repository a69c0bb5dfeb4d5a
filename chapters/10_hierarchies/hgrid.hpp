// The hierarchy of grids as an accelerator (given): chapter 07's grid at the root, a grid of its
// own in every cell that lists more than leaf_size objects, down to a depth limit; walked by your
// descent (10.5).
//
// The build (after Jevans and Wyvill 1989): the root is chapter 07's grid over every object. Each
// of its cells that lists more than leaf_size objects, above the depth limit, gets a child grid:
// over the cell's box (grown by the objects' margin, so the part of a ray inside the cell lies
// inside the child), shaped by the same cube-root rule (07.1) for the cell's objects, listing them
// as chapter 07 lists objects (list_objects). The child's crowded cells are subdivided in turn.
#pragma once

#include "07_uniform_grid/grid.hpp"
#include "10_hierarchies/10_hierarchies.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace rt {

struct HGridSettings {
    float lambda = 4.0f;  // cells per object at every level: chapter 07's default
    int leaf_size = 8;    // a cell listing more objects than this gets a grid of its own: the slides' "4-8"
    int max_depth = 2;    // the root is depth 0; no grid lies deeper than this
};

struct HGridStats {
    int grids = 0, depth = 0;
    int children_over_budget = 0;  // crowded cells left without a grid: it would pass the budgets
    long long cells = 0, references = 0;
    std::size_t bytes = 0;
    double build_seconds = 0.0;
};

class HGridAccel final : public MarginedAccelerator {
public:
    HGridAccel(const Objects& objects, const HGridSettings& settings = {}) : settings_(settings)
    {
        if (settings.max_depth < 0 || settings.max_depth > max_hgrid_depth)
            throw InputError("--max-depth for the hierarchy of grids must be between 0 and " +
                             std::to_string(max_hgrid_depth) + ", got " + std::to_string(settings.max_depth));
        const Timer timer;
        // The margins are the root's, at every level: each object's own (grid.hpp's Margins).
        margins_ = margins_of(objects);
        h_.grids.push_back({build_grid(objects, margins_, settings.lambda), {}});
        h_.grids[0].child.assign(static_cast<std::size_t>(h_.grids[0].grid.shape.cell_count()), -1);
        cells_ = h_.grids[0].grid.shape.cell_count();
        references_ = static_cast<long long>(h_.grids[0].grid.object_index.size());
        subdivide(objects, 0, 0);
        for (const GridNode& node : h_.grids) {
            finest_ = std::min({finest_, node.grid.shape.cell_size.x, node.grid.shape.cell_size.y, node.grid.shape.cell_size.z});
            stats_.cells += node.grid.shape.cell_count();
            stats_.references += static_cast<long long>(node.grid.object_index.size());
            stats_.bytes += sizeof(GridNode) +
                            (node.grid.cell_start.size() + node.grid.object_index.size() + node.child.size()) * 4;
        }
        stats_.grids = static_cast<int>(h_.grids.size());
        stats_.build_seconds = timer.seconds();
    }

    std::size_t bytes() const override { return stats_.bytes; }
    void report(std::ostream& out) const override
    {
        out << "hgrid_grids=" << stats_.grids << '\n'
            << "hgrid_depth=" << stats_.depth << '\n'
            << "hgrid_cells=" << stats_.cells << '\n'
            << "hgrid_references=" << stats_.references << '\n'
            << "hgrid_children_over_budget=" << stats_.children_over_budget << '\n'
            << "bytes=" << stats_.bytes << '\n'
            << "build_seconds=" << stats_.build_seconds << '\n';
    }
    const HGridStats& stats() const { return stats_; }
    const HGrid& hgrid() const { return h_; }

    // Why 8: each level multiplies the cells of a crowded region by lambda times its objects; past a
    // few levels a cell is far smaller than any object in it and a deeper grid only repeats it.
    static constexpr int max_hgrid_depth = 8;

private:
    // Besides the rays the margins leave (MarginedAccelerator, grid.hpp), those along which the
    // finest cells are narrower than t's steps get brute force's answer: a rule of this structure's
    // own, so it stays here.
    bool closest_covered(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const override
    {
        if (cells_finer_than_t(ray, range))
            return brute_force().closest(ray, range, objects, hit);
        ObjectHit best;
        if (!hgrid_closest(h_, 0, ray, range, range, objects, best))
            return false;
        hit = best;
        return true;
    }

    bool any_covered(const Ray& ray, Interval range, const Objects& objects) const override
    {
        if (cells_finer_than_t(ray, range))
            return brute_force().any(ray, range, objects);
        return any_in(0, ray, range, range, objects);
    }

    // Gives each crowded cell of grid g (above the depth limit) a grid of its own, depth first.
    void subdivide(const Objects& objects, int g, int depth)
    {
        if (depth >= settings_.max_depth)
            return;
        const GridShape shape = h_.grids[g].grid.shape;  // a copy: h_.grids grows below
        for (int p = 0; p < shape.cell_count(); ++p) {
            const std::uint32_t begin = h_.grids[g].grid.cell_start[p], end = h_.grids[g].grid.cell_start[p + 1];
            const int count = static_cast<int>(end - begin);
            if (count <= settings_.leaf_size)
                continue;
            const cell3 c{p / (shape.n.y * shape.n.z), (p / shape.n.z) % shape.n.y, p % shape.n.z};
            const point3 lo = shape.box.min + vec3(c) * shape.cell_size;
            const Bounds cell{lo, lo + shape.cell_size};
            // An object whose box holds the whole cell (a floor through it) would be listed in every
            // cell of a child grid: cutting the cell cannot separate it. Only the others count.
            int separable = 0;
            for (std::uint32_t i = begin; i < end; ++i)
                separable += !covers(objects.bounds(static_cast<int>(h_.grids[g].grid.object_index[i])), cell);
            if (separable <= settings_.leaf_size)
                continue;
            const cell3 n = grid_resolution(resolution_box(cell), count, settings_.lambda);
            if (n == cell3(1))
                continue;  // one cell again: nothing gained
            // Grown by the margin an object at the cell's coordinates gets (their rounding), and by the
            // parent's own rounding (the cell's corners here in float, the walk's in double).
            const GridShape child_shape = grid_shape(grown(cell, vec3(margins_.of(cell)) + grid_rounding(shape)), n);
            const std::vector<std::uint32_t> ids(h_.grids[g].grid.object_index.begin() + begin,
                                                 h_.grids[g].grid.object_index.begin() + end);
            std::vector<CellRange> ranges;
            const long long references = object_cell_ranges(child_shape, objects, ids, margins_, ranges);
            if (!separates(child_shape, references, ids.size()))
                continue;
            // Past the budgets of chapter 07's grid, counted over every level, the cell keeps its list:
            // a coarser hierarchy, never a refused or swollen one.
            if (cells_ + child_shape.cell_count() > max_grid_cells || references_ + references > max_grid_references) {
                ++stats_.children_over_budget;
                continue;
            }
            cells_ += child_shape.cell_count();
            references_ += references;
            GridNode node;
            node.grid.shape = child_shape;
            list_objects(node.grid, ids, ranges);
            node.child.assign(static_cast<std::size_t>(node.grid.shape.cell_count()), -1);
            const int number = static_cast<int>(h_.grids.size());
            h_.grids.push_back(std::move(node));
            h_.grids[g].child[p] = number;
            stats_.depth = std::max(stats_.depth, depth + 1);
            subdivide(objects, number, depth + 1);
        }
    }

    // Whether a child grid of these objects is worth building, by the cost its walk would have: a
    // ray through a box of n_x x n_y x n_z cells crosses about (n_x + n_y + n_z) / 3 of them (in a
    // cube of n cells of side s the mean chord is 2 n s / 3, and a random direction crosses 3/2 cell
    // faces per s of length: 2 n s / 3 x 3 / (2 s) = n), each listing references / cells objects on
    // average. Built only when that is fewer than the cell's objects, the tests a ray makes in the
    // cell without it. Objects
    // larger than the child's cells (long sticks across it) are listed in most of them: such a grid
    // would be walked for nothing, and subdivided again, each level multiplying the references.
    // Counted from the objects' cell ranges, before anything is listed.
    static bool separates(const GridShape& child, long long references, std::size_t objects)
    {
        const double crossed = (child.n.x + child.n.y + child.n.z) / 3.0;
        return crossed * static_cast<double>(references) / child.cell_count() < static_cast<double>(objects);
    }

    static bool covers(const Bounds& b, const Bounds& cell)
    {
        return b.min.x <= cell.min.x && b.min.y <= cell.min.y && b.min.z <= cell.min.z && b.max.x >= cell.max.x &&
               b.max.y >= cell.max.y && b.max.z >= cell.max.z;
    }

    // The any-hit walk: the cells in order, a child grid walked over the part inside its cell; any
    // object hit anywhere in the range ends it.
    bool any_in(int g, const Ray& ray, Interval part, Interval range, const Objects& objects) const
    {
        const GridNode& node = h_.grids[g];
        GridWalk walk = start_walk(node.grid.shape, ray, part);
        ObjectHit hit;
        return walk_cells(walk, [&](const GridWalk& w) {  // chapter 07's walk (grid.hpp)
            const int child = node.child[w.p];
            if (child >= 0)
                return any_in(child, ray, {w.t_enter, w.cell_exit()}, range, objects);
            return any_listed(node.grid, w.p, [&](int k) { return objects.intersect(k, ray, range, hit); });
        });
    }

    // Whether the float steps of t where the ray crosses the root's box are as large as a quarter of
    // the finest cell: there the walks' boundaries round together and a walk can stop with cells
    // still ahead (chapter 07's walk_cut_short, which the grids check exactly; here the walk of a
    // child grid is the student's 10.5, so the check is made once per ray, before it). Such a ray
    // (a scene 1e-6 across seen from 10 away) gets brute force's answer.
    bool cells_finer_than_t(const Ray& ray, Interval range) const
    {
        const std::optional<Interval> inside = hit_bounds(h_.grids[0].grid.shape.box, ray, range);
        if (!inside)
            return false;
        const float far = std::max(std::abs(inside->min), std::abs(inside->max));
        return 4.0f * far * 0x1p-23f >= finest_;
    }

    float finest_ = infinity;  // the smallest cell side of any grid of the hierarchy
    HGridSettings settings_;
    HGrid h_;
    HGridStats stats_;
    long long cells_ = 0, references_ = 0;  // over every level, for the budgets
};

}  // namespace rt
