// EXERCISES 10.1-10.3: the surface area heuristic's cost, the best plane between bins, and when a
// node becomes a leaf.
#include "10_hierarchies/bvh.hpp"
#include "tests/ch07/describe.hpp"

#include <iomanip>
#include <limits>
#include <sstream>

using namespace rt;
using namespace rt::grader;

namespace {

Bounds box(const point3& lo, const point3& hi) { return {lo, hi}; }

void check_cost(const Bounds& parent, const Bounds& l, int nl, const Bounds& r, int nr, float expected, const char* why,
                bool exact = false)
{
    std::ostringstream call;
    call << "sah_cost(parent " << show(parent) << ", left " << show(l) << " with " << nl << ", right " << show(r) << " with "
         << nr << ")";
    const WorkingOn on([&] { return call.str(); });
    const float got = sah_cost(parent, l, nl, r, nr);
    INFO(call.str() << ": got " << std::setprecision(9) << got << ", expected " << expected << (exact ? " exactly" : "")
                    << ": " << why);
    if (exact)
        CHECK(got == expected);
    else
        CHECK(std::abs(got - expected) <= 1e-6f * std::max(1.0f, expected));
}

}  // namespace

GRADED_TEST("sah_cost: each child's objects weighted by its share of the parent's surface area, plus a traversal", "10.1", 4)
{
    const Bounds cube = box({0, 0, 0}, {2, 2, 2});  // half area 12
    check_cost(cube, box({0, 0, 0}, {1, 2, 2}), 3, box({1, 0, 0}, {2, 2, 2}), 5, 0.125f + (8.0f / 12) * 3 + (8.0f / 12) * 5,
               "two halves of a cube: each 8 / 12 of its area");
    check_cost(cube, box({0, 0, 0}, {2, 2, 2}), 4, box({0, 0, 0}, {0.5f, 0.5f, 0.5f}), 1, 0.125f + 4 + 0.75f / 12,
               "a child as large as the parent counts all its objects");
    check_cost(cube, box({0, 0, 0}, {1, 1, 1}), 2, Bounds{}, 0, 0.125f + (3.0f / 12) * 2, "an empty child adds nothing");
}

STABILITY_TEST("sah_cost: a parent of no area (every object at one point) gives each child a share of 1", "10.1", 2)
{
    const Bounds point = box({1, 1, 1}, {1, 1, 1});
    check_cost(point, point, 2, point, 3, 0.125f + 5, "no area: the children's shares are 1");
    // A share of exactly 1: 1000 and 3000 objects cost 4000.125 to the bit (a share a float step
    // above 1 would cost 4000.1255).
    check_cost(point, point, 1000, point, 3000, 0.125f + 4000, "no area: the children's shares are exactly 1", true);
}

GRADED_TEST("sah_cost: a parent of the least area a float holds is not a parent of no area: its children share by area",
            "10.1", 1)
{
    // A sliver 1 long, the least float above 0 wide, and flat: its half area is that least float
    // (1.4e-45), which is more than no area. The sliver itself as a child has a share of 1; the
    // segment along its length (no area) a share of 0, not the 1 of a parent of no area.
    const float least = std::numeric_limits<float>::denorm_min();
    const Bounds sliver = box({0, 0, 0}, {1, least, 0});
    const Bounds segment = box({0, 0, 0}, {1, 0, 0});
    check_cost(sliver, sliver, 3, segment, 5, 0.125f + 3,
               "the parent's area is the least float above 0, not none: the segment without area has a share of 0", true);
}

namespace {

// Bins along x, one unit wide each, of a parent 4 x 1 x 1, holding `counts` objects.
std::vector<SahBin> unit_bins(const std::vector<int>& counts)
{
    std::vector<SahBin> bins(counts.size());
    for (size_t k = 0; k < bins.size(); ++k) {
        bins[k].count = counts[k];
        if (counts[k] > 0)
            bins[k].bounds = box({static_cast<float>(k), 0, 0}, {static_cast<float>(k) + 1, 1, 1});
    }
    return bins;
}

// Every plane's cost, worked out here from the SAH (not from the student's sah_cost), so a failure
// shows the whole table: "after bin 0: 4.57, after bin 1: 4.57, after bin 2: 9.01".
std::string plane_costs(const Bounds& parent, const std::vector<SahBin>& bins)
{
    std::ostringstream table;
    for (size_t plane = 0; plane + 1 < bins.size(); ++plane) {
        Bounds left, right;
        int n_left = 0, n_right = 0;
        for (size_t k = 0; k < bins.size(); ++k) {
            (k <= plane ? left : right).grow(bins[k].bounds);
            (k <= plane ? n_left : n_right) += bins[k].count;
        }
        table << (plane ? ", " : "") << "after bin " << plane << ": ";
        if (n_left == 0 || n_right == 0)
            table << "(a side is empty)";
        else
            table << sah_traversal_cost + (left.half_area() * n_left + right.half_area() * n_right) / parent.half_area();
    }
    return table.str();
}

void check_best_split(const Bounds& parent, const std::vector<int>& counts, int expected_split, float expected_cost,
                      const char* why)
{
    const std::vector<SahBin> bins = unit_bins(counts);
    std::ostringstream shown;
    for (const int c : counts)
        shown << c << ' ';
    const WorkingOn on([&] { return "best_split of bins along x holding " + shown.str() + "objects"; });
    const SahSplit got = best_split(parent, bins);
    INFO("bins along x holding " << shown.str() << "objects; each plane's cost: " << plane_costs(parent, bins)
         << ". Got the plane after bin " << got.split << " at cost " << got.cost << ", expected after bin "
         << expected_split << " at " << expected_cost << ": " << why);
    CHECK(got.split == expected_split);
    CHECK(std::abs(got.cost - expected_cost) < 1e-5f * expected_cost);
}

}  // namespace

GRADED_TEST("best_split: the cheapest plane between bins, by the SAH, with both sides non-empty", "10.2", 5)
{
    const Bounds parent = box({0, 0, 0}, {4, 1, 1});  // half area 9
    // 10 in [0,1] (half area 3) against 2 in [2,4] (5): 0.125 + 30/9 + 10/9. The plane after the
    // empty bin 1 has the same sides, so the same cost: the first of equals wins.
    check_best_split(parent, {10, 0, 1, 1}, 0, 0.125f + 30.0f / 9 + 10.0f / 9,
                     "the plane after the empty bin 1 costs the same; the first of equal planes wins");
    // The cheapest plane is the last: 3 in [0,3] (7) against 10 in [3,4] (3): 0.125 + 21/9 + 30/9.
    check_best_split(parent, {1, 1, 1, 10}, 2, 0.125f + 21.0f / 9 + 30.0f / 9, "the last plane is the cheapest");

    std::vector<SahBin> one(3);
    one[1].count = 7;
    one[1].bounds = box({1, 0, 0}, {2, 1, 1});
    const SahSplit none = best_split(parent, one);
    INFO("only bin 1 holds objects: got split " << none.split << " at " << none.cost << ", expected no split (-1, infinity)");
    CHECK(none.split == -1);
    CHECK(std::isinf(none.cost));

    // Fewer than two bins leave no plane between them: the builder never bins that few, but a
    // caller could, and must not read past the bins.
    for (const int n : {0, 1}) {
        std::vector<SahBin> few(n);
        if (n == 1) {
            few[0].count = 3;
            few[0].bounds = parent;
        }
        const SahSplit lone = best_split(parent, few);
        INFO(n << " bins: got split " << lone.split << " at " << lone.cost << ", expected no split (-1, infinity)");
        CHECK(lone.split == -1);
        CHECK(std::isinf(lone.cost));
    }
}

GRADED_TEST("best_split: the plane before the last bin holding objects, with two bins or with empty bins after it", "10.2", 2)
{
    // Two bins are the fewest with a plane between them: 3 in [0,1] (half area 3) against 5 in
    // [1,2] (3), in a parent 2 x 1 x 1 (5): 0.125 + 9/5 + 15/5.
    check_best_split(box({0, 0, 0}, {2, 1, 1}), {3, 5}, 0, 0.125f + 9.0f / 5 + 15.0f / 5,
                     "two bins leave one plane, after bin 0, with objects on both sides");
    // The same two bins and an empty third, in a parent 3 x 1 x 1 (7): the plane after bin 0 has
    // bin 1 alone on its right, and the empty bin after it does not make that side empty.
    check_best_split(box({0, 0, 0}, {3, 1, 1}), {3, 5, 0}, 0, 0.125f + 9.0f / 7 + 15.0f / 7,
                     "the right side of the plane after bin 0 holds bin 1's 5 objects; only the plane after bin 1 has an empty side");
}

GRADED_TEST("make_leaf: at most leaf_size objects, at the depth limit, or when no split pays", "10.3", 4)
{
    struct Case {
        int n, depth, leaf, max_depth;
        float cost;
        bool leaf_expected;
        const char* why;
    };
    for (const Case& c : std::vector<Case>{{4, 3, 4, 20, 1.0f, true, "exactly leaf_size objects"},
                                           {5, 3, 4, 20, 1.0f, false, "one more, and a split that pays"},
                                           {100, 20, 4, 20, 1.0f, true, "at the depth limit"},
                                           {100, 19, 4, 20, 1.0f, false, "one above it"},
                                           {6, 2, 4, 20, 6.5f, true, "the best split costs more than testing all 6"},
                                           {100, 21, 4, 20, 1.0f, true, "below the depth limit"},
                                           {6, 2, 4, 20, 6.0f, true, "it costs as much"},
                                           {6, 2, 4, 20, std::nextafter(6.0f, 0.0f), false,
                                            "it costs one float step less than testing all 6: it pays"},
                                           {6, 2, 4, 20, infinity, true, "no split is possible"}}) {
        const bool got = make_leaf(c.n, c.depth, c.leaf, c.max_depth, c.cost);
        INFO("make_leaf(" << c.n << " objects, depth " << c.depth << ", leaf_size " << c.leaf << ", max_depth "
             << c.max_depth << ", best split " << std::setprecision(9) << c.cost << "): got " << std::boolalpha << got << ", expected "
             << c.leaf_expected << ": " << c.why);
        CHECK(got == c.leaf_expected);
    }
}

GRADED_TEST("best_split: a single bin holding objects, first, last or between, among 2 to 16 bins, gives no split; the first and last bins holding objects give one",
            "10.2", 1)
{
    // Every plane has that bin's side holding all the objects and the other side none: no plane is
    // a split. With the bin last, the planes' loop must stop at the plane before it, after bin
    // bins.size() - 2; there is no plane after the last bin. With the first and the last bins
    // holding 7 objects each, every plane has both (half areas 3 and 3 in a parent of 2n + 1):
    // all cost the same, and the first, after bin 0, wins.
    for (int n = 2; n <= 16; ++n) {
        std::vector<int> ends(static_cast<size_t>(n), 0);
        ends.front() = ends.back() = 7;
        check_best_split(box({0, 0, 0}, {static_cast<float>(n), 1, 1}), ends, 0,
                         0.125f + 42.0f / static_cast<float>(2 * n + 1),
                         "the first and last bins hold objects: every plane has objects on both sides, at one cost");
    }
    for (int n = 2; n <= 16; ++n)
        for (const int full : {0, n / 2, n - 1}) {
            std::vector<int> counts(static_cast<size_t>(n), 0);
            counts[static_cast<size_t>(full)] = 7;
            const std::vector<SahBin> bins = unit_bins(counts);
            const Bounds parent = box({0, 0, 0}, {static_cast<float>(n), 1, 1});
            const WorkingOn on([&] { return "best_split of " + std::to_string(n) + " bins, only bin " + std::to_string(full) + " holding objects"; });
            const SahSplit got = best_split(parent, bins);
            INFO("10.2: " << n << " bins along x, only bin " << full << " holding objects (7): got the plane after bin "
                 << got.split << " at cost " << got.cost << ", expected no split (-1, infinity): every plane leaves one side "
                 "without objects");
            CHECK(got.split == -1);
            CHECK(std::isinf(got.cost));
        }
}
