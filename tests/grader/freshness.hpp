// A student's grader built before the last edit of a file it links would grade the old code
// without a word. Each student's grader knows the files it was built from (the exercises of its
// chapter and of every chapter before it, the contracts they include, the chapter's graded cases)
// and how to build itself; run after an edit of any of them, it rebuilds and then grades the new code.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace rt::grader {

// Called once, before main, by the student's graders (exercise_source.cpp): the files the grader
// is built from, and the command that rebuilds it.
bool register_exercise_sources(std::vector<std::string> sources, std::vector<std::string> rebuild_command);

// When a registered file is newer than this program: names it, rebuilds, and grades again with the
// rebuilt program and the same arguments; the answer is the exit status to end with. Nothing (and
// nothing done) when the program is up to date or grades no student's file.
std::optional<int> regrade_if_stale(const std::string& program, int argc, char** argv);

}  // namespace rt::grader
