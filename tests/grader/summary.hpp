// What a student reads first. A chapter that did not compile, or that is still the handed-out
// stubs, is one line; an exercise that is still its stub, or whose cases run another's stub, is one
// line; every other case is as graded. The points are the same before and after: a line that stands for several cases carries
// their maximum.
#pragma once

#include "tests/grader/points.hpp"

#include <string>
#include <vector>

namespace rt::grader {

// The graded cases as the report shows them. `NN.build` lines (a chapter that did not compile,
// written by grade.cmake) stand for their chapter's cases. Each line that stands for several cases
// has their status: untouched, stub or waits_for_stub, or the build line's own.
std::vector<CaseResult> summarize(const std::vector<CaseResult>& results);

// For a case that failed while a handed-out stub ran, the one line that says so ("07.3 is still
// the handed-out stub", or "07.5 cannot be graded yet: it runs 07.4, ..."); empty for any other.
std::string stub_verdict(const CaseResult& r);

// Whether a case ran the handed-out stub of an exercise of an earlier chapter than its own. In a
// handout (no solutions/), a later chapter's cases measure the student's answer against the
// student's own earlier chapters (brute force through 02.2 and 02.5, the camera of 01.1): with one
// of those still a stub, yardstick and answer share the stub's answer, and a case can pass without
// telling a stub from an answer (07.A's agreement case did, with every exercise a stub). Such a
// case is not passed: it waits for the stub.
bool rests_on_earlier_stub(const CaseResult& r);

// One chapter of a summarized grade, as the class page shows it: its points, and what an
// instructor should look at, from each line's status ("no file", "does not compile", "untouched",
// "stub 07.3", "stopped 07.2", "crashed 07.4"), empty when nothing.
struct ChapterMark {
    std::string chapter;
    int score = 0, max_score = 0;
    std::string marks;
};
std::vector<ChapterMark> chapter_marks(const std::vector<CaseResult>& summarized);

}  // namespace rt::grader
