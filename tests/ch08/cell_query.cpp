// EXERCISE 08.3: chapter 07's cell query through the mailboxes, on the small grid built by hand
// (tests/ch07/hand_grid.hpp): the same answers, and no object tested twice by one ray.
#include "08_mailboxing/mailbox_grid.hpp"
#include "tests/ch08/hand_mailboxes.hpp"

#include <iomanip>

using namespace rt;
using namespace rt::grader;
using namespace rt::grader::hand_grid;

GRADED_TEST("closest_in_cell_mailboxed: keeps the nearest hit inside the cell; a hit beyond it is left", "08.3", 4)
{
    const Grid grid = grid_of({{0, 1, 2}, {}, {0}});
    Mailboxes m = fresh_mailboxes();
    ObjectHit best;
    const bool got = closest_in_cell_mailboxed(grid, walk_in(0), m, 1, ray, all, objects(), best);
    INFO("cell 0 lists spheres 0 (t = 3.3, beyond the cell), 1 (t = 1.75) and 2 (t = 1.3): returned " << std::boolalpha
         << got << " with " << show(best) << ", expected sphere 2");
    CHECK(got);
    CHECK(best.object == 2);
    ObjectHit none;
    const bool beyond = closest_in_cell_mailboxed(grid_of({{0}, {}, {}}), walk_in(0), m, 2, ray, all, objects(), none);
    INFO("cell 0 lists only sphere 0, hit at t = 3.3 beyond it: returned " << beyond << " with " << show(none));
    CHECK(!beyond);
    CHECK(none.object == -1);
}

GRADED_TEST("closest_in_cell_mailboxed: a far hit set aside in one cell is accepted from the mailbox in its own cell", "08.3", 4)
{
    // Sphere 0 (t = 3.3) is listed in cells 0 and 2: tested in cell 0, answered in cell 2.
    const Grid grid = grid_of({{0}, {}, {0}});
    Mailboxes m = fresh_mailboxes();
    ObjectHit best;
    reset_counters();
    const bool in_0 = closest_in_cell_mailboxed(grid, walk_in(0), m, 5, ray, all, objects(), best);
    const bool in_2 = closest_in_cell_mailboxed(grid, walk_in(2), m, 5, ray, all, objects(), best);
    const std::uint64_t tests = total_count(Counter::intersection_tests), answers = total_count(Counter::mailbox_hits);
    INFO("ray 5 in cell 0 then cell 2: returned " << std::boolalpha << in_0 << " then " << in_2 << " with " << show(best)
         << " after " << tests << " tests and " << answers << " answers from the mailbox; expected false, then sphere 0 "
         "from its mailbox (1 test, 1 answer): a far hit set aside must not mark the object as finished");
    CHECK(!in_0);
    CHECK(in_2);
    CHECK(best.object == 0);
    CHECK(tests == 1);
    CHECK(answers == 1);
}

GRADED_TEST("the grid with mailboxes: a near object in a later cell beats a far one found earlier, tested once each", "08.3", 4)
{
    std::vector<Sphere> s = {{{2.5f, 0.5f, 0.5f}, 0.2f}, {{1.5f, 0.5f, 0.5f}, 0.2f}};
    Objects o;
    o.spheres = s.data();
    o.sphere_count = 2;
    const MailboxGrid grid(grid_of({{0}, {1}, {0}}), 2);
    ObjectHit hit;
    const bool found = grid.closest(ray, all, o, hit);
    INFO("far sphere 0 (t = 3.3) in cells 0 and 2, near sphere 1 (t = 2.3) in cell 1: got "
         << (found ? show(hit) : "no hit") << ", expected object 1");
    CHECK(found);
    CHECK(hit.object == 1);
    // The far sphere listed in every cell, nothing else: found in the last, tested once.
    reset_counters();
    const MailboxGrid everywhere(grid_of({{0}, {0}, {0}}), 2);
    const bool far = everywhere.closest(ray, all, o, hit);
    INFO("sphere 0 alone, listed in cells 0, 1 and 2: got " << (far ? show(hit) : "no hit") << " after "
         << total_count(Counter::intersection_tests) << " tests; expected object 0 after 1 test");
    CHECK(far);
    CHECK(hit.object == 0);
    CHECK(total_count(Counter::intersection_tests) == 1);
}

GRADED_TEST("closest_in_cell_mailboxed: a hit exactly at the cell's exit is kept, one float step beyond it is left; equal t go to the lower object number",
            "08.3", 3)
{
    // Triangles 3, 4 and 5 are one triangle thrice, hit at exactly t = 2: where cell 0 ends.
    const Grid grid = grid_of({{3, 4, 5}, {}, {}});
    Mailboxes m = fresh_mailboxes();
    ObjectHit best;
    reset_counters();
    const bool at_exit = closest_in_cell_mailboxed(grid, walk_in(0), m, 1, ray, all, objects(), best);
    INFO("08.3: cell 0 (the ray leaves it at t = 2) lists triangles 3, 4 and 5, all hit at t = 2: returned " << std::boolalpha
         << at_exit << " with " << show(best) << " after " << total_count(Counter::intersection_tests)
         << " tests; expected true with object 3 after 3 tests: a hit no farther than the cell's exit is kept, and of "
         "equal t the lower object number wins");
    CHECK(at_exit);
    CHECK(best.object == 3);
    CHECK(best.t == 2.0f);
    CHECK(total_count(Counter::intersection_tests) == 3);

    // The same cell, its exit one float step before t = 2.
    GridWalk short_walk = walk_in(0);
    short_walk.t_max[0] = std::nextafter(2.0f, 0.0f);
    ObjectHit none;
    const bool beyond = closest_in_cell_mailboxed(grid, short_walk, m, 2, ray, all, objects(), none);
    INFO("08.3: the same cell, its exit moved one float step nearer (t = " << std::setprecision(9) << short_walk.cell_exit()
         << "): returned " << beyond << " with " << show(none) << "; expected false and best untouched (object -1): the hits "
         "at t = 2 lie beyond the cell");
    CHECK(!beyond);
    CHECK(none.object == -1);

    // A best already found at t = 2: object 3 beats object 4 there, object 5 does not.
    ObjectHit four{2.0f, 4, 0.0f, 0.0f};
    const bool beats = closest_in_cell_mailboxed(grid, walk_in(0), m, 3, ray, all, objects(), four);
    ObjectHit three{2.0f, 3, 0.0f, 0.0f};
    const bool beaten = closest_in_cell_mailboxed(grid_of({{4, 5}, {}, {}}), walk_in(0), m, 4, ray, all, objects(), three);
    INFO("08.3: best so far object 4 at t = 2, cell 0 lists 3, 4, 5: returned " << beats << " with " << show(four)
         << " (expected true, object 3); best so far object 3 at t = 2, the cell lists 4 and 5: returned " << beaten
         << " with " << show(three) << " (expected false, object 3 still)");
    CHECK(beats);
    CHECK(four.object == 3);
    CHECK(!beaten);
    CHECK(three.object == 3);
}

GRADED_TEST("closest_in_cell_mailboxed: only hits inside the query's range count", "08.3", 2)
{
    // Cell 0 lists spheres 1 (the ray enters it at t = 1.75) and 2 (enters at t = 1.3, leaves at 1.7).
    const Grid grid = grid_of({{1, 2}, {}, {}});
    Mailboxes m = fresh_mailboxes();
    ObjectHit from_min;
    const bool late = closest_in_cell_mailboxed(grid, walk_in(0), m, 1, ray, {1.72f, infinity}, objects(), from_min);
    INFO("08.3: cell 0 lists spheres 1 (the ray enters it at t = 1.75) and 2 (enters at t = 1.3, leaves at 1.7), the "
         "range is t in (1.72, infinity): returned " << std::boolalpha << late << " with " << show(from_min)
         << "; expected true with sphere 1 at t = 1.75: both of sphere 2's hits lie before the range");
    CHECK(late);
    CHECK(from_min.object == 1);
    ObjectHit short_range;
    const bool none = closest_in_cell_mailboxed(grid, walk_in(0, 1.2f), m, 2, ray, {0.0f, 1.2f}, objects(), short_range);
    INFO("08.3: the same cell, the range t in (0, 1.2): returned " << none << " with " << show(short_range)
         << "; expected false, nothing in the range");
    CHECK(!none);
    CHECK(short_range.object == -1);
}

GRADED_TEST("closest_in_cell_mailboxed: only the current cell's own list is asked: an empty cell changes nothing and tests nothing, even when the next cell lists an object hit inside it", "08.3", 2)
{
    // A cell's objects are object_index[cell_start[p]] up to, not including, cell_start[p + 1]:
    // the entry at cell_start[p + 1] is the next cell's first object. Sphere 2 (t = 1.3, before cell
    // 0's exit at t = 2) is listed in cell 1 only.
    const Grid grid = grid_of({{}, {2}, {}});
    Mailboxes m = fresh_mailboxes();
    ObjectHit best;
    const std::uint64_t tests_before = total_count(Counter::intersection_tests);
    const bool got = closest_in_cell_mailboxed(grid, walk_in(0), m, 1, ray, all, objects(), best);
    const std::uint64_t tests = total_count(Counter::intersection_tests) - tests_before;
    INFO("08.3: cell 0 lists nothing, cell 1 lists sphere 2 (hit at t = 1.3): in cell 0 returned " << std::boolalpha
         << got << " with " << show(best) << " after " << tests << " intersection tests, sphere 2's mailbox holding ray "
         << m.box[2].ray << "; expected false, no hit, no test and sphere 2's mailbox untouched (0): cell 0 has no objects");
    CHECK(!got);
    CHECK(best.object == -1);
    CHECK(tests == 0);
    CHECK(m.box[2].ray == 0u);
    ObjectHit own;
    const bool found = closest_in_cell_mailboxed(grid, walk_in(1), m, 1, ray, all, objects(), own);
    INFO("08.3: then in cell 1, which lists sphere 2: returned " << found << " with " << show(own)
         << "; expected true with sphere 2 at t = 1.3");
    CHECK(found);
    CHECK(own.object == 2);
}
