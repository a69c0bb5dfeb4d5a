// Keeps the lessons' measured tables the code's own (common/lesson_table.hpp writes them).
//
//   lesson_tables refresh TABLES.md... : pastes each table into the lesson that has its marker
//   lesson_tables check TABLES.md LESSON.md : exit 1 when a lesson's cell differs from the code's
//     in a column that is not timed, or a table of one is missing from the other
//
// A block is `<!-- table NAME [timed: header; header] -->`, the table, its caption, and
// `<!-- end table -->`. refresh finds the lessons as chapters/*/README.md under --kit (default: .).
//
// A number the prose states is a cell of one of those tables, marked where it stands:
// `<!-- cell NAME [KEY] COLUMN -->3,645<!-- /cell -->`, where KEY is the row's first cells, joined by
// ", " ("8, 2": leaf size 8, depth limit 2), and COLUMN the column's header. refresh writes the
// code's cell there; check holds it to the code's, as it holds the tables (a timed column's cell
// is refreshed, not compared).
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
const std::string cell_marker = "<!-- cell ", cell_close = "<!-- /cell -->";

// A number of the prose, marked as a cell of a table: where it stands and what it names.
struct Cell {
    std::string table, key, column;
    std::string value;   // the text between the markers
    int line = 0;        // 1-based
    size_t value_at = 0; // where the value starts in its line
};

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

// The marked cells of a lesson's lines; a marker that does not parse is an error naming its line.
std::vector<Cell> cells_of(const fs::path& path, const std::vector<std::string>& lines)
{
    std::vector<Cell> cells;
    for (size_t k = 0; k < lines.size(); ++k)
        for (size_t at = lines[k].find(cell_marker); at != std::string::npos;
             at = lines[k].find(cell_marker, at + 1)) {
            const std::string& line = lines[k];
            const std::string where = path.string() + ":" + std::to_string(k + 1) + ": ";
            const size_t open = line.find(" [", at), close = line.find("] ", at), end = line.find(" -->", at);
            const size_t stop = end == std::string::npos ? end : line.find(cell_close, end);
            if (open == std::string::npos || close == std::string::npos || end == std::string::npos ||
                stop == std::string::npos || !(open < close && close < end))
                throw std::runtime_error(where + "a cell marker is not '" + cell_marker + "TABLE [KEY] COLUMN -->" +
                                         "value" + cell_close + "'");
            Cell c;
            c.table = line.substr(at + cell_marker.size(), open - at - cell_marker.size());
            c.key = line.substr(open + 2, close - open - 2);
            c.column = line.substr(close + 2, end - close - 2);
            c.value_at = end + 4;
            c.value = line.substr(c.value_at, stop - c.value_at);
            c.line = static_cast<int>(k) + 1;
            cells.push_back(c);
        }
    return cells;
}

// The code's value of a marked cell, and whether its column is timed; an error message instead
// when the table, the row or the column is not the code's.
struct Lookup {
    std::string value, error;
    bool timed = false;
};

Lookup look_up(const std::vector<Block>& code, const Cell& c)
{
    Lookup l;
    for (const Block& b : code) {
        if (b.name != c.table)
            continue;
        const auto rows = rows_of(b);
        if (rows.size() < 2) {
            l.error = "table " + c.table + " has no rows";
            return l;
        }
        const std::vector<std::string>& header = rows.front();
        size_t column = header.size();
        for (size_t h = 0; h < header.size(); ++h)
            if (header[h] == c.column)
                column = h;
        if (column == header.size()) {
            l.error = "table " + c.table + " has no column '" + c.column + "'";
            return l;
        }
        for (const std::string& t : b.timed)
            l.timed = l.timed || t == c.column;
        for (size_t r = 2; r < rows.size(); ++r) {
            std::string key;
            for (size_t k = 0; k < rows[r].size() && key.size() < c.key.size(); ++k)
                key += (k == 0 ? "" : ", ") + rows[r][k];
            if (key == c.key && column < rows[r].size()) {
                l.value = rows[r][column];
                return l;
            }
        }
        l.error = "table " + c.table + " has no row [" + c.key + "]";
        return l;
    }
    l.error = "no table " + c.table + " among the sweep's";
    return l;
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
    const std::vector<Cell> cells = cells_of(lesson, read_lines(lesson));
    for (const Cell& c : cells) {
        const Lookup l = look_up(code, c);
        const std::string where = lesson.string() + ":" + std::to_string(c.line) + ": the prose's cell " + c.table +
                                  " [" + c.key + "] " + c.column;
        if (!l.error.empty()) {
            std::cout << where << ": " << l.error << '\n';
            ++problems;
        } else if (!l.timed && l.value != c.value) {
            std::cout << where << ": the lesson says " << c.value << ", the code gives " << l.value << '\n';
            ++problems;
        }
    }
    std::cout << lesson.string() << ": " << code.size() << " table(s) and " << cells.size()
              << " cell(s) of prose against the code, " << problems << " difference(s)\n";
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
        // The prose's cells, from the tables as they now stand in the lesson.
        const std::vector<Block> now = blocks_of(lesson, out);
        std::vector<Cell> cells = cells_of(lesson, out);
        // From the end, so that a line's earlier cells keep their place.
        for (auto c = cells.rbegin(); c != cells.rend(); ++c) {
            const Lookup l = look_up(now, *c);
            if (!l.error.empty())
                std::cout << lesson.string() << ":" << c->line << ": the prose's cell " << c->table << " [" << c->key
                          << "] " << c->column << ": " << l.error << ": not refreshed\n";
            else
                out[static_cast<size_t>(c->line - 1)].replace(c->value_at, c->value.size(), l.value);
        }
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
