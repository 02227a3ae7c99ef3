#pragma once
/// @file TextParsing.hh
/// @ingroup io
/// Small helpers shared by the text readers (.hexex, .ovm, hex mesh files).

#include "../Core/Error.hh"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

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

/// Parses the whole token @p tok as a double like parseReal(), with a fast path for plain
/// decimals ("-12.0625": optional sign, a digit, digits, optional fraction, no exponent) whose digits
/// form an integer m <= 2^53 with at most 22 fraction digits: m and 10^k are then exact
/// doubles and one IEEE division m / 10^k is correctly rounded, i.e. the same value
/// std::from_chars gives. Every other token goes through parseReal().
inline NumberParse parseRealFast(std::string_view tok, double& value) {
    static constexpr double kPow10[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                          1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    const char* p = tok.data();
    const char* const last = p + tok.size();
    bool negative = false;
    if (p != last && (*p == '-' || *p == '+')) negative = (*p++ == '-');
    if (p == last || static_cast<unsigned>(*p) - '0' >= 10) return parseReal(tok, value);  // e.g. ".5", "+-1"
    unsigned long long m = 0;
    int digits = 0, fraction = -1;  // fraction: digits after the point (-1: no point)
    for (; p != last; ++p) {
        const unsigned d = static_cast<unsigned>(*p) - '0';
        if (d < 10) {
            if (++digits > 19) return parseReal(tok, value);  // m stays below 2^64
            m = 10 * m + d;
            if (fraction >= 0) ++fraction;
        } else if (*p == '.' && fraction < 0) {
            fraction = 0;
        } else {
            return parseReal(tok, value);
        }
    }
    if (digits == 0 || fraction == 0 || fraction > 22 || m > (1ULL << 53)) return parseReal(tok, value);
    const double v = static_cast<double>(m) / kPow10[fraction < 0 ? 0 : fraction];
    value = negative ? -v : v;
    return NumberParse::Ok;
}

/// Parses @p tok as a vertex index in [0, @p bound): digits only (a fast path), anything
/// else through parseInteger(). False if it is not such an index.
inline bool parseIndex(std::string_view tok, long long bound, long long& value) {
    if (tok.empty() || tok.size() > 18) {
        return parseInteger(tok, value) == NumberParse::Ok && value >= 0 && value < bound;
    }
    long long v = 0;
    for (const char ch : tok) {
        const unsigned d = static_cast<unsigned>(ch) - '0';
        if (d >= 10) return parseInteger(tok, value) == NumberParse::Ok && value >= 0 && value < bound;
        v = 10 * v + d;
    }
    value = v;
    return v < bound;
}

/// Case-insensitive comparison of a token with a keyword.
inline bool iequals(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

/// Throws InputError "<name>:<line>: <reason>" (without the line if @p line <= 0).
[[noreturn]] inline void failAt(const std::string& name, long long line, const std::string& reason) {
    if (line > 0) throw InputError(name + ":" + std::to_string(line) + ": " + reason);
    throw InputError(name + ": " + reason);
}

/// A token and the line it is on.
struct Token {
    std::string_view text;  ///< the characters
    long long line = 0;     ///< 1-based line
};

/// Whitespace-separated tokens of a text with line numbers, optional comments, and raw
/// byte blocks (binary data after a header line). Every failure throws InputError
/// "<name>:<line>: <reason>".
class Lexer {
public:
    /// Tokens of @p text (named @p name in errors), whose first character is on line
    /// @p firstLine; @p comment starts a comment up to the end of the line ('\0': none).
    Lexer(std::string_view text, const std::string& name, long long firstLine = 1, char comment = '\0')
        : text_(text), name_(name), line_(firstLine), comment_(comment) {}

    /// Throws InputError at @p line.
    [[noreturn]] void fail(long long line, const std::string& reason) const { failAt(name_, line, reason); }

    /// Skips whitespace and comments; true if a token follows.
    bool more() {
        for (; pos_ < text_.size(); ++pos_) {
            const char ch = text_[pos_];
            if (ch == '\n') ++line_;
            else if (comment_ && ch == comment_)
                while (pos_ + 1 < text_.size() && text_[pos_ + 1] != '\n') ++pos_;
            else if (!isFormatSpace(ch)) return true;
        }
        return false;
    }
    /// Line of the last token read, or of the end of the text.
    long long line() const { return line_; }
    /// Line to report for an unexpected end of the text.
    long long eofLine() const { return (!text_.empty() && text_.back() == '\n' && line_ > 1) ? line_ - 1 : line_; }
    /// Bytes left.
    std::size_t remaining() const { return text_.size() - pos_; }
    /// Byte offset in the text.
    std::size_t offset() const { return pos_; }
    /// Moves on to byte @p offset, @p lineBreaks line breaks further, after the caller
    /// parsed the text up to there itself (a fast path over a run of tokens).
    void advance(std::size_t offset, long long lineBreaks) {
        pos_ = offset;
        line_ += lineBreaks;
    }

    /// The next token; fails at the end of the text, naming @p what was expected.
    Token next(const std::string& what) {
        if (!more()) fail(eofLine(), "unexpected end of file, expected " + what);
        const std::size_t b = pos_;
        while (pos_ < text_.size() && !isFormatSpace(text_[pos_]) && !(comment_ && text_[pos_] == comment_)) ++pos_;
        tokenEnd_ = pos_;
        tokenLine_ = line_;
        return {text_.substr(b, pos_ - b), line_};
    }
    /// The tokens of the next non-blank line (none at the end of the text).
    std::vector<Token> lineTokens() {
        std::vector<Token> t;
        for (const long long l = more() ? line_ : 0; more() && line_ == l;) t.push_back(next(""));
        return t;
    }
    /// The next token without consuming it (empty at the end).
    std::string_view peek() {
        if (!more()) return {};
        std::size_t e = pos_;
        while (e < text_.size() && !isFormatSpace(text_[e])) ++e;
        return text_.substr(pos_, e - pos_);
    }
    /// Reads an integer in [lo, hi].
    long long integer(const std::string& what, long long lo = LLONG_MIN, long long hi = LLONG_MAX) {
        const Token t = next(what);
        long long v = 0;
        if (parseInteger(t.text, v) != NumberParse::Ok) fail(t.line, "expected " + what + ", got " + quoteToken(t.text));
        if (v < lo || v > hi)
            fail(t.line, what + " " + std::to_string(v) + " out of range [" + std::to_string(lo) + ", " +
                             std::to_string(hi) + "]");
        return v;
    }
    /// Reads a count of items of at least @p bytesPerItem bytes each that the rest of the text can hold.
    long long count(const std::string& what, long long bytesPerItem = 2) {
        const long long limit = static_cast<long long>(remaining() / static_cast<std::size_t>(std::max(bytesPerItem, 1LL)));
        const long long v = integer(what);
        if (v < 0) fail(line(), what + " is negative (" + std::to_string(v) + ")");
        if (v > limit + 1 || v > INT_MAX) fail(line(), what + " " + std::to_string(v) + " is larger than the file can hold");
        return v;
    }
    /// Reads a finite real number.
    double real(const std::string& what) {
        const Token t = next(what);
        double v = 0;
        if (parseReal(t.text, v) != NumberParse::Ok) fail(t.line, "expected " + what + ", got " + quoteToken(t.text));
        if (!std::isfinite(v)) fail(t.line, what + " is not finite");
        return v;
    }
    /// Reads the keyword @p kw (case-insensitive).
    void keyword(std::string_view kw) {
        const Token t = next("'" + std::string(kw) + "'");
        if (!iequals(t.text, kw)) fail(t.line, "expected '" + std::string(kw) + "', got " + quoteToken(t.text));
    }
    /// Skips the rest of the line of the last token read and returns the next @p n raw bytes.
    std::string_view bytes(std::size_t n, const std::string& what) {
        pos_ = tokenEnd_;  // undo any look-ahead of peek()
        line_ = tokenLine_;
        const std::size_t eol = text_.find('\n', pos_);
        if (eol == std::string_view::npos) fail(eofLine(), "unexpected end of file, expected " + what);
        pos_ = eol + 1;
        ++line_;
        if (n > remaining())
            fail(line_, what + ": " + std::to_string(n) + " bytes needed at byte " + std::to_string(pos_) + ", " +
                            std::to_string(remaining()) + " left");
        const std::string_view b = text_.substr(pos_, n);
        line_ += std::count(b.begin(), b.end(), '\n');
        pos_ += n;
        return b;
    }

private:
    std::string_view text_;
    const std::string& name_;
    std::size_t pos_ = 0, tokenEnd_ = 0;
    long long line_ = 1, tokenLine_ = 1;
    char comment_ = '\0';
};

} // namespace detail
} // namespace HexEx
