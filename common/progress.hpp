// A progress line on stderr for long work: what is being done, how far, the time so far and an
// estimate of what is left. On a terminal it updates in place, at most ten times a second; in a
// log or a pipe it writes a line every progress_log_seconds (RT_PROGRESS_SECONDS overrides), and
// nothing for work shorter than that, so short runs and CI output stay clean. Safe to tick from
// many threads; a total of 0 shows nothing.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

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

// Work of an unknown number of uneven steps (a sweep's measurements, one of which may take half a
// minute): from its own thread, a whole line on stderr every period, the steps done and the time so
// far, step_terminal_seconds apart on a terminal, progress_log_seconds in a log or a pipe
// (RT_PROGRESS_SECONDS overrides both). Whole lines, never updated in place, so that what the
// program prints on stdout meanwhile stays whole. step() is safe from any thread.
class StepProgress {
public:
    explicit StepProgress(std::string steps_done);  // "structures measured"
    ~StepProgress();
    void step() { ++done_; }

private:
    void say_every_period();

    std::string steps_done_;
    std::atomic<long> done_{0};
    double period_;
    bool said_ = false, stopping_ = false;
    std::chrono::steady_clock::time_point start_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::thread sayer_;
};

// Why 3 s: someone at a terminal waiting on a sweep of a minute or more sees that it moves without
// a screenful of lines.
constexpr double step_terminal_seconds = 3.0;

// "12 s", "3 min 20 s", "1 h 05 min": a duration as a person reads it.
std::string readable_duration(double seconds);

}  // namespace rt
