// EXERCISE 07.6: the cell query, on a small grid built by hand: three cells of size 1 along x over
// the box from (0, 0, 0) to (3, 1, 1), the ray from (-1, 0.5, 0.5) along +x. It enters cell 0 at
// t = 1, cell 1 at t = 2, cell 2 at t = 3, and leaves the box at t = 4.
#include "tests/ch07/describe.hpp"

using namespace rt;
using namespace rt::grader;

namespace {

const Ray ray{{-1, 0.5f, 0.5f}, {1, 0, 0}};
const Interval all{0.0f, infinity};

// Objects 0-2 are spheres on the ray; 3-5 are one triangle thrice, across the ray in the plane
// x = 1 (cell 0's far boundary), so all three are hit at exactly t = 2.
const std::vector<Sphere> spheres = {
    {{2.5f, 0.5f, 0.5f}, 0.2f},   // 0: hit at x = 2.3, t = 3.3 (in cell 2)
    {{0.95f, 0.5f, 0.5f}, 0.2f},  // 1: hit at x = 0.75, t = 1.75 (in cell 0)
    {{0.5f, 0.5f, 0.5f}, 0.2f},   // 2: hit at x = 0.3, t = 1.3 (in cell 0)
};
const Triangle across{{1, -1, -1}, {1, 3, -1}, {1, -1, 3}};
const std::vector<Triangle> triangles = {across, across, across};

Objects objects()
{
    Objects o;
    o.spheres = spheres.data();
    o.sphere_count = static_cast<int>(spheres.size());
    o.triangles = triangles.data();
    o.triangle_count = static_cast<int>(triangles.size());
    o.tests = {SphereTest::precise, TriangleTest::watertight};
    return o;
}

// The grid with `lists[c]` in cell c.
Grid grid_of(const std::vector<std::vector<std::uint32_t>>& lists)
{
    Grid g;
    g.shape = grid_shape({{0, 0, 0}, {3, 1, 1}}, {3, 1, 1});
    g.cell_start = {0};
    for (const auto& list : lists) {
        g.object_index.insert(g.object_index.end(), list.begin(), list.end());
        g.cell_start.push_back(static_cast<std::uint32_t>(g.object_index.size()));
    }
    return g;
}

// The walk in cell c, as start_walk and next_cell leave it there.
GridWalk walk_in(int c, float range_max = infinity)
{
    GridWalk w;
    w.missed = false;
    w.p = c;
    w.step_p[0] = 1;
    w.t_first[0] = 2.0f;
    w.t_delta[0] = 1.0f;
    w.steps[0] = c;
    w.t_max[0] = 2.0f + static_cast<float>(c);
    w.t_enter = 1.0f + static_cast<float>(c);
    w.t_end = std::min(4.0f, range_max);
    w.t_range = range_max;
    return w;
}

std::string show(const ObjectHit& h)
{
    if (h.object < 0)
        return "no hit";
    std::ostringstream s;
    s.precision(9);
    s << "object " << h.object << " at t = " << h.t;
    return s.str();
}

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
    INFO("closest_in_cell in cell " << c.cell << " (it ends at t = " << walk.cell_exit() << "), " << lists.str()
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
    INFO("the grid's closest hit along " << show(ray) << " with the far sphere 0 (t = 3.3) listed in cells 0 and 2 and "
         "the near sphere 1 (t = 2.3) in cell 1: got " << (found ? show(hit) : "no hit") << ", expected object 1: the hit "
         "of sphere 0 found in cell 0 lies beyond it, and must not end the walk");
    CHECK(found);
    CHECK(hit.object == 1);
}
