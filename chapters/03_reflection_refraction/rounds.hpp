// Timing several pieces of work against each other on a shared machine: in rounds, each round
// running every piece once, so that a load which comes and goes (another build, another user)
// falls on all of them alike; each piece's time is its spread over the rounds. Timing one piece
// `repeat` times and then the next would give whichever ran during the load a time of its own.
#pragma once

#include "common/stats.hpp"
#include "common/trade.hpp"

#include <algorithm>
#include <functional>
#include <vector>

namespace rt {

inline std::vector<Timing> time_in_rounds(int rounds, const std::vector<std::function<void()>>& works)
{
    std::vector<std::vector<double>> seconds(works.size());
    for (int round = 0; round < std::max(1, rounds); ++round)
        for (size_t k = 0; k < works.size(); ++k) {
            const Timer timer;
            works[k]();
            seconds[k].push_back(timer.seconds());
        }
    std::vector<Timing> timings;
    for (std::vector<double>& s : seconds)
        timings.push_back(timing_of(std::move(s)));
    return timings;
}

}  // namespace rt
