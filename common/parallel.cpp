#include "common/parallel.hpp"

#include "common/notice.hpp"

#include <string>

namespace rt {

int resolve_threads(int requested)
{
    if (requested > 0)
        return requested;
    // hardware_concurrency() may answer 0 where the system does not say.
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void warn_threads_started(int requested, int started)
{
    static std::once_flag once;
    std::call_once(once, [&] {
        notice("asked for " + std::to_string(requested) + " threads, but the system started only " +
               std::to_string(started) + ": rendering on " + std::to_string(started) + " (the picture is the same)");
    });
}

}  // namespace rt
