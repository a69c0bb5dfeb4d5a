// Running one graded case in a process of its own, on POSIX and on Windows alike: the grader starts
// itself again for each case (posix_spawn, or CreateProcess), so a crash or an endless loop costs
// that case only, and no platform needs fork.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace rt::grader {

struct ChildStatus {
    enum class End { exited, crashed, stopped, not_started } end = End::not_started;
    int code = 0;  // the exit status; for `crashed`, the signal (POSIX) or exception code (Windows)
};

// This program's own file, to start again.
std::string this_program(const char* argv0);

// Runs `program` with `args`, sharing this process's stdout and stderr, and waits for it; after
// `wall_seconds` it is killed and the answer is `stopped`.
ChildStatus run_child(const std::string& program, const std::vector<std::string>& args, double wall_seconds);

// Seconds of CPU time this process has used, all its threads together.
double process_cpu_seconds();

// Stops this process with exit status `code` once it has used `cpu_seconds` of CPU time: a thread
// that looks every few milliseconds, and calls `last_words` (if any) just before. A case's limit in
// CPU time is the same on a busy machine and a quiet one, where a wall-clock limit would stop a
// correct case that waited for a core.
void limit_cpu_time(double cpu_seconds, int code, std::function<void()> last_words = {});

// The file that discards what is written to it ("/dev/null", or "NUL" on Windows).
const char* null_device();

}  // namespace rt::grader
