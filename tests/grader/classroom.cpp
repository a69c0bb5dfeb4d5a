#include "tests/grader/classroom.hpp"

#include "tests/grader/summary.hpp"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace rt::grader {

namespace {

std::string json_string(const std::string& s) { return '"' + escape_json(s) + '"'; }

// A case that could not run to a verdict is an error to Classroom (a chapter that did not compile
// or has no file, a crash, a stop), a failed check a failure.
std::string status_of(const CaseResult& r)
{
    switch (r.status) {
    case CaseStatus::passed:
        return "pass";
    case CaseStatus::crashed:
    case CaseStatus::stopped:
    case CaseStatus::does_not_compile:
    case CaseStatus::no_file:
        return "error";
    default:
        return "fail";
    }
}

// What a student types to grade that case's exercise again (or rebuild its chapter).
std::string rerun_command(const CaseResult& r)
{
    const std::string nn = chapter_of(r);
    if (r.number.size() == 2)
        return "cmake --build --preset grade --target check_" + nn;
    return "./build/grade/tests/grade_" + nn + " \"[" + r.number + "]\"";
}

// The first `limit` bytes of a message, cut at a line (or at least a character) boundary, saying so.
std::string cut_message(const std::string& message, size_t limit)
{
    if (message.size() <= limit)
        return message;
    if (limit == 0)
        return "";
    if (limit < 40)  // a few characters would say nothing
        return "(cut: the job's summary page, or the grade step's log, has the message)";
    const std::string note = "... (cut here: the job's summary page, or the grade step's log, has it whole)";
    size_t cut = limit;
    const size_t line = message.rfind('\n', limit);
    if (line != std::string::npos && line > limit / 2)
        cut = line + 1;
    while (cut > 0 && (static_cast<unsigned char>(message[cut]) & 0xC0) == 0x80)
        --cut;  // not inside a UTF-8 character
    std::string out = message.substr(0, cut);
    if (!out.empty() && out.back() != '\n')
        out += '\n';
    return out + note;
}

// `message_limit`: the longest a message may be; npos: whole. `bare`: each case's name, status and
// score only, with no message and no command to run it again.
std::string result_json(const std::vector<CaseResult>& results, size_t message_limit, bool bare = false)
{
    int max_score = 0;
    bool all_passed = true, any_error = false;
    for (const CaseResult& r : results) {
        max_score += r.max_score;
        all_passed = all_passed && r.passed();
        any_error = any_error || status_of(r) == "error";
    }
    std::ostringstream out;
    out << "{\"version\": 1, \"status\": \"" << (all_passed ? "pass" : any_error ? "error" : "fail")
        << "\", \"max_score\": " << max_score << ", \"tests\": [";
    for (size_t k = 0; k < results.size(); ++k) {
        const CaseResult& r = results[k];
        out << (k ? ", " : "") << "{\"name\": " << json_string(r.number + " " + r.name) << ", \"status\": \""
            << status_of(r) << "\", \"score\": " << r.score;
        if (!r.passed() && !bare)
            out << ", \"message\": "
                << json_string(std::to_string(r.score) + " of " + std::to_string(r.max_score) + " points. " +
                               cut_message(r.output, message_limit));
        if (!bare)
            out << ", \"test_code\": " << json_string(rerun_command(r));
        out << "}";
    }
    out << "]}";
    return out.str();
}

// Markdown text: the characters that would start markup, escaped.
std::string md(const std::string& s)
{
    std::string out;
    for (const char c : s) {
        if (std::string("\\`*_[]<>|#").find(c) != std::string::npos)
            out += '\\';
        out += c == '\n' ? ' ' : c;
    }
    return out;
}

// A fence longer than any run of backticks in the text.
std::string fence_for(const std::string& text)
{
    size_t longest = 0, run = 0;
    for (const char c : text) {
        run = c == '`' ? run + 1 : 0;
        longest = std::max(longest, run);
    }
    return std::string(std::max<size_t>(3, longest + 1), '`');
}

}  // namespace

std::string base64_encode(const std::string& bytes)
{
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t k = 0; k < bytes.size(); k += 3) {
        const size_t n = std::min<size_t>(3, bytes.size() - k);
        unsigned v = 0;
        for (size_t j = 0; j < 3; ++j)
            v = (v << 8) | (j < n ? static_cast<unsigned char>(bytes[k + j]) : 0u);
        out += digits[(v >> 18) & 63];
        out += digits[(v >> 12) & 63];
        out += n > 1 ? digits[(v >> 6) & 63] : '=';
        out += n > 2 ? digits[v & 63] : '=';
    }
    return out;
}

std::string classroom_result_json(const std::vector<CaseResult>& summarized, size_t budget)
{
    // Whole messages when they fit, else each cut to the longest length that lets them all fit,
    // down to none; when even the cut messages' "N of M points." and the commands do not fit (every
    // case of ten chapters failing), the cases bare: their names and points always go, and the
    // job's summary page has the rest.
    const auto fits = [&](const std::string& json) { return (json.size() + 2) / 3 * 4 <= budget; };
    std::string json = result_json(summarized, std::string::npos);
    if (fits(json))
        return json;
    if (!fits(result_json(summarized, 0)))
        return result_json(summarized, 0, true);
    size_t low = 0, high = 4000;  // fits(low) holds; fits(high) is taken not to
    while (high - low > 1) {
        const size_t mid = (low + high) / 2;
        (fits(result_json(summarized, mid)) ? low : high) = mid;
    }
    return result_json(summarized, low);
}

bool append_classroom_output(const std::string& path, const std::vector<CaseResult>& summarized)
{
    std::ofstream out(path, std::ios::app);
    out << "result=" << base64_encode(classroom_result_json(summarized)) << '\n';
    return static_cast<bool>(out);
}

bool append_step_summary(const std::string& path, const std::vector<CaseResult>& summarized)
{
    // GitHub shows at most 1 MiB of a step's summary: past about 800 KB the messages stop.
    constexpr size_t message_budget = 800 * 1000;
    int score = 0, max_score = 0;
    for (const CaseResult& r : summarized) {
        score += r.score;
        max_score += r.max_score;
    }
    std::ostringstream out;
    out << "## Points: " << score << " / " << max_score << "\n\n| chapter | points | look at |\n|---|---:|---|\n";
    for (const ChapterMark& m : chapter_marks(summarized))
        out << "| " << m.chapter << " | " << m.score << " / " << m.max_score << " | " << md(m.marks) << " |\n";
    // The open exercises' costs against the reference's, as the class leaderboard ranks them.
    const std::vector<CaseResult> board = leaderboard_of(summarized);
    if (!board.empty()) {
        out << "\n### Your cost against the reference's (lower is better)\n\n| measure | yours | the reference's |\n|---|---:|---:|\n";
        for (const CaseResult& m : board)
            out << "| " << md(m.measure) << " | " << std::fixed << std::setprecision(3) << m.measured << " | " << m.reference
                << std::defaultfloat << " |\n";
    }
    std::map<std::string, std::vector<const CaseResult*>> by_chapter;
    for (const CaseResult& r : summarized)
        by_chapter[chapter_of(r)].push_back(&r);
    size_t written = 0;
    bool cut = false;
    for (const auto& [chapter, cases] : by_chapter) {
        std::map<std::string, std::pair<int, int>> by_exercise;
        int chapter_score = 0, chapter_max = 0;
        for (const CaseResult* r : cases) {
            by_exercise[r->number].first += r->score;
            by_exercise[r->number].second += r->max_score;
            chapter_score += r->score;
            chapter_max += r->max_score;
        }
        out << "\n### Chapter " << chapter << ": " << chapter_score << " / " << chapter_max
            << "\n\n| exercise | points |\n|---|---:|\n";
        for (const auto& [number, points] : by_exercise)
            out << "| " << number << " | " << points.first << " / " << points.second << " |\n";
        for (const CaseResult* r : cases) {
            if (r->passed())
                continue;
            out << "\n**FAIL " << r->number << " " << r->score << "/" << r->max_score << "** " << md(r->name) << '\n';
            if (r->output.empty())
                continue;
            if (written + r->output.size() > message_budget) {
                cut = true;
                continue;
            }
            written += r->output.size();
            const std::string fence = fence_for(r->output);
            out << '\n' << fence << "text\n" << r->output << (r->output.back() == '\n' ? "" : "\n") << fence << '\n';
        }
    }
    if (cut)
        out << "\n(Some messages did not fit on this page: the grade step's log has every one.)\n";
    // The workflow uploads build/grade/grade-results (the pictures, report.html) as `grade-report`.
    const bool picture_failed = std::any_of(summarized.begin(), summarized.end(), [](const CaseResult& r) {
        return !r.passed() && r.number.size() > 3 && r.number.substr(2) == ".P";
    });
    if (picture_failed)
        out << "\nA failed picture case's images (expected, yours, and their difference) are in this run's "
               "artifact **grade-report**, with report.html: the run's Summary page, under Artifacts.\n";
    std::ofstream file(path, std::ios::app);
    file << out.str();
    return static_cast<bool>(file);
}

}  // namespace rt::grader
