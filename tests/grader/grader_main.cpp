// The grader's main: Catch2 plus a listener that turns test cases into points.
//
// Options beside Catch2's own:
//   --results FILE        write one line per graded case (read by grade_report)
//   --expect-score WHAT   the grader checking itself: `full` (every case passes), `zero` (none
//                         does: the untouched stubs) or `less` (some case fails: a mutant). The exit
//                         status then says whether the expectation held, not whether tests passed.
//   --artifacts DIR       where picture tests write expected, actual and difference images
//   --list-cases FILE     write every graded case at 0 points (a chapter that did not compile)
//   --case-timeout S      with --results: run each graded case in its own process, stopped after S
//                         seconds of its own CPU time (or ten times that on the clock, whatever the
//                         machine's load), so an endless loop or a crash in one case costs that case only
//   --case-process S      (what the grader gives each case's process) run the one case named, append
//                         its result to --results, and stop after S seconds of CPU time
//   --expect-loss-in NN.k with --expect-score less: the points must be lost in exercise NN.k's own
//                         cases (a kept mutant of NN.k), not only in the chapter's agreement or picture
//   --check-clauses FILE  check the chapter's clause table against the grader's cases (clauses.hpp)
//
// Each case is said as the student reads it: its input once, its first failed checks (about a
// screenful), then how many more failed. Without --case-timeout too, Catch2's own report goes
// nowhere when every case selected is graded, unless a reporter, an output file or a listing is
// asked for on the command line. The kit's notices (common/notice.hpp) are off: they speak of the
// test scenes, not of the student's work.
//
// Catch2 v2 and v3 differ in the few interfaces a runner with a listener uses; RT_CATCH2_V3 picks.
#ifdef RT_CATCH2_V3
#include <catch2/catch_all.hpp>
#else
#define CATCH_CONFIG_RUNNER
#define CATCH_CONFIG_EXTERNAL_INTERFACES
#include <catch2/catch.hpp>
#endif

#include "tests/grader/child_process.hpp"
#include "tests/grader/clauses.hpp"
#include "tests/grader/freshness.hpp"
#include "tests/grader/graded.hpp"
#include "tests/grader/measure.hpp"
#include "tests/grader/picture.hpp"
#include "tests/grader/points.hpp"
#include "tests/grader/summary.hpp"

#include "common/notice.hpp"
#include "common/stub.hpp"
#include "common/words.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <regex>
#include <set>
#include <sstream>

namespace rt::grader {

namespace {

#ifdef RT_CATCH2_V3
using ListenerBase = Catch::EventListenerBase;
namespace clara = Catch::Clara;
const Catch::TestCaseInfo& info_of(const Catch::TestCaseHandle& test) { return test.getTestCaseInfo(); }
std::string text_of(const Catch::Tag& tag) { return std::string(tag.original); }
#else
using ListenerBase = Catch::TestEventListenerBase;
namespace clara = Catch::clara;
const Catch::TestCaseInfo& info_of(const Catch::TestCase& test) { return test; }
const std::string& text_of(const std::string& tag) { return tag; }
#endif

// How the output of a case that crashed or was stopped begins (its status says so too).
constexpr const char* stopped_words = "stopped: ";
constexpr const char* crashed_words = "crashed: ";

// Exit status of a case's process stopped by its CPU limit (the `timeout` command's).
constexpr int exit_cpu_limit = 124;

// How long a case may take on the clock, as a multiple of its CPU limit: a backstop for a case that
// sleeps or waits, generous enough that a correct case on a machine busy with ten times its work
// still finishes.
constexpr double wall_backstop_factor = 10.0;

std::vector<CaseResult> results;
std::string results_path;  // appended to after every case, so a crash still leaves the cases before it

// Graded in this process (no --case-timeout), each case is said as it ends, as a grading run says
// it, in place of Catch2's own report (which repeats every failed check in full).
bool say_cases_as_they_end = false;

// A case as the console says it: as graded, or, for an exercise still its stub, one line for all of
// its cases (`last_stub`: the exercise said last).
void say_case(std::ostream& out, const CaseResult& r, std::string& last_stub)
{
    const std::string verdict = stub_verdict(r);
    if (verdict.empty())
        print_case(out, r);
    else if (r.number != last_stub)
        out << "  STUB  " << r.number << "  " << verdict << '\n';
    if (!verdict.empty())
        last_stub = r.number;
}

// "[ch01][01.2][2pt]": the number is the tag of form NN.k, the points the tag ending in "pt".
void read_tags(const Catch::TestCaseInfo& info, CaseResult& r)
{
    static const std::regex number_tag(R"(\d\d\.\w+)");
    static const std::regex points_tag(R"((\d+)pt)");
    for (const auto& t : info.tags) {
        const std::string tag = text_of(t);
        std::smatch m;
        if (std::regex_match(tag, number_tag))
            r.number = tag;
        else if (std::regex_match(tag, m, points_tag))
            r.max_score = std::stoi(m[1]);
    }
}

class PointsListener : public ListenerBase {
public:
    using ListenerBase::ListenerBase;

    void testCaseStarting(const Catch::TestCaseInfo& info) override
    {
        current_ = CaseResult{};
        said_.clear();
        unshown_checks_ = 0;
        current_.name = info.name;
        read_tags(info, current_);
        rt::forget_stubs();
        measured_now.reset();
    }

#ifdef RT_CATCH2_V3
    void assertionEnded(const Catch::AssertionStats& stats) override { record(stats); }
#else
    bool assertionEnded(const Catch::AssertionStats& stats) override
    {
        record(stats);
        return true;
    }
#endif

    void record(const Catch::AssertionStats& stats)
    {
        const Catch::AssertionResult& a = stats.assertionResult;
        if (a.isOk())
            return;
        if (a.getResultType() == Catch::ResultWas::FatalErrorCondition) {
            // The student's code crashed: what the case was working on, if it said, and where.
            std::ostringstream out;
            out << crashed_words << a.getMessage() << '\n';
            if (working_on_now && *working_on_now)
                out << "while working on " << (*working_on_now)() << '\n';
            for (const Catch::MessageInfo& m : stats.infoMessages)
                if (m.message != std::string(a.getMessage()))
                    out << m.message << '\n';
            out << "  after the check at " << a.getSourceInfo().file << ':' << a.getSourceInfo().line << '\n';
            current_.output = out.str() + current_.output;
            current_.status = CaseStatus::crashed;
            return;
        }
        // A case's description of its input (INFO) is said once in the case, before the first
        // failed check that has it.
        std::ostringstream out;
        std::vector<std::string> new_info;
        for (const Catch::MessageInfo& m : stats.infoMessages)
            if (!said_.count(m.message)) {
                out << m.message << '\n';
                new_info.push_back(m.message);
            }
        if (a.hasExpression())
            out << "failed: " << a.getExpressionInMacro() << "\n  with: " << a.getExpandedExpression() << '\n';
        if (a.hasMessage())
            out << a.getMessage() << '\n';
        out << "  at " << a.getSourceInfo().file << ':' << a.getSourceInfo().line << '\n';
        // About a screenful: the first failed checks say what is wrong; the rest are counted.
        const std::string block = out.str();
        if (!current_.output.empty() && lines_in(current_.output) + lines_in(block) > check_lines) {
            ++unshown_checks_;
            return;
        }
        said_.insert(new_info.begin(), new_info.end());
        current_.output += block;
    }

    void testCaseEnded(const Catch::TestCaseStats& stats) override
    {
        current_.stubs = rt::join_words(rt::stubs_that_ran(), " ");
        if (measured_now) {
            current_.measure = measured_now->name;
            current_.measured = measured_now->value;
            current_.reference = measured_now->reference;
            current_.measure_detail = measured_now->detail;
        }
        const bool passed = stats.totals.assertions.failed == 0 && stats.totals.assertions.passed > 0 &&
                            !rests_on_earlier_stub(current_);
        if (passed)
            current_.status = CaseStatus::passed;
        current_.score = passed ? current_.max_score : 0;
        if (unshown_checks_ > 0)
            current_.output += "... and " + std::to_string(unshown_checks_) + " more failed check" +
                               (unshown_checks_ == 1 ? "" : "s") + " in this case\n";
        if (stats.totals.assertions.passed == 0 && stats.totals.assertions.failed == 0)
            current_.output += "the test checked nothing: it earns no points\n";
        // An exercise's case (not a picture or agreement case) points to the hint for its trap.
        if (!passed && current_.number.size() > 3 && std::isdigit(static_cast<unsigned char>(current_.number[3])))
            current_.output += "the trap this case checks: ./build/grade/hint " + current_.number + " 2\n";
        if (current_.number.empty())
            return;
        results.push_back(current_);
        if (!results_path.empty())
            append_result(results_path, current_);
        if (say_cases_as_they_end) {
            say_case(std::cout, current_, last_stub_);
            std::cout.flush();  // before a crash in the next case ends the process
        }
    }

private:
    // The failed checks' share of a case's output: its lines but the few said after them.
    static constexpr size_t check_lines = case_output_lines - 4;

    static size_t lines_in(const std::string& text) { return static_cast<size_t>(std::count(text.begin(), text.end(), '\n')); }

    CaseResult current_;
    std::set<std::string> said_;  // the INFO messages this case has said
    int unshown_checks_ = 0;      // failed checks past check_lines, counted only
    std::string last_stub_;       // (say_case's)
};

CATCH_REGISTER_LISTENER(PointsListener)

}  // namespace

std::string artifacts_dir = "picture-failures";

namespace {

// The graded cases this run would run: every one, or those the command line's test spec selects.
std::vector<CaseResult> planned_cases(Catch::Session& session)
{
    std::vector<CaseResult> plan;
    const Catch::Config& config = session.config();
    for (const auto& test :
         Catch::filterTests(Catch::getRegistryHub().getTestCaseRegistry().getAllTests(), config.testSpec(), config)) {
        CaseResult r;
        r.name = info_of(test).name;
        read_tags(info_of(test), r);
        if (!r.number.empty())
            plan.push_back(r);
    }
    // In exercise order (01.1 before 01.2), whatever order the test files were linked in.
    std::stable_sort(plan.begin(), plan.end(),
                     [](const CaseResult& a, const CaseResult& b) { return a.number < b.number; });
    return plan;
}

// A test name as a Catch2 test spec that matches it alone: its spec characters escaped.
std::string catch_literal(const std::string& name)
{
    std::string spec;
    for (const char c : name) {
        if (std::string(",[]*\"\\~").find(c) != std::string::npos)
            spec += '\\';
        spec += c;
    }
    return spec;
}

// Whether Catch2 would write its console report on standard output: no reporter, file or listing
// asked for on the command line.
bool catch_reports_to_console(const Catch::ConfigData& data)
{
#ifdef RT_CATCH2_V3
    return data.reporterSpecifications.empty() && data.defaultOutputFilename.empty() && !data.listTests &&
           !data.listTags && !data.listReporters && !data.listListeners;
#else
    return data.reporterName == "console" && data.outputFilename.empty() && !data.listTests &&
           !data.listTestNamesOnly && !data.listTags && !data.listReporters;
#endif
}

// Whether every test case this run would run is a graded one: a grader's run, not one of the kit's
// own tests, which link this main too and keep Catch2's report.
bool only_graded_cases(Catch::Session& session)
{
    const Catch::Config& config = session.config();
    const size_t selected =
        Catch::filterTests(Catch::getRegistryHub().getTestCaseRegistry().getAllTests(), config.testSpec(), config).size();
    return selected > 0 && planned_cases(session).size() == selected;
}

// Catch2's report to nowhere: the listener says the cases instead.
void quiet_catch_report(Catch::Session& session)
{
    Catch::ConfigData data = session.configData();
#ifdef RT_CATCH2_V3
    data.defaultOutputFilename = null_device();
#else
    data.outputFilename = null_device();
#endif
    session.useConfigData(data);  // (the Config made from the command line is made again)
}

// Where a case's process stopped at its CPU limit leaves the stubs that had run: beside the results.
std::string stubs_path() { return results_path + ".stubs"; }

// The stubs a stopped case's process left (and the file gone), or "".
std::string stubs_left_by_a_stopped_case()
{
    std::string stubs;
    if (std::ifstream in(stubs_path()); in)
        std::getline(in, stubs);
    std::remove(stubs_path().c_str());
    return stubs;
}

size_t results_so_far()
{
    std::vector<CaseResult> got;
    read_results(results_path, got);
    return got.size();
}

// Each case in a process of its own (this program again, given that case alone): it stops itself
// after `cpu_limit` seconds of CPU time, and the grader stops it after ten times that on the clock.
// A case whose process ended without reporting is recorded as crashed or stopped.
void run_isolated(Catch::Session& session, const std::string& program, int cpu_limit)
{
    std::string last_stub;  // an exercise still its stub is said once, not once per case
    for (const CaseResult& planned : planned_cases(session)) {
        const size_t before = results_so_far();
        std::remove(stubs_path().c_str());
        std::cout.flush();
        const std::vector<std::string> args = {catch_literal(planned.name), "--out", null_device(),
                                               "--results", results_path, "--artifacts", artifacts_dir,
                                               "--case-process", std::to_string(cpu_limit)};
        const ChildStatus status = run_child(program, args, wall_backstop_factor * cpu_limit);
        std::vector<CaseResult> got;
        read_results(results_path, got);
        if (got.size() > before) {
            say_case(std::cout, got.back(), last_stub);
            continue;
        }
        CaseResult lost = planned;
        lost.stubs = stubs_left_by_a_stopped_case();
        const std::string limit = std::to_string(cpu_limit);
        switch (status.end) {
        case ChildStatus::End::exited:
            lost.status = status.code == exit_cpu_limit ? CaseStatus::stopped : CaseStatus::crashed;
            lost.output = status.code == exit_cpu_limit
                              ? stopped_words + ("the case used more than " + limit + " s of CPU time: an endless loop?")
                              : crashed_words + ("the case ended without reporting (exit status " + std::to_string(status.code) + ")");
            break;
        case ChildStatus::End::crashed:
            lost.status = CaseStatus::crashed;
            lost.output = crashed_words + std::string("the case crashed (") +
#ifdef _WIN32
                          std::string("exception code ") + std::to_string(static_cast<unsigned>(status.code)) +
#else
                          std::string("signal ") + std::to_string(status.code) +
#endif
                          ") before it could report";
            break;
        case ChildStatus::End::stopped:
            lost.status = CaseStatus::stopped;
            lost.output = stopped_words + ("the case was still running after " +
                                          std::to_string(static_cast<int>(wall_backstop_factor * cpu_limit)) +
                                          " s on the clock: is it waiting for something?");
            break;
        case ChildStatus::End::not_started:
            lost.output = "the grader could not start a process for the case (" + program + ")";
            break;
        }
        append_result(results_path, lost);
        say_case(std::cout, lost, last_stub);
    }
    read_results(results_path, results);
}

}  // namespace

}  // namespace rt::grader

int main(int argc, char* argv[])
{
    using namespace rt::grader;
    // The kit's notices (a grid built at a lower lambda than asked) speak of the test scenes the
    // cases build, not of the student's work: a grading run keeps them out of its output.
    rt::set_notices(false);
    if (const std::optional<int> regraded = regrade_if_stale(this_program(argv[0]), argc, argv))
        return *regraded;
    Catch::Session session;
    Catch::StringMaker<float>::precision = 9;  // so a tolerance like 2e-6 does not print as 0.0
    std::string expect, list_path, loss_in, clause_table;
    int case_timeout = 0;
    double cpu_limit = 0.0;
    using clara::Opt;
    session.cli(session.cli() |
                Opt(results_path, "file")["--results"]("write the graded cases, one a line, to this file") |
                Opt(expect, "full|zero|less")["--expect-score"]("check the grader itself: exit 0 when the score is as expected") |
                Opt(artifacts_dir, "dir")["--artifacts"]("where failing picture tests write their images") |
                Opt(case_timeout, "seconds")["--case-timeout"]("with --results: each case in its own process, stopped after this much CPU time") |
                Opt(cpu_limit, "seconds")["--case-process"]("(the grader's own) one case's process, stopped after this much CPU time") |
                Opt(list_path, "file")["--list-cases"]("write every graded case at 0 points to this file, and run none") |
                Opt(loss_in, "NN.k")["--expect-loss-in"]("with --expect-score less: the points are lost in this exercise's own cases") |
                Opt(clause_table, "file")["--check-clauses"]("check the chapter's clause table against its cases, and run none"));
    if (const int rc = session.applyCommandLine(argc, argv); rc != 0)
        return rc;
    if (cpu_limit > 0.0) {
        // One case's process: its result goes to the file the grader reads, which holds the cases
        // before it; the grader prints the verdict and the table.
        // A case stopped at its limit often waits on a stub (a search that a stub's miss never
        // ends): it leaves the stubs that ran so far, for the grader to say which.
        limit_cpu_time(cpu_limit, exit_cpu_limit, [] {
            std::ofstream(stubs_path()) << rt::join_words(rt::stubs_that_ran(), " ");
        });
        session.run();
        return 0;
    }
    if (!clause_table.empty()) {
        std::vector<GradedCase> cases;
        for (const CaseResult& c : planned_cases(session))
            cases.push_back({c.number, c.name});
        const std::vector<std::string> problems = check_clause_table(clause_table, cases);
        for (const std::string& p : problems)
            std::cerr << p << '\n';
        return problems.empty() ? 0 : 1;
    }
    if (!list_path.empty()) {
        // The cases of a chapter whose exercise file did not compile: each at 0 of its points.
        if (!write_results(list_path, planned_cases(session))) {
            std::cerr << list_path << ": cannot write the cases\n";
            return 2;
        }
        return 0;
    }
    if (!expect.empty() && expect != "full" && expect != "zero" && expect != "less") {
        std::cerr << "--expect-score takes full, zero or less, got '" << expect << "'\n";
        return 2;
    }
    if (!results_path.empty() && !write_results(results_path, {})) {
        std::cerr << results_path << ": cannot write the results\n";
        return 2;
    }
    if (case_timeout > 0 && results_path.empty()) {
        std::cerr << "--case-timeout needs --results\n";
        return 2;
    }
    int failed = 0;
    if (case_timeout > 0)
        run_isolated(session, this_program(argv[0]), case_timeout);
    else {
        say_cases_as_they_end = catch_reports_to_console(session.configData()) && only_graded_cases(session);
        if (say_cases_as_they_end)
            quiet_catch_report(session);
        failed = session.run();
    }

    print_points_table(std::cout, summarize(results), results);
    if (expect.empty())
        return failed;
    if (!check_expectation(std::cout, results, expect))
        return 1;
    if (!loss_in.empty()) {
        const bool lost = std::any_of(results.begin(), results.end(),
                                      [&](const CaseResult& r) { return r.number == loss_in && r.score < r.max_score; });
        if (!lost) {
            std::cout << "expected a loss in " << loss_in << "'s own cases; its cases all passed\n";
            return 1;
        }
    }
    return 0;
}
