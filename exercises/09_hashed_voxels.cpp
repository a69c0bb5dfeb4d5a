// Chapter 09, hashed voxels: your exercises.
//
// Each function below states what to compute (not how); its contract is documented in
// chapters/09_hashed_voxels/09_hashed_voxels.hpp and the lesson in that folder's README.md.
// Each stub compiles and returns a harmless value, so the chapter's program always runs: with
// the stubs, the hashed grid finds nothing and the picture shows only the background.
// Check your work with:  cmake --build --preset grade --target check_09
// Stuck? Hints in tiers you open one at a time: chapters/09_hashed_voxels/hints.md, or
// ./build/grade/hint 09.1 (tier 1, the idea), ./build/grade/hint 09.1 2 (the trap), ... 3 (the walk-through).
//
// This chapter uses chapter 07's grid shape and walk (07.4, 07.5) and chapter 02's objects.
#include "09_hashed_voxels/09_hashed_voxels.hpp"
#include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

#include "common/stats.hpp"

#include <algorithm>

namespace rt {

std::int32_t residue_step(std::int32_t step_p, std::uint32_t M)
{
    // EXERCISE 09.1: the residue a step adds
    // Return step_p mod M as a number with step_p's own sign, strictly between -M and M: what one
    // step along an axis adds to the walk's residue r. Negative steps, steps larger than M,
    // multiples of M and M = 1 all occur; M is any 32-bit unsigned size. Nudge: step_p is signed
    // and M is not; mind what C++ does when the two meet.
    // Lesson: "The residue without division (EXERCISES 09.1 and 09.2)".
    // Stuck? hint 09.1 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("09.1", 0);
}

std::uint32_t advance_residue(std::uint32_t r, std::int32_t step, std::uint32_t M)
{
    // EXERCISE 09.2: the residue after a step
    // Return r + step brought back into [0, M), for r in [0, M) and step in (-M, M), with no
    // division or remainder. The sum can be negative, can land exactly on M, and can be larger
    // than any 32-bit signed number.
    // DETAIL BEGIN: how, step by step (kept by an introductory course's handout, CONTRACTS=detailed)
    // One comparison and at most one correction by M.
    // DETAIL END
    // Lesson: "The residue without division (EXERCISES 09.1 and 09.2)".
    // Stuck? hint 09.2 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("09.2", r);
}

bool occupied(const OccupancyBits& bits, std::int32_t p)
{
    // EXERCISE 09.3: the occupancy bit
    // Return whether cell p's bit is set in the array (OccupancyBits in the header: 64 bits to a
    // word, counted from word 0's least significant bit). p is a cell address, 0 or more.
    // Nudge: whatever you shift must be 64 bits wide.
    // Lesson: "The occupancy bits (EXERCISES 09.3 and 09.5)".
    // Stuck? hint 09.3 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("09.3", false);
}

const HashedCell* find_cell(const HashTable& table, std::int32_t p, std::uint32_t r)
{
    // EXERCISE 09.4: the cell in its bucket
    // Return a pointer to the table's own cell whose key is p, looking only in bucket r (r = p mod M;
    // HashTable in the header says where a bucket's cells lie), or nullptr when the bucket holds no
    // cell with key p: it may be empty, or hold only other cells that share the residue.
    // Lesson: "The table".
    // Stuck? hint 09.4 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("09.4", nullptr);
}

bool closest_in_hashed_cell(const HashTable& table, const OccupancyBits& bits, const GridWalk& walk, std::uint32_t r,
                            const Ray& ray, Interval range, const Objects& objects, ObjectHit& best)
{
    // EXERCISE 09.5: the cell query on the hashed grid
    // Chapter 07's cell query (07.6) for the cell the walk is in (its residue is r), with the table
    // read only when the cell's occupancy bit is on. Each call counts once: a skipped lookup
    // (Counter::table_lookups_skipped) when the bit is off, else a lookup (Counter::table_lookups),
    // even when the table then holds no such cell. Returns whether best changed.
    // Lesson: "The occupancy bits (EXERCISES 09.3 and 09.5)", and chapter 07's "The cell query
    // (EXERCISE 07.6): a hit beyond the cell must not end the walk".
    // Stuck? hint 09.5 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("09.5", false);
}

TableHash choose_table_hash(const std::vector<std::int32_t>& cells, cell3 n)
{
    // EXERCISE 09.6 (open): the hash and the table size.
    // Choose the table's size M (1 to max_table_buckets(cells.size()): at least one occupied cell a
    // bucket) and the numbers your bucket_of reads (TableHash), from the occupied cells' addresses
    // (increasing) and the grid's resolution n. Any design; the grader checks that the table finds
    // every occupied cell and no other and that the grid answers as brute force does, then counts
    // the keys compared per lookup against the reference's.
    // Lesson: "The hash and the table size (EXERCISE 09.6, open)".
    // Stuck? hint 09.6 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("09.6", TableHash{});
}

std::uint32_t bucket_of(const TableHash& hash, std::int32_t p)
{
    // EXERCISE 09.6 (open): the bucket of cell p, in [0, hash.M), read from `hash` alone.
    // Lesson: "The hash and the table size (EXERCISE 09.6, open)".
    return stub("09.6", 0u);
}

}  // namespace rt
