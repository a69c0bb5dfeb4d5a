// Compiled into each student's grader (grade_NN) with the exercise file it grades and the command
// that rebuilds it (freshness.hpp).
#include "tests/grader/freshness.hpp"

namespace {

const bool registered = rt::grader::register_exercise_source(
    RT_EXERCISE_SOURCE, {RT_CMAKE_COMMAND, "--build", RT_BUILD_DIR, "--target", RT_GRADER_TARGET, "--config", RT_CONFIG});

}  // namespace
