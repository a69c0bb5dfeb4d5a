// SOLUTION BEGIN
// Chapter 08, mailboxing: the reference solution.
//
// This file is also the source of exercises/08_mailboxing.cpp: the kit's cutter drops every block
// between SOLUTION BEGIN and SOLUTION END and keeps the STUB lines as code
// (`cmake --build <build> --target cut_exercises`; a test checks that the two agree).
// SOLUTION END
// STUB // Chapter 08, mailboxing: your exercises.
// STUB //
// STUB // Each function below states what to compute (not how); its contract is documented in
// STUB // chapters/08_mailboxing/08_mailboxing.hpp and the lesson in that folder's README.md.
// STUB // Each stub compiles and returns a harmless value, so the chapter's program always runs: with
// STUB // the stubs, the grid with mailboxes finds nothing and the picture shows only the background.
// STUB // Check your work with:  cmake --build --preset grade --target check_08
// STUB // Stuck? Hints in tiers you open one at a time: chapters/08_mailboxing/hints.md, or
// STUB // ./build/grade/hint 08.1 (tier 1, the idea), ./build/grade/hint 08.1 2 (the trap), ... 3 (the walk-through).
// STUB //
// STUB // This chapter uses chapter 07's grid and walk (07.4, 07.5) and chapter 02's objects.
#include "08_mailboxing/08_mailboxing.hpp"
// STUB #include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

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
    // SOLUTION BEGIN
    std::uint32_t s = m.last_signature + 1u;
    if (s == 0u) {
        // Every stored signature may come round again: forget them all.
        for (Mailbox& b : m.box)
            b.ray = 0u;
        s = 1u;
    }
    m.last_signature = s;
    return s;
    // SOLUTION END
    // STUB return stub("08.1", 1u);
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
    // SOLUTION BEGIN
    Mailbox& b = m.box[k];
    if (b.ray == signature) {
        count(Counter::mailbox_hits);
        if (!range.surrounds(b.t))
            return false;  // a miss (t = infinity), or a hit no longer inside the range
        hit = {b.t, k, b.beta, b.gamma};
        return true;
    }
    ObjectHit h;
    const bool found = objects.intersect(k, ray, range, h);
    b = {signature, found ? h.t : infinity, h.beta, h.gamma};
    if (found)
        hit = h;
    return found;
    // SOLUTION END
    // STUB return stub("08.2", false);
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
    // SOLUTION BEGIN
    bool found = false;
    const float exit = walk.cell_exit();
    for (std::uint32_t i = grid.cell_start[walk.p]; i < grid.cell_start[walk.p + 1]; ++i) {
        const int k = static_cast<int>(grid.object_index[i]);
        ObjectHit hit;
        if (mailboxed_intersect(m, signature, objects, k, ray, closer_than(range, best, k), hit) && hit.t <= exit) {
            best = hit;
            found = true;
        }
    }
    return found;
    // SOLUTION END
    // STUB return stub("08.3", false);
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
    // SOLUTION BEGIN
    // The reference: a set-associative cache of the objects this ray missed, with 08.1's signature
    // trick once per set. 32 sets of 8 words, object k in set k mod 32: {the signature the set's
    // keys belong to, the next way to fill, 6 keys of k + 1}. A set holding another ray's signature
    // is emptied when this ray first reaches it; a full set forgets its oldest key (round robin). A
    // hit is not kept: an object hit beyond its cell is tested again in the next cell that lists it.
    constexpr std::uint32_t sets = 32, set_words = 8, ways = 6;
    std::uint32_t* set = cache.word.data() + set_words * (static_cast<std::uint32_t>(k) % sets);
    const std::uint32_t key = static_cast<std::uint32_t>(k) + 1;
    if (set[0] != signature) {
        std::fill(set, set + set_words, 0u);
        set[0] = signature;
    }
    std::uint32_t* keys = set + 2;
    if (std::find(keys, keys + ways, key) != keys + ways) {
        count(Counter::mailbox_hits);
        return false;  // a miss this ray already tested
    }
    if (objects.intersect(k, ray, range, hit))
        return true;
    keys[set[1]] = key;
    set[1] = (set[1] + 1) % ways;
    return false;
    // SOLUTION END
    // STUB return stub("08.4", false);
}

}  // namespace rt
