#include "tests/grader/class_stats.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

namespace rt::grader {

namespace {

// The kit's order of exercise numbers: by chapter, then 1, 2, ..., 10, then the letters (A, P).
bool kit_order(const std::string& a, const std::string& b)
{
    const auto key = [](const std::string& n) {
        const std::string rest = n.size() > 3 ? n.substr(3) : "";
        const bool numeric = !rest.empty() && std::all_of(rest.begin(), rest.end(), [](char c) {
            return std::isdigit(static_cast<unsigned char>(c));
        });
        return std::make_tuple(chapter_of(n), numeric ? 0 : 1, numeric ? std::stoi(rest) : 0, rest);
    };
    return key(a) < key(b);
}

// A message's first line, no longer than a table's cell should be.
std::string first_line(const std::string& output)
{
    std::string line = output.substr(0, output.find('\n'));
    constexpr size_t longest = 200;
    if (line.size() > longest)
        line = line.substr(0, longest - 3) + "...";
    return line;
}

// One student's points on one exercise, and whether their own code ran in it.
struct Attempt {
    int score = 0, max_score = 0;
    bool own_code_ran = false;  // a case ran with none of the handed-out stubs
};

}  // namespace

bool read_student_results(const std::string& name, const std::vector<std::string>& paths, StudentResults& student)
{
    student.name = name;
    student.cases.clear();
    for (const std::string& path : paths)
        if (std::ifstream(path).good() && !read_results(path, student.cases))
            return false;
    return true;
}

std::vector<ExerciseStats> class_stats(const std::vector<StudentResults>& students)
{
    // Each exercise's cases in the order the graders ran them (for ties among the most failed).
    std::map<std::string, std::vector<std::string>> case_order;
    std::map<std::string, int> max_score;
    std::vector<std::map<std::string, Attempt>> attempts(students.size());
    for (size_t s = 0; s < students.size(); ++s) {
        std::set<std::string> not_built;  // chapters missing or not compiling
        for (const CaseResult& r : students[s].cases)
            if (is_build_line(r))
                not_built.insert(chapter_of(r.number));
        for (const CaseResult& r : students[s].cases) {
            if (is_build_line(r))
                continue;
            Attempt& a = attempts[s][r.number];
            a.score += r.score;
            a.max_score += r.max_score;
            a.own_code_ran = a.own_code_ran || (!not_built.count(chapter_of(r.number)) && r.stubs.empty());
            std::vector<std::string>& order = case_order[r.number];
            if (std::find(order.begin(), order.end(), r.name) == order.end())
                order.push_back(r.name);
        }
        // (Every student lists every case, at 0 when the chapter did not build: the most any of
        // them lists is the exercise's maximum.)
        for (const auto& [number, a] : attempts[s])
            max_score[number] = std::max(max_score[number], a.max_score);
    }
    std::vector<std::string> numbers;
    for (const auto& entry : max_score)
        numbers.push_back(entry.first);
    std::sort(numbers.begin(), numbers.end(), kit_order);

    std::vector<ExerciseStats> out;
    for (const std::string& number : numbers) {
        ExerciseStats e;
        e.number = number;
        e.max_score = max_score[number];
        e.students = static_cast<int>(students.size());
        // case name -> students who failed it, and each first line with how many got it
        std::map<std::string, int> failed;
        std::map<std::string, std::vector<std::pair<std::string, int>>> lines;
        for (size_t s = 0; s < students.size(); ++s) {
            const auto at = attempts[s].find(number);
            const Attempt a = at == attempts[s].end() ? Attempt{} : at->second;
            e.points += a.score;
            e.full_marks += e.max_score > 0 && a.score == e.max_score ? 1 : 0;
            e.not_graded += a.own_code_ran ? 0 : 1;
            if (!a.own_code_ran)
                continue;
            std::set<std::string> counted;  // a case a student failed counts once
            for (const CaseResult& r : students[s].cases) {
                if (r.number != number || r.passed() || !r.stubs.empty() || !counted.insert(r.name).second)
                    continue;
                ++failed[r.name];
                const std::string line = first_line(r.output);
                auto& seen = lines[r.name];
                const auto same = std::find_if(seen.begin(), seen.end(), [&](const auto& l) { return l.first == line; });
                if (same == seen.end())
                    seen.emplace_back(line, 1);
                else
                    ++same->second;
            }
        }
        for (const std::string& name : case_order[number]) {
            if (!failed.count(name))
                continue;
            const auto& seen = lines[name];
            // The line most students got; the first of those on a tie.
            const auto most = std::max_element(seen.begin(), seen.end(),
                                               [](const auto& a, const auto& b) { return a.second < b.second; });
            e.most_failed.push_back(FailedCase{name, failed[name], most->first});
        }
        std::stable_sort(e.most_failed.begin(), e.most_failed.end(),
                         [](const FailedCase& a, const FailedCase& b) { return a.students > b.students; });
        if (e.most_failed.size() > 3)
            e.most_failed.resize(3);
        out.push_back(e);
    }
    return out;
}

std::string mean_points(const ExerciseStats& e)
{
    if (e.students == 0)
        return "0.00";
    const long long hundredths = (200LL * e.points + e.students) / (2LL * e.students);
    std::string cents = std::to_string(hundredths % 100);
    return std::to_string(hundredths / 100) + "." + (cents.size() < 2 ? "0" : "") + cents;
}

bool write_exercises_csv(const std::string& path, const std::vector<ExerciseStats>& stats)
{
    std::ofstream out(path);
    out << "exercise,max,students,full_marks,mean,not_graded";
    for (int k = 1; k <= 3; ++k)
        out << ",failed_" << k << ",failed_" << k << "_students,failed_" << k << "_message";
    out << '\n';
    for (const ExerciseStats& e : stats) {
        out << csv_field(e.number) << ',' << e.max_score << ',' << e.students << ',' << e.full_marks << ','
            << mean_points(e) << ',' << e.not_graded;
        for (size_t k = 0; k < 3; ++k) {
            if (k < e.most_failed.size())
                out << ',' << csv_field(e.most_failed[k].name) << ',' << e.most_failed[k].students << ','
                    << csv_field(e.most_failed[k].first_line);
            else
                out << ",,,";
        }
        out << '\n';
    }
    return static_cast<bool>(out);
}

std::string exercises_table_html(const std::vector<ExerciseStats>& stats)
{
    std::ostringstream out;
    out << "<table class=\"exercises\"><tr><th>exercise</th><th>at full marks</th><th>mean points</th>"
           "<th>not graded</th><th>cases most often failed (students; first line of the message)</th></tr>\n";
    for (const ExerciseStats& e : stats) {
        const int percent = e.students ? (200 * e.full_marks + e.students) / (2 * e.students) : 0;
        const char* look = e.students && e.full_marks == e.students ? "ok" : e.full_marks * 2 >= e.students ? "part" : "flag";
        out << "<tr><td>" << escape_xml(e.number) << "</td><td class=\"" << look << "\">" << e.full_marks << " of "
            << e.students << " (" << percent << "%)</td><td>" << mean_points(e) << " / " << e.max_score << "</td><td>"
            << e.not_graded << "</td><td>";
        if (e.most_failed.empty())
            out << "&mdash;";
        else {
            out << "<ol>";
            for (const FailedCase& f : e.most_failed)
                out << "<li>" << escape_xml(f.name) << " (" << f.students << (f.students == 1 ? " student" : " students")
                    << ")" << (f.first_line.empty() ? "" : "<br><code>" + escape_xml(f.first_line) + "</code>") << "</li>";
            out << "</ol>";
        }
        out << "</td></tr>\n";
    }
    out << "</table>\n";
    return out.str();
}

std::string pseudonym_of(const std::string& student, const std::string& key)
{
    static const char* const words[] = {"Otter", "Heron", "Lynx", "Badger", "Falcon", "Marten", "Ibex", "Puffin",
                                        "Gecko", "Bison", "Crane", "Dingo", "Egret", "Ferret", "Gannet", "Hare"};
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a, 64 bits
    for (const char c : key + '\n' + student) {
        h ^= static_cast<unsigned char>(c);
        h *= 1099511628211ull;
    }
    std::ostringstream s;
    s << words[h % std::size(words)] << '-' << std::hex << std::setw(4) << std::setfill('0') << ((h >> 16) & 0xffff);
    return s.str();
}

std::vector<Leaderboard> class_leaderboards(const std::vector<StudentResults>& students, LeaderboardNames names,
                                            const std::string& key)
{
    std::vector<Leaderboard> boards;
    for (const StudentResults& student : students)
        for (const CaseResult& r : leaderboard_of(student.cases)) {
            auto board = std::find_if(boards.begin(), boards.end(), [&](const Leaderboard& b) { return b.measure == r.measure; });
            if (board == boards.end())
                board = boards.insert(boards.end(), Leaderboard{r.measure, r.reference, {}});
            board->ranked.push_back({student.name,
                                     names == LeaderboardNames::pseudonyms ? pseudonym_of(student.name, key) : student.name,
                                     r.measured});
        }
    for (Leaderboard& b : boards)
        std::sort(b.ranked.begin(), b.ranked.end(), [](const LeaderboardEntry& x, const LeaderboardEntry& y) {
            return std::tie(x.value, x.student) < std::tie(y.value, y.student);
        });
    std::sort(boards.begin(), boards.end(), [](const Leaderboard& x, const Leaderboard& y) { return kit_order(x.measure, y.measure); });
    return boards;
}

std::string leaderboards_html(const std::vector<Leaderboard>& boards, bool with_names)
{
    std::ostringstream out;
    for (const Leaderboard& b : boards) {
        out << "<h3>" << escape_xml(b.measure) << "</h3>\n<table class=\"leaderboard\"><tr><th>rank</th><th>who</th>"
            << (with_names ? "<th>student</th>" : "") << "<th>" << escape_xml(b.measure) << " (lower is better; the reference: "
            << b.reference << ")</th></tr>\n";
        size_t rank = 0;
        for (size_t k = 0; k < b.ranked.size(); ++k) {
            const LeaderboardEntry& e = b.ranked[k];
            // Equal costs share a rank (1, 1, 3): the order among them is only the names'.
            if (k == 0 || e.value != b.ranked[k - 1].value)
                rank = k + 1;
            out << "<tr><td>" << rank << "</td><td>" << escape_xml(e.shown) << "</td>"
                << (with_names ? "<td>" + escape_xml(e.student) + "</td>" : "") << "<td class=\""
                << (e.value <= b.reference ? "ok" : "part") << "\">" << std::fixed << std::setprecision(3) << e.value
                << std::defaultfloat << "</td></tr>\n";
        }
        out << "</table>\n";
    }
    return out.str();
}

}  // namespace rt::grader
