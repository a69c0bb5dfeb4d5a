// SOLUTION BEGIN
// Chapter 09, hashed voxels: the reference solution.
//
// This file is also the source of exercises/09_hashed_voxels.cpp: the kit's cutter drops every
// block between SOLUTION BEGIN and SOLUTION END and keeps the STUB lines as code
// (`cmake --build <build> --target cut_exercises`; a test checks that the two agree).
// SOLUTION END
// STUB // Chapter 09, hashed voxels: your exercises.
// STUB //
// STUB // Each function below says what to compute and gives a hint; its contract is documented in
// STUB // chapters/09_hashed_voxels/09_hashed_voxels.hpp and the lesson in that folder's README.md.
// STUB // Each stub compiles and returns a harmless value, so the chapter's program always runs: with
// STUB // the stubs, the hashed grid finds nothing and the picture shows only the background.
// STUB // Check your work with:  cmake --build --preset grade --target check_09
// STUB //
// STUB // This chapter uses chapter 07's grid shape and walk (07.4, 07.5) and chapter 02's objects.
#include "09_hashed_voxels/09_hashed_voxels.hpp"
// STUB #include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

#include "common/stats.hpp"

namespace rt {

std::int32_t residue_step(std::int32_t step_p, std::uint32_t M)
{
    // EXERCISE 09.1: step_p mod M, keeping step_p's sign.
    // Hint: C++'s % on signed numbers keeps the sign of the left one (-7 % 5 is -2); cast M to
    // std::int64_t first so that the unsigned M does not turn a negative step_p unsigned.
    // SOLUTION BEGIN
    return static_cast<std::int32_t>(static_cast<std::int64_t>(step_p) % static_cast<std::int64_t>(M));
    // SOLUTION END
    // STUB return stub("09.1", 0);
}

std::uint32_t advance_residue(std::uint32_t r, std::int32_t step, std::uint32_t M)
{
    // EXERCISE 09.2: r + step, brought back into [0, M) with one addition or subtraction of M.
    // Hint: compute in std::int64_t (r + step may be negative, or pass M); no % here.
    // SOLUTION BEGIN
    std::int64_t next = static_cast<std::int64_t>(r) + step;
    if (next >= static_cast<std::int64_t>(M))
        next -= M;
    else if (next < 0)
        next += M;
    return static_cast<std::uint32_t>(next);
    // SOLUTION END
    // STUB return stub("09.2", r);
}

bool occupied(const OccupancyBits& bits, std::int32_t p)
{
    // EXERCISE 09.3: bit p: word p / 64 (p >> 6), bit p % 64 (p & 63) of it.
    // Hint: (word >> bit) & 1, with the word a std::uint64_t.
    // SOLUTION BEGIN
    const auto u = static_cast<std::uint32_t>(p);
    return (bits.words[u >> 6] >> (u & 63u)) & 1u;
    // SOLUTION END
    // STUB return stub("09.3", false);
}

const HashedCell* find_cell(const HashTable& table, std::int32_t p, std::uint32_t r)
{
    // EXERCISE 09.4: the bucket's cells are table.cells[table.bucket_start[r]] up to, not including,
    // table.cells[table.bucket_start[r + 1]]: return the one whose p matches, else nullptr.
    // Hint: the residue alone does not name a cell: compare the keys.
    // SOLUTION BEGIN
    for (std::uint32_t i = table.bucket_start[r]; i < table.bucket_start[r + 1]; ++i)
        if (table.cells[i].p == p)
            return &table.cells[i];
    return nullptr;
    // SOLUTION END
    // STUB return stub("09.4", nullptr);
}

bool closest_in_hashed_cell(const HashTable& table, const OccupancyBits& bits, const GridWalk& walk, std::uint32_t r,
                            const Ray& ray, Interval range, const Objects& objects, ObjectHit& best)
{
    // EXERCISE 09.5: the cell query on the hashed grid.
    // 1. !occupied(bits, walk.p): count(Counter::table_lookups_skipped) and return false.
    // 2. count(Counter::table_lookups); cell = find_cell(table, walk.p, r); none: return false.
    // 3. For each object k = table.object_index[i], i from cell->first up to cell->first +
    //    cell->count: 07.6's test (objects.intersect in closer_than(range, best, k), kept when
    //    hit.t <= walk.cell_exit()). Return whether best changed.
    // SOLUTION BEGIN
    if (!occupied(bits, walk.p)) {
        count(Counter::table_lookups_skipped);
        return false;
    }
    count(Counter::table_lookups);
    const HashedCell* cell = find_cell(table, walk.p, r);
    if (!cell)
        return false;
    bool found = false;
    const float exit = walk.cell_exit();
    for (std::uint32_t i = cell->first; i < cell->first + cell->count; ++i) {
        const int k = static_cast<int>(table.object_index[i]);
        ObjectHit hit;
        if (objects.intersect(k, ray, closer_than(range, best, k), hit) && hit.t <= exit) {
            best = hit;
            found = true;
        }
    }
    return found;
    // SOLUTION END
    // STUB return stub("09.5", false);
}

}  // namespace rt
