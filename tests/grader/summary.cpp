#include "tests/grader/summary.hpp"

#include "common/words.hpp"

#include <algorithm>
#include <iterator>
#include <map>
#include <sstream>

namespace rt::grader {

namespace {

bool ran_stub(const CaseResult& r, const std::string& exercise)
{
    std::istringstream words(r.stubs);
    std::string w;
    while (words >> w)
        if (w == exercise)
            return true;
    return false;
}

// "07.1 07.3 07.4" as "07.1, 07.3 and 07.4".
std::string in_words(const std::string& list)
{
    std::istringstream words(list);
    return join_words({std::istream_iterator<std::string>(words), std::istream_iterator<std::string>()}, ", ", " and ");
}

std::string grep_hint(const std::string& exercise)
{
    return "grep -n \"EXERCISE " + exercise + "\" exercises/*.cpp";
}

// A case numbered by a letter is no exercise of the student's file, so its line says what it is
// (the lessons' points tables say it at length).
std::string case_in_words(const std::string& number)
{
    if (number.size() == 4 && number[3] == 'A')
        return number + " (your whole structure against brute force)";
    if (number.size() == 4 && number[3] == 'P')
        return number + " (the chapter's figure against the reference)";
    return number;
}

const std::string untouched_words = " is still the handed-out stubs";
const std::string stub_words = " is still the handed-out stub";

}  // namespace

std::string stub_verdict(const CaseResult& r)
{
    if (r.passed() || r.stubs.empty())
        return "";
    if (ran_stub(r, r.number))
        return r.number + stub_words;
    const bool several = r.stubs.find(' ') != std::string::npos;
    return case_in_words(r.number) + " cannot be graded yet: it runs " + in_words(r.stubs) + (several ? ", which are" : ", which is") +
           stub_words.substr(3) + (several ? "s" : "");
}

bool rests_on_earlier_stub(const CaseResult& r)
{
    std::istringstream words(r.stubs);
    std::string w;
    while (words >> w)
        if (chapter_of(w) < chapter_of(r.number))
            return true;
    return false;
}

std::vector<CaseResult> summarize(const std::vector<CaseResult>& results)
{
    // Chapters in the order they came, each with its cases.
    std::vector<std::string> order;
    std::map<std::string, std::vector<CaseResult>> cases;
    std::map<std::string, CaseResult> builds;
    for (const CaseResult& r : results) {
        const std::string nn = chapter_of(r.number);
        if (!cases.count(nn) && !builds.count(nn))
            order.push_back(nn);
        if (is_build_line(r))
            builds[nn] = r;
        else
            cases[nn].push_back(r);
    }
    std::vector<CaseResult> out;
    for (const std::string& nn : order) {
        const std::vector<CaseResult>& chapter = cases[nn];
        int max_score = 0, score = 0;
        // (Graded one exercise alone, the chapter is that exercise: no chapter line.)
        bool every_case_on_stubs = !chapter.empty() && std::any_of(chapter.begin(), chapter.end(), [&](const CaseResult& r) {
                                       return r.number != chapter.front().number;
                                   });
        for (const CaseResult& r : chapter) {
            max_score += r.max_score;
            score += r.score;
            every_case_on_stubs = every_case_on_stubs && !r.passed() && !r.stubs.empty();
        }
        if (builds.count(nn)) {
            CaseResult line = builds[nn];
            line.number = nn;
            line.max_score = max_score;
            line.score = 0;
            out.push_back(line);
            continue;
        }
        if (every_case_on_stubs) {
            CaseResult line;
            line.number = nn;
            line.name = "chapter " + nn + untouched_words;
            line.status = CaseStatus::untouched;
            line.max_score = max_score;
            line.output = "every case ran a stub you were handed; start with " + grep_hint(nn + ".1");
            out.push_back(line);
            continue;
        }
        // An exercise still its stub, or waiting for one: its failing cases become one line,
        // where the first of them was.
        std::map<std::string, size_t> stub_line;  // exercise -> index in out
        for (const CaseResult& r : chapter) {
            const std::string verdict = stub_verdict(r);
            if (verdict.empty()) {
                out.push_back(r);
                continue;
            }
            const auto at = stub_line.find(r.number);
            if (at != stub_line.end()) {
                CaseResult& line = out[at->second];
                line.max_score += r.max_score;
                if (ran_stub(r, r.number)) {  // its own stub outranks another's
                    line.name = verdict;
                    line.status = CaseStatus::stub;
                }
                continue;
            }
            CaseResult line;
            line.number = r.number;
            line.name = verdict;
            line.status = ran_stub(r, r.number) ? CaseStatus::stub : CaseStatus::waits_for_stub;
            line.max_score = r.max_score;
            line.stubs = r.stubs;
            line.output = "to find it: " + grep_hint(r.stubs.substr(0, r.stubs.find(' '))) +
                          "; to start: ./build/grade/hint " + r.stubs.substr(0, r.stubs.find(' '));
            stub_line[r.number] = out.size();
            out.push_back(line);
        }
    }
    return out;
}

std::vector<ChapterMark> chapter_marks(const std::vector<CaseResult>& summarized)
{
    std::vector<ChapterMark> marks;
    std::vector<std::vector<std::string>> words;  // each chapter's marks
    for (const CaseResult& r : summarized) {
        const std::string nn = chapter_of(r.number);
        if (marks.empty() || marks.back().chapter != nn) {
            marks.push_back(ChapterMark{nn, 0, 0, ""});
            words.emplace_back();
        }
        ChapterMark& m = marks.back();
        m.score += r.score;
        m.max_score += r.max_score;
        switch (r.status) {
        case CaseStatus::no_file: words.back().push_back("no file"); break;
        case CaseStatus::untouched: words.back().push_back("untouched"); break;
        case CaseStatus::does_not_compile: words.back().push_back("does not compile"); break;
        case CaseStatus::stub: words.back().push_back("stub " + r.number); break;
        case CaseStatus::stopped: words.back().push_back("stopped " + r.number); break;
        case CaseStatus::crashed: words.back().push_back("crashed " + r.number); break;
        case CaseStatus::passed:
        case CaseStatus::failed:
        case CaseStatus::waits_for_stub: break;
        }
    }
    for (size_t k = 0; k < marks.size(); ++k)
        marks[k].marks = join_words(words[k], ", ");
    return marks;
}

}  // namespace rt::grader
