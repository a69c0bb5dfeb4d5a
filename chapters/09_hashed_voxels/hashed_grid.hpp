// The hashed grid (given): chapter 07's grid shape and walk at a resolution no dense array could
// hold, only its occupied cells stored, in a hash table of M buckets (cell p in bucket p mod M),
// and one bit per cell saying whether to look there at all.
//
// The build sorts every (cell, object) reference by cell, makes one HashedCell per occupied cell,
// and files the cells by bucket with a counting sort: three flat arrays and the bit array.
#pragma once

#include "02_spheres_triangles/scene_query.hpp"
#include "07_uniform_grid/grid.hpp"
#include "09_hashed_voxels/09_hashed_voxels.hpp"
#include "common/error.hpp"
#include "common/stats.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

namespace rt {

struct HashedGridStats {
    int objects = 0;
    cell3 resolution{1};
    float lambda = 0.0f;       // the lambda built with: the one asked for, or lower (plan_grid)
    long long cells = 0;       // of the whole grid, empty or not
    long long occupied = 0;    // cells that hold an object: the table's entries
    long long references = 0;  // (cell, object) pairs
    std::uint32_t M = 1;
    long long collisions = 0;  // cells filed in a bucket that already held one
    std::size_t table_bytes = 0, bits_bytes = 0, bytes = 0;
    double build_seconds = 0.0;
};

// The least prime at least n: a table size with no factor in common with the walk's strides, so
// that cells a stride apart do not pile into a few buckets (the lesson measures a power of two).
inline std::uint32_t prime_at_least(std::uint64_t n)
{
    if (n <= 2)
        return 2;
    for (std::uint64_t m = n | 1u;; m += 2) {
        bool prime = true;
        for (std::uint64_t d = 3; d * d <= m && prime; d += 2)
            prime = m % d != 0;
        if (prime)
            return static_cast<std::uint32_t>(m);
    }
}

class HashedGrid final : public Accelerator {
public:
    // lambda cells per object, up to max_hashed_cells_per_axis; table_size 0 takes the least
    // prime at least twice the occupied cells. Throws InputError past the limits.
    HashedGrid(const Objects& objects, float lambda, std::uint32_t table_size = 0) { build(objects, lambda, table_size); }

    bool closest(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const override
    {
        GridWalk walk = start_walk(shape_, ray, range);
        if (walk.missed)
            return false;
        Residue r = residue_of(walk);
        const auto query = [&](const GridWalk& w, ObjectHit& best) {
            return closest_in_hashed_cell(table_, bits_, w, r.r, ray, range, objects, best);
        };
        // Chapter 07's walk (grid.hpp), each step keeping the residue along.
        return grid_closest(shape_, walk, ray, range, objects, hit, query, [&](GridWalk& w) { return step(w, r); });
    }

    bool any(const Ray& ray, Interval range, const Objects& objects) const override
    {
        GridWalk walk = start_walk(shape_, ray, range);
        if (walk.missed)
            return false;
        Residue r = residue_of(walk);
        ObjectHit hit;
        const auto any_in = [&](const GridWalk& w) {
            if (!occupied(bits_, w.p)) {
                count(Counter::table_lookups_skipped);
                return false;
            }
            count(Counter::table_lookups);
            const HashedCell* cell = find_cell(table_, w.p, r.r);
            if (!cell)
                return false;
            for (std::uint32_t i = cell->first; i < cell->first + cell->count; ++i)
                if (objects.intersect(static_cast<int>(table_.object_index[i]), ray, range, hit))
                    return true;
            return false;
        };
        return grid_any(shape_, walk, ray, range, objects, any_in, [&](GridWalk& w) { return step(w, r); });
    }

    std::size_t bytes() const override { return stats_.bytes; }
    const HashedGridStats& stats() const { return stats_; }

    void report(std::ostream& out) const override
    {
        const HashedGridStats& s = stats_;
        out << "grid_resolution=" << s.resolution.x << 'x' << s.resolution.y << 'x' << s.resolution.z << '\n'
            << "grid_lambda=" << s.lambda << '\n'
            << "grid_cells=" << s.cells << '\n'
            << "occupied_cells=" << s.occupied << '\n'
            << "table_size=" << s.M << '\n'
            << "table_load=" << static_cast<double>(s.occupied) / s.M << '\n'
            << "table_collisions=" << s.collisions << '\n'
            << "references_per_object=" << (s.objects > 0 ? static_cast<double>(s.references) / s.objects : 0.0)
            << '\n'
            << "table_bytes=" << s.table_bytes << '\n'
            << "bits_bytes=" << s.bits_bytes << '\n'
            << "bytes=" << s.bytes << '\n'
            << "build_seconds=" << s.build_seconds << '\n';
    }
    const HashTable& table() const { return table_; }
    const GridShape& shape() const { return shape_; }

private:
    // The walk's residue r = p mod M, and what a step along each axis adds to it (09.1).
    struct Residue {
        std::uint32_t r;
        std::int32_t step[3];
    };

    Residue residue_of(const GridWalk& walk) const
    {
        // One division per ray, when the walk starts; none in the loop.
        Residue res{static_cast<std::uint32_t>(static_cast<std::uint32_t>(walk.p) % table_.M), {0, 0, 0}};
        for (int a = 0; a < 3; ++a)
            res.step[a] = residue_step(walk.step_p[a], table_.M);
        return res;
    }

    // The next cell (07.5) and its residue (09.2): the axis stepped is the one whose step_p p moved by.
    bool step(GridWalk& walk, Residue& res) const
    {
        const int before = walk.p;
        if (!next_cell(walk))
            return false;
        const int moved = walk.p - before;
        const int a = moved == walk.step_p[0] ? 0 : moved == walk.step_p[1] ? 1 : 2;
        res.r = advance_residue(res.r, res.step[a], table_.M);
        return true;
    }

    // The build in four phases: the grid's shape (chapter 07's plan), the references sorted into
    // one HashedCell per occupied cell, the cells filed by bucket, and the occupancy bits.
    void build(const Objects& objects, float lambda, std::uint32_t table_size)
    {
        const Timer timer;
        const GridPlan plan = plan_shape(objects, lambda);
        shape_ = plan.shape;
        const std::vector<HashedCell> by_address = sort_references(plan.ranges, plan.references);
        const long long collisions = file_by_bucket(by_address, table_size);
        set_bits(by_address);

        const HashTable& t = table_;
        stats_.objects = objects.size();
        stats_.resolution = shape_.n;
        stats_.lambda = plan.lambda;
        stats_.cells = static_cast<long long>(shape_.n.x) * shape_.n.y * shape_.n.z;
        stats_.occupied = static_cast<long long>(by_address.size());
        stats_.references = static_cast<long long>(t.object_index.size());
        stats_.M = t.M;
        stats_.collisions = collisions;
        stats_.table_bytes = t.bucket_start.size() * sizeof(std::uint32_t) + t.cells.size() * sizeof(HashedCell) +
                             t.object_index.size() * sizeof(std::uint32_t);
        stats_.bits_bytes = bits_.words.size() * sizeof(std::uint64_t);
        stats_.bytes = stats_.table_bytes + stats_.bits_bytes;
        stats_.build_seconds = timer.seconds();
    }

    // The grid's shape and each object's cells, lambda cells per object up to
    // max_hashed_cells_per_axis: chapter 07's plan, whose references are counted before anything is
    // allocated, and which lowers lambda where such a grid would not pay (grid_pays).
    static GridPlan plan_shape(const Objects& objects, float lambda)
    {
        const int count = objects.size();
        const Bounds scene = bounds_of_all(objects);
        const cell3 asked = grid_resolution(resolution_box(scene), count, lambda, max_hashed_cells_per_axis);
        if (static_cast<long long>(asked.x) * asked.y * asked.z >= (1LL << 31))
            throw InputError("a hashed grid of " + std::to_string(asked.x) + " x " + std::to_string(asked.y) + " x " +
                             std::to_string(asked.z) +
                             " cells passes the limit of 2^31 cell addresses: choose a smaller lambda");
        return plan_over_all(objects, scene, lambda, max_hashed_cells_per_axis, "the hashed grid");
    }

    // Every (cell, object) reference as one 64-bit key, cell above object, sorted; then one
    // HashedCell per occupied cell, in increasing address, its objects (table_.object_index) in
    // increasing number.
    std::vector<HashedCell> sort_references(const std::vector<CellRange>& ranges, long long references)
    {
        const long long cells = static_cast<long long>(shape_.n.x) * shape_.n.y * shape_.n.z;
        std::vector<std::uint64_t> keys;
        keys.reserve(static_cast<std::size_t>(references));
        for (std::size_t k = 0; k < ranges.size(); ++k)
            for (int i = ranges[k].first.x; i <= ranges[k].last.x; ++i)
                for (int j = ranges[k].first.y; j <= ranges[k].last.y; ++j)
                    for (int l = ranges[k].first.z; l <= ranges[k].last.z; ++l) {
                        const int p = shape_.address({i, j, l});
                        if (p >= 0 && p < cells)  // a student's 07.3 may step outside the grid
                            keys.push_back((static_cast<std::uint64_t>(p) << 32) | static_cast<std::uint32_t>(k));
                    }
        std::sort(keys.begin(), keys.end());

        std::vector<HashedCell> by_address;
        table_.object_index.resize(keys.size());
        for (std::size_t i = 0; i < keys.size(); ++i) {
            const auto p = static_cast<std::int32_t>(keys[i] >> 32);
            table_.object_index[i] = static_cast<std::uint32_t>(keys[i] & 0xffffffffu);
            if (by_address.empty() || by_address.back().p != p)
                by_address.push_back({p, static_cast<std::uint32_t>(i), 0});
            ++by_address.back().count;
        }
        return by_address;
    }

    // The cells filed by bucket, cell p in bucket p mod M (a counting sort, stable: by increasing
    // address within a bucket), M = table_size or, for 0, the least prime at least twice the
    // occupied cells. Returns the collisions: cells filed in a bucket that already held one.
    long long file_by_bucket(const std::vector<HashedCell>& by_address, std::uint32_t table_size)
    {
        HashTable& t = table_;
        t.M = table_size > 0 ? table_size : prime_at_least(2 * std::max<std::uint64_t>(1, by_address.size()));
        t.bucket_start.assign(static_cast<std::size_t>(t.M) + 1, 0);
        for (const HashedCell& c : by_address)
            ++t.bucket_start[static_cast<std::uint32_t>(c.p) % t.M + 1];
        long long collisions = 0;
        for (std::uint32_t b = 0; b < t.M; ++b) {
            collisions += std::max<long long>(0, static_cast<long long>(t.bucket_start[b + 1]) - 1);
            t.bucket_start[b + 1] += t.bucket_start[b];
        }
        t.cells.resize(by_address.size());
        std::vector<std::uint32_t> fill(t.bucket_start.begin(), t.bucket_start.end() - 1);
        for (const HashedCell& c : by_address)
            t.cells[fill[static_cast<std::uint32_t>(c.p) % t.M]++] = c;
        return collisions;
    }

    // One bit per cell of the grid, set for the occupied ones.
    void set_bits(const std::vector<HashedCell>& by_address)
    {
        const long long cells = static_cast<long long>(shape_.n.x) * shape_.n.y * shape_.n.z;
        bits_.words.assign(static_cast<std::size_t>((cells + 63) / 64), 0);
        for (const HashedCell& c : by_address) {
            const auto p = static_cast<std::uint32_t>(c.p);
            bits_.words[p >> 6] |= std::uint64_t{1} << (p & 63u);
        }
    }

    GridShape shape_;
    HashTable table_;
    OccupancyBits bits_;
    HashedGridStats stats_;
};

}  // namespace rt
