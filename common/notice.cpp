#include "common/notice.hpp"

#include <atomic>
#include <cstdio>
#include <mutex>

namespace rt {

namespace {

std::atomic<bool> notices_on{true};
std::mutex print_mutex;

}  // namespace

void notice(const std::string& line)
{
    if (!notices_on.load(std::memory_order_relaxed))
        return;
    const std::lock_guard<std::mutex> lock(print_mutex);
    std::fprintf(stderr, "%s\n", line.c_str());
    std::fflush(stderr);
}

void set_notices(bool on) { notices_on.store(on, std::memory_order_relaxed); }

}  // namespace rt
