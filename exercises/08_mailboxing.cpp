// Chapter 08, mailboxing: your exercises.
//
// Each function below states what to compute (not how); its contract is documented in
// chapters/08_mailboxing/08_mailboxing.hpp and the lesson in that folder's README.md.
// Each stub compiles and returns a harmless value, so the chapter's program always runs: with
// the stubs, the grid with mailboxes finds nothing and the picture shows only the background.
// Check your work with:  cmake --build --preset grade --target check_08
// Stuck? Hints in tiers you open one at a time: chapters/08_mailboxing/hints.md, or
// ./build/grade/hint 08.1 (tier 1, the idea), ./build/grade/hint 08.1 2 (the trap), ... 3 (the walk-through).
//
// This chapter uses chapter 07's grid and walk (07.4, 07.5) and chapter 02's objects.
#include "08_mailboxing/08_mailboxing.hpp"
#include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

#include "common/stats.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

std::uint32_t next_signature(Mailboxes& m)
{
    // EXERCISE 08.1: the next signature.
    // Return the next ray's signature, one more than the last one handed out, and remember it in m.
    // 0 means "no ray" and is never handed out: when the 32-bit counter wraps, every mailbox of m
    // must first forget its ray, and the count starts again at 1. Until then leave the mailboxes alone.
    // Lesson: "Signatures (EXERCISE 08.1)".
    // Stuck? hint 08.1 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("08.1", 1u);
}

bool mailboxed_intersect(Mailboxes& m, std::uint32_t signature, const Objects& objects, int k, const Ray& ray,
                         Interval range, ObjectHit& hit)
{
    // EXERCISE 08.2: one object through its mailbox.
    // Return whether `ray` hits object k strictly inside `range`, with `hit` filled in, testing k at
    // most once per signature: the first call for a signature makes the one counted test and leaves
    // what it found (hit or miss, kept by the caller or not) in k's mailbox; later calls are answered
    // from the mailbox, untested, each counted in Counter::mailbox_hits, a stored hit counting only
    // strictly inside the range asked now.
    // Lesson: "Through the mailbox (EXERCISE 08.2)".
    // Stuck? hint 08.2 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("08.2", false);
}

bool closest_in_cell_mailboxed(const Grid& grid, const GridWalk& walk, Mailboxes& m, std::uint32_t signature,
                               const Ray& ray, Interval range, const Objects& objects, ObjectHit& best)
{
    // EXERCISE 08.3: the cell query of 07.6, each object asked through its mailbox.
    // The contract of 07.6 (the nearest hit within the current cell, each object in the range that
    // beats `best`; return whether `best` changed), with each object asked through 08.2 for this
    // ray's `signature` in the mailboxes m. A hit beyond the cell is left, not marked done: the
    // cell that holds it will ask again and get its answer from the mailbox.
    // Lesson: "The cell query through the mailboxes (EXERCISE 08.3)".
    // Stuck? hint 08.3 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("08.3", false);
}

bool cached_intersect(RayCache& cache, std::uint32_t signature, const Objects& objects, int k, const Ray& ray,
                      Interval range, ObjectHit& hit)
{
    // EXERCISE 08.4 (open): mailboxes in 1 KB.
    // Answer as objects.intersect(k, ray, range, hit) would, bit for bit, testing k only when this
    // ray's cache (RayCache, 256 words yours to lay out) cannot answer; an answer from the cache
    // counts one Counter::mailbox_hits and no test. Any design; the grader checks the grid's answers
    // against brute force, then counts its tests per ray against the reference's.
    // Lesson: "Mailboxes in 1 KB (EXERCISE 08.4, open)".
    // Stuck? hint 08.4 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("08.4", false);
}

}  // namespace rt
