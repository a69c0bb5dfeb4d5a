// What a class did, exercise by exercise: from every student's results files (points.hpp's lines,
// as each chapter's grader wrote them), the share of students at full marks, the mean points and the
// cases most often failed, for the class page and a CSV beside the gradebook (batch grading:
// grade_report --class-page, called by tests/grade_batch.cmake).
#pragma once

#include "tests/grader/points.hpp"

#include <string>
#include <vector>

namespace rt::grader {

// One student's grade as the grader wrote it: every case of every chapter graded, not summarized.
struct StudentResults {
    std::string name;
    std::vector<CaseResult> cases;
};

// A case the class failed: how many students' own code failed it, and the first line of its message
// (the line most of them got; the first student's on a tie).
struct FailedCase {
    std::string name;
    int students = 0;
    std::string first_line;
};

struct ExerciseStats {
    std::string number;       // "01.2"
    int max_score = 0;        // the exercise's points
    int students = 0;         // every student of the class
    int full_marks = 0;       // students with every point of it
    int points = 0;           // the class's points on it, summed: the mean is points / students
    int not_graded = 0;       // students at 0 whose own code never ran in it: the chapter's file is
                              // missing or does not compile, or every case ran a handed-out stub
    std::vector<FailedCase> most_failed;  // at most three, most students first
};

// Reads each student's results files (any that do not exist are skipped; false when one cannot be
// read as results).
bool read_student_results(const std::string& name, const std::vector<std::string>& paths, StudentResults& student);

// Every exercise any student's results name, in the kit's order (01.2 before 01.10, the agreement
// and picture cases after the numbered ones). A student who has no case of an exercise, or whose
// chapter did not compile or is missing (an NN.build line), counts at 0 points for it. A case counts
// as failed only when the student's own code ran in it: a failed case that ran a handed-out stub,
// or that stands for a missing or non-compiling chapter, says nothing of what the class got wrong.
std::vector<ExerciseStats> class_stats(const std::vector<StudentResults>& students);

// The mean points, points / students, rounded half up to hundredths: "12.67" (kept to integers so
// every reader gets the same digits).
std::string mean_points(const ExerciseStats& stats);

// exercise,max,students,full_marks,mean,not_graded, then for each of three failed cases its name,
// how many students failed it and its message's first line (empty when fewer failed).
bool write_exercises_csv(const std::string& path, const std::vector<ExerciseStats>& stats);

// The class page's second table: an exercise a row, with its share at full marks, its mean, the
// students not graded on it and the cases most often failed, each with its message's first line.
std::string exercises_table_html(const std::vector<ExerciseStats>& stats);

// A leaderboard: the students ranked by a measure their results carry (an open exercise's cost,
// graded.hpp's report_measure), lower first, ties by name. Only a correct answer reports one, so
// only students past the exercise's gate are ranked.
enum class LeaderboardNames { names, pseudonyms };

struct LeaderboardEntry {
    std::string student;    // the folder's name
    std::string shown;      // what the shared leaderboard says: the name, or its pseudonym
    double value = 0.0;
};

struct Leaderboard {
    std::string measure;     // "10.7 cost"
    double reference = 0.0;  // the reference solution's value
    std::vector<LeaderboardEntry> ranked;
};

// A student's pseudonym on a shared leaderboard: a word and four hex digits from a hash of `key`
// and the name, so the same key gives the same pseudonyms at every regrade. Without a key of the
// instructor's own, anyone holding the class list could work them out.
std::string pseudonym_of(const std::string& student, const std::string& key);

std::vector<Leaderboard> class_leaderboards(const std::vector<StudentResults>& students, LeaderboardNames names,
                                            const std::string& key);

// The leaderboards as HTML tables: rank, who (as shown; with `with_names` also the student's own
// name beside a pseudonym, for the instructor's page) and the value against the reference's.
std::string leaderboards_html(const std::vector<Leaderboard>& boards, bool with_names);

}  // namespace rt::grader
