// The hashed grid's memory: a flat scene fills every cell of its one layer, and at lambda 256 its
// build holds about a hundred times chapter 07's dense grid. A build that holds
// more than hashed_memory_factor times the dense grid's memory at lambda 4, and more than
// hashed_memory_floor, says so in one notice, with the lambdas that would not; the lambda asked for
// is built all the same. Every scene of legal_scenes_test.cpp is held to the same rule there.
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

TEST_CASE("8,000 triangles flat at z = 0: the hashed grid says its build holds 100 times the dense grid's memory, and which lambdas would not", "[structures]")
{
    LitScene floor;
    floor.add_material({});
    const int n = 63;  // 2 n^2 = 7,938 triangles, each a cell of the dense grid's layer, 256 of the hashed one's
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const point3 a(i, j, 0), b(i + 1, j, 0), c(i + 1, j + 1, 0), d(i, j + 1, 0);
            floor.add_triangle({a, b, c}, 0);
            floor.add_triangle({a, c, d}, 0);
        }
    const Objects objects = objects_of(floor, lit_tests);
    const Built built = build_saying(objects, ch09::default_hashed_lambda);
    memory_weighed::check(objects, *built.grid, built.said);

    const HashedGridStats& s = built.grid->stats();
    const std::size_t dense = memory_weighed::dense_peak(objects);
    INFO("the hashed grid at lambda " << s.lambda << " holds up to " << s.peak_bytes / 1e6 << " MB, the dense grid "
                                      << dense / 1e6 << " MB");
    REQUIRE(memory_weighed::over_budget(s.peak_bytes, dense));
    const std::vector<std::string> lines = memory_weighed::memory_lines(built.said);
    REQUIRE(lines.size() == 1);
    const std::string& line = lines.front();
    INFO("its notice: " << line);
    // Both figures in MB, the references per object, and the scene's part in it.
    char figures[128];
    std::snprintf(figures, sizeof figures, "up to %.3g MB, %.0f times the %.3g MB of chapter 07's dense grid",
                  s.peak_bytes / 1e6, static_cast<double>(s.peak_bytes) / dense, dense / 1e6);
    CHECK(line.find(figures) != std::string::npos);
    CHECK(line.find("listed in " + std::to_string(std::lround(static_cast<double>(s.references) / s.objects)) +
                    " cells each") != std::string::npos);
    CHECK(line.find("the scene is flat: they fill 100% of the cells of its one layer") != std::string::npos);
    CHECK(line.find("built at lambda 256 as asked") != std::string::npos);

    // The lambdas offered: the largest halvings of 256 under the floor, then within the factor.
    const std::vector<float> offered = lambdas_offered(line);
    REQUIRE(offered.size() == 2);
    const double bounds[2] = {hashed_memory_floor, hashed_memory_factor * static_cast<double>(dense)};
    for (int k = 0; k < 2; ++k) {
        INFO("--lambda " << offered[k] << " is offered as the largest halving of 256 holding no more than "
                         << bounds[k] / 1e6 << " MB");
        const Built at = build_saying(objects, offered[k]);
        memory_weighed::check(objects, *at.grid, at.said);
        CHECK(static_cast<double>(at.grid->stats().peak_bytes) <= bounds[k]);
        if (2 * offered[k] < ch09::default_hashed_lambda) {
            const Built twice = build_saying(objects, 2 * offered[k]);
            INFO("at lambda " << 2 * offered[k] << " it holds " << twice.grid->stats().peak_bytes / 1e6 << " MB");
            CHECK(static_cast<double>(twice.grid->stats().peak_bytes) > bounds[k]);
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
    }
}
