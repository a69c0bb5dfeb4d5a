// Reading a decimal number from text, the same on every standard library.
//
// std::from_chars reads doubles in libstdc++ (GCC 11+) and MSVC, but not in libc++ before LLVM 20
// (Apple clang): there the kit checks the same grammar itself and converts with strtod, which is
// correctly rounded like from_chars and, with the "C" locale the kit never changes, reads the same
// digits. Both paths are always compiled, and a test holds them to the same answers.
#pragma once

#include <string_view>

namespace rt {

enum class NumberStatus { ok, not_a_number, out_of_range };

// Parses the whole of `text` as a decimal number: "%g" forms ("-1.5", ".5", "2.", "1e-3", "+4"),
// and the words "nan" and "inf", which a caller refuses by name. out_of_range: beyond a double's
// range, or so small that it rounds to zero. `value` is set only when the answer is ok.
NumberStatus parse_double(std::string_view text, double& value);

// The same answers, by the kit's own grammar check and strtod: what parse_double uses where the
// standard library has no floating-point from_chars.
NumberStatus parse_double_portable(std::string_view text, double& value);

}  // namespace rt
