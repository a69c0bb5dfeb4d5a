// EXERCISE 09.5: the cell query on the hashed grid: the bit first, the table only when it is on.
#include "09_hashed_voxels/09_hashed_voxels.hpp"
#include "tests/ch07/hand_grid.hpp"

using namespace rt;
using namespace rt::grader;
using namespace rt::grader::hand_grid;

namespace {

std::uint64_t counter(Counter c) { return total_counts()[static_cast<size_t>(c)]; }

// The hand grid's three cells as a hashed grid of M = 2: cells 0 and 2 share bucket 0.
struct Hashed {
    HashTable table;
    OccupancyBits bits;
};

Hashed hashed(const std::vector<std::vector<std::uint32_t>>& lists)
{
    Hashed h;
    h.table.M = 2;
    h.bits.words = {0};
    std::vector<HashedCell> bucket[2];
    for (int p = 0; p < 3; ++p) {
        if (lists[p].empty())
            continue;
        bucket[p % 2].push_back({p, static_cast<std::uint32_t>(h.table.object_index.size()),
                                 static_cast<std::uint32_t>(lists[p].size())});
        h.table.object_index.insert(h.table.object_index.end(), lists[p].begin(), lists[p].end());
        h.bits.words[0] |= std::uint64_t{1} << p;
    }
    h.table.bucket_start = {0};
    for (const auto& b : bucket) {
        h.table.cells.insert(h.table.cells.end(), b.begin(), b.end());
        h.table.bucket_start.push_back(static_cast<std::uint32_t>(h.table.cells.size()));
    }
    return h;
}

}  // namespace

GRADED_TEST("closest_in_hashed_cell: an empty cell costs its bit alone, no lookup; an occupied one is looked up", "09.5", 4)
{
    const Hashed h = hashed({{}, {}, {0}});
    ObjectHit best;
    reset_counters();
    const bool empty = closest_in_hashed_cell(h.table, h.bits, walk_in(1), 1, ray, all, objects(), best);
    INFO("cell 1, empty: returned " << std::boolalpha << empty << " after " << counter(Counter::table_lookups)
         << " lookups and " << counter(Counter::table_lookups_skipped) << " skipped; expected false, 0 and 1");
    CHECK(!empty);
    CHECK(counter(Counter::table_lookups) == 0);
    CHECK(counter(Counter::table_lookups_skipped) == 1);
    reset_counters();
    const bool full = closest_in_hashed_cell(h.table, h.bits, walk_in(2), 0, ray, all, objects(), best);
    INFO("cell 2 (bucket 0 of M = 2), sphere 0 hit at t = 3.3 inside it: returned " << full << " with " << show(best)
         << " after " << counter(Counter::table_lookups) << " lookups; expected sphere 0 after 1");
    CHECK(full);
    CHECK(best.object == 0);
    CHECK(counter(Counter::table_lookups) == 1);
    CHECK(counter(Counter::intersection_tests) == 1);

    // A bit that is on for a cell the table does not hold (the build never writes one, but bits and
    // table come from separate arrays): the lookup finds nothing, and nothing is tested.
    Hashed stray = h;
    stray.bits.words[0] |= std::uint64_t{1} << 1;
    reset_counters();
    const bool lost = closest_in_hashed_cell(stray.table, stray.bits, walk_in(1), 1, ray, all, objects(), best);
    INFO("cell 1 with its bit on but no entry in the table: returned " << lost << " after "
         << counter(Counter::table_lookups) << " lookups and " << counter(Counter::intersection_tests)
         << " tests; expected false, 1 and 0");
    CHECK(!lost);
    CHECK(counter(Counter::table_lookups) == 1);
    CHECK(counter(Counter::intersection_tests) == 0);
}

GRADED_TEST("closest_in_hashed_cell: the cell's own list, not its bucket neighbour's; a hit beyond the cell is left", "09.5", 4)
{
    // Cells 0 and 2 share bucket 0: cell 0 lists spheres 1 and 2, cell 2 sphere 0.
    const Hashed h = hashed({{1, 2}, {}, {0}});
    ObjectHit best;
    const bool in_0 = closest_in_hashed_cell(h.table, h.bits, walk_in(0), 0, ray, all, objects(), best);
    INFO("cell 0: returned " << std::boolalpha << in_0 << " with " << show(best) << ", expected sphere 2 (t = 1.3)");
    CHECK(in_0);
    CHECK(best.object == 2);
    const Hashed far = hashed({{0}, {}, {}});
    ObjectHit none;
    const bool beyond = closest_in_hashed_cell(far.table, far.bits, walk_in(0), 0, ray, all, objects(), none);
    INFO("cell 0 lists sphere 0, hit at t = 3.3 beyond it: returned " << beyond << " with " << show(none));
    CHECK(!beyond);
}
