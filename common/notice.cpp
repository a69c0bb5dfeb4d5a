#include "common/notice.hpp"

#include <atomic>
#include <cstdio>
#include <mutex>
#include <stdexcept>

namespace rt {

namespace {

std::atomic<bool> notices_on{true};
std::mutex print_mutex;
std::vector<std::string>* captured = nullptr;  // the live NoticeCapture's lines, under print_mutex

}  // namespace

void notice(const std::string& line)
{
    const std::lock_guard<std::mutex> lock(print_mutex);
    if (captured)
        captured->push_back(line);
    if (!notices_on.load(std::memory_order_relaxed))
        return;
    std::fprintf(stderr, "%s\n", line.c_str());
    std::fflush(stderr);
}

void set_notices(bool on) { notices_on.store(on, std::memory_order_relaxed); }

NoticeCapture::NoticeCapture()
{
    const std::lock_guard<std::mutex> lock(print_mutex);
    if (captured)
        throw std::logic_error("NoticeCapture: one at a time");
    captured = &lines_;
}

NoticeCapture::~NoticeCapture()
{
    const std::lock_guard<std::mutex> lock(print_mutex);
    captured = nullptr;
}

std::vector<std::string> NoticeCapture::lines() const
{
    const std::lock_guard<std::mutex> lock(print_mutex);
    return lines_;
}

bool NoticeCapture::said(const std::string& words) const
{
    for (const std::string& line : lines())
        if (line.find(words) != std::string::npos)
            return true;
    return false;
}

}  // namespace rt
