// The kit's maintenance tool, five verbs:
//
//   kit_tool cut SOLUTION EXERCISE        write the exercise file cut from an annotated solution
//   kit_tool trace SOLUTION OUT           the solution, each exercise noting that it ran (below)
//   kit_tool check-cut SOLUTION EXERCISE  exit 1 (saying where) when EXERCISE is not what cut makes
//   kit_tool mutate MUTANT SOLUTION OUT   apply a mutant (a common mistake) to a solution
//   kit_tool share SOLUTION               how much of each exercise's solution its stub's comments
//                                         already spell out (below)
//
// Cutting: the lines from `// SOLUTION BEGIN` to `// SOLUTION END` are dropped, and a line
// `// STUB text` becomes `text` at the same indentation. So an exercise cannot drift from its
// solution: both come from one file, as Crafting Interpreters cuts its chapters from one tree.
//
// A mutant file: `#` comment lines saying what mistake it is, then one or more pairs of blocks,
// `---` followed by lines to find in the solution (exactly once) and `+++` followed by the lines
// that replace them.
#include <cctype>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Failure {
    std::string message;
};

std::vector<std::string> read_lines(const std::string& path)
{
    std::ifstream in(path);
    if (!in)
        throw Failure{path + ": cannot read the file"};
    std::vector<std::string> lines;
    std::string line;
    while (std::getline(in, line))
        lines.push_back(line);
    return lines;
}

std::string join(const std::vector<std::string>& lines)
{
    std::string text;
    for (const std::string& l : lines)
        text += l + '\n';
    return text;
}

void write_text(const std::string& path, const std::string& text)
{
    std::ofstream out(path);
    out << text;
    if (!out)
        throw Failure{path + ": cannot write the file"};
}

std::string trim_left(const std::string& s, std::string* indent = nullptr)
{
    const size_t k = s.find_first_not_of(" \t");
    if (indent)
        *indent = s.substr(0, k == std::string::npos ? s.size() : k);
    return k == std::string::npos ? "" : s.substr(k);
}

std::string cut(const std::string& solution_path)
{
    const std::vector<std::string> lines = read_lines(solution_path);
    std::vector<std::string> out;
    bool in_solution = false;
    size_t begin_line = 0;
    for (size_t k = 0; k < lines.size(); ++k) {
        std::string indent;
        const std::string text = trim_left(lines[k], &indent);
        const std::string where = solution_path + ":" + std::to_string(k + 1) + ": ";
        if (text == "// SOLUTION BEGIN") {
            if (in_solution)
                throw Failure{where + "SOLUTION BEGIN inside another SOLUTION block"};
            in_solution = true;
            begin_line = k + 1;
        } else if (text == "// SOLUTION END") {
            if (!in_solution)
                throw Failure{where + "SOLUTION END without a SOLUTION BEGIN"};
            in_solution = false;
        } else if (in_solution) {
            continue;
        } else if (text.rfind("// STUB", 0) == 0) {
            const std::string rest = text.substr(7);
            if (!rest.empty() && rest[0] != ' ')
                throw Failure{where + "write `// STUB ` followed by the stub's code"};
            out.push_back(rest.empty() ? "" : indent + rest.substr(1));
        } else {
            out.push_back(lines[k]);
        }
    }
    if (in_solution)
        throw Failure{solution_path + ":" + std::to_string(begin_line) + ": SOLUTION BEGIN is never closed"};
    return join(out);
}

// Tracing: the solution whole, its cutting marks kept as comments, with a call
// `rt::note_stub("NN.k")` opening the first SOLUTION block after each `// EXERCISE NN.k` mark. A
// grader built on traced solutions then lists, per case, every exercise the case ran, of every
// chapter (the stubs field of its results): what a chapter's lesson says its cases need.
std::string trace(const std::string& solution_path)
{
    const std::vector<std::string> lines = read_lines(solution_path);
    std::vector<std::string> out = {"#include \"common/stub.hpp\"  // (traced: rt::note_stub)"};
    std::string exercise;  // the last EXERCISE mark not yet traced
    for (const std::string& line : lines) {
        std::string indent;
        const std::string text = trim_left(line, &indent);
        out.push_back(line);
        if (text.rfind("// EXERCISE ", 0) == 0) {
            const size_t end = text.find_first_of(": ", 12);
            exercise = text.substr(12, end == std::string::npos ? std::string::npos : end - 12);
        } else if (text == "// SOLUTION BEGIN" && !indent.empty() && !exercise.empty()) {
            out.push_back(indent + "rt::note_stub(\"" + exercise + "\");");
            exercise.clear();
        }
    }
    return join(out);
}

void check_cut(const std::string& solution_path, const std::string& exercise_path)
{
    const std::string expected = cut(solution_path);
    const std::string actual = join(read_lines(exercise_path));
    if (expected == actual)
        return;
    std::istringstream e(expected), a(actual);
    std::string el, al;
    int line = 1;
    while (true) {
        const bool more_e = static_cast<bool>(std::getline(e, el));
        const bool more_a = static_cast<bool>(std::getline(a, al));
        if (!more_e && !more_a)
            break;
        if (!more_e || !more_a || el != al)
            throw Failure{exercise_path + ":" + std::to_string(line) + ": differs from what " + solution_path +
                          " cuts (expected \"" + (more_e ? el : "<end of file>") + "\"); regenerate it with the "
                          "`cut_exercises` target"};
        ++line;
    }
}

void mutate(const std::string& mutant_path, const std::string& solution_path, const std::string& out_path)
{
    const std::vector<std::string> lines = read_lines(mutant_path);
    std::string text = join(read_lines(solution_path));
    std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>> hunks;
    std::vector<std::string>* block = nullptr;
    for (size_t k = 0; k < lines.size(); ++k) {
        if (lines[k] == "---") {
            hunks.emplace_back();
            block = &hunks.back().first;
        } else if (lines[k] == "+++") {
            if (hunks.empty())
                throw Failure{mutant_path + ":" + std::to_string(k + 1) + ": +++ before any ---"};
            block = &hunks.back().second;
        } else if (block) {
            block->push_back(lines[k]);
        } else if (!lines[k].empty() && lines[k][0] != '#') {
            throw Failure{mutant_path + ":" + std::to_string(k + 1) + ": expected a # comment or ---"};
        }
    }
    if (hunks.empty())
        throw Failure{mutant_path + ": no --- block: the mutant changes nothing"};
    for (const auto& [find, replace] : hunks) {
        const std::string from = join(find), to = join(replace);
        const size_t at = text.find(from);
        if (from.empty() || at == std::string::npos)
            throw Failure{mutant_path + ": its --- lines are not in " + solution_path + " (the solution changed?)"};
        if (text.find(from, at + 1) != std::string::npos)
            throw Failure{mutant_path + ": its --- lines stand more than once in " + solution_path};
        text.replace(at, from.size(), to);
    }
    write_text(out_path, text);
}

// The tokens of C++ code or of a comment: names, numbers and single punctuation characters, less
// those that say nothing of the answer (declarations' types, `std`, `;` and braces).
std::vector<std::string> tokens(const std::string& text)
{
    static const std::set<std::string> ignored = {"const", "auto", "float", "int", "bool", "double", "std", "return",
                                                  "static_cast", ";", "{", "}", ":"};
    std::vector<std::string> out;
    for (size_t k = 0; k < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[k]);
        size_t end = k + 1;
        if (std::isalpha(c) || c == '_')
            while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_'))
                ++end;
        else if (std::isdigit(c))
            while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '.'))
                ++end;
        else if (std::isspace(c)) {
            ++k;
            continue;
        }
        const std::string t = text.substr(k, end - k);
        if (!ignored.count(t))
            out.push_back(t);
        k = end;
    }
    return out;
}

std::set<std::string> shingles(const std::vector<std::string>& t, size_t n)
{
    std::set<std::string> out;
    for (size_t k = 0; k + n <= t.size(); ++k) {
        std::string s;
        for (size_t j = 0; j < n; ++j)
            s += t[k + j] + ' ';
        out.insert(s);
    }
    return out;
}

// For each exercise: the share of its solution's code fragments (runs of 3 tokens) that stand in its
// stub's comments, the comment lines from `// EXERCISE NN.k` to `// SOLUTION BEGIN`; and the same
// for every exercise of the file together. A stub that states only the contract shares little; one
// that lists the code to type shares most of it.
void share(const std::string& solution_path)
{
    const std::vector<std::string> lines = read_lines(solution_path);
    std::string exercise, comments, code;
    bool in_stub = false, in_solution = false;
    size_t all_fragments = 0, all_shared = 0;
    const auto report = [&] {
        const std::set<std::string> said = shingles(tokens(comments), 3), done = shingles(tokens(code), 3);
        size_t shared = 0;
        for (const std::string& f : done)
            shared += said.count(f);
        all_fragments += done.size();
        all_shared += shared;
        std::cout << "  " << exercise << std::setw(5) << (done.empty() ? 0 : 100 * shared / done.size()) << "%  (" << shared
                  << " of " << done.size() << " fragments)\n";
    };
    for (const std::string& line : lines) {
        const std::string text = trim_left(line);
        if (text.rfind("// EXERCISE ", 0) == 0) {
            exercise = text.substr(12, text.find_first_of(": ", 12) - 12);
            comments.clear();
            code.clear();
            in_stub = true;
        }
        if (text == "// SOLUTION BEGIN") {
            in_stub = false;
            in_solution = true;
        } else if (text == "// SOLUTION END") {
            in_solution = false;
            if (!exercise.empty())
                report();
            exercise.clear();
        } else if (in_stub && text.rfind("//", 0) == 0) {
            comments += text.substr(2) + '\n';
        } else if (in_solution && text.rfind("//", 0) != 0) {
            code += text.substr(0, text.find("//")) + '\n';
        }
    }
    std::cout << "  all  " << std::setw(5) << (all_fragments ? 100 * all_shared / all_fragments : 0) << "%  (" << all_shared
              << " of " << all_fragments << " fragments)\n";
}

}  // namespace

int main(int argc, char** argv)
{
    const std::vector<std::string> args(argv + 1, argv + argc);
    try {
        if (args.size() == 3 && args[0] == "cut")
            write_text(args[2], cut(args[1]));
        else if (args.size() == 3 && args[0] == "trace")
            write_text(args[2], trace(args[1]));
        else if (args.size() == 3 && args[0] == "check-cut")
            check_cut(args[1], args[2]);
        else if (args.size() == 4 && args[0] == "mutate")
            mutate(args[1], args[2], args[3]);
        else if (args.size() == 2 && args[0] == "share")
            share(args[1]);
        else {
            std::cerr << "usage: kit_tool cut SOLUTION EXERCISE | trace SOLUTION OUT | check-cut SOLUTION EXERCISE | "
                         "mutate MUTANT SOLUTION OUT | share SOLUTION\n";
            return 2;
        }
    } catch (const Failure& f) {
        std::cerr << f.message << '\n';
        return 1;
    }
    return 0;
}
