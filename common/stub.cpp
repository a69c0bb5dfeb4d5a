#include "common/stub.hpp"

#include <array>
#include <atomic>
#include <cstdio>

namespace rt {

namespace {

// Chapters 00-99, exercises 0-15 in each: "NN.k" maps to one flag.
constexpr int exercises_per_chapter = 16;
std::array<std::atomic<bool>, 100 * exercises_per_chapter> ran{};

int index_of(const char* exercise)
{
    int chapter = 0, k = 0;
    if (std::sscanf(exercise, "%2d.%d", &chapter, &k) != 2 || chapter < 0 || k < 0 || k >= exercises_per_chapter)
        return -1;
    return chapter * exercises_per_chapter + k;
}

}  // namespace

void note_stub(const char* exercise)
{
    const int i = index_of(exercise);
    if (i >= 0 && !ran[i].load(std::memory_order_relaxed))
        ran[i].store(true, std::memory_order_relaxed);
}

std::vector<std::string> stubs_that_ran()
{
    std::vector<std::string> names;
    for (int i = 0; i < static_cast<int>(ran.size()); ++i)
        if (ran[i].load(std::memory_order_relaxed)) {
            char name[8];
            std::snprintf(name, sizeof name, "%02d.%d", i / exercises_per_chapter, i % exercises_per_chapter);
            names.emplace_back(name);
        }
    return names;
}

void forget_stubs()
{
    for (std::atomic<bool>& flag : ran)
        flag.store(false, std::memory_order_relaxed);
}

}  // namespace rt
