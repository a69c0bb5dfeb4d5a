// The hashed grid (given): chapter 07's grid shape and walk at a resolution no dense array could
// hold, only its occupied cells stored, in a hash table of M buckets (cell p in bucket p mod M),
// and one bit per cell saying whether to look there at all.
//
// The build sets the bit array, sorts every (cell, object) reference by cell, makes one HashedCell
// per occupied cell, and files the cells by bucket with a counting sort: three flat arrays and the
// bits. Before any of the large ones, it counts the occupied cells (a grid mostly full is built at
// chapter 07's lambda instead: hashed_most_occupied), weighs what they will take against chapter 07's
// dense grid, and says so when that is many times more (say_memory_weighed).
#pragma once

#include "02_spheres_triangles/scene_query.hpp"
#include "07_uniform_grid/grid.hpp"
#include "09_hashed_voxels/09_hashed_voxels.hpp"
#include "common/error.hpp"
#include "common/notice.hpp"
#include "common/stats.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
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
    std::size_t peak_bytes = 0;   // the most the build held at once (hashed_build_bytes)
    std::size_t dense_bytes = 0;  // chapter 07's dense grid's build at dense_grid_lambda, same objects
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

// The lambda of chapter 07's dense grid the hashed grid's memory is weighed against: its default
// (ch07::default_lambda, chapter 07's figure.hpp; chapter 09's figure.hpp checks they agree).
constexpr float dense_grid_lambda = 4.0f;

// Why 8 times: where the hashed grid does what it is for, each object smaller than a cell, a box
// straddles at most 2 cells an axis, 8 in all. At 8 references an object, each in a cell of its
// own, its build holds about 24 + 8 x 44 + 32 bytes an object (hashed_build_bytes, while the cells
// are filed: a range; for each reference its object number, 4, its cell twice, by address and in
// the table, 24, and two bucket words for each, M being about twice the cells, 16; and 256 cells of
// bits), against the dense grid's at least 28 + 32 + 4 (a number and a range; two words for each of
// its 4 cells an object; one reference): about 6 times. Past 8 times, objects are listed in more
// cells than a box smaller than a cell can reach: the finer cells slice them rather than sort them
// apart, and the memory grows with lambda.
constexpr double hashed_memory_factor = 8.0;

// Why half: the table stores an occupied cell at about three times a dense cell's cost (its 12 bytes
// and two bucket words, against two offsets) and skips an empty one by a bit; it is for grids whose
// cells are mostly empty. Where at least half the cells hold something, the cells are finer than
// the objects (a flat scene's one layer: every cell holds part of a triangle), a finer grid slices
// them rather than sorts them apart, and every cell it adds is one more the table holds. Such a
// scene is built at chapter 07's lambda (dense_grid_lambda): the table then holds no more cells
// than the dense grid, the occupied cells it was asked to hold sized from what it will hold.
constexpr double hashed_most_occupied = 0.5;

// Why 64 MB: below it a build's memory concerns no machine the kit runs on, whatever the ratio
// (chapter 07's dense grid alone may take 128 MB of offsets, max_grid_cells). As below
// grid_pays_floor tests a ray, a scene of a few thousand objects keeps the lambda it asks for
// without a word. The chapter's figure, the stadium at lambda 256, stays under it, many times its
// dense grid's memory: the memory that buys its tenfold speed (the lesson's "When the build says what
// it holds" gives the figures).
constexpr double hashed_memory_floor = 64e6;

// The most the hashed grid's build holds at once, in bytes, from its counts: each object's range of
// cells (kept through the build) and the bits (set first), then, while the references are sorted,
// their 8-byte keys, the 4-byte object numbers and the 12-byte cells by address; or, while the cells
// are filed, the object numbers, the cells by address, the table's cells, its M + 1 bucket offsets
// and the filing's M cursors; whichever is more. Exact but for the allocator's own overhead.
inline std::size_t hashed_build_bytes(long long objects, long long references, long long occupied, long long cells,
                                      std::uint32_t M)
{
    const double kept = static_cast<double>(objects) * sizeof(CellRange) +
                        static_cast<double>((cells + 63) / 64) * sizeof(std::uint64_t);
    const double R = static_cast<double>(references), occ = static_cast<double>(occupied);
    const double sorting = R * (sizeof(std::uint64_t) + sizeof(std::uint32_t)) + occ * sizeof(HashedCell);
    const double filing = R * sizeof(std::uint32_t) + 2 * occ * sizeof(HashedCell) +
                          (2.0 * M + 1) * sizeof(std::uint32_t);
    return static_cast<std::size_t>(kept + std::max(sorting, filing));
}

// The most chapter 07's dense grid's build (build_grid) holds at once: each object's number and range
// of cells, the cells' offsets (cells + 1) and the listing's cursor (cells), and the references.
inline std::size_t dense_build_bytes(long long objects, long long references, long long cells)
{
    return static_cast<std::size_t>(static_cast<double>(objects) * (sizeof(std::uint32_t) + sizeof(CellRange)) +
                                    (2.0 * cells + 1) * sizeof(std::uint32_t) +
                                    static_cast<double>(references) * sizeof(std::uint32_t));
}

// A hash of EXERCISE 09.6's shape (TableHash, the contract): chosen once per build over the occupied
// cells, then asked the bucket of each cell, within `budget` buckets. Yours within 09.6's budget by
// default; the grader measures others through the same grid (p mod M with M chosen other ways, and
// the chapter's default at twice the budget, for the lesson's table).
struct OpenHashing {
    TableHash (*choose)(const std::vector<std::int32_t>& cells, cell3 n) = choose_table_hash;
    std::uint32_t (*bucket)(const TableHash& hash, std::int32_t p) = bucket_of;
    std::uint32_t (*budget)(std::size_t occupied) = max_table_buckets;
};

// What the build made of an open hash: where it broke the contract, if it did (the grader's gate
// and the program's notice say so). A table it broke holds no cell: every lookup finds nothing.
struct OpenHashBuild {
    bool over_budget = false;      // M of 0, or past max_table_buckets(occupied)
    bool lost = false;             // some cell's bucket lay past the table
    std::int32_t lost_p = 0;       // the first such cell
    std::uint32_t lost_bucket = 0;  // and the bucket it was given
};

class HashedGrid final : public MarginedAccelerator {
public:
    // lambda cells per object, up to max_hashed_cells_per_axis; table_size 0 takes the least
    // prime at least twice the occupied cells. Throws InputError past the limits.
    HashedGrid(const Objects& objects, float lambda, std::uint32_t table_size = 0) { build(objects, lambda, table_size); }

    // The same grid, its cells filed by an open hash (EXERCISE 09.6: yours unless told otherwise)
    // instead of p mod M: cell p in bucket hashing.bucket(hash, p), looked up by comparing keys along
    // its bucket, each key compared counted (Counter::table_probes). The walk carries no residue.
    HashedGrid(const Objects& objects, float lambda, OpenHashing hashing) : open_(true), hashing_(hashing)
    {
        build(objects, lambda, 0);
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
            << "table_hash=" << (open_ ? "open" : "mod") << '\n'
            << "table_load=" << static_cast<double>(s.occupied) / s.M << '\n'
            << "table_collisions=" << s.collisions << '\n'
            << "references_per_object=" << (s.objects > 0 ? static_cast<double>(s.references) / s.objects : 0.0)
            << '\n'
            << "table_bytes=" << s.table_bytes << '\n'
            << "bits_bytes=" << s.bits_bytes << '\n'
            << "bytes=" << s.bytes << '\n'
            << "build_peak_bytes=" << s.peak_bytes << '\n'
            << "dense_grid_peak_bytes=" << s.dense_bytes << '\n'
            << "build_seconds=" << s.build_seconds << '\n';
    }
    const HashTable& table() const { return table_; }
    const GridShape& shape() const { return shape_; }
    const OccupancyBits& bits() const { return bits_; }

    // Built with an open hash: the hash chosen and what the build made of it.
    bool open() const { return open_; }
    const TableHash& hash() const { return hash_; }
    const OpenHashBuild& open_build() const { return open_build_; }

    // The open table's cell of key p (nullptr: none), read along the bucket its hash gives from the
    // bucket's first cell, each key compared counted (Counter::table_probes); a bucket past the
    // table holds nothing.
    const HashedCell* find_open(std::int32_t p) const
    {
        if (open_build_.over_budget)
            return nullptr;
        const std::uint32_t b = hashing_.bucket(hash_, p);
        if (b >= table_.M)
            return nullptr;
        for (std::uint32_t i = table_.bucket_start[b]; i < table_.bucket_start[b + 1]; ++i) {
            count(Counter::table_probes);
            if (table_.cells[i].p == p)
                return &table_.cells[i];
        }
        return nullptr;
    }

private:
    bool closest_covered(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const override
    {
        if (open_)
            return open_closest(ray, range, objects, hit);
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

    bool any_covered(const Ray& ray, Interval range, const Objects& objects) const override
    {
        if (open_)
            return open_any(ray, range, objects);
        GridWalk walk = start_walk(shape_, ray, range);
        if (walk.missed)
            return false;
        Residue r = residue_of(walk);
        const auto any_in = [&](const GridWalk& w) {
            if (!occupied(bits_, w.p)) {
                count(Counter::table_lookups_skipped);
                return false;
            }
            count(Counter::table_lookups);
            return any_hit_in(find_cell(table_, w.p, r.r), ray, range, objects);
        };
        return grid_any(shape_, walk, ray, range, objects, any_in, [&](GridWalk& w) { return step(w, r); });
    }

    // Whether any object a table's cell lists is hit in the range (no cell: none).
    bool any_hit_in(const HashedCell* cell, const Ray& ray, Interval range, const Objects& objects) const
    {
        if (!cell)
            return false;
        ObjectHit hit;
        for (std::uint32_t i = cell->first; i < cell->first + cell->count; ++i)
            if (objects.intersect(static_cast<int>(table_.object_index[i]), ray, range, hit))
                return true;
        return false;
    }

    // The open table's cell the walk is in, when its bit is on: one skipped lookup counted when the
    // bit is off, one lookup when it is on (as 09.5 counts), then the keys compared (find_open).
    const HashedCell* open_cell(const GridWalk& w) const
    {
        const auto p = static_cast<std::uint32_t>(w.p);
        if (((bits_.words[p >> 6] >> (p & 63u)) & 1u) == 0) {
            count(Counter::table_lookups_skipped);
            return nullptr;
        }
        count(Counter::table_lookups);
        return find_open(w.p);
    }

    // Chapter 07's walk over the open table, each cell's objects asked by 07.6's rules.
    bool open_closest(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const
    {
        GridWalk walk = start_walk(shape_, ray, range);
        const auto query = [&](const GridWalk& w, ObjectHit& best) {
            const HashedCell* cell = open_cell(w);
            if (!cell)
                return false;
            const auto each_listed = [&](auto&& f) {
                for (std::uint32_t i = cell->first; i < cell->first + cell->count; ++i)
                    f(static_cast<int>(table_.object_index[i]));
            };
            return closest_in_listed(each_listed, w.cell_exit(), range, best, [&](int k, Interval r, ObjectHit& h) {
                return objects.intersect(k, ray, r, h);
            });
        };
        return grid_closest(shape_, walk, ray, range, objects, hit, query, next_cell);
    }

    bool open_any(const Ray& ray, Interval range, const Objects& objects) const
    {
        GridWalk walk = start_walk(shape_, ray, range);
        const auto any_in = [&](const GridWalk& w) { return any_hit_in(open_cell(w), ray, range, objects); };
        return grid_any(shape_, walk, ray, range, objects, any_in, next_cell);
    }

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

    // The build in five phases: the grid's shape (chapter 07's plan), the occupancy bits, the memory
    // weighed, the references sorted into one HashedCell per occupied cell, and the cells filed by
    // bucket.
    void build(const Objects& objects, float lambda, std::uint32_t table_size)
    {
        const Timer timer;
        const Bounds scene = bounds_of_all(objects);
        margins_ = margins_of(objects);
        GridPlan plan = plan_shape(objects, scene, margins_, lambda);
        shape_ = plan.shape;
        // The bits first: they count the occupied cells, so that what the build will hold is known
        // before any of its large arrays is allocated.
        long long occupied = set_bits(shape_, plan.ranges, bits_);
        if (static_cast<double>(occupied) > hashed_most_occupied * static_cast<double>(cells_of(shape_)) &&
            plan.lambda > dense_grid_lambda) {
            GridPlan dense_cells = plan_shape(objects, scene, margins_, dense_grid_lambda);
            say_mostly_occupied(plan, occupied, dense_cells.lambda);
            plan = std::move(dense_cells);
            shape_ = plan.shape;
            occupied = set_bits(shape_, plan.ranges, bits_);
        }
        const std::size_t dense = weigh_memory(objects, scene, margins_, plan, occupied, lambda, table_size);
        const std::vector<HashedCell> by_address = sort_references(plan.ranges, plan.references, occupied);
        const long long collisions = open_ ? file_by_open_hash(by_address)
                                           : file_by_bucket(by_address, table_size_for(table_size, occupied),
                                                            [](std::int32_t p, std::uint32_t M) {
                                                                return static_cast<std::uint32_t>(p) % M;
                                                            });

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
        stats_.peak_bytes = hashed_build_bytes(stats_.objects, stats_.references, stats_.occupied, stats_.cells, t.M);
        stats_.dense_bytes = dense;
        stats_.build_seconds = timer.seconds();
    }

    // The grid's shape and each object's cells, lambda cells per object up to
    // max_hashed_cells_per_axis: chapter 07's plan, whose references are counted before anything is
    // allocated, and which lowers lambda where such a grid would not pay (grid_pays).
    static GridPlan plan_shape(const Objects& objects, const Bounds& scene, const Margins& margins, float lambda)
    {
        const int count = objects.size();
        const cell3 asked = grid_resolution(resolution_box(scene), count, lambda, max_hashed_cells_per_axis);
        if (static_cast<long long>(asked.x) * asked.y * asked.z >= (1LL << 31))
            throw InputError("a hashed grid of " + std::to_string(asked.x) + " x " + std::to_string(asked.y) + " x " +
                             std::to_string(asked.z) +
                             " cells passes the limit of 2^31 cell addresses: choose a smaller lambda");
        return plan_over_all(objects, scene, margins, lambda, max_hashed_cells_per_axis, "the hashed grid");
    }

    // The table's size: the one asked for, or, for 0, the least prime at least twice the occupied cells.
    static std::uint32_t table_size_for(std::uint32_t table_size, long long occupied)
    {
        return table_size > 0 ? table_size : prime_at_least(2 * static_cast<std::uint64_t>(std::max(1LL, occupied)));
    }

    static long long cells_of(const GridShape& shape)
    {
        return static_cast<long long>(shape.n.x) * shape.n.y * shape.n.z;
    }

    // The notice of a grid whose cells would be mostly occupied (hashed_most_occupied), built at
    // chapter 07's lambda instead.
    static void say_mostly_occupied(const GridPlan& plan, long long occupied, float built)
    {
        const cell3 n = plan.shape.n;
        char line[512];
        std::snprintf(line, sizeof line,
                      "the hashed grid: at lambda %g (%d x %d x %d cells) %.0f%% of its cells would hold objects: "
                      "they are finer than the objects (a flat scene fills its one layer), and finer cells would "
                      "slice them rather than sort them apart; built at lambda %g, chapter 07's, instead",
                      static_cast<double>(plan.lambda), n.x, n.y, n.z,
                      100.0 * static_cast<double>(occupied) / static_cast<double>(cells_of(plan.shape)),
                      static_cast<double>(built));
        notice(line);
    }

    // A lambda the notice offers instead, and what its build would hold (0: none found).
    struct Coarser {
        float lambda = 0.0f;
        std::size_t peak = 0;
    };

    // What the build will hold at its peak (hashed_build_bytes), weighed against chapter 07's dense
    // grid at dense_grid_lambda over the same objects (its plan: a pass over the objects; nothing is
    // built). Past hashed_memory_factor times that, and past hashed_memory_floor, it says so
    // (say_memory_weighed), with the largest power-of-two fractions of the lambda asked for whose
    // plans stay under the floor and within the factor (a pass over the objects and their cells for
    // each). The build goes on at the lambda asked for: memory is the user's to trade for speed
    // (finer cells test fewer objects), and nothing is answered wrong. Returns the dense grid's bytes.
    static std::size_t weigh_memory(const Objects& objects, const Bounds& scene, const Margins& margins,
                                    const GridPlan& plan, long long occupied, float asked, std::uint32_t table_size)
    {
        const int count = objects.size();
        const auto peak_of = [&](const GridPlan& p, long long occ) {
            return hashed_build_bytes(count, p.references, occ,
                                      static_cast<long long>(p.shape.n.x) * p.shape.n.y * p.shape.n.z,
                                      table_size_for(table_size, occ));
        };
        const std::size_t peak = peak_of(plan, occupied);
        std::vector<std::uint32_t> all(static_cast<std::size_t>(count));
        std::iota(all.begin(), all.end(), 0u);
        const GridPlan dense_plan = plan_grid(scene, objects, all, dense_grid_lambda, margins, max_cells_per_axis);
        const std::size_t dense = dense_build_bytes(count, dense_plan.references, dense_plan.shape.cell_count());
        const double within = hashed_memory_factor * static_cast<double>(dense);
        const double budget = std::max(hashed_memory_floor, within);
        if (static_cast<double>(peak) <= budget)
            return dense;

        // The coarser plans, halving lambda each time, until one holds no more than `within`, or the
        // grid is one cell.
        Coarser under_budget, under_within;
        float l = plan.lambda;
        for (int halvings = 0; halvings < 40 && under_within.lambda == 0.0f; ++halvings) {
            l *= 0.5f;
            const GridPlan coarser = plan_grid(scene, objects, all, l, margins, max_hashed_cells_per_axis);
            OccupancyBits bits;
            const std::size_t p = peak_of(coarser, set_bits(coarser.shape, coarser.ranges, bits));
            if (under_budget.lambda == 0.0f && static_cast<double>(p) <= budget)
                under_budget = {l, p};
            if (static_cast<double>(p) <= within)
                under_within = {l, p};
            if (coarser.shape.n == cell3(1))
                break;
        }
        say_memory_weighed(plan, occupied, count, peak, dense, asked, table_size, under_budget, under_within);
        return dense;
    }

    // The notice (common/notice.hpp) of a build that holds many times the dense grid's memory: both
    // figures, the references per object and the scene's part in it, and the lambdas that would not.
    static void say_memory_weighed(const GridPlan& plan, long long occupied, int objects, std::size_t peak,
                                   std::size_t dense, float asked, std::uint32_t table_size,
                                   const Coarser& under_budget, const Coarser& under_within)
    {
        const auto number = [](double x, const char* format) {
            char s[64];
            std::snprintf(s, sizeof s, format, x);
            return std::string(s);
        };
        const auto MB = [&](double bytes) { return number(bytes / 1e6, bytes < 1e9 ? "%.3g MB" : "%.0f MB"); };
        const auto lambda = [&](float l) { return number(static_cast<double>(l), "%g"); };
        const cell3 n = plan.shape.n;
        const double cells = static_cast<double>(n.x) * n.y * n.z;
        const bool flat = (n.x == 1) + (n.y == 1) + (n.z == 1) == 1;
        const std::string filled = number(100.0 * static_cast<double>(occupied) / cells, "%.0f%%");

        std::string line = "the hashed grid: at lambda " + lambda(plan.lambda) + " (" + std::to_string(n.x) + " x " +
                           std::to_string(n.y) + " x " + std::to_string(n.z) + " cells) its build holds up to " +
                           MB(static_cast<double>(peak)) + ", " +
                           number(static_cast<double>(peak) / std::max(1.0, static_cast<double>(dense)), "%.0f") +
                           " times the " + MB(static_cast<double>(dense)) + " of chapter 07's dense grid at lambda " +
                           lambda(dense_grid_lambda) + ": its " + std::to_string(objects) + " objects are listed in " +
                           number(static_cast<double>(plan.references) / std::max(1, objects), "%.0f") +
                           " cells each on average (an object much larger than a cell is listed in every cell it "
                           "overlaps), " +
                           (flat ? "and the scene is flat: they fill " + filled + " of the cells of its one layer"
                                 : "filling " + filled + " of the grid's cells");
        if (table_size > 0)  // the buckets' offsets and the filing's cursors
            line += ", and the " + std::to_string(table_size) + " buckets asked for (--table-size) take " +
                    MB((2.0 * table_size + 1) * sizeof(std::uint32_t)) + " of it";
        // "--lambda A would hold X MB, under 64 MB, and --lambda B Y MB, within 8 times", or either alone.
        const bool both = under_budget.lambda > 0.0f && under_budget.lambda != under_within.lambda;
        if (both)
            line += "; --lambda " + lambda(under_budget.lambda) + " would hold " +
                    MB(static_cast<double>(under_budget.peak)) + ", under " + MB(hashed_memory_floor) +
                    (under_within.lambda > 0.0f ? ", and " : "; ");
        else
            line += "; ";
        if (under_within.lambda > 0.0f)
            line += "--lambda " + lambda(under_within.lambda) + (both ? " " : " would hold ") +
                    MB(static_cast<double>(under_within.peak)) + ", within " + lambda(hashed_memory_factor) + " times";
        else
            line += "no lower lambda holds less than " + lambda(hashed_memory_factor) + " times as much";
        line += "; built at lambda " + lambda(plan.lambda) + (plan.lambda == asked ? " as asked" : "");
        notice(line);
    }

    // Every (cell, object) reference as one 64-bit key, cell above object, sorted; then one
    // HashedCell per occupied cell, in increasing address, its objects (table_.object_index) in
    // increasing number.
    std::vector<HashedCell> sort_references(const std::vector<CellRange>& ranges, long long references,
                                            long long occupied)
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
        by_address.reserve(static_cast<std::size_t>(occupied));
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

    // The cells filed by bucket, cell p in bucket bucket(p, M) (p mod M, or an open hash's; a counting
    // sort, stable: by increasing address within a bucket). A cell whose bucket lies past the table
    // is left out, the first such noted (open_build_). Returns the collisions: cells filed in a
    // bucket that already held one.
    template <class Bucket>
    long long file_by_bucket(const std::vector<HashedCell>& by_address, std::uint32_t M, Bucket&& bucket)
    {
        HashTable& t = table_;
        t.M = M;
        t.bucket_start.assign(static_cast<std::size_t>(t.M) + 1, 0);
        const auto lose = [&](std::int32_t p, std::uint32_t b) {
            if (!open_build_.lost)
                open_build_.lost = true, open_build_.lost_p = p, open_build_.lost_bucket = b;
        };
        for (const HashedCell& c : by_address) {
            const std::uint32_t b = bucket(c.p, M);
            if (b < M)
                ++t.bucket_start[b + 1];
            else
                lose(c.p, b);
        }
        long long collisions = 0;
        for (std::uint32_t b = 0; b < t.M; ++b) {
            collisions += std::max<long long>(0, static_cast<long long>(t.bucket_start[b + 1]) - 1);
            t.bucket_start[b + 1] += t.bucket_start[b];
        }
        t.cells.assign(t.bucket_start[t.M], HashedCell{-1, 0, 0});
        std::vector<std::uint32_t> fill(t.bucket_start.begin(), t.bucket_start.end() - 1);
        // The bucket asked again: a hash that answers otherwise the second time (kept in a static) would
        // write past its bucket's room; such a cell is lost instead, and the room it leaves holds no key.
        for (const HashedCell& c : by_address) {
            const std::uint32_t b = bucket(c.p, M);
            if (b < M && fill[b] < t.bucket_start[b + 1])
                t.cells[fill[b]++] = c;
            else
                lose(c.p, b);
        }
        return collisions;
    }

    // The cells filed by the open hash (EXERCISE 09.6) chosen over their addresses. A hash whose M is
    // 0 or past the budget (max_table_buckets) makes a table of no cell (1 empty bucket), noted
    // (open_build_), so that no build allocates what the budget forbids.
    long long file_by_open_hash(const std::vector<HashedCell>& by_address)
    {
        std::vector<std::int32_t> addresses(by_address.size());
        for (std::size_t i = 0; i < by_address.size(); ++i)
            addresses[i] = by_address[i].p;
        hash_ = hashing_.choose(addresses, shape_.n);
        open_build_ = {};
        if (hash_.M == 0 || hash_.M > hashing_.budget(by_address.size())) {
            notice("the hashed grid: your choose_table_hash (09.6) gave M = " + std::to_string(hash_.M) +
                   ", outside 1 to " + std::to_string(hashing_.budget(by_address.size())) +
                   " (max_table_buckets, one bucket per occupied cell): the table holds no cell, and rays find "
                   "nothing");
            open_build_.over_budget = true;
            table_.M = 1;
            table_.bucket_start.assign(2, 0);
            table_.cells.clear();
            return 0;
        }
        const long long collisions = file_by_bucket(
            by_address, hash_.M, [&](std::int32_t p, std::uint32_t) { return hashing_.bucket(hash_, p); });
        if (open_build_.lost)
            notice("the hashed grid: your bucket_of (09.6) gave cell " + std::to_string(open_build_.lost_p) +
                   " bucket " + std::to_string(open_build_.lost_bucket) + " of a table of M = " +
                   std::to_string(hash_.M) +
                   (open_build_.lost_bucket >= hash_.M ? ", past its last" : ", another than the first time asked") +
                   ": that cell is lost, and rays through it miss its objects");
        return collisions;
    }

    // One bit per cell of `shape`, set for the cells each object's range reaches (the occupied ones:
    // the same cells sort_references lists). Returns how many are set.
    static long long set_bits(const GridShape& shape, const std::vector<CellRange>& ranges, OccupancyBits& bits)
    {
        const long long cells = static_cast<long long>(shape.n.x) * shape.n.y * shape.n.z;
        bits.words.assign(static_cast<std::size_t>((cells + 63) / 64), 0);
        long long occupied = 0;
        for (const CellRange& r : ranges)
            for (int i = r.first.x; i <= r.last.x; ++i)
                for (int j = r.first.y; j <= r.last.y; ++j)
                    for (int l = r.first.z; l <= r.last.z; ++l) {
                        const int p = shape.address({i, j, l});
                        if (p < 0 || p >= cells)  // a student's 07.3 may step outside the grid
                            continue;
                        std::uint64_t& word = bits.words[static_cast<std::uint32_t>(p) >> 6];
                        const std::uint64_t bit = std::uint64_t{1} << (static_cast<std::uint32_t>(p) & 63u);
                        occupied += (word & bit) == 0;
                        word |= bit;
                    }
        return occupied;
    }

    GridShape shape_;
    HashTable table_;
    OccupancyBits bits_;
    HashedGridStats stats_;
    bool open_ = false;
    OpenHashing hashing_;
    TableHash hash_;
    OpenHashBuild open_build_;
};

}  // namespace rt
