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
#include "common/stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <string>
#include <utility>

namespace rt {

// Why 1e-5 of the scene's size: a hit's t carries a relative error of a few 1e-7 to 1e-6
// (chapter 02's table), so the hit point can stand that far, times its distance, outside the
// object's box, and the walk's boundaries are rounded too. Each object is listed in the cells its
// box reaches when grown by this margin, so a hit found near a cell boundary is always inside a
// cell that lists its object. It costs a few extra references where a box ends next to a boundary.
constexpr float grid_margin = 1e-5f;

// Why 1 << 25 cells (32 Mi, 128 MB of offsets): a dense grid pays for every cell, empty or not;
// past this the build would take seconds and most of the machine's memory for one scene.
constexpr long long max_grid_cells = 1LL << 25;

// What the grid's build reports (--stats, the trade tables).
struct GridStats {
    cell3 resolution{1};
    long long cells = 0;
    long long references = 0;
    long long empty_cells = 0;
    std::size_t bytes = 0;
    double build_seconds = 0.0;
};

// The margin each object's box grows by: grid_margin of the scene's largest extent, and at least
// a few float steps of its farthest coordinate (a scene far from the origin rounds coarser).
inline float grid_margin_of(const Bounds& scene)
{
    const float size = std::max({scene.extent().x, scene.extent().y, scene.extent().z});
    const float far = std::max({std::abs(scene.min.x), std::abs(scene.min.y), std::abs(scene.min.z),
                                std::abs(scene.max.x), std::abs(scene.max.y), std::abs(scene.max.z)});
    return std::max(grid_margin * size, 16.0f * far * 0x1p-24f);
}

inline Bounds grown(const Bounds& b, float margin)
{
    return {b.min - vec3(margin), b.max + vec3(margin)};
}

// Lists the objects `ids` (in increasing number) in the cells of grid.shape that their boxes,
// grown by `margin`, overlap: a counting sort into grid.cell_start and grid.object_index.
// Chapter 10's hierarchy of grids lists a cell's objects in its child grid the same way.
inline void list_objects(Grid& grid, const Objects& objects, const std::vector<std::uint32_t>& ids, float margin)
{
    const GridShape& shape = grid.shape;
    const int cell_count = shape.cell_count();
    std::vector<CellRange> ranges(ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i)
        ranges[i] = cells_overlapping(shape, grown(objects.bounds(static_cast<int>(ids[i])), margin));
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

// Builds the grid over every object, lambda cells per object. Throws InputError when the
// resolution would pass max_grid_cells.
inline Grid build_grid(const Objects& objects, float lambda, GridStats* stats = nullptr)
{
    const Timer timer;
    const int count = objects.size();
    Bounds scene;
    for (int k = 0; k < count; ++k)
        scene.grow(objects.bounds(k));
    Grid grid;
    const cell3 n = grid_resolution(scene, count, lambda);
    const long long cells = static_cast<long long>(n.x) * n.y * n.z;
    if (cells > max_grid_cells)
        throw InputError("a grid of " + std::to_string(n.x) + " x " + std::to_string(n.y) + " x " + std::to_string(n.z) +
                         " cells (lambda " + std::to_string(lambda) + ", " + std::to_string(count) +
                         " objects) passes the limit of " + std::to_string(max_grid_cells) +
                         " cells: choose a smaller lambda");
    const float margin = count > 0 ? grid_margin_of(scene) : 0.0f;
    grid.shape = grid_shape(count > 0 ? grown(scene, margin) : Bounds{point3(0.0f), point3(1.0f)}, n);
    std::vector<std::uint32_t> all(static_cast<std::size_t>(count));
    std::iota(all.begin(), all.end(), 0u);
    list_objects(grid, objects, all, margin);
    const int cell_count = grid.shape.cell_count();

    if (stats) {
        stats->resolution = n;
        stats->cells = cell_count;
        stats->references = static_cast<long long>(grid.object_index.size());
        stats->empty_cells = 0;
        for (int p = 0; p < cell_count; ++p)
            stats->empty_cells += grid.cell_start[p] == grid.cell_start[p + 1];
        stats->bytes = (grid.cell_start.size() + grid.object_index.size()) * sizeof(std::uint32_t);
        stats->build_seconds = timer.seconds();
    }
    return grid;
}

// The slides' walk for the closest hit: the cells in order along the ray, each asked with the cell
// query (07.6); the first cell that keeps a hit ends it, since every later cell lies farther on.
// The any-hit walk asks each object for any hit in the whole range: any one ends it.
class UniformGrid final : public Accelerator {
public:
    UniformGrid(const Objects& objects, float lambda) : grid_(build_grid(objects, lambda, &stats_)) {}
    // A grid built by other means (the tests build small ones by hand).
    explicit UniformGrid(Grid grid) : grid_(std::move(grid)) {}

    bool closest(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const override
    {
        GridWalk walk = start_walk(grid_.shape, ray, range);
        if (walk.missed)
            return false;
        ObjectHit best;
        do {
            count(Counter::cells_visited);
            if (closest_in_cell(grid_, walk, ray, range, objects, best)) {
                hit = best;
                return true;
            }
        } while (next_cell(walk));
        return false;
    }

    bool any(const Ray& ray, Interval range, const Objects& objects) const override
    {
        GridWalk walk = start_walk(grid_.shape, ray, range);
        if (walk.missed)
            return false;
        ObjectHit hit;
        do {
            count(Counter::cells_visited);
            for (std::uint32_t i = grid_.cell_start[walk.p]; i < grid_.cell_start[walk.p + 1]; ++i)
                if (objects.intersect(static_cast<int>(grid_.object_index[i]), ray, range, hit))
                    return true;
        } while (next_cell(walk));
        return false;
    }

    std::size_t bytes() const override { return stats_.bytes; }

    const Grid& grid() const { return grid_; }
    const GridStats& stats() const { return stats_; }

private:
    GridStats stats_;
    Grid grid_;
};

}  // namespace rt
