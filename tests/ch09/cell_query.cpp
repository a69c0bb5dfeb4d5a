// EXERCISE 09.5: the cell query on the hashed grid: the bit first, the table only when it is on.
#include "09_hashed_voxels/09_hashed_voxels.hpp"
#include "tests/ch07/hand_grid.hpp"

using namespace rt;
using namespace rt::grader;
using namespace rt::grader::hand_grid;

namespace {

// The hand grid's three cells as a hashed grid of M = 2: cells 0 and 2 share bucket 0.
struct Hashed {
    HashTable table;
    OccupancyBits bits;
};

Hashed hand_hashed(const std::vector<std::vector<std::uint32_t>>& lists)
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
    const Hashed h = hand_hashed({{}, {}, {0}});
    ObjectHit best;
    reset_counters();
    const bool empty = closest_in_hashed_cell(h.table, h.bits, walk_in(1), 1, ray, all, objects(), best);
    INFO("09.5 cell 1, empty: returned " << std::boolalpha << empty << " after " << total_count(Counter::table_lookups)
         << " lookups and " << total_count(Counter::table_lookups_skipped) << " skipped; expected false, 0 and 1");
    CHECK(!empty);
    CHECK(total_count(Counter::table_lookups) == 0);
    CHECK(total_count(Counter::table_lookups_skipped) == 1);
    reset_counters();
    const bool full = closest_in_hashed_cell(h.table, h.bits, walk_in(2), 0, ray, all, objects(), best);
    INFO("09.5 cell 2 (bucket 0 of M = 2), sphere 0 hit at t = 3.3 inside it: returned " << full << " with " << show(best)
         << " after " << total_count(Counter::table_lookups) << " lookups; expected sphere 0 after 1");
    CHECK(full);
    CHECK(best.object == 0);
    CHECK(total_count(Counter::table_lookups) == 1);
    CHECK(total_count(Counter::intersection_tests) == 1);

    // A bit that is on for a cell the table does not hold (the build never writes one, but bits and
    // table come from separate arrays): the lookup finds nothing, and nothing is tested.
    Hashed stray = h;
    stray.bits.words[0] |= std::uint64_t{1} << 1;
    reset_counters();
    const bool lost = closest_in_hashed_cell(stray.table, stray.bits, walk_in(1), 1, ray, all, objects(), best);
    INFO("09.5 cell 1 with its bit on but no entry in the table: returned " << lost << " after "
         << total_count(Counter::table_lookups) << " lookups and " << total_count(Counter::intersection_tests)
         << " tests; expected false, 1 and 0");
    CHECK(!lost);
    CHECK(total_count(Counter::table_lookups) == 1);
    CHECK(total_count(Counter::intersection_tests) == 0);
}

GRADED_TEST("closest_in_hashed_cell: the cell's own list, not its bucket neighbour's; a hit beyond the cell is left", "09.5", 4)
{
    // Cells 0 and 2 share bucket 0: cell 0 lists spheres 1 and 2, cell 2 sphere 0.
    const Hashed h = hand_hashed({{1, 2}, {}, {0}});
    ObjectHit best;
    const bool in_0 = closest_in_hashed_cell(h.table, h.bits, walk_in(0), 0, ray, all, objects(), best);
    INFO("09.5 cell 0: returned " << std::boolalpha << in_0 << " with " << show(best) << ", expected sphere 2 (t = 1.3)");
    CHECK(in_0);
    CHECK(best.object == 2);
    const Hashed far = hand_hashed({{0}, {}, {}});
    ObjectHit none;
    const bool beyond = closest_in_hashed_cell(far.table, far.bits, walk_in(0), 0, ray, all, objects(), none);
    INFO("09.5 cell 0 lists sphere 0, hit at t = 3.3 beyond it: returned " << beyond << " with " << show(none));
    CHECK(!beyond);
}

namespace {

// One call of closest_in_hashed_cell, with every count it makes checked exactly: lookups, skipped
// lookups and intersection tests.
struct Counts {
    std::uint64_t lookups, skipped, tests;
};

void check_query(const Hashed& h, const GridWalk& walk, std::uint32_t r, Interval range, const Objects& o, bool changed,
                 int object, float t, const Counts& counts, const char* why)
{
    ObjectHit best;
    reset_counters();
    const bool got = closest_in_hashed_cell(h.table, h.bits, walk, r, ray, range, o, best);
    const Counts made{total_count(Counter::table_lookups), total_count(Counter::table_lookups_skipped),
                      total_count(Counter::intersection_tests)};
    INFO("09.5 closest_in_hashed_cell in cell " << walk.p << " (residue " << r << " of M = 2, it ends at t = "
         << walk.cell_exit() << "), t in (" << range.min << ", " << range.max << "): returned " << std::boolalpha << got
         << " with " << show(best) << " after " << made.lookups << " lookups, " << made.skipped << " skipped and "
         << made.tests << " intersection tests; expected " << changed << " with " << show(ObjectHit{t, object})
         << " after " << counts.lookups << ", " << counts.skipped << " and " << counts.tests << ": " << why);
    CHECK(got == changed);
    CHECK(best.object == object);
    if (object >= 0)
        CHECK(best.t == t);
    CHECK(made.lookups == counts.lookups);
    CHECK(made.skipped == counts.skipped);
    CHECK(made.tests == counts.tests);
}

}  // namespace

GRADED_TEST("closest_in_hashed_cell: every call counts exactly one lookup or one skipped lookup, and tests each listed object once", "09.5", 3)
{
    const Hashed h = hand_hashed({{1, 2}, {}, {0}});
    ObjectHit two, zero;
    REQUIRE(objects().intersect(2, ray, all, two));
    REQUIRE(objects().intersect(0, ray, all, zero));
    check_query(h, walk_in(0), 0, all, objects(), true, 2, two.t, {1, 0, 2},
                "cell 0 lists spheres 1 and 2: one lookup, two tests, sphere 2 at t = 1.3 nearest");
    check_query(h, walk_in(1), 1, all, objects(), false, -1, 0, {0, 1, 0}, "cell 1 is empty: its bit alone");
    check_query(h, walk_in(2), 0, all, objects(), true, 0, zero.t, {1, 0, 1}, "cell 2 lists sphere 0: one lookup, one test");
    // The bit is the authority: off, the table is not read, even when it holds the cell.
    Hashed bit_off = h;
    bit_off.bits.words[0] &= ~std::uint64_t{1};
    check_query(bit_off, walk_in(0), 0, all, objects(), false, -1, 0, {0, 1, 0},
                "cell 0's bit is off though the table lists it: skipped, the table not read, nothing tested");
}

GRADED_TEST("closest_in_hashed_cell: a hit exactly at the cell's exit is kept, one ulp beyond it left; in the last cell, up to the range's end", "09.5", 3)
{
    // Triangle 3 in x = 1 is hit at exactly t = 2, where cell 0 ends; triangle 6 in x = 3.001 at
    // t = 4.001, past the box's face x = 3 (t = 4), in the walk's last cell 2.
    const Objects o = objects_with_one_past_the_box();
    ObjectHit past;
    REQUIRE(o.intersect(6, ray, all, past));
    const Hashed h = hand_hashed({{3}, {}, {6}});
    check_query(h, walk_in(0), 0, all, o, true, 3, 2.0f, {1, 0, 1}, "the hit at t = 2 is exactly where cell 0 ends: kept");
    GridWalk before = walk_in(0);
    before.t_max[0] = std::nextafter(2.0f, 1.0f);
    check_query(h, before, 0, all, o, false, -1, 0, {1, 0, 1}, "cell 0 made to end one ulp before t = 2: the hit is beyond it");
    check_query(h, walk_in(2), 0, all, o, true, 6, past.t, {1, 0, 1},
                "the last cell reaches to the range's end (cell_exit): the hit at t = 4.001, past t_max = 4, is kept");
}

GRADED_TEST("closest_in_hashed_cell: each object in the range that beats best (closer_than): a tie in t goes to the lower number, a hit before range.min is none", "09.5", 2)
{
    // Objects 3, 4 and 5 are one triangle, hit at t = 2; sphere 2 spans t = 1.3 to 1.7.
    const Hashed ties = hand_hashed({{5, 3}, {}, {}});
    ObjectHit best{2.0f, 4};
    const bool changed = closest_in_hashed_cell(ties.table, ties.bits, walk_in(0), 0, ray, all, objects(), best);
    INFO("09.5 closest_in_hashed_cell in cell 0, which lists objects 5 and 3 (one triangle, hit at t = 2), best before: "
         "object 4 at t = 2: returned " << std::boolalpha << changed << " with " << show(best)
         << "; expected true with object 3 at t = 2: 3 beats 4 on the tie, and 5 does not");
    CHECK(changed);
    CHECK(best.object == 3);
    CHECK(best.t == 2.0f);
    const Hashed early = hand_hashed({{2}, {}, {}});
    ObjectHit none;
    const bool found = closest_in_hashed_cell(early.table, early.bits, walk_in(0), 0, ray, {1.8f, infinity}, objects(), none);
    INFO("09.5 closest_in_hashed_cell in cell 0, which lists sphere 2 (t = 1.3 to 1.7), t in (1.8, inf): returned "
         << found << " with " << show(none) << "; expected false and no hit: the sphere lies before the range");
    CHECK(!found);
    CHECK(none.object == -1);
}
