// SOLUTION BEGIN
// Chapter 08, mailboxing: the reference solution.
//
// This file is also the source of exercises/08_mailboxing.cpp: the kit's cutter drops every block
// between SOLUTION BEGIN and SOLUTION END and keeps the STUB lines as code
// (`cmake --build <build> --target cut_exercises`; a test checks that the two agree).
// SOLUTION END
// STUB // Chapter 08, mailboxing: your exercises.
// STUB //
// STUB // Each function below says what to compute and gives a hint; its contract is documented in
// STUB // chapters/08_mailboxing/08_mailboxing.hpp and the lesson in that folder's README.md.
// STUB // Each stub compiles and returns a harmless value, so the chapter's program always runs: with
// STUB // the stubs, the grid with mailboxes finds nothing and the picture shows only the background.
// STUB // Check your work with:  cmake --build --preset grade --target check_08
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
    // 1. s = m.last_signature + 1 (an unsigned 32-bit sum: after 4294967295 it is 0).
    // 2. s == 0: the counter has wrapped. Set every mailbox's ray to 0 (no ray), and s = 1.
    // 3. m.last_signature = s; return s.
    // Hint: for (Mailbox& b : m.box) b.ray = 0;
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
    // 1. Mailbox& b = m.box[k].
    // 2. b.ray == signature: this ray tested k before. count(Counter::mailbox_hits). A miss
    //    (b.t infinite) is a miss; a hit counts only when range.surrounds(b.t): then
    //    hit = {b.t, k, b.beta, b.gamma}, return true. Else return false.
    // 3. Otherwise: found = objects.intersect(k, ray, range, h) with a fresh ObjectHit h; store
    //    b = {signature, found ? h.t : infinity, h.beta, h.gamma}; when found, hit = h. Return found.
    // Hint: the stored answer is what the test found, whatever the caller does with it.
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
    // For each object k of the cell (grid.object_index[i], i from grid.cell_start[walk.p] up to, not
    // including, grid.cell_start[walk.p + 1]): when mailboxed_intersect(m, signature, objects, k,
    // ray, closer_than(range, best, k), hit) and hit.t <= walk.cell_exit(), best = hit.
    // Return whether best changed.
    // Hint: your 07.6 with one call changed.
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

}  // namespace rt
