// The speed/accuracy trade, measured: each chapter program can sweep its own knob and print a
// table of cost against error, and write it as CSV.
#pragma once

#include "common/image.hpp"

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace rt {

// A time measured over several runs: its median is what a table reports, and min and max its
// spread, which says how far to trust a difference between two rows (a busy machine widens it).
// A time computed from others (a difference of two medians) has no runs of its own: runs is 0.
struct Timing {
    double median = 0.0, min = 0.0, max = 0.0;
    int runs = 0;
};

// The median, min and max of `seconds` (all 0 with runs 0 for none).
Timing timing_of(std::vector<double> seconds);

// `t` in other units, e.g. scaled(t, 1e3) in milliseconds.
Timing scaled(const Timing& t, double factor);

struct TradeRow {
    std::string knob;      // what was varied, e.g. "spp"
    std::string value;     // its value in this row
    Timing seconds;        // over the repeats
    std::uint64_t rays;    // rays of one run
    double error;          // against the reference, in the table's metric
};

struct TradeTable {
    std::string chapter;
    std::string error_metric;  // e.g. "rmse_linear_rgb against 1024 spp"
    std::vector<TradeRow> rows;
};

// Root mean square difference of two equal-sized images over all channels, in linear RGB.
double rmse(const Image& a, const Image& b);

// The median of the values (the mean of the middle two for an even count); 0 for none.
double median(std::vector<double> values);

// Runs `work` `repeats` times (at least once) and returns its wall-clock seconds.
Timing time_runs(int repeats, const std::function<void()>& work);

void print_trade_table(std::ostream& out, const TradeTable& table);

// Where a second table of the same run goes, beside `path`: ("out/name.csv", "_missed") gives
// "out/name_missed.csv"; a path not ending in .csv gets the suffix and ".csv" appended.
std::string csv_beside(const std::string& path, const std::string& suffix);

// CSV columns: chapter,knob,value,seconds,rays,rays_per_second,error,error_metric,seconds_min,
// seconds_max,runs (the spread last, so that a reader of the older columns by position still works).
// Throws InputError naming the path when it cannot be written.
void write_trade_csv(const std::string& path, const TradeTable& table);

}  // namespace rt
