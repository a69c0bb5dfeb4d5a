#include "common/progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#ifdef _WIN32
#include <io.h>
#else
#include <unistd.h>
#endif

namespace rt {

namespace {

bool stderr_is_terminal()
{
#ifdef _WIN32
    return _isatty(_fileno(stderr)) != 0;
#else
    return isatty(fileno(stderr)) != 0;
#endif
}

}  // namespace

std::string readable_duration(double seconds)
{
    const long s = std::lround(std::max(0.0, seconds));
    char text[32];
    if (s < 60)
        std::snprintf(text, sizeof text, "%ld s", s);
    else if (s < 3600)
        std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
    else
        std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, (s / 60) % 60);
    return text;
}

Progress::Progress(std::string what, long total)
    : what_(std::move(what)), total_(total), enabled_(total > 0), terminal_(stderr_is_terminal()),
      log_period_(progress_log_seconds), start_(std::chrono::steady_clock::now()), last_print_(start_)
{
    if (const char* period = std::getenv("RT_PROGRESS_SECONDS"))
        log_period_ = std::atof(period);
}

Progress::~Progress()
{
    if (enabled_ && (terminal_ || logged_))
        std::fprintf(stderr, "%s%s: done in %s%20s\n", terminal_ ? "\r" : "", what_.c_str(),
                     readable_duration(std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count()).c_str(),
                     "");
}

void Progress::tick()
{
    const long done = ++done_;
    if (!enabled_)
        return;
    // Never wait for the lock: a busy thread skips the print.
    std::unique_lock<std::mutex> lock(print_mutex_, std::try_to_lock);
    if (!lock.owns_lock())
        return;
    const auto now = std::chrono::steady_clock::now();
    const double since_print = std::chrono::duration<double>(now - last_print_).count();
    if (terminal_ ? since_print < 0.1 && done != total_ : since_print < log_period_)
        return;
    last_print_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double left = done > 0 ? elapsed * static_cast<double>(total_ - done) / static_cast<double>(done) : 0.0;
    std::fprintf(stderr, "%s%s: %3ld%% (%s, about %s left)%s", terminal_ ? "\r" : "", what_.c_str(),
                 100 * done / total_, readable_duration(elapsed).c_str(), readable_duration(left).c_str(),
                 terminal_ ? "   " : "\n");
    logged_ = logged_ || !terminal_;
    std::fflush(stderr);
}

StepProgress::StepProgress(std::string steps_done)
    : steps_done_(std::move(steps_done)), period_(stderr_is_terminal() ? step_terminal_seconds : progress_log_seconds),
      start_(std::chrono::steady_clock::now())
{
    // (A tenth of a second at least: a period of 0, which Progress takes as "at every tick", would
    // be a line without end here.)
    if (const char* period = std::getenv("RT_PROGRESS_SECONDS"))
        period_ = std::max(0.1, std::atof(period));
    sayer_ = std::thread([this] { say_every_period(); });
}

StepProgress::~StepProgress()
{
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_one();
    sayer_.join();
    if (said_)
        std::fprintf(stderr, "%ld %s in %s\n", done_.load(), steps_done_.c_str(),
                     readable_duration(std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count()).c_str());
}

void StepProgress::say_every_period()
{
    std::unique_lock<std::mutex> lock(mutex_);
    const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(period_));
    for (auto next = start_ + period; !wake_.wait_until(lock, next, [this] { return stopping_; }); next += period) {
        said_ = true;
        std::fprintf(stderr, "%ld %s so far (%s)\n", done_.load(), steps_done_.c_str(),
                     readable_duration(std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count()).c_str());
        std::fflush(stderr);
    }
}

}  // namespace rt
