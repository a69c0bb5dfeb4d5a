// Chapter 09, hashed voxels: your exercises.
//
// Each function below says what to compute and gives a hint; its contract is documented in
// chapters/09_hashed_voxels/09_hashed_voxels.hpp and the lesson in that folder's README.md.
// Each stub compiles and returns a harmless value, so the chapter's program always runs: with
// the stubs, the hashed grid finds nothing and the picture shows only the background.
// Check your work with:  cmake --build --preset grade --target check_09
//
// This chapter uses chapter 07's grid shape and walk (07.4, 07.5) and chapter 02's objects.
#include "09_hashed_voxels/09_hashed_voxels.hpp"
#include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

#include "common/stats.hpp"

namespace rt {

std::int32_t residue_step(std::int32_t step_p, std::uint32_t M)
{
    // EXERCISE 09.1: step_p mod M, keeping step_p's sign.
    // Hint: C++'s % on signed numbers keeps the sign of the left one (-7 % 5 is -2); cast M to
    // std::int64_t first so that the unsigned M does not turn a negative step_p unsigned.
    return stub("09.1", 0);
}

std::uint32_t advance_residue(std::uint32_t r, std::int32_t step, std::uint32_t M)
{
    // EXERCISE 09.2: r + step, brought back into [0, M) with one addition or subtraction of M.
    // Hint: compute in std::int64_t (r + step may be negative, or pass M); no % here.
    return stub("09.2", r);
}

bool occupied(const OccupancyBits& bits, std::int32_t p)
{
    // EXERCISE 09.3: bit p: word p / 64 (p >> 6), bit p % 64 (p & 63) of it.
    // Hint: (word >> bit) & 1, with the word a std::uint64_t.
    return stub("09.3", false);
}

const HashedCell* find_cell(const HashTable& table, std::int32_t p, std::uint32_t r)
{
    // EXERCISE 09.4: the bucket's cells are table.cells[table.bucket_start[r]] up to, not including,
    // table.cells[table.bucket_start[r + 1]]: return the one whose p matches, else nullptr.
    // Hint: the residue alone does not name a cell: compare the keys.
    return stub("09.4", nullptr);
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
    return stub("09.5", false);
}

}  // namespace rt
