// The grader's main: Catch2 plus a listener that turns test cases into points.
//
// Options beside Catch2's own:
//   --results FILE        write one line per graded case (read by grade_report)
//   --expect-score WHAT   the grader checking itself: `full` (every case passes), `zero` (none
//                         does: the untouched stubs) or `less` (some case fails: a mutant). The exit
//                         status then says whether the expectation held, not whether tests passed.
//   --artifacts DIR       where picture tests write expected, actual and difference images
#define CATCH_CONFIG_RUNNER
#define CATCH_CONFIG_EXTERNAL_INTERFACES
#include <catch2/catch.hpp>

#include "tests/grader/picture.hpp"
#include "tests/grader/points.hpp"

#include <iostream>
#include <regex>
#include <sstream>

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

}  // namespace rt::grader

int main(int argc, char* argv[])
{
    using namespace rt::grader;
    Catch::Session session;
    Catch::StringMaker<float>::precision = 9;  // so a tolerance like 2e-6 does not print as 0.0
    std::string expect;
    using namespace Catch::clara;
    session.cli(session.cli() |
                Opt(results_path, "file")["--results"]("write the graded cases, one a line, to this file") |
                Opt(expect, "full|zero|less")["--expect-score"]("check the grader itself: exit 0 when the score is as expected") |
                Opt(artifacts_dir, "dir")["--artifacts"]("where failing picture tests write their images"));
    if (const int rc = session.applyCommandLine(argc, argv); rc != 0)
        return rc;
    if (!expect.empty() && expect != "full" && expect != "zero" && expect != "less") {
        std::cerr << "--expect-score takes full, zero or less, got '" << expect << "'\n";
        return 2;
    }
    if (!results_path.empty() && !write_results(results_path, {})) {
        std::cerr << results_path << ": cannot write the results\n";
        return 2;
    }
    const int failed = session.run();

    print_points_table(std::cout, results);
    if (expect.empty())
        return failed;
    return check_expectation(std::cout, results, expect) ? 0 : 1;
}
