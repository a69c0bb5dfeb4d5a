// Keeps the lessons' measured tables the code's own (common/lesson_table.hpp writes them).
//
//   lesson_tables refresh TABLES.md... : pastes each table into the lesson that has its marker
//   lesson_tables check TABLES.md LESSON.md : exit 1 when a lesson's cell differs from the code's
//     in a column that is not timed, or a table of one is missing from the other
//
// A block is `<!-- table NAME [timed: header; header] -->`, the table, its caption, and
// `<!-- end table -->`. refresh finds the lessons as chapters/*/README.md under --kit (default: .).
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Block {
    std::string name;
    std::vector<std::string> timed;  // headers of the timed columns
    std::vector<std::string> lines;  // from the marker to the end marker, both included
    int line = 0;                    // of the marker, 1-based
};

const std::string open_marker = "<!-- table ", close_marker = "<!-- end table -->";

std::vector<std::string> split(const std::string& text, char by)
{
    std::vector<std::string> parts;
    std::stringstream s(text);
    for (std::string part; std::getline(s, part, by);)
        parts.push_back(part);
    return parts;
}

std::string trim(const std::string& s)
{
    const size_t first = s.find_first_not_of(" \t"), last = s.find_last_not_of(" \t");
    return first == std::string::npos ? "" : s.substr(first, last - first + 1);
}

std::vector<std::string> read_lines(const fs::path& path)
{
    std::ifstream in(path);
    if (!in)
        throw std::runtime_error(path.string() + ": cannot be read");
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

// The blocks of a file, by the line they start on; an unclosed block is an error naming its line.
std::vector<Block> blocks_of(const fs::path& path, const std::vector<std::string>& lines)
{
    std::vector<Block> blocks;
    for (size_t k = 0; k < lines.size(); ++k) {
        if (lines[k].rfind(open_marker, 0) != 0)
            continue;
        Block b;
        b.line = static_cast<int>(k) + 1;
        std::string head = lines[k].substr(open_marker.size());
        head = trim(head.substr(0, head.rfind("-->")));
        const size_t timed = head.find(" timed: ");
        b.name = trim(head.substr(0, timed));
        if (timed != std::string::npos)
            for (const std::string& h : split(head.substr(timed + 8), ';'))
                b.timed.push_back(trim(h));
        size_t end = k;
        while (end < lines.size() && lines[end] != close_marker)
            ++end;
        if (end == lines.size())
            throw std::runtime_error(path.string() + ":" + std::to_string(b.line) + ": table " + b.name +
                                     " has no '" + close_marker + "'");
        b.lines.assign(lines.begin() + static_cast<long>(k), lines.begin() + static_cast<long>(end) + 1);
        blocks.push_back(b);
        k = end;
    }
    return blocks;
}

std::vector<std::vector<std::string>> rows_of(const Block& b)
{
    std::vector<std::vector<std::string>> rows;
    for (const std::string& line : b.lines)
        if (line.rfind('|', 0) == 0) {
            std::vector<std::string> cells = split(line.substr(1), '|');
            for (std::string& c : cells)
                c = trim(c);
            rows.push_back(cells);
        }
    return rows;
}

// Every difference between the lesson's block and the code's, in the columns that are not timed.
int compare(const fs::path& lesson, const Block& in_lesson, const Block& from_code)
{
    const auto ours = rows_of(in_lesson), theirs = rows_of(from_code);
    const std::string where = lesson.string() + ":" + std::to_string(in_lesson.line) + ": table " + in_lesson.name;
    if (ours.empty() || theirs.empty() || ours.front() != theirs.front() || ours.size() != theirs.size()) {
        std::cout << where << ": the lesson's table has " << ours.size() << " lines (header first), the code's "
                  << theirs.size() << ", or their headers differ: refresh it (`lesson_tables` target)\n";
        return 1;
    }
    int differences = 0;
    const std::vector<std::string>& header = ours.front();
    for (size_t r = 2; r < ours.size(); ++r)
        for (size_t c = 0; c < header.size() && c < ours[r].size() && c < theirs[r].size(); ++c) {
            bool timed = false;
            for (const std::string& h : from_code.timed)
                timed = timed || h == header[c];
            if (!timed && ours[r][c] != theirs[r][c]) {
                std::cout << where << ", row " << r - 1 << " (" << ours[r][0] << "), column '" << header[c]
                          << "': the lesson says " << ours[r][c] << ", the code gives " << theirs[r][c] << '\n';
                ++differences;
            }
        }
    return differences;
}

int check(const fs::path& tables, const fs::path& lesson)
{
    const std::vector<Block> code = blocks_of(tables, read_lines(tables));
    const std::vector<Block> shown = blocks_of(lesson, read_lines(lesson));
    int problems = 0;
    for (const Block& c : code) {
        bool found = false;
        for (const Block& s : shown)
            if (s.name == c.name) {
                found = true;
                problems += compare(lesson, s, c);
            }
        if (!found) {
            std::cout << lesson.string() << ": has no '<!-- table " << c.name << " -->' for the sweep's table\n";
            ++problems;
        }
    }
    for (const Block& s : shown) {
        bool found = false;
        for (const Block& c : code)
            found = found || c.name == s.name;
        if (!found) {
            std::cout << lesson.string() << ":" << s.line << ": table " << s.name << " is not one the sweep writes\n";
            ++problems;
        }
    }
    std::cout << lesson.string() << ": " << code.size() << " table(s) against the code, " << problems
              << " difference(s)\n";
    return problems == 0 ? 0 : 1;
}

int refresh(const std::vector<fs::path>& tables, const fs::path& kit)
{
    std::map<std::string, Block> code;
    for (const fs::path& t : tables)
        for (Block& b : blocks_of(t, read_lines(t)))
            code[b.name] = b;
    size_t pasted = 0;
    for (const fs::directory_entry& chapter : fs::directory_iterator(kit / "chapters")) {
        const fs::path lesson = chapter.path() / "README.md";
        if (!fs::exists(lesson))
            continue;
        const std::vector<std::string> lines = read_lines(lesson);
        const std::vector<Block> shown = blocks_of(lesson, lines);
        if (shown.empty())
            continue;
        std::vector<std::string> out;
        size_t next = 0;
        for (const Block& s : shown) {
            out.insert(out.end(), lines.begin() + static_cast<long>(next), lines.begin() + s.line - 1);
            const auto found = code.find(s.name);
            const std::vector<std::string>& replacement = found == code.end() ? s.lines : found->second.lines;
            out.insert(out.end(), replacement.begin(), replacement.end());
            next = static_cast<size_t>(s.line - 1) + s.lines.size();
            if (found != code.end()) {
                ++pasted;
                code.erase(found);
                std::cout << lesson.string() << ":" << s.line << ": " << s.name << '\n';
            }
        }
        out.insert(out.end(), lines.begin() + static_cast<long>(next), lines.end());
        std::ofstream file(lesson);
        for (const std::string& line : out)
            file << line << '\n';
    }
    for (const auto& [name, block] : code)
        std::cout << "no lesson has '<!-- table " << name << " -->': not pasted\n";
    std::cout << pasted << " table(s) pasted\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    try {
        const std::vector<std::string> args(argv + 1, argv + argc);
        if (args.size() == 3 && args[0] == "check")
            return check(args[1], args[2]);
        if (args.size() >= 2 && args[0] == "refresh") {
            fs::path kit = ".";
            std::vector<fs::path> tables;
            for (size_t k = 1; k < args.size(); ++k)
                if (args[k] == "--kit" && k + 1 < args.size())
                    kit = args[++k];
                else
                    tables.push_back(args[k]);
            return refresh(tables, kit);
        }
        std::cerr << "usage: lesson_tables refresh TABLES.md... [--kit DIR]\n"
                     "       lesson_tables check TABLES.md LESSON.md\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "lesson_tables: " << e.what() << '\n';
        return 2;
    }
}
