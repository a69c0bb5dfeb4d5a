// The kit's two error paths: `assert` for the kit's own assumptions, and an
// InputError for bad input, which the programs turn into one line and exit status 2.
#pragma once

#include <stdexcept>
#include <string>

namespace rt {

struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Exit status for bad input (an unknown flag, an impossible value, a malformed file).
constexpr int exit_bad_input = 2;

// Exit status for a picture with a NaN or infinite pixel: the kit's own bug, not the input's.
constexpr int exit_kit_bug = 3;

}  // namespace rt
