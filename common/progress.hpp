// A progress line on stderr for long renders, shown only when stderr is a terminal, so logs,
// pipes and CI output stay clean. Safe to tick from many threads; a total of 0 shows nothing.
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

namespace rt {

class Progress {
public:
    Progress(std::string what, long total);
    ~Progress();
    void tick();  // one more unit of `total` done

private:
    std::string what_;
    long total_;
    std::atomic<long> done_{0};
    bool enabled_;
    std::mutex print_mutex_;
    std::chrono::steady_clock::time_point last_print_;
};

}  // namespace rt
