// Counters (rays by kind, intersection tests) and a timer, for `--stats` and the trade tables.
//
// Each thread counts into its own thread_local block, with no atomics on the hot path, and adds it
// to the global totals once, when its share of a render is done (flush_counters). The block is an
// inline variable defined here, so counting a test compiles to one increment of thread-local
// memory, not a call: the acceleration chapters (07-10) measure times that a call per test would
// distort.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace rt {

enum class Counter {
    primary_rays,
    shadow_rays,
    reflected_rays,
    refracted_rays,
    intersection_tests,
    // Counted only by the classic NFF test mode (chapter 04's --classic), which reports them under
    // the SPD names (print_classic_stats); print_stats leaves them out.
    primary_hits,
    secondary_hits,
    shadow_blocked,
    // Counted by the acceleration structures (chapters 07-10), which report them in their own
    // --stats lines.
    cells_visited,
    mailbox_hits,  // object tests answered from a mailbox (chapter 08), not counted as tests
    table_lookups,          // hash-table lookups of the hashed grid (chapter 09)
    table_lookups_skipped,  // cells whose occupancy bit was off: no lookup (chapter 09)
    nodes_visited,          // tree nodes whose box a ray was tested against (chapter 10)
    table_probes,           // keys compared in a bucket of the hashed grid's open table (chapter 09, 09.6)
    count_  // the number of counters, not a counter
};

// The counters every program reports, those before primary_hits, and their --stats names.
constexpr size_t standard_counters = static_cast<size_t>(Counter::primary_hits);
constexpr std::array<const char*, standard_counters> counter_names = {
    "rays_primary", "rays_shadow", "rays_reflected", "rays_refracted", "intersection_tests"};

using Counts = std::array<std::uint64_t, static_cast<size_t>(Counter::count_)>;

// This thread's running counts.
inline thread_local Counts thread_counts{};
inline Counts& local_counts() { return thread_counts; }

#ifdef RT_NO_COUNTERS
// Built with -DRT_COUNTERS=OFF, only to measure what counting costs (chapter 07's lesson): nothing
// is counted, and --stats reports zeros.
inline void count(Counter, std::uint64_t = 1) {}
#else
inline void count(Counter c, std::uint64_t n = 1) { thread_counts[static_cast<size_t>(c)] += n; }
#endif

inline std::uint64_t counted(const Counts& counts, Counter c) { return counts[static_cast<size_t>(c)]; }

// Adds this thread's counts to the totals and zeroes them.
void flush_counters();

// The totals flushed so far (and this thread's unflushed counts), and a way to start over.
Counts total_counts();
void reset_counters();

inline std::uint64_t total_count(Counter c) { return counted(total_counts(), c); }

// Every ray of every kind.
std::uint64_t total_rays(const Counts& counts);

class Timer {
public:
    Timer() : start_(std::chrono::steady_clock::now()) {}
    double seconds() const
    {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    std::chrono::steady_clock::time_point start_;
};

// A line a program adds to its --stats beyond the counters (what a scene file's reader skipped, say):
// printed as key=value after rays_per_second, by both printers below. A key noted again keeps its
// last value.
void note_stat(const std::string& key, const std::string& value);

// The `--stats` format: one key=value per line, counters first, then seconds and rays_per_second.
void print_stats(std::ostream& out, const Counts& counts, double seconds);

// The same format with the names of the classic NFF test rules (Haines' Standard Procedural
// Databases): eye_rays, eye_hits, reflect_rays, refract_rays, shadow_rays, shadow_blocked,
// secondary_hits, then intersection_tests, rays, seconds and rays_per_second.
void print_classic_stats(std::ostream& out, const Counts& counts, double seconds);

}  // namespace rt
