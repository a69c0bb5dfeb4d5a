#include "tests/grader/clauses.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>

namespace rt::grader {

namespace {

bool is_exercise_number(const std::string& n)
{
    return n.size() >= 4 && std::isdigit(static_cast<unsigned char>(n[0])) && n[2] == '.' &&
           std::all_of(n.begin() + 3, n.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

// `| a | b |` -> its last cell.
std::string last_cell(const std::string& row)
{
    const size_t end = row.find_last_of('|');
    const size_t begin = row.find_last_of('|', end == 0 ? 0 : end - 1);
    return begin == std::string::npos || end == begin ? "" : row.substr(begin + 1, end - begin - 1);
}

bool is_header_or_rule(const std::string& row)
{
    return row.find("---") != std::string::npos || row.rfind("| clause", 0) == 0;
}

}  // namespace

std::vector<std::string> check_clause_table(const std::string& path, const std::vector<GradedCase>& cases)
{
    std::vector<std::string> problems;
    std::ifstream in(path);
    if (!in)
        return {path + ": cannot read the clause table"};
    std::set<std::string> names, exercises, sections;
    for (const GradedCase& c : cases) {
        names.insert(c.name);
        if (is_exercise_number(c.number))
            exercises.insert(c.number);
    }
    std::string line, section;
    for (int number = 1; std::getline(in, line); ++number) {
        const std::string where = path + ":" + std::to_string(number) + ": ";
        if (line.rfind("## ", 0) == 0) {
            section = line.substr(3, line.find(' ', 3) - 3);
            sections.insert(section);
            continue;
        }
        if (line.rfind("|", 0) != 0 || is_header_or_rule(line))
            continue;
        if (section.empty()) {
            problems.push_back(where + "a clause before any exercise's heading (## NN.k name)");
            continue;
        }
        const std::string cell = last_cell(line);
        int named = 0;
        for (size_t open = cell.find('`'); open != std::string::npos; open = cell.find('`', open)) {
            const size_t close = cell.find('`', open + 1);
            if (close == std::string::npos) {
                problems.push_back(where + "an unclosed ` in the cases");
                break;
            }
            const std::string name = cell.substr(open + 1, close - open - 1);
            ++named;
            if (!names.count(name))
                problems.push_back(where + section + ": no graded case is named '" + name + "'");
            open = close + 1;
        }
        if (named == 0)
            problems.push_back(where + section + ": a clause with no case on it: " + line);
    }
    for (const std::string& e : exercises)
        if (!sections.count(e))
            problems.push_back(path + ": exercise " + e + " has graded cases but no section (## " + e + " name)");
    return problems;
}

}  // namespace rt::grader
