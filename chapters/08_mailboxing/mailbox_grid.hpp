// Chapter 07's grid with mailboxes (given): the same build and walk, each cell asked with your
// 08.3, so an object met again in a later cell is answered from its mailbox instead of tested.
//
// Where the mailboxes live: one set per thread (a vector of one 16-byte Mailbox per object), made
// on the thread's first query and kept for the thread's later ones. The kit's render runs its rows
// on several threads at once, and a mailbox written by two threads would mix two rays' answers; a
// set per thread is never shared, needs no lock, and costs N x 16 bytes per thread (16 MB per
// thread for a million objects). The other answer, a small cache per thread that remembers only
// the current ray's last few hundred objects, costs a fixed 1 KB whatever the scene but forgets what
// it has no room for: RayCacheGrid below walks the same grid through your cache (EXERCISE 08.4,
// open), and the lesson measures both.
#pragma once

#include "07_uniform_grid/grid.hpp"
#include "08_mailboxing/08_mailboxing.hpp"

#include <atomic>
#include <cassert>
#include <cstdint>
#include <utility>

namespace rt {

// A new number for each grid made, never reused: a thread's mailboxes or cache name the grid they
// belong to, and are made afresh when the thread queries another grid.
inline std::uint64_t next_grid_id()
{
    static std::atomic<std::uint64_t> last{0};
    return ++last;
}

class MailboxGrid final : public Accelerator {
public:
    MailboxGrid(const Objects& objects, float lambda) : grid_(objects, lambda), objects_(objects.size()) {}
    // A grid built by other means (the tests build small ones by hand) over `objects` objects.
    MailboxGrid(Grid grid, int objects) : grid_(std::move(grid)), objects_(objects) {}

    bool closest(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const override
    {
        if (!grid_.margins().covers(ray, range))
            return brute_force().closest(ray, range, objects, hit);  // outside the margins' reach (grid.hpp)
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

    bool any(const Ray& ray, Interval range, const Objects& objects) const override
    {
        if (!grid_.margins().covers(ray, range))
            return brute_force().any(ray, range, objects);
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
    struct ThreadMailboxes {
        std::uint64_t owner = 0;
        Mailboxes set;
    };
    static ThreadMailboxes& thread_mailboxes()
    {
        thread_local ThreadMailboxes mine;
        return mine;
    }
    UniformGrid grid_;
    int objects_;
    std::uint64_t id_ = next_grid_id();
};

// A cell's closest hit asked through a ray cache (08.4), by 07.6's rules (as 08.3 asks through the
// mailboxes): each object the cell lists, in the range that beats `best`, kept when no farther than
// the cell's exit. Returns whether `best` changed.
inline bool closest_in_cell_cached(const Grid& grid, const GridWalk& walk, RayCache& cache, std::uint32_t signature,
                                   const Ray& ray, Interval range, const Objects& objects, ObjectHit& best)
{
    bool found = false;
    const float exit = walk.cell_exit();
    for (std::uint32_t i = grid.cell_start[walk.p]; i < grid.cell_start[walk.p + 1]; ++i) {
        const int k = static_cast<int>(grid.object_index[i]);
        ObjectHit hit;
        if (cached_intersect(cache, signature, objects, k, ray, closer_than(range, best, k), hit) && hit.t <= exit) {
            best = hit;
            found = true;
        }
    }
    return found;
}

// Chapter 07's grid with a ray cache per thread (EXERCISE 08.4, open) in place of the mailboxes:
// ray_cache_bytes per thread, whatever the scene. Each ray that meets a cell takes the thread's
// next signature (1, 2, ..., 2^32 - 1, then 1 again with every word of the cache 0, as 08.1 does
// for the mailboxes) and asks each object through your cached_intersect.
class RayCacheGrid final : public Accelerator {
public:
    RayCacheGrid(const Objects& objects, float lambda) : grid_(objects, lambda) {}
    // A grid built by other means (the tests build small ones by hand).
    explicit RayCacheGrid(Grid grid) : grid_(std::move(grid)) {}

    bool closest(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const override
    {
        if (!grid_.margins().covers(ray, range))
            return brute_force().closest(ray, range, objects, hit);  // outside the margins' reach (grid.hpp)
        const Grid& g = grid_.grid();
        GridWalk walk = start_walk(g.shape, ray, range);
        if (walk.missed)
            return false;
        ThreadCache& t = thread_cache();
        const std::uint32_t signature = t.next();
        const auto query = [&](const GridWalk& w, ObjectHit& best) {
            return closest_in_cell_cached(g, w, t.cache, signature, ray, range, objects, best);
        };
        return grid_closest(g.shape, walk, ray, range, objects, hit, query, next_cell);
    }

    bool any(const Ray& ray, Interval range, const Objects& objects) const override
    {
        if (!grid_.margins().covers(ray, range))
            return brute_force().any(ray, range, objects);
        const Grid& g = grid_.grid();
        GridWalk walk = start_walk(g.shape, ray, range);
        if (walk.missed)
            return false;
        ThreadCache& t = thread_cache();
        const std::uint32_t signature = t.next();
        ObjectHit hit;
        const auto ask = [&](int k) { return cached_intersect(t.cache, signature, objects, k, ray, range, hit); };
        const auto any_in = [&](const GridWalk& w) { return any_listed(g, w.p, ask); };
        return grid_any(g.shape, walk, ray, range, objects, any_in, next_cell);
    }

    std::size_t bytes() const override { return grid_.bytes(); }
    void report(std::ostream& out) const override
    {
        grid_.report(out);
        out << "mailbox_bytes_per_thread=" << sizeof(RayCache) << '\n';
    }
    const UniformGrid& grid() const { return grid_; }

    // This thread's cache and ray counter for this grid: fresh (every word 0, no signature handed
    // out) on the thread's first query, and again when the thread last queried another grid.
    struct ThreadCache {
        std::uint64_t owner = 0;
        std::uint32_t last_signature = 0;
        RayCache cache;
        std::uint32_t next()
        {
            if (++last_signature == 0) {  // the counter wrapped: no word may hold a signature handed out again
                cache = RayCache{};
                last_signature = 1;
            }
            return last_signature;
        }
    };
    ThreadCache& thread_cache() const
    {
        thread_local ThreadCache mine;
        if (mine.owner != id_)
            mine = ThreadCache{id_, 0, RayCache{}};
        return mine;
    }

private:
    UniformGrid grid_;
    std::uint64_t id_ = next_grid_id();
};

}  // namespace rt
