// The kit's one parallel loop, on std::thread: the same on every compiler and platform, OpenMP or not
// (Apple clang ships without it), so `--threads 2` means two threads everywhere.
//
// Work is handed out dynamically, `chunk` items at a time, as each thread finishes its last share.
// Which thread takes an item never changes a result: each caller keeps its own results per item (a
// pixel's own random stream, a ray's own answer) and adds per-thread counts in the end.
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace rt {

// The threads to use: `requested`, or one a core when 0 (at least 1).
int resolve_threads(int requested);

// Said once, as a notice (common/notice.hpp), when the system would not start all the threads asked for.
void warn_threads_started(int requested, int started);

// Runs body(k) for every k in [0, count), on `threads` threads (the caller's own among them). Each
// thread calls finish() once, after its last item: where a thread adds its counts to the totals.
// An exception thrown by a body is thrown again here, after every thread has stopped. Returns how
// many threads ran.
template <class Body, class Finish>
int parallel_for(long count, int threads, long chunk, const Body& body, const Finish& finish)
{
    threads = static_cast<int>(std::clamp<long>(resolve_threads(threads), 1, std::max(1L, count)));
    chunk = std::max(1L, chunk);
    std::atomic<long> next{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    const auto work = [&] {
        try {
            for (long start; (start = next.fetch_add(chunk)) < count;)
                for (long k = start; k < std::min(count, start + chunk); ++k)
                    body(k);
        } catch (...) {
            const std::lock_guard<std::mutex> lock(error_mutex);
            if (!error)
                error = std::current_exception();
            next = count;  // the others stop after their current item
        }
        finish();
    };
    std::vector<std::thread> helpers;
    helpers.reserve(static_cast<size_t>(threads - 1));
    try {
        while (static_cast<int>(helpers.size()) < threads - 1)
            helpers.emplace_back(work);
    } catch (const std::system_error&) {
        warn_threads_started(threads, static_cast<int>(helpers.size()) + 1);
    }
    const int started = static_cast<int>(helpers.size()) + 1;
    work();
    for (std::thread& t : helpers)
        t.join();
    if (error)
        std::rethrow_exception(error);
    return started;
}

}  // namespace rt
