#include "tests/grader/points.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <cstdlib>
#include <map>
#include <sstream>

namespace rt::grader {

namespace {

std::string escape_line(const std::string& s)
{
    std::string out;
    for (const char c : s) {
        if (c == '\\') out += "\\\\";
        else if (c == '\t') out += "\\t";
        else if (c == '\n') out += "\\n";
        else out += c;
    }
    return out;
}

// A measure as the results file and results.json write it: six significant digits (0.982, not
// 0.98199999999999998), finer than any tier.
std::string number_text(double v)
{
    std::ostringstream s;
    s << std::setprecision(6) << v;
    return s.str();
}

std::string unescape_line(const std::string& s)
{
    std::string out;
    for (size_t k = 0; k < s.size(); ++k) {
        if (s[k] != '\\' || k + 1 == s.size()) {
            out += s[k];
            continue;
        }
        const char c = s[++k];
        out += c == 't' ? '\t' : c == 'n' ? '\n' : c;
    }
    return out;
}


// The results file's words for CaseStatus, in its order.
constexpr const char* status_words[] = {"passed", "failed", "crashed", "stopped", "stub",
                                        "waits_for_stub", "untouched", "does_not_compile", "no_file"};

}  // namespace

std::string escape_json(const std::string& s)
{
    std::ostringstream out;
    for (const unsigned char c : s) {
        switch (c) {
        case '"': out << "\\\""; break;
        case '\\': out << "\\\\"; break;
        case '\n': out << "\\n"; break;
        case '\t': out << "\\t"; break;
        case '\r': out << "\\r"; break;
        default:
            if (c < 0x20)
                out << "\\u" << std::hex << std::setw(4) << std::setfill('0') << int(c) << std::dec;
            else
                out << c;
        }
    }
    return out.str();
}

const char* status_word(CaseStatus status) { return status_words[static_cast<int>(status)]; }

std::optional<CaseStatus> status_of_word(const std::string& word)
{
    for (int k = 0; k < static_cast<int>(std::size(status_words)); ++k)
        if (word == status_words[k])
            return static_cast<CaseStatus>(k);
    return std::nullopt;
}

std::string csv_field(const std::string& s)
{
    std::string out = "\"";
    for (const char c : s)
        out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + '"';
}

std::string escape_xml(const std::string& s)
{
    std::string out;
    for (const char c : s) {
        if (c == '&') out += "&amp;";
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '"') out += "&quot;";
        else out += c;
    }
    return out;
}

void print_case(std::ostream& out, const CaseResult& r)
{
    out << (r.passed() ? "  ok    " : "  FAIL  ") << std::left << std::setw(6) << r.number << std::right << std::setw(2)
        << r.score << '/' << r.max_score << "  " << r.name << '\n';
    if (r.passed())
        return;
    std::istringstream lines(tidy_output(r.output));
    std::string line;
    while (std::getline(lines, line))
        out << "          " << line << '\n';
}

void print_points_table(std::ostream& out, const std::vector<CaseResult>& results, const std::vector<CaseResult>& cases)
{
    // number -> (score, max), ordered; chapter totals alongside. An untouched chapter's one line
    // is split into its exercises again where the cases are at hand, and said once above them.
    std::map<std::string, std::pair<int, int>> by_exercise, by_chapter;
    std::map<std::string, std::string> untouched;  // chapter -> its line's words
    for (const CaseResult& r : results) {
        by_chapter[chapter_of(r)].first += r.score;
        by_chapter[chapter_of(r)].second += r.max_score;
        const bool split = r.status == CaseStatus::untouched &&
                           std::any_of(cases.begin(), cases.end(), [&](const CaseResult& c) { return chapter_of(c) == r.number; });
        if (!split) {
            by_exercise[r.number].first += r.score;
            by_exercise[r.number].second += r.max_score;
            continue;
        }
        untouched[r.number] = "lost " + std::to_string(r.max_score) + ": " + r.name;
        for (const CaseResult& c : cases)
            if (chapter_of(c) == r.number)
                by_exercise[c.number].second += c.max_score;
    }
    out << "\nPoints\n";
    for (const auto& [chapter, total] : by_chapter) {
        out << "  chapter " << chapter << std::setw(14) << total.first << " / " << total.second << '\n';
        if (untouched.count(chapter))
            out << "    " << untouched[chapter] << '\n';
        for (const auto& [number, points] : by_exercise) {
            if (number.compare(0, 2, chapter) != 0)
                continue;
            out << "    " << std::left << std::setw(8) << number << std::right << std::setw(13) << points.first
                << " / " << points.second << '\n';
            for (const CaseResult& r : results)
                if (r.number == number && !r.passed())
                    out << "      lost " << r.max_score << ": " << r.name << '\n';
        }
    }
    // An open exercise's measure, as the leaderboard ranks it.
    // Three decimals, as the leaderboard shows it ("1.000", not "1"), and the figures scene by scene:
    // a design that already passes every tier is improved by these alone.
    for (const CaseResult& m : leaderboard_of(results)) {
        std::ostringstream value;
        value << std::fixed << std::setprecision(3) << m.measured;
        out << "  " << m.measure << ": " << value.str() << " (the reference: " << number_text(m.reference)
            << "; lower is better, and the class leaderboard ranks it)";
        std::string detail = m.measure_detail;  // its lines under it, one step further in
        for (size_t at = detail.find('\n'); at != std::string::npos; at = detail.find('\n', at + 3))
            detail.insert(at + 1, "  ");
        out << detail << '\n';
    }
}

bool append_gradebook_row(const std::string& path, const std::string& student, const std::vector<CaseResult>& results)
{
    std::map<std::string, int> by_chapter;
    int total = 0;
    for (const CaseResult& r : results) {
        by_chapter[chapter_of(r)] += r.score;
        total += r.score;
    }
    const bool is_new = !std::ifstream(path).good();
    std::ofstream out(path, std::ios::app);
    if (is_new) {
        // The header, then the most each column can score: a row a spreadsheet divides by.
        std::map<std::string, int> max_by_chapter;
        int max_total = 0;
        for (const CaseResult& r : results) {
            max_by_chapter[chapter_of(r)] += r.max_score;
            max_total += r.max_score;
        }
        out << "student";
        for (const auto& entry : by_chapter)
            out << ",ch" << entry.first;
        out << ",total\n\"(maximum)\"";
        for (const auto& entry : max_by_chapter)
            out << ',' << entry.second;
        out << ',' << max_total << '\n';
    }
    out << csv_field(student);
    for (const auto& entry : by_chapter)
        out << ',' << entry.second;
    out << ',' << total << '\n';
    return static_cast<bool>(out);
}

std::string tidy_output(std::string output)
{
#ifdef RT_KIT_DIR
    // The grading machine's own folders say nothing to a student: paths are the kit's.
    const std::string kit = std::string(RT_KIT_DIR) + "/";
    for (size_t at = output.find(kit); at != std::string::npos; at = output.find(kit, at))
        output.erase(at, kit.size());
#endif
    // A stub that fails every input of a loop would write thousands of lines: the first ones say
    // what is wrong. What is cut becomes one line, so the result is case_output_lines long at most,
    // and tidying it again changes nothing.
    constexpr size_t max_chars = 4000;
    const size_t lines = static_cast<size_t>(std::count(output.begin(), output.end(), '\n')) +
                         (!output.empty() && output.back() != '\n' ? 1 : 0);
    size_t cut = std::string::npos;
    if (lines > case_output_lines) {
        cut = 0;
        for (size_t kept = 0; kept + 1 < case_output_lines; ++kept)
            cut = output.find('\n', cut) + 1;
    }
    // (Room under max_chars for the line that says what was cut.)
    if (output.size() > max_chars && (cut == std::string::npos || cut > max_chars - 64)) {
        cut = output.rfind('\n', max_chars - 64);
        cut = cut == std::string::npos ? max_chars - 64 : cut + 1;
    }
    if (cut != std::string::npos) {
        const size_t kept = static_cast<size_t>(std::count(output.begin(), output.begin() + static_cast<long>(cut), '\n'));
        output = output.substr(0, cut) + "... and " + std::to_string(lines - kept) + " more lines";
    }
    return output;
}

static void write_line(std::ostream& out, const CaseResult& r)
{
    out << escape_line(r.number) << '\t' << r.max_score << '\t' << r.score << '\t' << escape_line(r.name) << '\t'
        << escape_line(tidy_output(r.output)) << '\t' << escape_line(r.stubs) << '\t' << status_word(r.status);
    if (!r.measure.empty())
        out << '\t' << escape_line(r.measure) << '\t' << number_text(r.measured) << '\t' << number_text(r.reference)
            << '\t' << escape_line(r.measure_detail);
    out << '\n';
}

std::vector<CaseResult> leaderboard_of(const std::vector<CaseResult>& results)
{
    std::vector<CaseResult> board;
    for (const CaseResult& r : results)
        if (!r.measure.empty() && std::none_of(board.begin(), board.end(), [&](const CaseResult& b) { return b.measure == r.measure; }))
            board.push_back(r);
    return board;
}

bool write_results(const std::string& path, const std::vector<CaseResult>& results)
{
    // A results file in a folder not made yet (--results grade/01.results) gets its folder.
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    std::error_code ignored;
    if (!parent.empty())
        std::filesystem::create_directories(parent, ignored);
    std::ofstream out(path);
    for (const CaseResult& r : results)
        write_line(out, r);
    return static_cast<bool>(out);
}

bool append_result(const std::string& path, const CaseResult& result)
{
    std::ofstream out(path, std::ios::app);
    write_line(out, result);
    return static_cast<bool>(out);
}

bool read_results(const std::string& path, std::vector<CaseResult>& results)
{
    std::ifstream in(path);
    if (!in)
        return false;
    std::string line;
    while (std::getline(in, line)) {
        std::vector<std::string> fields;
        std::istringstream cols(line);
        std::string field;
        while (std::getline(cols, field, '\t'))
            fields.push_back(unescape_line(field));
        if (fields.size() < 4)
            return false;
        CaseResult r;
        r.number = fields[0];
        r.max_score = std::stoi(fields[1]);
        r.score = std::stoi(fields[2]);
        r.name = fields[3];
        r.output = fields.size() > 4 ? fields[4] : "";
        r.stubs = fields.size() > 5 ? fields[5] : "";
        const std::optional<CaseStatus> status = fields.size() > 6 ? status_of_word(fields[6]) : std::nullopt;
        if (fields.size() > 6 && !status)
            return false;
        // (A line from before the status field: what its score and number say.)
        const bool build_line = r.number.size() > 2 && r.number.compare(2, std::string::npos, ".build") == 0;
        r.status = status                        ? *status
                   : build_line                  ? CaseStatus::does_not_compile
                   : r.score == r.max_score      ? CaseStatus::passed
                                                 : CaseStatus::failed;
        if (fields.size() > 9 && !fields[7].empty()) {
            r.measure = fields[7];
            r.measured = std::strtod(fields[8].c_str(), nullptr);
            r.reference = std::strtod(fields[9].c_str(), nullptr);
            r.measure_detail = fields.size() > 10 ? fields[10] : "";
        }
        results.push_back(r);
    }
    return true;
}

bool write_gradescope_json(const std::string& path, const std::vector<CaseResult>& results,
                           const std::function<std::string(const CaseResult&)>& as_html)
{
    int score = 0;
    for (const CaseResult& r : results)
        score += r.score;
    std::ofstream out(path);
    out << "{\n  \"score\": " << score << ",\n  \"tests\": [";
    for (size_t k = 0; k < results.size(); ++k) {
        const CaseResult& r = results[k];
        out << (k ? "," : "") << "\n    {\"name\": \"" << escape_json(r.name) << "\", \"number\": \""
            << escape_json(r.number) << "\", \"score\": " << r.score << ", \"max_score\": " << r.max_score
            << ", \"output\": \"";
        const std::string html = as_html && !r.passed() ? as_html(r) : "";
        if (html.empty())
            out << escape_json(r.output) << "\"}";
        else
            out << escape_json(html) << "\", \"output_format\": \"html\"}";
    }
    out << "\n  ]";
    // Gradescope's leaderboard: each measure, lower first.
    const std::vector<CaseResult> board = leaderboard_of(results);
    if (!board.empty()) {
        out << ",\n  \"leaderboard\": [";
        for (size_t k = 0; k < board.size(); ++k)
            out << (k ? "," : "") << "\n    {\"name\": \"" << escape_json(board[k].measure)
                << "\", \"value\": " << number_text(board[k].measured) << ", \"order\": \"asc\"}";
        out << "\n  ]";
    }
    out << "\n}\n";
    return static_cast<bool>(out);
}

bool write_junit_xml(const std::string& path, const std::vector<CaseResult>& results)
{
    std::map<std::string, std::vector<const CaseResult*>> by_chapter;
    for (const CaseResult& r : results)
        by_chapter[chapter_of(r)].push_back(&r);
    std::ofstream out(path);
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n";
    for (const auto& [chapter, cases] : by_chapter) {
        int failures = 0;
        for (const CaseResult* r : cases)
            failures += r->passed() ? 0 : 1;
        out << "  <testsuite name=\"chapter " << chapter << "\" tests=\"" << cases.size() << "\" failures=\""
            << failures << "\">\n";
        for (const CaseResult* r : cases) {
            out << "    <testcase classname=\"ch" << chapter << '.' << escape_xml(r->number) << "\" name=\""
                << escape_xml(r->name) << "\">";
            if (!r->passed())
                out << "<failure message=\"lost " << r->max_score << " points\">" << escape_xml(r->output)
                    << "</failure>";
            out << "</testcase>\n";
        }
        out << "  </testsuite>\n";
    }
    out << "</testsuites>\n";
    return static_cast<bool>(out);
}

bool check_expectation(std::ostream& out, const std::vector<CaseResult>& results, const std::string& expect)
{
    if (results.empty()) {
        out << "grader self-check: no graded case ran\n";
        return false;
    }
    int score = 0, max_score = 0;
    for (const CaseResult& r : results) {
        score += r.score;
        max_score += r.max_score;
    }
    bool ok = true;
    if (expect == "full") {
        ok = score == max_score;
        for (const CaseResult& r : results)
            if (!r.passed())
                out << "grader self-check: the solution fails " << r.number << " '" << r.name << "'\n";
    } else if (expect == "zero") {
        ok = score == 0;
        for (const CaseResult& r : results)
            if (r.passed())
                out << "grader self-check: the untouched stub passes " << r.number << " '" << r.name
                    << "': that case cannot tell a stub from an answer\n";
        // The report says "still the handed-out stub" only of a case that saw a stub run.
        for (const CaseResult& r : results)
            if (!r.passed() && r.stubs.empty()) {
                ok = false;
                out << "grader self-check: " << r.number << " '" << r.name
                    << "' fails on the stubs but ran none of them: the report cannot say it waits for a stub\n";
            }
    } else if (expect == "less") {
        ok = score < max_score;
        if (!ok)
            out << "grader self-check: the mutant scores full points: no graded case catches it\n";
    }
    out << "grader self-check: " << score << " / " << max_score << " points, expected " << expect << ": "
        << (ok ? "as expected" : "NOT as expected") << '\n';
    return ok;
}

}  // namespace rt::grader
