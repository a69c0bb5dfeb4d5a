// Chapter 07's grid with mailboxes (given): the same build and walk, each cell asked with your
// 08.3, so an object met again in a later cell is answered from its mailbox instead of tested.
//
// Where the mailboxes live: one set per thread (a vector of one 16-byte Mailbox per object), made
// on the thread's first query and kept for the thread's later ones. The kit's render runs its rows
// on several threads at once, and a mailbox written by two threads would mix two rays' answers; a
// set per thread is never shared, needs no lock, and costs N x 16 bytes per thread (16 MB per
// thread for a million objects). The other answer, a small cache carried by each ray, costs no
// memory per object but forgets objects met more than a few tests ago; the lesson measures the
// first.
#pragma once

#include "07_uniform_grid/grid.hpp"
#include "08_mailboxing/08_mailboxing.hpp"

#include <atomic>
#include <cassert>
#include <cstdint>
#include <utility>

namespace rt {

class MailboxGrid final : public MarginedAccelerator {
public:
    MailboxGrid(const Objects& objects, float lambda) : MailboxGrid(UniformGrid(objects, lambda), objects.size()) {}
    // A grid built by other means (the tests build small ones by hand) over `objects` objects.
    MailboxGrid(Grid grid, int objects) : MailboxGrid(UniformGrid(std::move(grid)), objects) {}

    std::size_t bytes() const override { return grid_.bytes(); }
    void report(std::ostream& out) const override
    {
        grid_.report(out);
        out << "mailbox_bytes_per_thread=" << mailbox_bytes_per_thread() << '\n';
    }
    std::size_t mailbox_bytes_per_thread() const { return static_cast<std::size_t>(objects_) * sizeof(Mailbox); }
    const UniformGrid& grid() const { return grid_; }

    // This thread's mailboxes for this grid: made empty on the thread's first query, and again
    // when the thread last queried another grid (each grid has its own number, never reused).
    Mailboxes& mailboxes() const
    {
        ThreadMailboxes& t = thread_mailboxes();
        if (t.owner != id_) {
            t.owner = id_;
            t.set.box.assign(static_cast<std::size_t>(objects_), Mailbox{});
            t.set.last_signature = 0;
        }
        assert(t.set.box.size() == static_cast<std::size_t>(objects_));
        return t.set;
    }

private:
    // The grid's margins: it answers the rays they cover, brute force the others.
    MailboxGrid(UniformGrid grid, int objects)
        : MarginedAccelerator(grid.margins()), grid_(std::move(grid)), objects_(objects)
    {
    }

    bool closest_covered(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const override
    {
        const Grid& g = grid_.grid();
        GridWalk walk = start_walk(g.shape, ray, range);
        if (walk.missed)
            return false;  // before next_signature: a ray that meets no cell takes no signature
        Mailboxes& m = mailboxes();
        const std::uint32_t signature = next_signature(m);
        const auto query = [&](const GridWalk& w, ObjectHit& best) {
            return closest_in_cell_mailboxed(g, w, m, signature, ray, range, objects, best);
        };
        return grid_closest(g.shape, walk, ray, range, objects, hit, query, next_cell);  // (grid.hpp)
    }

    bool any_covered(const Ray& ray, Interval range, const Objects& objects) const override
    {
        const Grid& g = grid_.grid();
        GridWalk walk = start_walk(g.shape, ray, range);
        if (walk.missed)
            return false;
        Mailboxes& m = mailboxes();
        const std::uint32_t signature = next_signature(m);
        ObjectHit hit;
        const auto ask = [&](int k) { return mailboxed_intersect(m, signature, objects, k, ray, range, hit); };
        const auto any_in = [&](const GridWalk& w) { return any_listed(g, w.p, ask); };
        return grid_any(g.shape, walk, ray, range, objects, any_in, next_cell);
    }

    struct ThreadMailboxes {
        std::uint64_t owner = 0;
        Mailboxes set;
    };
    static ThreadMailboxes& thread_mailboxes()
    {
        thread_local ThreadMailboxes mine;
        return mine;
    }
    static std::uint64_t next_id()
    {
        static std::atomic<std::uint64_t> last{0};
        return ++last;
    }

    UniformGrid grid_;
    int objects_;
    std::uint64_t id_ = next_id();
};

}  // namespace rt
