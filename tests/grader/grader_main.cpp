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
//                         seconds, so an endless loop or a crash in one case costs that case only
#define CATCH_CONFIG_RUNNER
#define CATCH_CONFIG_EXTERNAL_INTERFACES
#include <catch2/catch.hpp>

#include "tests/grader/picture.hpp"
#include "tests/grader/points.hpp"

#include <algorithm>
#include <iostream>
#include <regex>
#include <sstream>
#include <thread>

#include <csignal>
#include <sys/wait.h>
#include <unistd.h>

namespace rt::grader {

namespace {

std::vector<CaseResult> results;
std::string results_path;  // appended to after every case, so a crash still leaves the cases before it

// "[ch01][01.2][2pt]": the number is the tag of form NN.k, the points the tag ending in "pt".
void read_tags(const Catch::TestCaseInfo& info, CaseResult& r)
{
    static const std::regex number_tag(R"(\d\d\.\w+)");
    static const std::regex points_tag(R"((\d+)pt)");
    for (const std::string& tag : info.tags) {
        std::smatch m;
        if (std::regex_match(tag, number_tag))
            r.number = tag;
        else if (std::regex_match(tag, m, points_tag))
            r.max_score = std::stoi(m[1]);
    }
}

class PointsListener : public Catch::TestEventListenerBase {
public:
    using TestEventListenerBase::TestEventListenerBase;

    void testCaseStarting(const Catch::TestCaseInfo& info) override
    {
        current_ = CaseResult{};
        current_.name = info.name;
        read_tags(info, current_);
    }

    bool assertionEnded(const Catch::AssertionStats& stats) override
    {
        const Catch::AssertionResult& a = stats.assertionResult;
        if (a.isOk())
            return true;
        std::ostringstream out;
        for (const Catch::MessageInfo& m : stats.infoMessages)
            out << m.message << '\n';
        if (a.hasExpression())
            out << "failed: " << a.getExpressionInMacro() << "\n  with: " << a.getExpandedExpression() << '\n';
        if (a.hasMessage())
            out << a.getMessage() << '\n';
        out << "  at " << a.getSourceInfo().file << ':' << a.getSourceInfo().line << '\n';
        current_.output += out.str();
        return true;
    }

    void testCaseEnded(const Catch::TestCaseStats& stats) override
    {
        current_.passed = stats.totals.assertions.failed == 0 && stats.totals.assertions.passed > 0;
        current_.score = current_.passed ? current_.max_score : 0;
        if (stats.totals.assertions.passed == 0 && stats.totals.assertions.failed == 0)
            current_.output += "the test checked nothing: it earns no points\n";
        if (current_.number.empty())
            return;
        results.push_back(current_);
        if (!results_path.empty())
            append_result(results_path, current_);
    }

private:
    CaseResult current_;
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
    for (const Catch::TestCase& test :
         Catch::filterTests(Catch::getRegistryHub().getTestCaseRegistry().getAllTests(), config.testSpec(), config)) {
        CaseResult r;
        r.name = test.name;
        read_tags(test, r);
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

size_t results_so_far()
{
    std::vector<CaseResult> got;
    read_results(results_path, got);
    return got.size();
}

// Each case in a child process: the parent waits at most `timeout` seconds, then stops it and
// records the case as lost, and records a case whose process died without reporting as crashed.
void run_isolated(Catch::Session& session, int timeout)
{
    for (const CaseResult& planned : planned_cases(session)) {
        const size_t before = results_so_far();
        std::cout.flush();
        const pid_t pid = fork();
        if (pid == 0) {
            Catch::ConfigData data = session.configData();
            data.testsOrTags = {catch_literal(planned.name)};
            data.outputFilename = "/dev/null";  // the parent prints the verdict; the student's own prints stay
            session.useConfigData(data);
            session.run();
            std::cout.flush();
            std::_Exit(0);
        }
        int status = 0;
        bool finished = false;
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeout);
        while (!(finished = waitpid(pid, &status, WNOHANG) == pid) && std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        if (!finished) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
        }
        std::vector<CaseResult> got;
        read_results(results_path, got);
        if (got.size() > before) {
            print_case(std::cout, got.back());
            continue;
        }
        CaseResult lost = planned;
        if (!finished)
            lost.output = "the case ran longer than " + std::to_string(timeout) + " seconds and was stopped: an endless loop?";
        else if (WIFSIGNALED(status))
            lost.output = "the case crashed (signal " + std::to_string(WTERMSIG(status)) + ") before it could report";
        else
            lost.output = "the case ended without reporting (exit status " + std::to_string(WEXITSTATUS(status)) + ")";
        append_result(results_path, lost);
        print_case(std::cout, lost);
    }
    read_results(results_path, results);
}

}  // namespace

}  // namespace rt::grader

int main(int argc, char* argv[])
{
    using namespace rt::grader;
    Catch::Session session;
    Catch::StringMaker<float>::precision = 9;  // so a tolerance like 2e-6 does not print as 0.0
    std::string expect, list_path;
    int case_timeout = 0;
    using namespace Catch::clara;
    session.cli(session.cli() |
                Opt(results_path, "file")["--results"]("write the graded cases, one a line, to this file") |
                Opt(expect, "full|zero|less")["--expect-score"]("check the grader itself: exit 0 when the score is as expected") |
                Opt(artifacts_dir, "dir")["--artifacts"]("where failing picture tests write their images") |
                Opt(case_timeout, "seconds")["--case-timeout"]("with --results: each case in its own process, stopped after this long") |
                Opt(list_path, "file")["--list-cases"]("write every graded case at 0 points to this file, and run none"));
    if (const int rc = session.applyCommandLine(argc, argv); rc != 0)
        return rc;
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
        run_isolated(session, case_timeout);
    else
        failed = session.run();

    print_points_table(std::cout, results);
    if (expect.empty())
        return failed;
    return check_expectation(std::cout, results, expect) ? 0 : 1;
}
