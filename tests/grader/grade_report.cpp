// Merges the per-chapter results of a grading run into one points table and the files a course
// platform reads.
//
//   grade_report --json results.json --junit junit.xml [--html report.html [--title T]] RESULTS...
//
// A chapter that did not compile comes as a line numbered NN.build, saying why, and its cases
// listed at 0 of their points; the report shows it as one line worth all of them, so the maximum is
// the same for every student (summary.hpp). So is a chapter still the handed-out stubs, and an
// exercise still its stub.
//
// A missing results file is named, and the report still covers the others. With --gradebook FILE --student NAME it also appends the
// student's points per chapter to a CSV gradebook, and with --class-row FILE a row of the class
// page (batch grading): the student's points per chapter, each marked with what went wrong there.
// With --classroom-output FILE it appends GitHub Classroom's `result=` line to a step's output
// file, and with --step-summary FILE the points as Markdown to the job's summary (classroom.hpp).
//
// After a batch, the class page and what the class did per exercise (class_stats.hpp):
//
//   grade_report --class-page class.html --class-rows ROWS --link-gradebook gradebook.csv
//                --exercises-csv exercises.csv [--leaderboard names|pseudonyms [--pseudonym-key KEY]]
//                [--leaderboard-page leaderboard.html] STUDENT_FOLDER...
//
// Each student's folder (named after the student) holds their chapters' results files (NN.results);
// ROWS is the students' table that --class-row appended to; the page links both CSV files.
#include "tests/grader/class_stats.hpp"
#include "tests/grader/classroom.hpp"
#include "tests/grader/html_report.hpp"
#include "tests/grader/points.hpp"
#include "tests/grader/summary.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <sstream>
#include <vector>

namespace {

// The class page and the exercises' CSV from every student's folder of results files.
int write_class(const std::string& page, const std::string& rows_path, const std::string& gradebook,
                const std::string& exercises_csv, const std::vector<std::string>& folders,
                rt::grader::LeaderboardNames names, const std::string& key, const std::string& leaderboard_page)
{
    using namespace rt::grader;
    namespace fs = std::filesystem;
    std::vector<StudentResults> students;
    for (const std::string& folder : folders) {
        std::vector<std::string> files;
        std::error_code error;
        for (const fs::directory_entry& entry : fs::directory_iterator(folder, error))
            if (entry.path().extension() == ".results")
                files.push_back(entry.path().string());
        if (error)
            return std::cerr << "grade_report: " << folder << ": cannot list its results files\n", 2;
        std::sort(files.begin(), files.end());
        StudentResults student;
        if (!read_student_results(fs::path(folder).lexically_normal().filename().string(), files, student))
            return std::cerr << "grade_report: " << folder << ": a results file cannot be read\n", 2;
        students.push_back(student);
    }
    const std::vector<ExerciseStats> stats = class_stats(students);
    if (!exercises_csv.empty()) {
        if (!write_exercises_csv(exercises_csv, stats))
            return std::cerr << "grade_report: " << exercises_csv << ": cannot write\n", 2;
        std::cout << "wrote " << exercises_csv << '\n';
    }
    std::ostringstream rows;
    if (std::ifstream in{rows_path})
        rows << in.rdbuf();
    const std::vector<Leaderboard> boards = class_leaderboards(students, names, key);
    const std::string shared = boards.empty() ? "" : leaderboard_page;
    if (!shared.empty()) {
        if (!write_leaderboard_page(shared, boards))
            return std::cerr << "grade_report: " << shared << ": cannot write\n", 2;
        std::cout << "wrote " << shared << '\n';
    }
    if (!write_class_page(page, rows.str(), stats, gradebook, exercises_csv, boards, shared))
        return std::cerr << "grade_report: " << page << ": cannot write\n", 2;
    std::cout << "wrote " << page << '\n';
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    using namespace rt::grader;
    std::string json, junit, gradebook, student, html, class_row, title = "Grade", classroom_output, step_summary;
    std::string class_page, class_rows, link_gradebook, exercises_csv, pseudonym_key, leaderboard_page;
    rt::grader::LeaderboardNames leaderboard_names = rt::grader::LeaderboardNames::names;
    std::vector<std::string> inputs;
    for (int k = 1; k < argc; ++k) {
        const std::string arg = argv[k];
        if (arg == "--json" && k + 1 < argc)
            json = argv[++k];
        else if (arg == "--junit" && k + 1 < argc)
            junit = argv[++k];
        else if (arg == "--gradebook" && k + 1 < argc)
            gradebook = argv[++k];
        else if (arg == "--student" && k + 1 < argc)
            student = argv[++k];
        else if (arg == "--html" && k + 1 < argc)
            html = argv[++k];
        else if (arg == "--class-row" && k + 1 < argc)
            class_row = argv[++k];
        else if (arg == "--title" && k + 1 < argc)
            title = argv[++k];
        else if (arg == "--classroom-output" && k + 1 < argc)
            classroom_output = argv[++k];
        else if (arg == "--step-summary" && k + 1 < argc)
            step_summary = argv[++k];
        else if (arg == "--class-page" && k + 1 < argc)
            class_page = argv[++k];
        else if (arg == "--class-rows" && k + 1 < argc)
            class_rows = argv[++k];
        else if (arg == "--link-gradebook" && k + 1 < argc)
            link_gradebook = argv[++k];
        else if (arg == "--exercises-csv" && k + 1 < argc)
            exercises_csv = argv[++k];
        else if (arg == "--leaderboard" && k + 1 < argc) {
            const std::string how = argv[++k];
            if (how != "names" && how != "pseudonyms")
                return std::cerr << "grade_report: --leaderboard takes names or pseudonyms, got '" << how << "'\n", 2;
            leaderboard_names = how == "names" ? rt::grader::LeaderboardNames::names : rt::grader::LeaderboardNames::pseudonyms;
        } else if (arg == "--pseudonym-key" && k + 1 < argc)
            pseudonym_key = argv[++k];
        else if (arg == "--leaderboard-page" && k + 1 < argc)
            leaderboard_page = argv[++k];
        else if (arg.rfind("--", 0) == 0) {
            std::cerr << "grade_report: unknown option '" << arg << "'\n";
            return 2;
        } else
            inputs.push_back(arg);
    }
    if (!class_page.empty())
        return write_class(class_page, class_rows, link_gradebook, exercises_csv, inputs, leaderboard_names, pseudonym_key,
                           leaderboard_page);
    std::vector<CaseResult> results;
    int missing = 0;
    for (const std::string& path : inputs)
        if (!read_results(path, results)) {
            std::cerr << "grade_report: " << path << ": no results (did that chapter's grader crash?)\n";
            ++missing;
        }
    // A chapter that did not compile or is untouched, and an exercise still its stub: one line each.
    const std::vector<CaseResult> cases = results;
    results = summarize(results);
    print_points_table(std::cout, results, cases);
    int score = 0, max_score = 0;
    for (const CaseResult& r : results) {
        score += r.score;
        max_score += r.max_score;
    }
    std::cout << "  total" << std::setw(20) << score << " / " << max_score << '\n';
    if (!json.empty()) {
        if (!write_gradescope_json(json, results, case_output_html))
            return std::cerr << "grade_report: " << json << ": cannot write\n", 2;
        std::cout << "wrote " << json << '\n';
    }
    if (!junit.empty()) {
        if (!write_junit_xml(junit, results))
            return std::cerr << "grade_report: " << junit << ": cannot write\n", 2;
        std::cout << "wrote " << junit << '\n';
    }
    if (!html.empty()) {
        if (!write_html_report(html, student.empty() ? title : student, results))
            return std::cerr << "grade_report: " << html << ": cannot write\n", 2;
        std::cout << "wrote " << html << '\n';
    }
    if (!gradebook.empty()) {
        if (!append_gradebook_row(gradebook, student, results))
            return std::cerr << "grade_report: " << gradebook << ": cannot write\n", 2;
        std::cout << "added " << student << " to " << gradebook << '\n';
    }
    if (!class_row.empty()) {
        if (!append_class_row(class_row, student, chapter_marks(results)))
            return std::cerr << "grade_report: " << class_row << ": cannot write\n", 2;
    }
    if (!classroom_output.empty() && !append_classroom_output(classroom_output, results))
        return std::cerr << "grade_report: " << classroom_output << ": cannot write\n", 2;
    if (!step_summary.empty() && !append_step_summary(step_summary, results))
        return std::cerr << "grade_report: " << step_summary << ": cannot write\n", 2;
    return missing == 0 ? 0 : 1;
}
