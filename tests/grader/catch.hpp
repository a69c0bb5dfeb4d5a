// Catch2 v2 or v3, whichever tests/CMakeLists.txt found: Debian 12 ships v2 (one header), Ubuntu
// 24.04, Fedora, Homebrew and vcpkg ship v3 (a library, in many headers). The tests include this
// file, never Catch2's own headers, and use the names below, which mean the same in both.
#pragma once

#include <string>

#ifdef RT_CATCH2_V3

#ifdef TWOBLUECUBES_SINGLE_INCLUDE_CATCH_HPP_INCLUDED
#error "Catch2 v2's catch.hpp was included in a build against Catch2 v3: include tests/grader/catch.hpp instead"
#endif
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/catch_tostring.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

using Catch::Approx;  // v2 put Approx in the global namespace

namespace rt::grader {
inline auto contains_text(const std::string& text) { return Catch::Matchers::ContainsSubstring(text); }
inline auto starts_with_text(const std::string& text) { return Catch::Matchers::StartsWith(text); }
}  // namespace rt::grader

#else

#include <catch2/catch.hpp>

namespace rt::grader {
inline auto contains_text(const std::string& text) { return Catch::Matchers::Contains(text); }
inline auto starts_with_text(const std::string& text) { return Catch::Matchers::StartsWith(text); }
}  // namespace rt::grader

#endif
