// The kit's own notices: what a program says about its work that is neither its result nor an error
// ("built at lambda 100 instead", "shaded opaque here", "the system started only 2 threads"). A
// chapter program's user reads them on standard error; the grader turns them off, since they speak
// of the kit's own test scenes and concern no student. Every such line goes through notice().
#pragma once

#include <string>

namespace rt {

// Says one line (no newline of its own) on standard error, unless notices are off. Safe from many
// threads: lines never interleave.
void notice(const std::string& line);

// Turns the kit's notices off (the grader) or back on; they are on when a program starts.
void set_notices(bool on);

}  // namespace rt
