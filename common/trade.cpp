#include "common/trade.hpp"

#include "common/output.hpp"

#include "common/error.hpp"
#include "common/stats.hpp"

#include <algorithm>
#include <utility>
#include <cassert>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>

namespace rt {

double rmse(const Image& a, const Image& b)
{
    assert(a.width == b.width && a.height == b.height);
    double sum = 0.0;
    for (size_t p = 0; p < a.pixels.size(); ++p)
        for (int k = 0; k < 3; ++k) {
            const double d = static_cast<double>(a.pixels[p][k]) - static_cast<double>(b.pixels[p][k]);
            sum += d * d;
        }
    return std::sqrt(sum / (3.0 * static_cast<double>(a.pixels.size())));
}

double median(std::vector<double> values)
{
    if (values.empty())
        return 0.0;
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

Timing timing_of(std::vector<double> seconds)
{
    if (seconds.empty())
        return {};
    const auto [least, most] = std::minmax_element(seconds.begin(), seconds.end());
    return {median(seconds), *least, *most, static_cast<int>(seconds.size())};
}

Timing scaled(const Timing& t, double factor)
{
    return {t.median * factor, t.min * factor, t.max * factor, t.runs};
}

Timing time_runs(int repeats, const std::function<void()>& work)
{
    std::vector<double> seconds;
    for (int k = 0; k < std::max(1, repeats); ++k) {
        const Timer timer;
        work();
        seconds.push_back(timer.seconds());
    }
    return timing_of(std::move(seconds));
}

static double rays_per_second(const TradeRow& row)
{
    return row.seconds.median > 0.0 ? static_cast<double>(row.rays) / row.seconds.median : 0.0;
}

void print_trade_table(std::ostream& out, const TradeTable& table)
{
    out << table.chapter << ": error is " << table.error_metric << '\n';
    // The first column as wide as its longest entry, so rows stay aligned whatever they are named.
    int width = std::max(10, static_cast<int>(table.rows.front().knob.size()) + 2);
    for (const TradeRow& row : table.rows)
        width = std::max(width, static_cast<int>(row.value.size()) + 2);
    out << std::left << std::setw(width) << table.rows.front().knob << std::right << std::setw(12) << "seconds"
        << std::setw(14) << "rays" << std::setw(16) << "rays/second" << std::setw(14) << "error" << '\n';
    for (const TradeRow& row : table.rows)
        out << std::left << std::setw(width) << row.value << std::right << std::fixed << std::setprecision(4)
            << std::setw(12) << row.seconds.median << std::setw(14) << row.rays << std::setprecision(0)
            << std::setw(16) << rays_per_second(row) << std::scientific << std::setprecision(3) << std::setw(14)
            << row.error << std::defaultfloat << '\n';
}

std::string csv_beside(const std::string& path, const std::string& suffix)
{
    const std::string extension = ".csv";
    const bool has_extension =
        path.size() >= extension.size() && path.compare(path.size() - extension.size(), extension.size(), extension) == 0;
    return (has_extension ? path.substr(0, path.size() - extension.size()) : path) + suffix + extension;
}

void write_trade_csv(const std::string& path, const TradeTable& table)
{
    check_writable(path, "CSV");
    std::ofstream out(path);
    if (!out)
        throw InputError(path + ": cannot write the CSV file");
    out << "chapter,knob,value,seconds,rays,rays_per_second,error,error_metric,seconds_min,seconds_max,runs\n";
    out << std::setprecision(6);
    for (const TradeRow& row : table.rows)
        out << table.chapter << ',' << row.knob << ',' << row.value << ',' << row.seconds.median << ',' << row.rays << ','
            << rays_per_second(row) << ',' << row.error << ',' << table.error_metric << ',' << row.seconds.min << ','
            << row.seconds.max << ',' << row.seconds.runs << '\n';
    if (!out)
        throw InputError(path + ": cannot write the CSV file");
}

}  // namespace rt
