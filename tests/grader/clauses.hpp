// A chapter's clause table (tests/chNN/CLAUSES.md) read against its grader: each clause of an
// exercise's contract (a comparison, a precision, an integer range, a NaN/infinity/-0 rule, a tie
// rule, a count) and the graded cases that sit exactly on it, as a table row
//
//   | a count of 0 or less gives 1 x 1 x 1 | `no objects give one cell` |
//
// under a heading `## NN.k name`. The check: every exercise with graded cases has a section, every
// clause names at least one case, and every case named is one of the grader's, spelled exactly.
#pragma once

#include <string>
#include <vector>

namespace rt::grader {

struct GradedCase {
    std::string number;  // "07.5"
    std::string name;
};

// What is wrong with the table at `path`, one line each ("FILE:LINE: what"); empty when nothing.
std::vector<std::string> check_clause_table(const std::string& path, const std::vector<GradedCase>& cases);

}  // namespace rt::grader
