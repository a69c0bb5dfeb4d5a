// Graded cases and their points: the table a student reads, the files a course platform reads
// (Gradescope's results.json, JUnit XML), and the line format the grade binaries hand to
// grade_report.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace rt::grader {

// How a case ended. The results file carries it as a word ("passed", "crashed", ...), so whatever
// reads a grade (the report, the class page) knows a case's state from this field, never from the
// words of its message.
enum class CaseStatus {
    passed,            // every check held
    failed,            // a check failed, or the case checked nothing
    crashed,           // the student's code crashed in the case, or its process ended without reporting
    stopped,           // the case ran past its time and was stopped
    // A line of the summary (summary.hpp) standing for several cases:
    stub,              // an exercise still its handed-out stub
    waits_for_stub,    // an exercise whose cases run another exercise's stub
    untouched,         // a chapter whose every case ran a stub
    does_not_compile,  // a chapter that did not compile (grade.cmake's NN.build line)
    no_file,           // a chapter whose file the submission does not have (the same)
};

// The status as the results file writes it ("waits_for_stub"), and back; an unknown word is nullopt.
const char* status_word(CaseStatus status);
std::optional<CaseStatus> status_of_word(const std::string& word);

struct CaseResult {
    std::string number;   // "NN.k": chapter NN, exercise k (or P for the picture)
    std::string name;     // the behaviour checked
    int max_score = 0;
    int score = 0;
    CaseStatus status = CaseStatus::failed;
    std::string output;   // what went in and what came out, for a failed case
    std::string stubs;    // the exercises whose handed-out stubs ran in the case: "07.1 07.3"
    // What the case measured for the class leaderboard (graded.hpp's report_measure), lower first:
    // its name ("10.7 cost"; empty: none), the student's value and the reference solution's.
    std::string measure;
    double measured = 0.0, reference = 0.0;
    // Its figures scene by scene, which the points table prints under the measure, passed or not: a
    // student improving a design that already passes every tier needs them.
    std::string measure_detail;

    bool passed() const { return status == CaseStatus::passed; }
};

// The chapter of a case number: "07" of "07.3", "07.P" and "07.build".
inline std::string chapter_of(const std::string& number) { return number.substr(0, 2); }
inline std::string chapter_of(const CaseResult& r) { return chapter_of(r.number); }

// The line a chapter that did not build gets in place of its cases ("07.build").
inline bool is_build_line(const CaseResult& r) { return r.number.size() > 2 && r.number.compare(2, std::string::npos, ".build") == 0; }

// The most lines a case's output keeps (about a screenful): the first failed checks say what is
// wrong, and the rest are counted, not shown. The grader stops adding failed checks a few lines
// short of it; tidy_output cuts whatever is still longer.
constexpr std::size_t case_output_lines = 32;

// One case's verdict, and for a failed case what went in and came out, indented.
void print_case(std::ostream& out, const CaseResult& result);

// Points per exercise and per chapter, and the failed cases by name.
// With `cases` (the results before summarize), a chapter summed into one untouched line still shows
// each exercise's points, so a student sees how the chapter's points split.
void print_points_table(std::ostream& out, const std::vector<CaseResult>& results,
                        const std::vector<CaseResult>& cases = {});

// The measures of a run for its leaderboard, one per name in the order first met (every tier case of
// an open exercise reports the same one): name, the student's value and the reference's.
std::vector<CaseResult> leaderboard_of(const std::vector<CaseResult>& results);

// Text safe inside XML or HTML: & < > " escaped.
std::string escape_xml(const std::string& s);

// Text safe inside a JSON string (without the quotes): " \ and control characters escaped.
std::string escape_json(const std::string& s);

// s as one CSV field: in double quotes, each quote inside doubled (RFC 4180).
std::string csv_field(const std::string& s);

// A case's output as a student reads it: paths relative to the kit, and no more than the first
// case_output_lines lines (or 4000 characters), then how many more there were.
std::string tidy_output(std::string output);

// One case a line, tab-separated, with tabs, newlines and backslashes escaped: number, max score,
// score, name, output, stubs, status. A line without the status (a file written before it was
// added) reads as passed when its score is whole and failed otherwise, an NN.build line as
// does_not_compile; a reader that knows only the first six fields still reads this one.
// Three more fields when the case measured something: the measure's name, the value and the
// reference's; a fourth, its figures scene by scene, for check_NN's table (grade_report).
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
