// A grading run as a web page: the points per chapter and per case, each failed case's message,
// and for a picture case the expected, actual and difference images side by side. The images are
// embedded (data URIs), so the page can be copied, mailed or uploaded whole.
#pragma once

#include "tests/grader/class_stats.hpp"
#include "tests/grader/points.hpp"
#include "tests/grader/summary.hpp"

#include <string>
#include <vector>

namespace rt::grader {

bool write_html_report(const std::string& path, const std::string& title, std::vector<CaseResult> results);

// A picture case's output as HTML, its expected, actual and difference images embedded: what a
// course platform shows a student who cannot open the grading machine's files. Empty for a case
// whose output names no picture.
std::string case_output_html(const CaseResult& result);

// Appends a student's row to the class page's table (a header row first when the file is new):
// their total, linking to students/NAME/report.html, then each chapter's points with its marks
// (a missing file, a compile failure, untouched stubs, a stopped or crashed case) flagged.
bool append_class_row(const std::string& path, const std::string& student, const std::vector<ChapterMark>& chapters);

// The class page: the gradebook and the exercises' CSV as links (relative to the page), the
// students' table (the rows append_class_row wrote), the exercises' table (class_stats.hpp), then
// the open exercises' leaderboards (leaderboards_html, with each student's name), linking the page
// to share with the class (`leaderboard_page`, written by write_leaderboard_page; empty: none).
bool write_class_page(const std::string& path, const std::string& student_rows, const std::vector<ExerciseStats>& exercises,
                      const std::string& gradebook, const std::string& exercises_csv,
                      const std::vector<Leaderboard>& boards = {}, const std::string& leaderboard_page = "");

// The leaderboards alone, as the students may see them: each student as the board shows them
// (their name, or their pseudonym), no points and no messages.
bool write_leaderboard_page(const std::string& path, const std::vector<Leaderboard>& boards);

}  // namespace rt::grader
