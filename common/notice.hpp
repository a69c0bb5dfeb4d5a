// The kit's own notices: what a program says about its work that is neither its result nor an error
// ("built at lambda 100 instead", "shaded opaque here", "the system started only 2 threads"). A
// chapter program's user reads them on standard error; the grader turns them off, since they speak
// of the kit's own test scenes and concern no student. Every such line goes through notice().
#pragma once

#include <string>
#include <vector>

namespace rt {

// Says one line (no newline of its own) on standard error, unless notices are off. Safe from many
// threads: lines never interleave.
void notice(const std::string& line);

// Turns the kit's notices off (the grader) or back on; they are on when a program starts.
void set_notices(bool on);

// Keeps every notice said while it lives, whether notices are printed or off (the grader's): a test
// checks what a build said. One at a time; the lines are also printed as before, if notices are on.
class NoticeCapture {
public:
    NoticeCapture();
    ~NoticeCapture();
    NoticeCapture(const NoticeCapture&) = delete;
    NoticeCapture& operator=(const NoticeCapture&) = delete;

    // The lines said so far, in order.
    std::vector<std::string> lines() const;
    // Whether some line said so far contains `words`.
    bool said(const std::string& words) const;

private:
    std::vector<std::string> lines_;  // written by notice(), under its lock
};

}  // namespace rt
