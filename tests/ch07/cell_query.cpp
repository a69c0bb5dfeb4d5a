// EXERCISE 07.6: the cell query, on the small grid built by hand (hand_grid.hpp).
#include "tests/ch07/hand_grid.hpp"

using namespace rt;
using namespace rt::grader;

namespace {

using namespace rt::grader::hand_grid;

struct Case {
    std::vector<std::vector<std::uint32_t>> lists;
    int cell;
    Interval range;
    ObjectHit best_before;
    bool changed;
    int object;  // expected best.object afterwards
    float t;     // and best.t
    const char* why;
};

void check(const Case& c)
{
    const Grid grid = grid_of(c.lists);
    const GridWalk walk = walk_in(c.cell, c.range.max);
    ObjectHit best = c.best_before;
    const bool got = closest_in_cell(grid, walk, ray, c.range, objects(), best);
    std::ostringstream lists;
    for (size_t k = 0; k < c.lists.size(); ++k) {
        lists << (k ? "; cell " : "cell ") << k << ':';
        for (std::uint32_t o : c.lists[k])
            lists << ' ' << o;
    }
    INFO("07.6 closest_in_cell in cell " << c.cell << " (it ends at t = " << walk.cell_exit() << "), " << lists.str()
         << ", t in (" << c.range.min << ", " << c.range.max << "), best before: " << show(c.best_before)
         << ": returned " << std::boolalpha << got << " with best " << show(best) << "; expected " << c.changed
         << " with " << show(ObjectHit{c.t, c.object}) << ": " << c.why);
    CHECK(got == c.changed);
    CHECK(best.object == c.object);
    if (c.object >= 0)
        CHECK(best.t == c.t);
}

float t_of(int object)
{
    ObjectHit h;
    objects().intersect(object, ray, all, h);
    return h.t;
}

}  // namespace

GRADED_TEST("closest_in_cell: keeps the nearest hit inside the cell, whatever order the objects come in", "07.6", 3)
{
    check({{{2}, {}, {}}, 0, all, {}, true, 2, t_of(2), "sphere 2 is hit at t = 1.3, inside cell 0"});
    check({{{1, 2}, {}, {}}, 0, all, {}, true, 2, t_of(2), "sphere 2 (t = 1.3) is nearer than sphere 1 (t = 1.75)"});
    check({{{}, {}, {}}, 0, all, {}, false, -1, 0, "an empty cell holds no hit"});
    check({{{2}, {}, {}}, 0, {1.8f, infinity}, {}, false, -1, 0, "sphere 2 spans t = 1.3 to 1.7, before the range"});
}

GRADED_TEST("closest_in_cell: only the current cell's own list is tested: an empty cell changes nothing, even when the next cell lists an object hit inside it", "07.6", 2)
{
    // A cell's objects are object_index[cell_start[p]] up to, not including, cell_start[p + 1]:
    // the entry at cell_start[p + 1] is the next cell's first object.
    check({{{}, {2}, {}}, 0, all, {}, false, -1, 0,
           "cell 0 lists nothing; sphere 2 (t = 1.3, before cell 0's exit at t = 2) is listed in cell 1 only"});
    check({{{}, {}, {1}}, 1, all, {}, false, -1, 0,
           "cell 1 lists nothing; sphere 1 (t = 1.75, before cell 1's exit at t = 3) is listed in cell 2 only"});
    check({{{1}, {2}, {}}, 0, all, {}, true, 1, t_of(1),
           "cell 0 lists sphere 1 (t = 1.75); sphere 2 (t = 1.3, nearer), listed in cell 1 only, is not cell 0's"});
}

GRADED_TEST("closest_in_cell: a hit beyond the cell is not kept; one exactly on its far boundary is", "07.6", 4)
{
    check({{{0}, {}, {}}, 0, all, {}, false, -1, 0,
           "sphere 0 is hit at t = 3.3, in cell 2: beyond cell 0, which ends at t = 2"});
    check({{{0, 2}, {}, {}}, 0, all, {}, true, 2, t_of(2), "sphere 0 is beyond the cell, sphere 2 inside it"});
    check({{{3}, {}, {}}, 0, all, {}, true, 3, 2.0f, "the triangle in x = 1 is hit at t = 2, exactly where cell 0 ends"});
    check({{{}, {}, {0}}, 2, all, {}, true, 0, t_of(0), "in the last cell, sphere 0's hit at t = 3.3 is inside"});
}

GRADED_TEST("closest_in_cell: on an exact tie in t the lower object number wins, as brute force's order gives", "07.6", 3)
{
    check({{{3, 5}, {}, {}}, 0, all, ObjectHit{2.0f, 4}, true, 3, 2.0f,
           "objects 3, 4 and 5 are one triangle, hit at t = 2: 3 beats the best so far (4), and 5 does not"});
    check({{{5}, {}, {}}, 0, all, ObjectHit{2.0f, 4}, false, 4, 2.0f, "object 5 ties with object 4 at t = 2: 4 stays"});
}

GRADED_TEST("the grid: a near object that only occupies a later cell beats a far object found earlier", "07.6", 4)
{
    // Sphere 0 (t = 3.3) is listed in cell 0 too, as a large object would be; sphere 3 at
    // (1.5, 0.5, 0.5) is hit at t = 2.3, in cell 1 only.
    std::vector<Sphere> s = {{{2.5f, 0.5f, 0.5f}, 0.2f}, {{1.5f, 0.5f, 0.5f}, 0.2f}};
    Objects o;
    o.spheres = s.data();
    o.sphere_count = 2;
    const UniformGrid grid(grid_of({{0}, {1}, {0}}));
    ObjectHit hit;
    const bool found = grid.closest(ray, all, o, hit);
    INFO("07.6 the grid's closest hit along " << show(ray) << " with the far sphere 0 (t = 3.3) listed in cells 0 and 2 and "
         "the near sphere 1 (t = 2.3) in cell 1: got " << (found ? show(hit) : "no hit") << ", expected object 1: the hit "
         "of sphere 0 found in cell 0 lies beyond it, and must not end the walk");
    CHECK(found);
    CHECK(hit.object == 1);
}

namespace {

// One call of closest_in_cell on the hand grid with cell 0 listing `list`, from the walk `walk`
// (built by hand), over `o`: what it returns and leaves in best.
void check_in(const std::vector<std::vector<std::uint32_t>>& lists, const GridWalk& walk, Interval range,
              const Objects& o, bool changed, int object, float t, const char* why)
{
    const Grid grid = grid_of(lists);
    ObjectHit best;
    const bool got = closest_in_cell(grid, walk, ray, range, o, best);
    INFO("07.6 closest_in_cell in cell " << walk.p << " of the hand grid, from " << show(walk) << ", t in (" << range.min
         << ", " << range.max << "): returned " << std::boolalpha << got << " with best " << show(best) << "; expected "
         << changed << " with " << show(ObjectHit{t, object}) << ": " << why);
    CHECK(got == changed);
    CHECK(best.object == object);
    if (object >= 0)
        CHECK(best.t == t);
}

}  // namespace

GRADED_TEST("closest_in_cell: a hit one ulp beyond the cell's exit is left, one exactly on it or one ulp before it is kept", "07.6", 3)
{
    // Triangle 3, in x = 1, is hit at exactly t = 2; cell 0's walk is made to leave the cell one
    // ulp before that, at it, and one ulp after it.
    GridWalk exit_before = walk_in(0), exit_on = walk_in(0), exit_after = walk_in(0);
    exit_before.t_max[0] = std::nextafter(2.0f, 1.0f);
    exit_after.t_max[0] = std::nextafter(2.0f, 3.0f);
    check_in({{3}, {}, {}}, exit_before, all, objects(), false, -1, 0,
             "the cell ends one ulp before t = 2: the hit lies beyond it");
    check_in({{3}, {}, {}}, exit_on, all, objects(), true, 3, 2.0f, "the cell ends at t = 2: the hit is no farther");
    check_in({{3}, {}, {}}, exit_after, all, objects(), true, 3, 2.0f,
             "the cell ends one ulp after t = 2: the hit is inside");
}

GRADED_TEST("closest_in_cell: in the walk's last cell a hit past the box's face is kept, up to the range's end (cell_exit), not only up to the next boundary", "07.6", 3)
{
    // Object 6, a triangle in x = 3.001, is hit at t = 4.001: past the box's face x = 3 (t = 4),
    // where rounding can put a hit on that face. Listed in cell 2, the walk's last cell, whose
    // next boundary is that face (t_max = 4 = t_end): cell_exit() is the range's end there.
    const Objects o = objects_with_one_past_the_box();
    ObjectHit h;
    REQUIRE(o.intersect(6, ray, all, h));
    check_in({{}, {}, {6}}, walk_in(2), all, o, true, 6, h.t,
             "the last cell reaches to the range's end (infinity): the hit at t = 4.001, past t_max = 4, is kept");
    check_in({{}, {}, {6}}, walk_in(2, 4.5f), {0.0f, 4.5f}, o, true, 6, h.t,
             "the range ends at t = 4.5, past the face: the last cell reaches to 4.5 and keeps the hit at 4.001");
    check_in({{}, {6}, {}}, walk_in(1), all, o, false, -1, 0,
             "listed in cell 1, which ends at t = 3 and is not the last: the hit at 4.001 is beyond it");
}
