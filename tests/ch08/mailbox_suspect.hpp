// Chapter 08's diagnosis of one ray the grid with mailboxes answers wrongly (tests/ch07/suspect.hpp):
// the query replayed on that ray with a copy of this thread's mailboxes as the failing query left
// them, each exercise held to its own contract, in the order the query uses them:
//  - the signature (08.1): one more than the last one handed out, remembered; at the wrap (when
//    asked: the cases about the counter's wrap) 1, every mailbox emptied;
//  - in each cell of chapter 07's walk, each object the cell lists asked through its mailbox
//    (08.2) as 08.3 asks it, in the range that beats the best so far: a first meeting makes one
//    test, answers as the test does and stores the signature with the test's answer (t = infinity
//    for a miss); a later one makes no test, counts one answer and gives the stored hit only when
//    it lies strictly inside the range asked now;
//  - then the cell's query itself (08.3), on the mailboxes as they were before those asks: it
//    answers as chapter 07's cell query does over the cell's list (the same walk without
//    mailboxes), asks each listed object once (one test or one answer each), and leaves each with
//    the ray's signature.
#pragma once

#include "08_mailboxing/mailbox_grid.hpp"
#include "tests/ch07/grid_suspect.hpp"

#include <limits>
#include <utility>

namespace rt::grader::suspect {

inline std::string show_mailbox(const Mailbox& b)
{
    std::ostringstream s;
    s.precision(9);
    s << "{ray " << b.ray << ", t " << b.t << "}";
    return s.str();
}

inline bool same(const Mailbox& a, const Mailbox& b)
{
    return a.ray == b.ray && (a.t == b.t || (std::isnan(a.t) && std::isnan(b.t))) && (a.t == infinity || (a.beta == b.beta && a.gamma == b.gamma));
}

// 08.1 on `m`: the signature it hands out, or nullopt when it breaks its promise.
inline std::optional<std::uint32_t> check_signature(Diagnosis& d, Mailboxes& m)
{
    d.check("08.1", "next_signature");
    const std::uint32_t last = m.last_signature;
    const std::uint32_t want = last == std::numeric_limits<std::uint32_t>::max() ? 1u : last + 1u;
    const std::vector<Mailbox> before = m.box;
    const std::uint32_t got = next_signature(m);
    std::ostringstream s;
    s << "after signature " << last << " it returned " << got << " (last_signature " << m.last_signature << ")";
    if (got != want || m.last_signature != want) {
        d.fail("08.1", "next_signature", s.str() + "; its contract promises " + std::to_string(want) + ", remembered in last_signature (0 is never handed out: it marks an empty mailbox)");
        return std::nullopt;
    }
    for (size_t k = 0; k < m.box.size(); ++k) {
        const Mailbox promised = want == 1u && last != 0u ? Mailbox{0u, before[k].t, before[k].beta, before[k].gamma} : before[k];
        if (m.box[k].ray != promised.ray) {
            d.fail("08.1", "next_signature", s.str() + " and left object " + std::to_string(k) + "'s mailbox holding ray " + std::to_string(m.box[k].ray) +
                                                 "; its contract promises ray " + std::to_string(promised.ray) +
                                                 (want == 1u ? " (at the wrap every mailbox is emptied, since every old signature comes round again)" : " (mailboxes are left as they are until the wrap)"));
            return std::nullopt;
        }
    }
    return got;
}

// 08.1 at the wrap, on a small set of its own: 2^32 - 1 gives 1, every mailbox emptied.
inline bool check_wrap(Diagnosis& d)
{
    Mailboxes m;
    m.box = {Mailbox{1u, 2.0f, 0.0f, 0.0f}, Mailbox{std::numeric_limits<std::uint32_t>::max(), infinity, 0.0f, 0.0f}, Mailbox{}};
    m.last_signature = std::numeric_limits<std::uint32_t>::max();
    return check_signature(d, m).has_value();
}

// 08.2 on one ask: false (and the finding) when it breaks its promise; `found` and `hit` its answer.
inline bool check_lookup(Diagnosis& d, Mailboxes& m, std::uint32_t signature, const Objects& objects, int k, const Ray& ray,
                         Interval range, bool& found, ObjectHit& hit)
{
    d.check("08.2", "mailboxed_intersect");
    const Mailbox before = m.box[k];
    const std::uint64_t tests0 = counted(local_counts(), Counter::intersection_tests);
    const std::uint64_t answers0 = counted(local_counts(), Counter::mailbox_hits);
    found = mailboxed_intersect(m, signature, objects, k, ray, range, hit);
    const std::uint64_t tests = counted(local_counts(), Counter::intersection_tests) - tests0;
    const std::uint64_t answers = counted(local_counts(), Counter::mailbox_hits) - answers0;
    const Mailbox after = m.box[k];
    std::ostringstream at;
    at.precision(9);
    at << "object " << k << " asked by ray " << signature << " in t " << show_range(range) << ", its mailbox " << show_mailbox(before) << ": it ";
    const auto fail = [&](const std::string& what) {
        d.fail("08.2", "mailboxed_intersect", at.str() + what);
        return false;
    };
    if (before.ray != signature) {
        ObjectHit fresh;
        const bool want = objects.intersect(k, ray, range, fresh);
        if (tests != 1 || answers != 0)
            return fail("made " + std::to_string(tests) + " tests and counted " + std::to_string(answers) + " answers; its contract promises one test, no answer, at a first meeting");
        if (found != want || (want && (hit.t != fresh.t || hit.object != k || hit.beta != fresh.beta || hit.gamma != fresh.gamma)))
            return fail("answered " + std::string(found ? show(hit) : "no hit") + "; its contract promises the test's answer, " + (want ? show(fresh) : "no hit"));
        const Mailbox promised{signature, want ? fresh.t : infinity, want ? fresh.beta : after.beta, want ? fresh.gamma : after.gamma};
        if (!same(after, promised))
            return fail("left the mailbox " + show_mailbox(after) + "; its contract promises " + show_mailbox(promised) + " (the signature and what the test found, t = infinity for a miss)");
        return true;
    }
    const bool want = range.surrounds(before.t);
    if (tests != 0 || answers != 1)
        return fail("made " + std::to_string(tests) + " tests and counted " + std::to_string(answers) + " answers; its contract promises no test and one answer from the mailbox");
    if (found != want || (want && (hit.t != before.t || hit.object != k || hit.beta != before.beta || hit.gamma != before.gamma)))
        return fail("answered " + std::string(found ? show(hit) : "no hit") + "; its contract promises " +
                    (want ? "the stored hit, object " + std::to_string(k) + " at t = " + show_t(before.t) : std::string("no hit (the stored t is not strictly inside the range asked now)")));
    if (!same(after, before))
        return fail("changed the mailbox to " + show_mailbox(after) + "; its contract promises it left as it was when answering from it");
    return true;
}

// Chapter 08's diagnosis of `ray` over `range` through `grid`; `wrap_too` checks 08.1 at the wrap
// first (the cases about the counter's wrap).
inline std::string diagnose_mailboxed(const MailboxGrid& grid, const Ray& ray, Interval range, const Objects& objects, bool wrap_too = false)
{
    Diagnosis d;
    d.exercised = "08.1-08.3 (with chapter 07's grid and walk)";
    if (wrap_too && !check_wrap(d))
        return d.text();
    const Grid& g = grid.grid().grid();
    GridWalk w = start_walk(g.shape, ray, range);
    if (w.missed) {
        d.check("08.1", "next_signature");
        return d.text();
    }
    Mailboxes m = grid.mailboxes();  // a copy: the grid's own are left alone
    const std::optional<std::uint32_t> signature = check_signature(d, m);
    if (!signature)
        return d.text();
    ObjectHit best;
    do {
        const std::vector<std::uint32_t> list(g.object_index.begin() + g.cell_start[w.p], g.object_index.begin() + g.cell_start[w.p + 1]);
        // 08.2 as 08.3 asks it, then the mailboxes put back as they were for 08.3 itself.
        std::vector<std::pair<int, Mailbox>> saved;
        for (const std::uint32_t k : list)
            saved.emplace_back(static_cast<int>(k), m.box[k]);
        ObjectHit asked = best;
        for (const std::uint32_t object : list) {
            const int k = static_cast<int>(object);
            bool found = false;
            ObjectHit hit;
            if (!check_lookup(d, m, *signature, objects, k, ray, closer_than(range, asked, k), found, hit))
                return d.text();
            if (found && hit.t <= w.cell_exit())
                asked = hit;
        }
        for (auto it = saved.rbegin(); it != saved.rend(); ++it)
            m.box[it->first] = it->second;
        d.check("08.3", "closest_in_cell_mailboxed");
        ObjectHit got_best = best, want_best = best;
        const std::uint64_t tests0 = counted(local_counts(), Counter::intersection_tests);
        const std::uint64_t answers0 = counted(local_counts(), Counter::mailbox_hits);
        const bool got = closest_in_cell_mailboxed(g, w, m, *signature, ray, range, objects, got_best);
        const std::uint64_t asks = counted(local_counts(), Counter::intersection_tests) - tests0 + counted(local_counts(), Counter::mailbox_hits) - answers0;
        const bool want = cell_query_promised(list, ray, range, w.cell_exit(), objects, want_best);
        const std::string differs = cell_differs(got, got_best, want, want_best, w, best, list.size());
        if (!differs.empty()) {
            d.fail("08.3", "closest_in_cell_mailboxed", differs);
            return d.text();
        }
        if (asks != list.size()) {
            d.fail("08.3", "closest_in_cell_mailboxed", "in cell p = " + std::to_string(w.p) + " it asked " + std::to_string(asks) + " times (tests and answers) for the " +
                                                            std::to_string(list.size()) + " objects the cell lists; its contract promises each asked exactly once, through its mailbox (08.2)");
            return d.text();
        }
        for (const std::uint32_t k : list)
            if (m.box[k].ray != *signature) {
                d.fail("08.3", "closest_in_cell_mailboxed", "in cell p = " + std::to_string(w.p) + " it left object " + std::to_string(k) + "'s mailbox " + show_mailbox(m.box[k]) +
                                                                "; its contract promises every listed object asked through its mailbox (08.2), which then holds the ray's signature " +
                                                                std::to_string(*signature));
                return d.text();
            }
        best = want_best;
        if (want)
            break;
    } while (next_cell(w));
    // The any-hit query: a signature of its own, each listed object asked in the whole range until
    // one is hit.
    GridWalk a = start_walk(g.shape, ray, range);
    const std::optional<std::uint32_t> any_signature = check_signature(d, m);
    if (!any_signature)
        return d.text();
    do {
        for (std::uint32_t i = g.cell_start[a.p]; i < g.cell_start[a.p + 1]; ++i) {
            bool found = false;
            ObjectHit hit;
            if (!check_lookup(d, m, *any_signature, objects, static_cast<int>(g.object_index[i]), ray, range, found, hit))
                return d.text();
            if (found)
                return d.text();
        }
    } while (next_cell(a));
    return d.text();
}

}  // namespace rt::grader::suspect
