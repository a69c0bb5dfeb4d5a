#include "common/stats.hpp"

#include <mutex>
#include <utility>

namespace rt {

namespace {
std::mutex totals_mutex;
Counts totals{};
std::vector<std::pair<std::string, std::string>> notes;
}  // namespace

void flush_counters()
{
    Counts& mine = local_counts();
    const std::lock_guard<std::mutex> lock(totals_mutex);
    for (size_t k = 0; k < mine.size(); ++k) {
        totals[k] += mine[k];
        mine[k] = 0;
    }
}

Counts total_counts()
{
    flush_counters();
    const std::lock_guard<std::mutex> lock(totals_mutex);
    return totals;
}

void reset_counters()
{
    local_counts() = Counts{};
    const std::lock_guard<std::mutex> lock(totals_mutex);
    totals = Counts{};
}

void note_stat(const std::string& key, const std::string& value)
{
    for (auto& [k, v] : notes)
        if (k == key) {
            v = value;
            return;
        }
    notes.emplace_back(key, value);
}

std::uint64_t total_rays(const Counts& counts)
{
    return counts[static_cast<size_t>(Counter::primary_rays)] + counts[static_cast<size_t>(Counter::shadow_rays)] +
           counts[static_cast<size_t>(Counter::reflected_rays)] + counts[static_cast<size_t>(Counter::refracted_rays)];
}

namespace {

void print_totals(std::ostream& out, const Counts& counts, double seconds)
{
    out << "rays=" << total_rays(counts) << '\n';
    out << "seconds=" << seconds << '\n';
    out << "rays_per_second=" << (seconds > 0.0 ? static_cast<double>(total_rays(counts)) / seconds : 0.0) << '\n';
    for (const auto& [key, value] : notes)
        out << key << '=' << value << '\n';
}

}  // namespace

void print_stats(std::ostream& out, const Counts& counts, double seconds)
{
    for (size_t k = 0; k < standard_counters; ++k)
        out << counter_names[k] << '=' << counts[k] << '\n';
    print_totals(out, counts, seconds);
}

void print_classic_stats(std::ostream& out, const Counts& counts, double seconds)
{
    const std::pair<const char*, Counter> names[] = {
        {"eye_rays", Counter::primary_rays},     {"eye_hits", Counter::primary_hits},
        {"reflect_rays", Counter::reflected_rays}, {"refract_rays", Counter::refracted_rays},
        {"shadow_rays", Counter::shadow_rays},   {"shadow_blocked", Counter::shadow_blocked},
        {"secondary_hits", Counter::secondary_hits}, {"intersection_tests", Counter::intersection_tests}};
    for (const auto& [name, counter] : names)
        out << name << '=' << counts[static_cast<size_t>(counter)] << '\n';
    print_totals(out, counts, seconds);
}

}  // namespace rt
