// The scale families (chapter 04's scale_families.hpp) in the test command: 54 scenes, every family
// at scales 1e-3, 1 and 1e3, at the origin and 1e2 and 1e5 from it, and each once with the eye 1e3
// times as far. Every pixel unlike the double reference is explained or warned about; a wrong one
// prints its scene and pixel. (The chapter's --sweep runs all 990 for the lesson.)
#include "04_shadow_feelers/scale_families.hpp"
#include "tests/grader/graded.hpp"

using namespace rt;
using namespace rt::scale_families;

TEST_CASE("every family at every scale draws what double draws, or the kit warns", "[structures]")
{
    std::vector<Row> rows = run({-3, 0, 3}, {-1, 2, 5}, {1.0}, 16);
    for (Row& r : run({-3, 0, 3}, {-1}, {1e3}, 16))
        rows.push_back(std::move(r));
    int differ = 0, explained = 0;
    for (const Row& r : rows) {
        differ += r.c.differ;
        explained += r.c.explained;
        INFO(r.scene.name << " at s = " << r.at.s << ", " << r.at.out << " from the origin, the eye " << r.at.far
                          << " times as far: " << r.c.wrong() << " wrong of " << r.c.pixels << " pixels; the first "
                          << r.c.first << (r.warning.empty() ? "" : "; the kit warns: " + r.warning));
        CHECK((r.c.wrong() == 0 || !r.warning.empty()));
    }
    INFO(differ << " pixels unlike double over " << rows.size() << " scenes, " << explained << " explained");
    CHECK(rows.size() == 6u * 12u);
    CHECK(explained <= differ);
}
