#include "tests/grader/html_report.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

namespace rt::grader {

namespace {

std::string base64(const std::string& bytes)
{
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    size_t k = 0;
    for (; k + 2 < bytes.size(); k += 3) {
        const unsigned v = (static_cast<unsigned char>(bytes[k]) << 16) | (static_cast<unsigned char>(bytes[k + 1]) << 8) |
                           static_cast<unsigned char>(bytes[k + 2]);
        out += {digits[v >> 18], digits[(v >> 12) & 63], digits[(v >> 6) & 63], digits[v & 63]};
    }
    if (k < bytes.size()) {
        const unsigned v = (static_cast<unsigned char>(bytes[k]) << 16) |
                           (k + 1 < bytes.size() ? static_cast<unsigned char>(bytes[k + 1]) << 8 : 0u);
        out += {digits[v >> 18], digits[(v >> 12) & 63], k + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=', '='};
    }
    return out;
}

// A picture a case's output names ("expected:   build/.../x.expected.png"), as a data URI; empty
// when the file is not there. Paths in outputs are relative to the kit.
std::string image_uri(std::string path)
{
#ifdef RT_KIT_DIR
    if (!std::filesystem::path(path).is_absolute())
        path = std::string(RT_KIT_DIR) + "/" + path;
#endif
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return "";
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return "data:image/png;base64," + base64(bytes.str());
}

const char* style = R"(body{font-family:sans-serif;margin:2em;max-width:70em;color:#222}
table{border-collapse:collapse;margin:0.5em 0 1.5em}td,th{border:1px solid #ccc;padding:0.3em 0.6em;vertical-align:top;text-align:left}
tr.fail td.points{background:#fdd}tr.ok td.points{background:#dfd}pre{white-space:pre-wrap;margin:0.4em 0;font-size:90%}
figure{display:inline-block;margin:0.3em 0.6em 0 0}figure img{width:18em;image-rendering:pixelated;border:1px solid #999}
figcaption{font-size:85%;text-align:center})";

// The pictures a case's output names ("expected:   build/.../x.expected.png"), as figures with the
// images embedded; empty when it names none that exist.
std::string picture_figures(const std::string& output)
{
    static const std::regex picture(R"((expected|actual|difference): +(\S+\.png))");
    std::ostringstream out;
    std::set<std::string> shown;  // an output may name a picture twice
    for (auto m = std::sregex_iterator(output.begin(), output.end(), picture); m != std::sregex_iterator(); ++m) {
        if (!shown.insert((*m)[2]).second)
            continue;
        const std::string uri = image_uri((*m)[2]);
        if (!uri.empty())
            out << "<figure><img alt=\"" << (*m)[1] << "\" src=\"" << uri << "\"><figcaption>" << (*m)[1]
                << "</figcaption></figure>";
    }
    return out.str();
}

// A file as a link from the page at `page`: its path relative to the page's folder, with the bytes
// a URL cannot carry as they are (a space, #, ?, %) percent-encoded.
std::string relative_href(const std::string& file, const std::string& page)
{
    namespace fs = std::filesystem;
    std::error_code ignored;
    const fs::path target = fs::absolute(file, ignored).lexically_normal();
    fs::path relative = target.lexically_relative(fs::absolute(page, ignored).lexically_normal().parent_path());
    const std::string path = (relative.empty() ? target : relative).generic_string();
    std::string href;
    for (const unsigned char c : path) {
        if (std::isalnum(c) || std::strchr("-._~/", c))
            href += static_cast<char>(c);
        else {
            static const char* hex = "0123456789ABCDEF";
            href += {'%', hex[c >> 4], hex[c & 15]};
        }
    }
    return href;
}

std::string link(const std::string& file, const std::string& page)
{
    return "<a href=\"" + escape_xml(relative_href(file, page)) + "\">" +
           escape_xml(std::filesystem::path(file).filename().string()) + "</a>";
}

}  // namespace

std::string case_output_html(const CaseResult& r)
{
    const std::string figures = picture_figures(r.output);
    if (figures.empty())
        return "";
    return "<pre>" + escape_xml(r.output) + "</pre>" + figures;
}

bool write_html_report(const std::string& path, const std::string& title, std::vector<CaseResult> results)
{
    // In exercise order (01.1 before 01.2), whatever order the cases ran in.
    std::stable_sort(results.begin(), results.end(),
                     [](const CaseResult& a, const CaseResult& b) { return a.number < b.number; });
    std::map<std::string, std::pair<int, int>> chapters;  // points and maximum per chapter
    int score = 0, max_score = 0;
    for (const CaseResult& r : results) {
        auto& c = chapters[r.number.substr(0, 2)];
        c.first += r.score;
        c.second += r.max_score;
        score += r.score;
        max_score += r.max_score;
    }
    std::ofstream out(path);
    out << "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << escape_xml(title)
        << "</title>\n<style>" << style << "</style></head><body>\n<h1>" << escape_xml(title) << ": " << score << " / "
        << max_score << " points</h1>\n<table><tr><th>chapter</th><th>points</th></tr>\n";
    for (const auto& [chapter, points] : chapters)
        out << "<tr><td><a href=\"#ch" << chapter << "\">chapter " << chapter << "</a></td><td>" << points.first << " / "
            << points.second << "</td></tr>\n";
    out << "</table>\n";
    std::string chapter;
    for (const CaseResult& r : results) {
        if (r.number.substr(0, 2) != chapter) {
            if (!chapter.empty())
                out << "</table>\n";
            chapter = r.number.substr(0, 2);
            out << "<h2 id=\"ch" << chapter << "\">chapter " << chapter << ": " << chapters[chapter].first << " / "
                << chapters[chapter].second << "</h2>\n<table><tr><th>exercise</th><th>case</th><th>points</th></tr>\n";
        }
        out << "<tr class=\"" << (r.passed() ? "ok" : "fail") << "\"><td>" << escape_xml(r.number) << "</td><td>"
            << escape_xml(r.name);
        if (!r.passed() && !r.output.empty())
            out << "<pre>" << escape_xml(r.output) << "</pre>" << picture_figures(r.output);
        out << "</td><td class=\"points\">" << r.score << " / " << r.max_score << "</td></tr>\n";
    }
    if (!chapter.empty())
        out << "</table>\n";
    out << "</body></html>\n";
    return static_cast<bool>(out);
}

bool append_class_row(const std::string& path, const std::string& student, const std::vector<ChapterMark>& chapters)
{
    const bool is_new = !std::ifstream(path).good();
    std::ofstream out(path, std::ios::app);
    if (is_new) {
        out << "<tr><th>student</th><th>points</th>";
        for (const ChapterMark& c : chapters)
            out << "<th>" << escape_xml(c.chapter) << "</th>";
        out << "</tr>\n";
    }
    int score = 0, max_score = 0;
    for (const ChapterMark& c : chapters) {
        score += c.score;
        max_score += c.max_score;
    }
    out << "<tr><td><a href=\"students/" << escape_xml(student) << "/report.html\">" << escape_xml(student) << "</a></td><td>"
        << score << " / " << max_score << "</td>";
    for (const ChapterMark& c : chapters) {
        const char* look = c.score == c.max_score ? "ok" : c.marks.empty() ? "part" : "flag";
        out << "<td class=\"" << look << "\">" << c.score << " / " << c.max_score;
        if (!c.marks.empty())
            out << "<br><small>" << escape_xml(c.marks) << "</small>";
        out << "</td>";
    }
    out << "</tr>\n";
    return static_cast<bool>(out);
}

bool write_class_page(const std::string& path, const std::string& student_rows, const std::vector<ExerciseStats>& exercises,
                      const std::string& gradebook, const std::string& exercises_csv,
                      const std::vector<Leaderboard>& boards, const std::string& leaderboard_page)
{
    std::ofstream out(path);
    out << R"(<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>The class</title>
<style>body{font-family:sans-serif;margin:2em;color:#222}td,th{border:1px solid #ccc;padding:0.3em 0.6em;vertical-align:top;text-align:left}
table{border-collapse:collapse;margin:0.5em 0 1.5em}td.ok{background:#dfd}td.part{background:#ffd}td.flag{background:#fdd}small{color:#733}
table.exercises td:nth-child(-n+4){white-space:nowrap}table.exercises ol{margin:0;padding-left:1.4em}table.exercises code{font-size:85%;color:#555}</style>
</head><body><h1>The class</h1>
<p>Gradebook: )"
        << link(gradebook, path) << R"(. A chapter's cell is flagged with what an instructor
should look at: no file, does not compile, untouched (still the handed-out stubs), an exercise still its
stub, a case stopped by its time limit or crashed.</p>
<table>
)" << student_rows
        << R"(</table>
<h2>Each exercise</h2>
<p>Per exercise (also in )"
        << link(exercises_csv, path) << R"(): how many students have every point of it, the class's mean points
(of the exercise's maximum), and the cases most often failed, each with how many students failed it and the
first line of its message (the line most of them got). A student whose chapter file is missing or does not
compile counts as 0 points for each of its exercises, as does one whose cases all ran the handed-out stubs:
they are counted under <em>not graded</em>, not among those who failed a case.</p>
)" << exercises_table_html(exercises);
    if (!boards.empty()) {
        const bool pseudonyms = std::any_of(boards.begin(), boards.end(), [](const Leaderboard& b) {
            return std::any_of(b.ranked.begin(), b.ranked.end(), [](const LeaderboardEntry& e) { return e.shown != e.student; });
        });
        out << "<h2>Leaderboard</h2>\n<p>The open exercises' costs, counted by the grader (never timed), lower first: only "
               "students whose answers passed the exercise's gate are ranked."
            << (leaderboard_page.empty() ? std::string() : " The page to share with the class: " + link(leaderboard_page, path) + ".")
            << (pseudonyms ? " It shows each student by the pseudonym beside their name here." : "") << "</p>\n"
            << leaderboards_html(boards, pseudonyms);
    }
    out << "</body></html>\n";
    return static_cast<bool>(out);
}

bool write_leaderboard_page(const std::string& path, const std::vector<Leaderboard>& boards)
{
    std::ofstream out(path);
    out << R"(<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>Leaderboard</title>
<style>body{font-family:sans-serif;margin:2em;color:#222}td,th{border:1px solid #ccc;padding:0.3em 0.6em;text-align:left}
table{border-collapse:collapse;margin:0.5em 0 1.5em}td.ok{background:#dfd}td.part{background:#ffd}</style>
</head><body><h1>Leaderboard</h1>
<p>Each open exercise's cost as the grader counts it (objects tested and cells visited per ray for 07.7; intersection
tests per ray for 08.4; keys compared per table lookup for 09.6; nodes visited and objects tested per ray for 10.7;
never time),
lower first, against the reference solution's. Only correct answers are ranked.</p>
)" << leaderboards_html(boards, false)
        << "</body></html>\n";
    return static_cast<bool>(out);
}

}  // namespace rt::grader
