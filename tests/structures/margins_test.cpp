// Chapter 07's margins (grid.hpp), which every structure of chapters 07-10 grows its boxes by: the
// scene's bulk, the box that leaves out up to reach_outliers stray objects on each side.
#include "07_uniform_grid/grid.hpp"
#include "tests/grader/catch.hpp"

#include <algorithm>
#include <functional>
#include <random>
#include <vector>

using namespace rt;

TEST_CASE("the bulk's box runs from the (q + 1)-th least minimum to the (q + 1)-th greatest maximum on each axis", "[structures]")
{
    // The order statistics as a sort gives them, against bulk_of's one pass: boxes with repeated
    // coordinates, a few far outliers, and counts around each step of q = min(n / 100, 8).
    std::mt19937 rng(20261207);
    std::uniform_real_distribution<float> near(-10.0f, 10.0f), far(-1e6f, 1e6f);
    std::uniform_int_distribution<int> kind(0, 9);
    for (const std::size_t n : {1u, 2u, 99u, 100u, 101u, 250u, 799u, 800u, 801u, 900u, 5000u}) {
        std::vector<Bounds> boxes(n);
        for (Bounds& b : boxes) {
            // Ties in the middle (k == 1) and at both ends (k == 2, the least minimum; k == 3, the
            // greatest maximum), where the (q + 1)-th value falls among copies of itself.
            const int k = kind(rng);
            const point3 p = k == 0   ? point3(far(rng), far(rng), far(rng))
                             : k == 1 ? point3(1.0f, 2.0f, 3.0f)
                             : k == 2 ? point3(-1e7f)
                             : k == 3 ? point3(1e7f)
                                      : point3(near(rng), near(rng), near(rng));
            b = Bounds{p, p + vec3(static_cast<float>(k))};
        }
        const std::size_t q = std::min(n / 100, static_cast<std::size_t>(reach_outliers));
        const Bounds bulk = bulk_of(boxes);
        for (int a = 0; a < 3; ++a) {
            std::vector<float> low, high;
            for (const Bounds& b : boxes) {
                low.push_back(b.min[a]);
                high.push_back(b.max[a]);
            }
            std::sort(low.begin(), low.end());
            std::sort(high.begin(), high.end(), std::greater<float>());
            INFO(n << " boxes, q " << q << ", axis " << a << ": the bulk from " << bulk.min[a] << " to " << bulk.max[a]
                   << ", the sort's " << low[q] << " to " << high[q]);
            CHECK(bulk.min[a] == low[q]);
            CHECK(bulk.max[a] == high[q]);
        }
    }
    CHECK(bulk_of({}).empty());
}
