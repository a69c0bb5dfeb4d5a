// A grading run as a web page: the points per chapter and per case, each failed case's message,
// and for a picture case the expected, actual and difference images side by side. The images are
// embedded (data URIs), so the page can be copied, mailed or uploaded whole.
#pragma once

#include "tests/grader/points.hpp"

#include <string>
#include <vector>

namespace rt::grader {

bool write_html_report(const std::string& path, const std::string& title, std::vector<CaseResult> results);

}  // namespace rt::grader
