// The hints a student opens on purpose, one tier at a time:
//
//   hint NN.k [TIER]         tier TIER (1 by default) of exercise NN.k's hints: 1 the idea, 2 the
//                            trap the grader checks, 3 the walk-through
//   hint NN                  the exercises of chapter NN that have hints, and how many tiers
//   hint --check [TIERS]     (the kit's test) every exercise marked `EXERCISE NN.k` in exercises/
//                            has tiers 1..TIERS (3 by default) in its chapter's hints.md, and no more
//   --kit DIR                the kit's folder (default: the one this program was built from)
//
// The hints live in chapters/NN_name/hints.md, a section `## NN.k ...` per exercise holding its
// tiers as folded sections, `<details><summary>NN.k, tier T: ...</summary>` ... `</details>`, so a
// browser shows them folded too. A handout may carry fewer tiers (tests/handout.cmake).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Tier {
    std::string title, text;
};

// exercise "07.4" -> its tiers, by number.
using Hints = std::map<std::string, std::map<int, Tier>>;

std::string read_text(const fs::path& path)
{
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

fs::path chapter_folder(const fs::path& kit, const std::string& nn)
{
    std::error_code e;
    for (const auto& entry : fs::directory_iterator(kit / "chapters", e))
        if (entry.is_directory() && entry.path().filename().string().rfind(nn + "_", 0) == 0)
            return entry.path();
    return {};
}

Hints read_hints(const fs::path& file)
{
    Hints hints;
    const std::string text = read_text(file);
    static const std::regex tier(R"(<details><summary>(\d\d\.\w+), tier (\d): ([^<]*)</summary>([\s\S]*?)</details>)");
    for (auto m = std::sregex_iterator(text.begin(), text.end(), tier); m != std::sregex_iterator(); ++m) {
        std::string body = (*m)[4];
        body.erase(0, body.find_first_not_of('\n'));
        body.erase(body.find_last_not_of('\n') + 1);
        hints[(*m)[1]][std::stoi((*m)[2])] = Tier{(*m)[3], body};
    }
    return hints;
}

// The exercises a chapter's student file marks, in order: "// EXERCISE 07.4: ..." (once each).
std::vector<std::string> exercises_of(const fs::path& kit)
{
    std::vector<std::string> found;
    static const std::regex marker(R"(// EXERCISE (\d\d\.\w+))");
    std::error_code e;
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(kit / "exercises", e))
        if (entry.path().extension() == ".cpp")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) {
        const std::string text = read_text(f);
        for (auto m = std::sregex_iterator(text.begin(), text.end(), marker); m != std::sregex_iterator(); ++m)
            if (std::find(found.begin(), found.end(), (*m)[1]) == found.end())
                found.push_back((*m)[1]);
    }
    return found;
}

int check(const fs::path& kit, int tiers)
{
    int problems = 0, checked = 0;
    for (const std::string& exercise : exercises_of(kit)) {
        ++checked;
        const fs::path folder = chapter_folder(kit, exercise.substr(0, 2));
        const fs::path file = folder / "hints.md";
        const bool exists = fs::exists(file);
        const Hints hints = exists ? read_hints(file) : Hints{};
        if (tiers > 0 && !exists) {
            std::cout << exercise << ": no " << file.string() << '\n';
            ++problems;
            continue;
        }
        const auto at = hints.find(exercise);
        for (int t = 1; t <= 3; ++t) {
            const bool has = at != hints.end() && at->second.count(t) && !at->second.at(t).text.empty();
            if (has != (t <= tiers)) {
                std::cout << exercise << ": tier " << t << (has ? " is there, but this kit should have " : " is missing; this kit should have ")
                          << tiers << " tier(s)\n";
                ++problems;
            }
        }
    }
    std::cout << checked << " exercises, " << tiers << " tier(s) each expected: " << problems << " problem(s)\n";
    return problems == 0 && checked > 0 ? 0 : 1;
}

// A tier number, 0 to 3; -1 for anything else ("x", "7", "2a").
int tier_of(const std::string& text)
{
    return text.size() == 1 && text[0] >= '0' && text[0] <= '3' ? text[0] - '0' : -1;
}

int usage()
{
    std::cerr << "usage: hint NN.k [TIER] | hint NN | hint --check [TIERS]  [--kit DIR]\n";
    return 2;
}

}  // namespace

int main(int argc, char** argv)
{
    std::vector<std::string> args;
#ifdef RT_KIT_DIR
    fs::path kit = RT_KIT_DIR;
#else
    fs::path kit = ".";
#endif
    for (int k = 1; k < argc; ++k) {
        const std::string a = argv[k];
        if (a == "--kit" && k + 1 < argc)
            kit = argv[++k];
        else
            args.push_back(a);
    }
    if (args.empty())
        return usage();
    if (args[0] == "--check") {
        const int tiers = args.size() > 1 ? tier_of(args[1]) : 3;
        if (tiers < 0) {
            std::cerr << "hint: --check takes a number of tiers from 0 to 3, got '" << args[1] << "'\n";
            return 2;
        }
        return check(kit, tiers);
    }

    const std::string exercise = args[0];
    if (!std::regex_match(exercise, std::regex(R"(\d\d(\.\w+)?)")))
        return usage();
    const fs::path folder = chapter_folder(kit, exercise.substr(0, 2));
    const fs::path file = folder / "hints.md";
    if (folder.empty() || !fs::exists(file)) {
        std::cerr << "hint: chapter " << exercise.substr(0, 2) << " has no hints in this kit ("
                  << (folder.empty() ? (kit / "chapters").string() : file.string()) << ")\n";
        return 2;
    }
    const Hints hints = read_hints(file);
    if (exercise.size() == 2) {
        for (const auto& [name, tiers] : hints)
            if (name.rfind(exercise, 0) == 0)
                std::cout << name << ": " << tiers.size() << " tier(s)   hint " << name << '\n';
        return 0;
    }
    const auto at = hints.find(exercise);
    if (at == hints.end()) {
        std::cerr << "hint: no hints for " << exercise << " in " << file.string() << " (hint " << exercise.substr(0, 2)
                  << " lists them)\n";
        return 2;
    }
    const int tier = args.size() > 1 ? tier_of(args[1]) : 1;
    const auto t = at->second.find(tier);
    if (t == at->second.end()) {
        std::cerr << "hint: " << exercise << " has tier(s) 1 to " << at->second.rbegin()->first << " here, not " << args[1]
                  << '\n';
        return 2;
    }
    std::cout << exercise << ", tier " << tier << ": " << t->second.title << "\n\n" << t->second.text << "\n\n";
    if (at->second.count(tier + 1))
        std::cout << "(still stuck? hint " << exercise << ' ' << tier + 1 << ": " << at->second.at(tier + 1).title << ")\n";
    return 0;
}
