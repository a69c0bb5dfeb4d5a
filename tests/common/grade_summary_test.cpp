// The grade as a student and an instructor read it (tests/grader/summary.hpp): what stands for
// many cases is one line, and no point is lost or gained on the way.
#include "tests/grader/points.hpp"
#include "tests/grader/summary.hpp"

#include "tests/grader/catch.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <sstream>
#include <string>

namespace {

using rt::grader::CaseResult;
using rt::grader::CaseStatus;

CaseResult graded(const std::string& number, int max, bool passed, const std::string& stubs = "",
                  const std::string& output = "")
{
    CaseResult r;
    r.number = number;
    r.name = "case " + number;
    r.max_score = max;
    r.score = passed ? max : 0;
    r.status = passed ? CaseStatus::passed : CaseStatus::failed;
    r.stubs = stubs;
    r.output = output;
    return r;
}

// A failed case with the status the grader gave it.
CaseResult ended(const std::string& number, CaseStatus status, const std::string& output)
{
    CaseResult r = graded(number, 1, false, "", output);
    r.status = status;
    return r;
}

int maximum(const std::vector<CaseResult>& results)
{
    return std::accumulate(results.begin(), results.end(), 0, [](int sum, const CaseResult& r) { return sum + r.max_score; });
}

std::string show(const std::vector<CaseResult>& results)
{
    std::string s;
    for (const CaseResult& r : results)
        s += r.number + " " + std::to_string(r.score) + "/" + std::to_string(r.max_score) + " " + r.name + "\n";
    return s;
}

}  // namespace

TEST_CASE("a chapter whose every case ran a stub is one line worth all of its points", "[grader]")
{
    const std::vector<CaseResult> cases = {graded("07.1", 2, false, "07.1"), graded("07.2", 3, false, "07.1 07.2"),
                                           graded("07.P", 5, false, "07.1")};
    const auto summary = rt::grader::summarize(cases);
    INFO(show(summary));
    REQUIRE(summary.size() == 1);
    CHECK(summary[0].number == "07");
    CHECK(summary[0].name == "chapter 07 is still the handed-out stubs");
    CHECK(summary[0].max_score == 10);
    CHECK(summary[0].score == 0);
    CHECK(rt::grader::chapter_marks(summary)[0].marks == "untouched");
}

TEST_CASE("a lettered case waiting for a stub says what it is: A the whole structure, P the figure", "[grader]")
{
    const std::vector<CaseResult> cases = {graded("07.1", 2, true), graded("07.A", 4, false, "07.3"),
                                           graded("07.P", 3, false, "07.3 07.4")};
    const auto summary = rt::grader::summarize(cases);
    INFO(show(summary));
    REQUIRE(summary.size() == 3);
    CHECK(summary[1].name == "07.A (your whole structure against brute force) cannot be graded yet: it runs 07.3, "
                             "which is still the handed-out stub");
    CHECK(summary[2].name == "07.P (the chapter's figure against the reference) cannot be graded yet: it runs 07.3 "
                             "and 07.4, which are still the handed-out stubs");
}

TEST_CASE("an untouched chapter's points table still shows what each exercise is worth", "[grader]")
{
    const std::vector<CaseResult> cases = {graded("07.1", 2, false, "07.1"), graded("07.1", 3, false, "07.1"),
                                           graded("07.2", 4, false, "07.2"), graded("07.P", 5, false, "07.1")};
    std::ostringstream table;
    rt::grader::print_points_table(table, rt::grader::summarize(cases), cases);
    INFO(table.str());
    CHECK(table.str().find("chapter 07             0 / 14") != std::string::npos);
    CHECK(table.str().find("lost 14: chapter 07 is still the handed-out stubs") != std::string::npos);
    CHECK(table.str().find("07.1                0 / 5") != std::string::npos);
    CHECK(table.str().find("07.2                0 / 4") != std::string::npos);
    CHECK(table.str().find("07.P                0 / 5") != std::string::npos);
}

TEST_CASE("a chapter that did not compile is one line with the compiler's errors, worth all its cases", "[grader]")
{
    CaseResult build = graded("02.build", 0, false, "", "02_spheres_triangles.cpp:3:1: error: expected ';'");
    build.name = "chapter 02 does not compile";
    build.status = CaseStatus::does_not_compile;
    const std::vector<CaseResult> cases = {graded("01.1", 4, true), graded("02.1", 6, false), graded("02.2", 7, false), build};
    const auto summary = rt::grader::summarize(cases);
    INFO(show(summary));
    REQUIRE(summary.size() == 2);
    CHECK(summary[1].number == "02");
    CHECK(summary[1].max_score == 13);
    CHECK(summary[1].output == build.output);
    const auto marks = rt::grader::chapter_marks(summary);
    CHECK(marks[0].marks.empty());
    CHECK(marks[1].marks == "does not compile");
}

TEST_CASE("an exercise still its stub is one line; a case that waits for another's stub says which", "[grader]")
{
    const std::vector<CaseResult> cases = {
        graded("07.1", 2, true),
        graded("07.2", 3, false, "07.2", "the walk visits []"),
        graded("07.2", 4, false, "07.2", "the walk visits []"),
        graded("07.3", 5, false, "07.2", "wrong cell"),
        graded("07.4", 6, false, "", "the cell of (1, 2, 3) is 4; expected 5"),
        ended("07.5", CaseStatus::stopped, "stopped: the case used more than 10 s of CPU time"),
    };
    const auto summary = rt::grader::summarize(cases);
    INFO(show(summary));
    REQUIRE(summary.size() == 5);
    CHECK(summary[1].name == "07.2 is still the handed-out stub");
    CHECK(summary[1].max_score == 7);
    CHECK(summary[2].name == "07.3 cannot be graded yet: it runs 07.2, which is still the handed-out stub");
    CHECK(summary[3].output == cases[4].output);  // a plain failure keeps what went in and came out
    CHECK(maximum(summary) == maximum(cases));
    CHECK(rt::grader::chapter_marks(summary)[0].marks == "stub 07.2, stopped 07.5");
}

TEST_CASE("the class page marks a case by its status, whatever its message says", "[grader]")
{
    // A student's own message may begin like the grader's: only the status says crashed.
    const std::vector<CaseResult> cases = {ended("04.1", CaseStatus::failed, "crashed: the light is inside the sphere"),
                                           ended("04.2", CaseStatus::crashed, "the case crashed (signal 11)")};
    CHECK(rt::grader::chapter_marks(rt::grader::summarize(cases))[0].marks == "crashed 04.2");
}

TEST_CASE("a results file keeps each case's status, and a file from before the status still reads", "[grader]")
{
    const std::string path = "grade_summary_test.results";
    std::vector<CaseResult> cases = {graded("07.1", 2, true), ended("07.2", CaseStatus::crashed, "crashed: signal 11"),
                                     ended("07.3", CaseStatus::stopped, "stopped: over 10 s")};
    cases[1].stubs = "07.1";
    REQUIRE(rt::grader::write_results(path, cases));
    std::vector<CaseResult> read;
    REQUIRE(rt::grader::read_results(path, read));
    REQUIRE(read.size() == 3);
    for (size_t k = 0; k < 3; ++k) {
        CHECK(read[k].status == cases[k].status);
        CHECK(read[k].stubs == cases[k].stubs);
        CHECK(read[k].output == cases[k].output);
    }
    // The six fields of an older grader, and grade.cmake's older build line of five.
    {
        std::ofstream old(path);
        old << "07.1\t2\t2\tcase 07.1\t\t\n07.2\t3\t0\tcase 07.2\tfailed: ...\t07.2\n"
               "08.build\t0\t0\tchapter 08 does not compile\terror: expected ';'\n";
    }
    read.clear();
    REQUIRE(rt::grader::read_results(path, read));
    REQUIRE(read.size() == 3);
    CHECK(read[0].status == CaseStatus::passed);
    CHECK(read[1].status == CaseStatus::failed);
    CHECK(read[1].stubs == "07.2");
    CHECK(read[2].status == CaseStatus::does_not_compile);
    std::remove(path.c_str());
}

TEST_CASE("a failing case whose own stub ran in only some of its cases still reads as the stub", "[grader]")
{
    // The first case of 07.2 ran 07.1's stub only (07.1 unfinished); a later one ran its own.
    const std::vector<CaseResult> cases = {graded("07.2", 3, false, "07.1"), graded("07.2", 4, false, "07.1 07.2"),
                                           graded("07.3", 1, true)};
    const auto summary = rt::grader::summarize(cases);
    INFO(show(summary));
    REQUIRE(summary.size() == 2);
    CHECK(summary[0].name == "07.2 is still the handed-out stub");
    CHECK(summary[0].max_score == 7);
}

TEST_CASE("a case's output is cut to about a screenful, saying how much more there was, and cut once", "[grader]")
{
    std::string output;
    for (int k = 0; k < 500; ++k)
        output += "failed: CHECK( walked == crossed ) for ray " + std::to_string(k) + "\n";
    const std::string cut = rt::grader::tidy_output(output);
    CHECK(std::count(cut.begin(), cut.end(), '\n') + 1 == static_cast<long>(rt::grader::case_output_lines));
    CHECK_THAT(cut, rt::grader::contains_text("... and 469 more lines"));
    CHECK(rt::grader::tidy_output(cut) == cut);
    const std::string one_long_line(10000, 'x');
    const std::string cut_long = rt::grader::tidy_output(one_long_line);
    CHECK(cut_long.size() < 4000);
    CHECK(rt::grader::tidy_output(cut_long) == cut_long);
    CHECK(rt::grader::tidy_output("a\nb\n") == "a\nb\n");
}
