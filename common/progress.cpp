#include "common/progress.hpp"

#include <cstdio>
#include <unistd.h>

namespace rt {

Progress::Progress(std::string what, long total)
    : what_(std::move(what)), total_(total), enabled_(total > 0 && isatty(fileno(stderr)) != 0),
      last_print_(std::chrono::steady_clock::now())
{
}

Progress::~Progress()
{
    if (enabled_)
        std::fprintf(stderr, "\r%s: done%30s\n", what_.c_str(), "");
}

void Progress::tick()
{
    const long done = ++done_;
    if (!enabled_)
        return;
    // At most ten updates a second, and never wait for the lock: a busy thread skips the print.
    std::unique_lock<std::mutex> lock(print_mutex_, std::try_to_lock);
    if (!lock.owns_lock())
        return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_print_ < std::chrono::milliseconds(100) && done != total_)
        return;
    last_print_ = now;
    std::fprintf(stderr, "\r%s: %3ld%%", what_.c_str(), total_ > 0 ? 100 * done / total_ : 100);
    std::fflush(stderr);
}

}  // namespace rt
