#include "common/number.hpp"
#include "tests/grader/graded.hpp"

#include <charconv>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

using namespace rt;

namespace {

const char* status_name(NumberStatus s)
{
    return s == NumberStatus::ok ? "ok" : s == NumberStatus::not_a_number ? "not a number" : "out of range";
}

// Tokens at every corner of from_chars' grammar: signs, points, exponents, the words, hexadecimal
// (not a decimal form), and values at the ends of a double's range, subnormal and past it.
const std::vector<std::string> corner_tokens = {
    "0", "-0", "+4", "1", "-1.5", ".5", "-.5", "5.", "00012", "1e-3", "1E+3", "2.5e10", "1.5e3x", "1e", "1e+", "e5",
    ".", "-", "+", "", "+-1", "--1", "1..2", "1.2.3", " 1", "1 ", "0x1p3", "0x10", "1,5", "inf", "-inf", "INF",
    "Infinity", "infin", "nan", "-nan", "NaN", "nan(abc)", "nan()", "nan(a-b)", "1e-310", "4.9e-324",
    "2.4703282292062328e-324", "2.4703282292062327e-324", "1e-400", "-1e-400", "0e-400", "0.0000e999",
    "1.7976931348623157e308", "1.7976931348623159e308", "1e400", "-1e400", "123456789012345678901234567890",
    "0.1000000000000000055511151231257827", "3.14159265358979323846264338327950288"};

}  // namespace

TEST_CASE("NFF numbers read the same through from_chars and through the kit's own grammar and strtod", "[common]")
{
    std::vector<std::string> tokens = corner_tokens;
    // And every double printf writes for a spread of values, in %g, %.17g and %e.
    for (int k = -320; k <= 308; k += 7)
        for (const double m : {1.0, 2.2250738585072014, 4.9406564584124654, 9.999999999999999})
            for (const char* format : {"%g", "%.17g", "%.3e", "%+.9g"}) {
                char text[64];
                std::snprintf(text, sizeof text, format, m * std::pow(10.0, k));
                tokens.push_back(text);
            }
    for (const std::string& token : tokens) {
        double portable = -7.0, standard = -7.0;
        const NumberStatus a = parse_double_portable(token, portable);
        const NumberStatus b = parse_double(token, standard);
        INFO("token '" << token << "': portable " << status_name(a) << " " << portable << ", parse_double "
                       << status_name(b) << " " << standard);
        REQUIRE(a == b);
        if (a == NumberStatus::ok && !std::isnan(portable))
            CHECK(std::memcmp(&portable, &standard, sizeof portable) == 0);
    }
    double v = 0.0;
    CHECK(parse_double_portable("1e-310", v) == NumberStatus::ok);  // a subnormal is a number
    CHECK(v > 0.0);
    CHECK(parse_double_portable("1e-400", v) == NumberStatus::out_of_range);  // rounds to zero
    CHECK(parse_double_portable("0e-400", v) == NumberStatus::ok);           // is zero
    CHECK(parse_double_portable("0x1p3", v) == NumberStatus::not_a_number);
}
