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

// This thread's memory of type State for the grid numbered `grid`: made by make() on the thread's
// first query, and again when the thread last queried another grid. A thread owns it alone.
template <class State, class Make>
State& this_threads(std::uint64_t grid, Make&& make)
{
    thread_local std::pair<std::uint64_t, State> mine{0, State{}};
    if (mine.first != grid)
        mine = {grid, make()};
    return mine.second;
}

// The walk of a grid that remembers what each ray tested (the mailboxes, the ray cache), for a ray
// its margins cover (MarginedAccelerator, grid.hpp): a ray that meets no cell takes no signature;
// otherwise begin() hands out the ray's signature, and each cell is asked with cell(grid, walk,
// signature, best) for the closest hit, each listed object with ask(signature, k, hit) for any hit.
template <class Begin, class Cell>
bool remembering_closest(const UniformGrid& u, const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit,
                         Begin&& begin, Cell&& cell)
{
    const Grid& g = u.grid();
    GridWalk walk = start_walk(g.shape, ray, range);
    if (walk.missed)
        return false;
    const std::uint32_t signature = begin();
    const auto query = [&](const GridWalk& w, ObjectHit& best) { return cell(g, w, signature, best); };
    return grid_closest(g.shape, walk, ray, range, objects, hit, query, next_cell);
}

template <class Begin, class Ask>
bool remembering_any(const UniformGrid& u, const Ray& ray, Interval range, const Objects& objects, Begin&& begin, Ask&& ask)
{
    const Grid& g = u.grid();
    GridWalk walk = start_walk(g.shape, ray, range);
    if (walk.missed)
        return false;
    const std::uint32_t signature = begin();
    ObjectHit hit;
    const auto any_in = [&](const GridWalk& w) { return any_listed(g, w.p, [&](int k) { return ask(signature, k, hit); }); };
    return grid_any(g.shape, walk, ray, range, objects, any_in, next_cell);
}

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
        Mailboxes& m = this_threads<Mailboxes>(id_, [&] {
            Mailboxes fresh;
            fresh.box.assign(static_cast<std::size_t>(objects_), Mailbox{});
            return fresh;
        });
        assert(m.box.size() == static_cast<std::size_t>(objects_));
        return m;
    }

private:
    // The grid's margins: it answers the rays they cover, brute force the others.
    MailboxGrid(UniformGrid grid, int objects)
        : MarginedAccelerator(grid.margins()), grid_(std::move(grid)), objects_(objects)
    {
    }

    bool closest_covered(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const override
    {
        Mailboxes* m = nullptr;
        return remembering_closest(
            grid_, ray, range, objects, hit, [&] { return next_signature(*(m = &mailboxes())); },
            [&](const Grid& g, const GridWalk& w, std::uint32_t signature, ObjectHit& best) {
                return closest_in_cell_mailboxed(g, w, *m, signature, ray, range, objects, best);
            });
    }

    bool any_covered(const Ray& ray, Interval range, const Objects& objects) const override
    {
        Mailboxes* m = nullptr;
        return remembering_any(grid_, ray, range, objects, [&] { return next_signature(*(m = &mailboxes())); },
                               [&](std::uint32_t signature, int k, ObjectHit& hit) {
                                   return mailboxed_intersect(*m, signature, objects, k, ray, range, hit);
                               });
    }

    UniformGrid grid_;
    int objects_;
    std::uint64_t id_ = next_grid_id();
};

// A cell's closest hit by 07.6's rules, each object the cell lists asked with ask(k, range, hit) (a
// ray cache's, 08.4; the grader's check of each call) in the range that beats `best`, kept when no
// farther than the cell's exit. Returns whether `best` changed.
template <class Ask>
bool closest_in_cell_asking(const Grid& grid, const GridWalk& walk, Interval range, ObjectHit& best, Ask&& ask)
{
    return closest_in_listed([&](auto&& f) { for_each_listed(grid, walk.p, f); }, walk.cell_exit(), range, best, ask);
}

// One thread's ray cache and ray counter (RayCacheGrid): signatures 1, 2, ..., 2^32 - 1, then 1
// again with every word of the cache 0, as 08.1 does for the mailboxes.
struct ThreadRayCache {
    std::uint32_t last_signature = 0;
    RayCache cache;

    std::uint32_t next()
    {
        if (++last_signature == 0) {  // wrapped: no word may hold a signature handed out again
            cache = RayCache{};
            last_signature = 1;
        }
        return last_signature;
    }
};

// Chapter 07's grid with a ray cache per thread (EXERCISE 08.4, open) in place of the mailboxes:
// ray_cache_bytes per thread, whatever the scene. Each ray that meets a cell takes the thread's
// next signature and asks each object through your cached_intersect.
class RayCacheGrid final : public MarginedAccelerator {
public:
    RayCacheGrid(const Objects& objects, float lambda) : RayCacheGrid(UniformGrid(objects, lambda)) {}

    std::size_t bytes() const override { return grid_.bytes(); }
    void report(std::ostream& out) const override
    {
        grid_.report(out);
        out << "mailbox_bytes_per_thread=" << sizeof(RayCache) << '\n';
    }
    const UniformGrid& grid() const { return grid_; }

    // This thread's cache and counter for this grid: fresh on the thread's first query, and again
    // when the thread last queried another grid.
    ThreadRayCache& thread_cache() const
    {
        return this_threads<ThreadRayCache>(id_, [] { return ThreadRayCache{}; });
    }

private:
    explicit RayCacheGrid(UniformGrid grid) : MarginedAccelerator(grid.margins()), grid_(std::move(grid)) {}

    bool closest_covered(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const override
    {
        ThreadRayCache& t = thread_cache();
        return remembering_closest(grid_, ray, range, objects, hit, [&] { return t.next(); },
                                   [&](const Grid& g, const GridWalk& w, std::uint32_t signature, ObjectHit& best) {
                                       return closest_in_cell_asking(g, w, range, best, [&](int k, Interval r, ObjectHit& h) {
                                           return cached_intersect(t.cache, signature, objects, k, ray, r, h);
                                       });
                                   });
    }

    bool any_covered(const Ray& ray, Interval range, const Objects& objects) const override
    {
        ThreadRayCache& t = thread_cache();
        return remembering_any(grid_, ray, range, objects, [&] { return t.next(); },
                               [&](std::uint32_t signature, int k, ObjectHit& hit) {
                                   return cached_intersect(t.cache, signature, objects, k, ray, range, hit);
                               });
    }

    UniformGrid grid_;
    std::uint64_t id_ = next_grid_id();
};

}  // namespace rt
