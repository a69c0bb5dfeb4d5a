// The grade as a student and an instructor read it (tests/grader/summary.hpp): what stands for
// many cases is one line, and no point is lost or gained on the way.
#include "tests/grader/summary.hpp"

#include "tests/grader/catch.hpp"

#include <numeric>

namespace {

using rt::grader::CaseResult;

CaseResult graded(const std::string& number, int max, bool passed, const std::string& stubs = "",
                  const std::string& output = "")
{
    CaseResult r;
    r.number = number;
    r.name = "case " + number;
    r.max_score = max;
    r.score = passed ? max : 0;
    r.passed = passed;
    r.stubs = stubs;
    r.output = output;
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

TEST_CASE("a chapter that did not compile is one line with the compiler's errors, worth all its cases", "[grader]")
{
    CaseResult build = graded("02.build", 0, false, "", "02_spheres_triangles.cpp:3:1: error: expected ';'");
    build.name = "chapter 02 does not compile";
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
        graded("07.5", 1, false, "", std::string(rt::grader::stopped_mark) + "the case used more than 10 s of CPU time"),
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
