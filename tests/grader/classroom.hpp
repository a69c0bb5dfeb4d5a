// GitHub Classroom's side of a grade: the result its reporter action
// (classroom-resources/autograding-grading-reporter) reads from a step's output, and the job's
// summary page. Written by grade_report --classroom-output and --step-summary
// (the workflow is tests/classroom/classroom.yml, which the handout writes).
#pragma once

#include "tests/grader/points.hpp"

#include <string>
#include <vector>

namespace rt::grader {

// The reporter's object, as JSON: {"version": 1, "status", "max_score", "tests": [{"name",
// "status", "score", "message", "test_code"}]}, one test per (summarized) case carrying its own
// points, so a case's partial points reach Classroom, which sums the tests' scores. status is
// "pass" (full points), "error" (the case did not run to a verdict: its chapter does not compile or
// is missing, it crashed or was stopped) or "fail". The messages are cut so the whole object,
// base64-encoded, stays under `budget` bytes (the reporter gets it in one environment variable,
// which Linux caps at 128 KiB); the summary page has them whole.
std::string classroom_result_json(const std::vector<CaseResult>& summarized, size_t budget = 96 * 1024);

// Appends `result=<base64 of classroom_result_json>` to a step's output file ($GITHUB_OUTPUT).
bool append_classroom_output(const std::string& path, const std::vector<CaseResult>& summarized);

// Appends the points as Markdown to the job's summary ($GITHUB_STEP_SUMMARY): the total, a table
// of chapters, then per chapter its exercises' points and each failed case with its message, as
// the console prints them.
bool append_step_summary(const std::string& path, const std::vector<CaseResult>& summarized);

std::string base64_encode(const std::string& bytes);

}  // namespace rt::grader
