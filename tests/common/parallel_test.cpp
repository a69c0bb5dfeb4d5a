#include "common/parallel.hpp"
#include "tests/grader/graded.hpp"

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

using namespace rt;

TEST_CASE("the parallel loop runs every item once, on the threads asked for, each finishing once", "[common]")
{
    for (const int threads : {1, 2, 3, 8}) {
        for (const long count : {0L, 1L, 5L, 1000L}) {
            std::vector<std::atomic<int>> runs(static_cast<size_t>(count));
            std::mutex ids_mutex;
            std::set<std::thread::id> ids;
            std::atomic<int> finished{0};
            const int started = parallel_for(count, threads, 3, [&](long k) {
                ++runs[static_cast<size_t>(k)];
                const std::lock_guard<std::mutex> lock(ids_mutex);
                ids.insert(std::this_thread::get_id());
            }, [&] { ++finished; });
            INFO(threads << " threads, " << count << " items");
            // No more threads than items (but one, even for none), each finishing once.
            CHECK(started == std::max(1, static_cast<int>(std::min<long>(threads, std::max(1L, count)))));
            CHECK(finished == started);
            CHECK(static_cast<int>(ids.size()) <= started);
            for (long k = 0; k < count; ++k)
                REQUIRE(runs[static_cast<size_t>(k)] == 1);
        }
    }
    CHECK(resolve_threads(0) >= 1);
    CHECK(resolve_threads(5) == 5);
}

TEST_CASE("an exception in the parallel loop reaches its caller after every thread has stopped", "[common]")
{
    std::atomic<int> finished{0};
    CHECK_THROWS_WITH(parallel_for(100, 2, 1, [](long k) {
        if (k == 37)
            throw std::runtime_error("item 37 failed");
    }, [&] { ++finished; }), "item 37 failed");
    CHECK(finished == 2);
}
