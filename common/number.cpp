#include "common/number.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace rt {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

bool equal_ignoring_case(std::string_view text, std::string_view word)
{
    if (text.size() != word.size())
        return false;
    for (size_t k = 0; k < text.size(); ++k)
        if (std::tolower(static_cast<unsigned char>(text[k])) != word[k])
            return false;
    return true;
}

// from_chars' words: "inf", "infinity", "nan" and "nan(" letters, digits or '_' ")", any case.
bool is_special_word(std::string_view w)
{
    if (equal_ignoring_case(w, "inf") || equal_ignoring_case(w, "infinity") || equal_ignoring_case(w, "nan"))
        return true;
    if (w.size() < 5 || !equal_ignoring_case(w.substr(0, 4), "nan(") || w.back() != ')')
        return false;
    for (const char c : w.substr(4, w.size() - 5))
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
            return false;
    return true;
}

// from_chars' decimal form: digits with at most one '.', at least one digit, then an optional
// exponent: 'e' or 'E', an optional sign, digits. Sets `nonzero` when a significand digit is not 0.
bool is_decimal(std::string_view d, bool& nonzero)
{
    size_t k = 0, digits = 0;
    nonzero = false;
    bool point = false;
    for (; k < d.size(); ++k) {
        if (is_digit(d[k])) {
            ++digits;
            nonzero = nonzero || d[k] != '0';
        } else if (d[k] == '.' && !point) {
            point = true;
        } else {
            break;
        }
    }
    if (digits == 0)
        return false;
    if (k == d.size())
        return true;
    if (d[k] != 'e' && d[k] != 'E')
        return false;
    ++k;
    if (k < d.size() && (d[k] == '+' || d[k] == '-'))
        ++k;
    if (k == d.size())
        return false;
    for (; k < d.size(); ++k)
        if (!is_digit(d[k]))
            return false;
    return true;
}

// A leading '+', which printf's "%+g" writes, and which from_chars refuses.
std::string_view without_plus(std::string_view text)
{
    if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+')
        text.remove_prefix(1);
    return text;
}

}  // namespace

NumberStatus parse_double_portable(std::string_view text, double& value)
{
    text = without_plus(text);
    const std::string_view unsigned_part = !text.empty() && text[0] == '-' ? text.substr(1) : text;
    bool nonzero = false;
    const bool special = is_special_word(unsigned_part);
    if (!special && !is_decimal(unsigned_part, nonzero))
        return NumberStatus::not_a_number;
    const std::string copy(text);  // strtod reads up to a NUL
    const double v = std::strtod(copy.c_str(), nullptr);
    // strtod says ERANGE for subnormal answers too, which from_chars accepts: judge the value.
    if (!special && (std::isinf(v) || (v == 0.0 && nonzero)))
        return NumberStatus::out_of_range;
    value = v;
    return NumberStatus::ok;
}

NumberStatus parse_double(std::string_view text, double& value)
{
#ifdef RT_HAVE_FLOAT_FROM_CHARS
    text = without_plus(text);
    const char* end = text.data() + text.size();
    double v = 0.0;
    const auto [ptr, ec] = std::from_chars(text.data(), end, v, std::chars_format::general);
    if (ec == std::errc::result_out_of_range && ptr == end)
        return NumberStatus::out_of_range;
    if (ec != std::errc() || ptr != end)
        return NumberStatus::not_a_number;
    value = v;
    return NumberStatus::ok;
#else
    return parse_double_portable(text, value);
#endif
}

}  // namespace rt
