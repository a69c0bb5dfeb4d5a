// The hashed grid's memory: a flat scene fills every cell of its one layer, and at lambda 256 its
// build once held about a hundred times chapter 07's dense grid; it is built at chapter 07's lambda
// instead (hashed_most_occupied), and says so. Any other build that holds more than
// hashed_memory_factor times the dense grid's memory at lambda 4, and more than hashed_memory_floor,
// says so in one notice, with the lambdas that would not; the lambda asked for is built all the same.
// Every scene of legal_scenes_test.cpp is held to the same rule there.
#include "09_hashed_voxels/figure.hpp"
#include "tests/ch07/agreement.hpp"
#include "tests/structures/memory_weighed.hpp"

#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

using namespace rt;
using namespace rt::grader;

namespace {

// A hashed grid over `objects`, and the notices said while it was built.
struct Built {
    std::unique_ptr<HashedGrid> grid;
    std::vector<std::string> said;
};

Built build_saying(const Objects& objects, float lambda)
{
    Built b;
    const NoticeCapture capture;
    b.grid = std::make_unique<HashedGrid>(objects, lambda);
    b.said = capture.lines();
    return b;
}

// The number after each "--lambda " of a notice, in order.
std::vector<float> lambdas_offered(const std::string& line)
{
    std::vector<float> offered;
    for (std::size_t at = line.find("--lambda "); at != std::string::npos; at = line.find("--lambda ", at + 1))
        offered.push_back(std::strtof(line.c_str() + at + 9, nullptr));
    return offered;
}

}  // namespace

// A flat floor of 2 n^2 unit triangles at z = 0.
Objects flat_floor(LitScene& floor, int n)
{
    floor.add_material({});
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const point3 a(i, j, 0), b(i + 1, j, 0), c(i + 1, j + 1, 0), d(i, j + 1, 0);
            floor.add_triangle({a, b, c}, 0);
            floor.add_triangle({a, c, d}, 0);
        }
    return objects_of(floor, lit_tests);
}

TEST_CASE("a flat scene fills every cell of its layer: the hashed grid builds at chapter 07's lambda, within 4 times the dense grid's memory, and says so", "[structures]")
{
    // 7,938 and 49,928 triangles: at lambda 256 the first once held 100 MB (106 times the dense
    // grid's), the second 625 MB.
    for (const int n : {63, 158}) {
        LitScene floor;
        const Objects objects = flat_floor(floor, n);
        for (const float lambda : {ch09::default_hashed_lambda, 1024.0f}) {
            const Built built = build_saying(objects, lambda);
            memory_weighed::check(objects, *built.grid, built.said);
            const HashedGridStats& s = built.grid->stats();
            const std::size_t dense = memory_weighed::dense_peak(objects);
            INFO(objects.size() << " flat triangles at lambda " << lambda << ": the hashed grid built at lambda "
                                << s.lambda << " holds up to " << s.peak_bytes / 1e6 << " MB, the dense grid "
                                << dense / 1e6 << " MB");
            CHECK(s.lambda == dense_grid_lambda);
            CHECK(static_cast<double>(s.peak_bytes) <= 4.0 * static_cast<double>(dense));
            REQUIRE(built.said.size() == 1);
            INFO("its notice: " << built.said.front());
            CHECK(built.said.front().find("100% of its cells would hold objects") != std::string::npos);
            CHECK(built.said.front().find("built at lambda 4, chapter 07's, instead") != std::string::npos);
        }
    }
}

TEST_CASE("the chapter's figure at lambda 256 keeps to the hashed grid's memory budget without a word; at 1024 it says so", "[structures]")
{
    const LitScene stadium = lit_scene(ch09::figure_scene());
    const Objects objects = objects_of(stadium, lit_tests);
    for (const float lambda : {ch09::default_hashed_lambda, 1024.0f}) {
        INFO("the stadium at lambda " << lambda);
        const Built built = build_saying(objects, lambda);
        memory_weighed::check(objects, *built.grid, built.said);
        const HashedGridStats& s = built.grid->stats();
        CHECK(memory_weighed::over_budget(s.peak_bytes, s.dense_bytes) == (lambda > ch09::default_hashed_lambda));
        if (lambda == ch09::default_hashed_lambda)
            continue;
        // Its notice: both figures in MB, the references per object, and the lambdas that would not.
        const std::vector<std::string> lines = memory_weighed::memory_lines(built.said);
        REQUIRE(lines.size() == 1);
        const std::string& line = lines.front();
        INFO("its notice: " << line);
        char figures[128];
        std::snprintf(figures, sizeof figures, "up to %.3g MB, %.0f times the %.3g MB of chapter 07's dense grid",
                      s.peak_bytes / 1e6, static_cast<double>(s.peak_bytes) / s.dense_bytes, s.dense_bytes / 1e6);
        CHECK(line.find(figures) != std::string::npos);
        CHECK(line.find("listed in " + std::to_string(std::lround(static_cast<double>(s.references) / s.objects)) +
                        " cells each") != std::string::npos);
        CHECK(line.find("built at lambda 1024 as asked") != std::string::npos);
        // The lambdas offered: the largest halvings of 1024 under the floor, then within the factor.
        const std::vector<float> offered = lambdas_offered(line);
        REQUIRE(!offered.empty());
        for (const float l : offered) {
            INFO("--lambda " << l << " is offered as a halving of 1024 within the budget");
            const Built at = build_saying(objects, l);
            memory_weighed::check(objects, *at.grid, at.said);
            CHECK(!memory_weighed::over_budget(at.grid->stats().peak_bytes, s.dense_bytes));
        }
    }
}
