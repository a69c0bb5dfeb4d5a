// A progress line on stderr for long work: what is being done, how far, the time so far and an
// estimate of what is left. On a terminal it updates in place, at most ten times a second; in a
// log or a pipe it writes a line every progress_log_seconds (RT_PROGRESS_SECONDS overrides), and
// nothing for work shorter than that, so short runs and CI output stay clean. Safe to tick from
// many threads; a total of 0 shows nothing.
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

namespace rt {

// Why 15 s: a log line per quarter minute tells a waiting instructor the work is alive without
// drowning the log; anything shorter finishes before the first line.
constexpr double progress_log_seconds = 15.0;

class Progress {
public:
    Progress(std::string what, long total);
    ~Progress();
    void tick();  // one more unit of `total` done

private:
    std::string what_;
    long total_;
    std::atomic<long> done_{0};
    bool enabled_, terminal_;
    double log_period_;
    bool logged_ = false;
    std::mutex print_mutex_;
    std::chrono::steady_clock::time_point start_, last_print_;
};

// "12 s", "3 min 20 s", "1 h 05 min": a duration as a person reads it.
std::string readable_duration(double seconds);

}  // namespace rt
