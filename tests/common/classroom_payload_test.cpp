// GitHub Classroom's payload (tests/grader/classroom.hpp): one environment variable, so the whole
// result, base64-encoded, stays under its budget however many cases fail, and every case keeps its
// name and points.
#include "tests/grader/classroom.hpp"

#include "tests/grader/catch.hpp"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

using rt::grader::CaseResult;
using rt::grader::CaseStatus;

std::vector<CaseResult> cases(int count, bool passed, size_t output_length)
{
    std::vector<CaseResult> out;
    for (int k = 0; k < count; ++k) {
        CaseResult r;
        r.number = (k % 10 < 9 ? "0" : "") + std::to_string(k % 10 + 1) + "." + std::to_string(k % 7 + 1);
        r.name = "case " + std::to_string(k) + ": " + std::string(110, 'n');
        r.max_score = 3;
        r.score = passed ? 3 : 0;
        r.status = passed ? CaseStatus::passed : CaseStatus::failed;
        r.output = passed ? "" : std::string(output_length, 'o');
        out.push_back(r);
    }
    return out;
}

size_t occurrences(const std::string& text, const std::string& word)
{
    size_t n = 0;
    for (size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1))
        ++n;
    return n;
}

size_t encoded_size(const std::string& json) { return (json.size() + 2) / 3 * 4; }

}  // namespace

TEST_CASE("the Classroom payload stays in its budget when every case of ten chapters fails, each case still named", "[grader]")
{
    constexpr size_t budget = 96 * 1024;
    const std::vector<CaseResult> failing = cases(400, false, 3000);
    const std::string json = rt::grader::classroom_result_json(failing, budget);
    INFO("400 failing cases with 3000-byte messages: " << encoded_size(json) << " bytes encoded against a budget of "
         << budget);
    CHECK(encoded_size(json) <= budget);
    CHECK(occurrences(json, "\"name\":") == failing.size());
    CHECK(occurrences(json, "\"score\": 0") == failing.size());
}

TEST_CASE("the Classroom payload keeps messages, cut to fit, when a few cases fail", "[grader]")
{
    constexpr size_t budget = 96 * 1024;
    const std::vector<CaseResult> failing = cases(40, false, 10000);
    const std::string json = rt::grader::classroom_result_json(failing, budget);
    INFO("40 failing cases with 10,000-byte messages: " << encoded_size(json) << " bytes encoded");
    CHECK(encoded_size(json) <= budget);
    CHECK(occurrences(json, "\"message\":") == failing.size());
    CHECK(occurrences(json, "\"test_code\":") == failing.size());
}

TEST_CASE("the job's summary points a failed picture case to the artifact with its images, and only then", "[grader]")
{
    const auto summary_of = [](bool picture_fails) {
        CaseResult picture;
        picture.number = "01.P";
        picture.name = "the figure matches the reference picture";
        picture.max_score = 3;
        picture.score = picture_fails ? 0 : 3;
        picture.status = picture_fails ? CaseStatus::failed : CaseStatus::passed;
        picture.output = picture_fails ? "12 pixels differ" : "";
        const std::string path = std::string("classroom_summary_") + (picture_fails ? "fails" : "passes") + ".md";
        std::remove(path.c_str());
        rt::grader::append_step_summary(path, {picture});
        std::ifstream in(path);
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    };
    const std::string failed = summary_of(true), passed = summary_of(false);
    INFO("the summary with the picture failed:\n" << failed << "\nand passed:\n" << passed);
    CHECK(occurrences(failed, "artifact **grade-report**") == 1);
    CHECK(occurrences(passed, "grade-report") == 0);
}
