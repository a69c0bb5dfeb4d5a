// The open exercises' measure on its way out of the grader: the results file, Gradescope's
// results.json `leaderboard`, the Classroom job summary, and the class page's ranking (names or
// pseudonyms).
#include "tests/grader/class_stats.hpp"
#include "tests/grader/classroom.hpp"
#include "tests/grader/html_report.hpp"
#include "tests/grader/points.hpp"

#include "tests/grader/catch.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using rt::grader::CaseResult;
using rt::grader::CaseStatus;

// One of 10.7's tier cases: passed or not, with the cost it measured (none: a tree the gate failed).
CaseResult tier(int points, bool passed, double cost)
{
    CaseResult r;
    r.number = "10.7";
    r.name = "build_bvh (open): tier " + std::to_string(points);
    r.max_score = points;
    r.score = passed ? points : 0;
    r.status = passed ? CaseStatus::passed : CaseStatus::failed;
    if (cost > 0.0) {
        r.measure = "10.7 cost";
        r.measured = cost;
        r.reference = 1.0;
    }
    return r;
}

CaseResult plain(const std::string& number)
{
    CaseResult r;
    r.number = number;
    r.name = "case " + number;
    r.max_score = r.score = 2;
    r.status = CaseStatus::passed;
    return r;
}

std::string read_file(const std::string& path)
{
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

size_t occurrences(const std::string& text, const std::string& word)
{
    size_t n = 0;
    for (size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1))
        ++n;
    return n;
}

rt::grader::StudentResults student(const std::string& name, double cost)
{
    return {name, {plain("10.1"), tier(4, cost <= 2.0, cost), tier(4, cost <= 1.5, cost)}};
}

}  // namespace

TEST_CASE("a results file keeps a case's measure, and a line without one still reads", "[grader]")
{
    const std::string path = "leaderboard_test.results";
    REQUIRE(rt::grader::write_results(path, {plain("10.1"), tier(4, true, 1.74186)}));
    std::vector<CaseResult> read;
    REQUIRE(rt::grader::read_results(path, read));
    REQUIRE(read.size() == 2);
    CHECK(read[0].measure.empty());
    CHECK(read[1].measure == "10.7 cost");
    CHECK(read[1].measured == 1.74186);
    CHECK(read[1].reference == 1.0);
    CHECK(read[1].status == CaseStatus::passed);
    std::remove(path.c_str());
}

TEST_CASE("the points table prints an open exercise's figures scene by scene, read back from the results file", "[grader]")
{
    // check_NN's table comes from grade_report, which reads the results file: a student whose design
    // passes every tier sees the figures only if they survive the round trip.
    const std::string path = "leaderboard_detail_test.results";
    CaseResult measured = tier(4, true, 0.942);
    measured.measure_detail = "\n  teapot in a stadium 4: 3.70 per ray, the reference 3.93\n  sticks 3: 13.1 per ray, the reference 13.97";
    REQUIRE(rt::grader::write_results(path, {plain("10.1"), measured}));
    std::vector<CaseResult> read;
    REQUIRE(rt::grader::read_results(path, read));
    REQUIRE(read.size() == 2);
    CHECK(read[1].measure_detail == measured.measure_detail);
    std::ostringstream table;
    rt::grader::print_points_table(table, rt::grader::summarize(read), read);
    INFO(table.str());
    CHECK(table.str().find("10.7 cost: 0.942 (the reference: 1") != std::string::npos);
    CHECK(table.str().find("\n    teapot in a stadium 4: 3.70 per ray, the reference 3.93\n    sticks 3:") != std::string::npos);
    std::remove(path.c_str());
}

TEST_CASE("results.json carries Gradescope's leaderboard: each measure once, in ascending order", "[grader]")
{
    const std::string path = "leaderboard_test.json";
    // Three tier cases report the one measure: the board has it once.
    REQUIRE(rt::grader::write_gradescope_json(path, {plain("10.1"), tier(4, true, 0.98), tier(4, true, 0.98), tier(4, true, 0.98)}));
    const std::string json = read_file(path);
    INFO(json);
    CHECK(occurrences(json, "\"leaderboard\": [") == 1);
    CHECK(occurrences(json, "{\"name\": \"10.7 cost\", \"value\": 0.98, \"order\": \"asc\"}") == 1);
    // A run that measured nothing (a chapter without an open exercise, a tree the gate failed) has none.
    REQUIRE(rt::grader::write_gradescope_json(path, {plain("10.1"), tier(4, false, 0.0)}));
    CHECK(read_file(path).find("leaderboard") == std::string::npos);
    std::remove(path.c_str());
}

TEST_CASE("the Classroom job summary shows the student's cost against the reference's", "[grader]")
{
    const std::string path = "leaderboard_test.md";
    std::remove(path.c_str());
    REQUIRE(rt::grader::append_step_summary(path, {plain("10.1"), tier(4, true, 1.74186), tier(4, false, 1.74186)}));
    const std::string md = read_file(path);
    INFO(md);
    CHECK(md.find("| 10.7 cost | 1.742 | 1.000 |") != std::string::npos);
    std::remove(path.c_str());
}

TEST_CASE("the class leaderboard ranks students by their cost, lowest first, and leaves out those without one", "[grader]")
{
    const std::vector<rt::grader::StudentResults> students = {student("carol", 1.74), student("alice", 0.97),
                                                              {"dave", {plain("10.1"), tier(4, false, 0.0)}},
                                                              student("bob", 1.0)};
    const std::vector<rt::grader::Leaderboard> boards =
        rt::grader::class_leaderboards(students, rt::grader::LeaderboardNames::names, "");
    REQUIRE(boards.size() == 1);
    CHECK(boards[0].measure == "10.7 cost");
    REQUIRE(boards[0].ranked.size() == 3);
    CHECK(boards[0].ranked[0].shown == "alice");
    CHECK(boards[0].ranked[1].shown == "bob");
    CHECK(boards[0].ranked[2].shown == "carol");
    const std::string page = "leaderboard_test.html";
    REQUIRE(rt::grader::write_leaderboard_page(page, boards));
    const std::string html = read_file(page);
    CHECK(html.find("alice") < html.find("bob"));
    CHECK(html.find("bob") < html.find("carol"));
    CHECK(html.find("dave") == std::string::npos);
    std::remove(page.c_str());
}

TEST_CASE("students of equal cost share a rank, and the next cost's rank counts them", "[grader]")
{
    const std::vector<rt::grader::StudentResults> students = {student("carol", 1.742), student("bob", 1.0),
                                                              student("alice", 1.0)};
    const auto boards = rt::grader::class_leaderboards(students, rt::grader::LeaderboardNames::names, "");
    REQUIRE(boards.size() == 1);
    const std::string page = "leaderboard_test_ties.html";
    REQUIRE(rt::grader::write_leaderboard_page(page, boards));
    const std::string html = read_file(page);
    INFO(html);
    CHECK(html.find("<tr><td>1</td><td>alice</td>") != std::string::npos);
    CHECK(html.find("<tr><td>1</td><td>bob</td>") != std::string::npos);
    CHECK(html.find("<tr><td>3</td><td>carol</td>") != std::string::npos);
    std::remove(page.c_str());
}

TEST_CASE("with pseudonyms the shared leaderboard names no student; the same key gives the same pseudonyms", "[grader]")
{
    const std::vector<rt::grader::StudentResults> students = {student("carol", 1.74), student("alice", 0.97)};
    const auto boards = rt::grader::class_leaderboards(students, rt::grader::LeaderboardNames::pseudonyms, "our key");
    REQUIRE(boards.size() == 1);
    REQUIRE(boards[0].ranked.size() == 2);
    CHECK(boards[0].ranked[0].student == "alice");
    CHECK(boards[0].ranked[0].shown == rt::grader::pseudonym_of("alice", "our key"));
    CHECK(rt::grader::pseudonym_of("alice", "our key") != rt::grader::pseudonym_of("alice", "another key"));
    CHECK(rt::grader::pseudonym_of("alice", "our key") != rt::grader::pseudonym_of("carol", "our key"));
    const std::string page = "leaderboard_test_pseudonyms.html";
    REQUIRE(rt::grader::write_leaderboard_page(page, boards));
    const std::string html = read_file(page);
    INFO(html);
    CHECK(html.find("alice") == std::string::npos);
    CHECK(html.find("carol") == std::string::npos);
    CHECK(html.find(rt::grader::pseudonym_of("carol", "our key")) != std::string::npos);
    std::remove(page.c_str());
}
