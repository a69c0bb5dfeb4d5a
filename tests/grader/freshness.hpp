// A student's grader built before the last edit of the exercise it grades would grade the old code
// without a word. Each student's grader knows the file it was built from and how to build itself;
// run after an edit, it rebuilds and then grades the new code.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace rt::grader {

// Called once, before main, by the student's graders (exercise_source.cpp): the exercise file, and
// the command that rebuilds this grader.
bool register_exercise_source(const char* source, std::vector<std::string> rebuild_command);

// When the registered exercise file is newer than this program: says so, rebuilds, and grades again
// with the rebuilt program and the same arguments; the answer is the exit status to end with.
// Nothing (and nothing done) when the program is up to date or grades no student's file.
std::optional<int> regrade_if_stale(const std::string& program, int argc, char** argv);

}  // namespace rt::grader
