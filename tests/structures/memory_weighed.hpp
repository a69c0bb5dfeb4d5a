// The hashed grid's word on its memory (chapter 09's hashed_grid.hpp): a build that holds
// more than hashed_memory_factor times what chapter 07's dense grid at its default lambda holds for
// the same objects, and more than hashed_memory_floor, says so in one notice; any other says
// nothing of it. The dense grid's figure is taken from a dense grid built here, the hashed grid's
// from the counts its own build reports.
#pragma once

#include "07_uniform_grid/figure.hpp"
#include "09_hashed_voxels/hashed_grid.hpp"
#include "common/notice.hpp"
#include "tests/grader/graded.hpp"

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace rt::memory_weighed {

// What the notice of a hashed grid's memory starts with, and says (the notice of a lambda lowered,
// grid.hpp's say_lambda_lowered, starts the same).
inline const std::string said_start = "the hashed grid: at lambda ";
inline const std::string said_words = " its build holds up to ";

// What chapter 07's dense grid at its default lambda holds at its build's peak for `objects`.
inline std::size_t dense_peak(const Objects& objects)
{
    GridStats stats;
    build_grid(objects, margins_of(objects), ch07::default_lambda, &stats);
    return dense_build_bytes(objects.size(), stats.references, stats.cells);
}

inline bool over_budget(std::size_t peak, std::size_t dense)
{
    return static_cast<double>(peak) > std::max(hashed_memory_floor, hashed_memory_factor * static_cast<double>(dense));
}

// The lines of `said` that speak of the hashed grid's memory.
inline std::vector<std::string> memory_lines(const std::vector<std::string>& said)
{
    std::vector<std::string> lines;
    for (const std::string& line : said)
        if (line.rfind(said_start, 0) == 0 && line.find(said_words) != std::string::npos)
            lines.push_back(line);
    return lines;
}

// Checks that `grid`, built over `objects` while `said` was captured, spoke of its memory exactly
// when it was over its budget.
inline void check(const Objects& objects, const HashedGrid& grid, const std::vector<std::string>& said)
{
    const HashedGridStats& s = grid.stats();
    const std::size_t dense = dense_peak(objects);
    const std::vector<std::string> lines = memory_lines(said);
    INFO("the hashed grid at lambda " << s.lambda << " (" << s.resolution.x << " x " << s.resolution.y << " x "
                                      << s.resolution.z << " cells, " << s.occupied << " occupied, " << s.references
                                      << " references) holds up to " << s.peak_bytes / 1e6
                                      << " MB at its build's peak; chapter 07's dense grid at lambda "
                                      << ch07::default_lambda << " holds " << dense / 1e6 << " MB; the budget is "
                                      << std::max(hashed_memory_floor, hashed_memory_factor * static_cast<double>(dense)) / 1e6
                                      << " MB (" << hashed_memory_factor << " times that, at least "
                                      << hashed_memory_floor / 1e6 << " MB); its notices on memory: "
                                      << (lines.empty() ? std::string("none") : lines.front()));
    CHECK(s.peak_bytes >= s.bytes);
    CHECK(s.dense_bytes == dense);
    if (over_budget(s.peak_bytes, dense)) {
        INFO("over its budget: the build should say so in one notice");
        CHECK(lines.size() == 1);
    } else {
        INFO("within its budget: the build should say nothing of its memory");
        CHECK(lines.empty());
    }
}

}  // namespace rt::memory_weighed
