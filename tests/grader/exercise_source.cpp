// Compiled into each student's grader (grade_NN) with the files it is built from, joined by '|'
// (RT_GRADED_SOURCES), and the command that rebuilds it (freshness.hpp).
#include "tests/grader/freshness.hpp"

#include <string>
#include <vector>

namespace {

std::vector<std::string> split(const std::string& joined)
{
    std::vector<std::string> parts;
    std::string::size_type from = 0;
    for (std::string::size_type bar; (bar = joined.find('|', from)) != std::string::npos; from = bar + 1)
        parts.push_back(joined.substr(from, bar - from));
    parts.push_back(joined.substr(from));
    return parts;
}

const bool registered = rt::grader::register_exercise_sources(split(RT_GRADED_SOURCES),
    {RT_CMAKE_COMMAND, "--build", RT_BUILD_DIR, "--target", RT_GRADER_TARGET, "--config", RT_CONFIG});

}  // namespace
