// Graded cases and their points: the table a student reads, the files a course platform reads
// (Gradescope's results.json, JUnit XML), and the line format the grade binaries hand to
// grade_report.
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace rt::grader {

struct CaseResult {
    std::string number;   // "NN.k": chapter NN, exercise k (or P for the picture)
    std::string name;     // the behaviour checked
    int max_score = 0;
    int score = 0;
    bool passed = false;
    std::string output;   // what went in and what came out, for a failed case
    std::string stubs;    // the exercises whose handed-out stubs ran in the case: "07.1 07.3"
};

// One case's verdict, and for a failed case what went in and came out, indented.
void print_case(std::ostream& out, const CaseResult& result);

// Points per exercise and per chapter, and the failed cases by name.
void print_points_table(std::ostream& out, const std::vector<CaseResult>& results);

// Text safe inside XML or HTML: & < > " escaped.
std::string escape_xml(const std::string& s);

// A case's output as a student reads it: paths relative to the kit, and no more than the first 40
// lines (or 4000 characters), then how many more there were.
std::string tidy_output(std::string output);

// One case a line, tab-separated, with tabs, newlines and backslashes escaped.
bool write_results(const std::string& path, const std::vector<CaseResult>& results);
bool append_result(const std::string& path, const CaseResult& result);
bool read_results(const std::string& path, std::vector<CaseResult>& results);

// Gradescope's autograder format: {"score", "tests": [{"name","number","score","max_score","output"}]}.
// A case for which `as_html` gives HTML is written with that output and "output_format": "html".
bool write_gradescope_json(const std::string& path, const std::vector<CaseResult>& results,
                           const std::function<std::string(const CaseResult&)>& as_html = {});
bool write_junit_xml(const std::string& path, const std::vector<CaseResult>& results);

// Appends `student,chNN...,total` to a CSV gradebook, with a header when the file is new.
bool append_gradebook_row(const std::string& path, const std::string& student, const std::vector<CaseResult>& results);

// `full`: every case passed; `zero`: none did; `less`: at least one failed. Prints what broke the
// expectation, and says false, when no graded case ran at all.
bool check_expectation(std::ostream& out, const std::vector<CaseResult>& results, const std::string& expect);

}  // namespace rt::grader
