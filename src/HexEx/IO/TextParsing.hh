#pragma once
/// @file TextParsing.hh
/// Small helpers shared by the text readers (.hexex, .ovm, hex mesh files).

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>
#include <system_error>

namespace HexEx {
namespace detail {

/// Whitespace as understood by the text formats.
inline bool isFormatSpace(char ch) {
    return ch == ' ' || ch == '\n' || ch == '\t' || ch == '\r' || ch == '\v' || ch == '\f';
}

/// A token quoted for an error message: at most 40 characters, non-printable bytes as '?'.
inline std::string quoteToken(std::string_view tok) {
    std::string s = "'";
    const std::size_t n = std::min<std::size_t>(tok.size(), 40);
    for (std::size_t i = 0; i < n; ++i) {
        const unsigned char ch = static_cast<unsigned char>(tok[i]);
        s += (ch >= 0x20 && ch < 0x7f) ? static_cast<char>(ch) : '?';
    }
    if (tok.size() > n) s += "...";
    return s + "'";
}

/// Outcome of parsing a number token.
enum class NumberParse {
    Ok,         ///< the whole token is a number
    Malformed,  ///< not a number (or trailing characters)
    OutOfRange  ///< a number too large for the type (for doubles: overflow only)
};

/// Parses the whole token @p tok as an integer; one leading '+' is accepted.
inline NumberParse parseInteger(std::string_view tok, long long& value) {
    const char* first = tok.data();
    const char* last = first + tok.size();
    if (first != last && *first == '+' && last - first > 1 && first[1] != '-') ++first;
    const auto res = std::from_chars(first, last, value);
    if (res.ec == std::errc::result_out_of_range && res.ptr == last) return NumberParse::OutOfRange;
    if (res.ec != std::errc() || res.ptr != last) return NumberParse::Malformed;
    return NumberParse::Ok;
}

/// Parses the whole token @p tok as a double; one leading '+' is accepted. Underflow
/// (e.g. 1e-400) gives the value strtod gives (0 or a subnormal); overflow is OutOfRange.
/// "nan" and "inf" parse as such: callers decide about finiteness.
inline NumberParse parseReal(std::string_view tok, double& value) {
    const char* first = tok.data();
    const char* last = first + tok.size();
    if (first != last && *first == '+' && last - first > 1 && first[1] != '-') ++first;
    const auto res = std::from_chars(first, last, value, std::chars_format::general);
    if (res.ec == std::errc::result_out_of_range && res.ptr == last) {
        value = std::strtod(std::string(first, last).c_str(), nullptr);
        return (value == HUGE_VAL || value == -HUGE_VAL) ? NumberParse::OutOfRange : NumberParse::Ok;
    }
    if (res.ec != std::errc() || res.ptr != last) return NumberParse::Malformed;
    return NumberParse::Ok;
}

} // namespace detail
} // namespace HexEx
