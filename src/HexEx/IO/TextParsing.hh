#pragma once
/// @file TextParsing.hh
/// Small helpers shared by the text readers (.hexex, .ovm, hex mesh files).

#include <algorithm>
#include <string>
#include <string_view>

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

} // namespace detail
} // namespace HexEx
