/// @file TextParsingTest.cc
/// Tests of the number parsers of the text readers: the fast paths (plain decimals, digit-only
/// indices) give bit for bit what std::from_chars gives, and fall back for everything else.

#include <HexEx/IO/TextParsing.hh>

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>

using namespace HexEx;
using detail::NumberParse;

namespace {

/// Asserts that parseRealFast and parseReal agree on @p tok (status and bits).
void expectSameAsParseReal(const std::string& tok) {
    double fast = 12345, slow = 54321;
    const NumberParse rf = detail::parseRealFast(tok, fast);
    const NumberParse rs = detail::parseReal(tok, slow);
    ASSERT_EQ(rf, rs) << "token '" << tok << "'";
    if (rs != NumberParse::Ok) return;
    std::uint64_t a = 0, b = 0;
    std::memcpy(&a, &fast, sizeof a);
    std::memcpy(&b, &slow, sizeof b);
    ASSERT_EQ(a, b) << "token '" << tok << "': " << fast << " vs " << slow;
}

} // namespace

TEST(TextParsing, RealFastPathEdgeCases) {
    for (const char* tok : {"0", "-0", "+0", "0.0", "-0.0", "5", "+5", "-5", "5.", ".5", "-.5", "+-5", "-+5", "+", "-", ".",
                            "", "0.1", "0.0125", "-12.0625", "007", "1e5", "1E-5", "2.5e+3", "nan", "-inf", "0x10",
                            "1.2.3", "1 ", "9007199254740992", "9007199254740993", "-9007199254740993",
                            "0.9007199254740993", "123456789012345678901", "0.12345678901234567890123",
                            "1.0000000000000000000001", "0.0000000000000000000001", "3.14159265358979",
                            "1e400", "1e-400", "12abc"})
        expectSameAsParseReal(tok);
}

TEST(TextParsing, RealFastPathRandomDecimals) {
    std::mt19937_64 rng(23);
    for (int n = 0; n < 200000; ++n) {
        const int digits = 1 + static_cast<int>(rng() % 19);
        std::string s;
        if (rng() % 3 == 0) s += '-';
        for (int i = 0; i < digits; ++i) s += static_cast<char>('0' + rng() % 10);
        const std::size_t sign = s[0] == '-' ? 1 : 0;
        const std::size_t point = sign + 1 + rng() % static_cast<std::size_t>(digits);
        if (point < s.size()) s.insert(point, 1, '.');
        expectSameAsParseReal(s);
    }
    // Shortest representations of random doubles, as the writer produces them.
    std::uniform_real_distribution<double> dist(-1000, 1000);
    for (int n = 0; n < 200000; ++n) {
        char buf[64];
        const double x = n % 2 ? dist(rng) : std::round(dist(rng) * 80) / 80;
        expectSameAsParseReal(std::string(buf, std::to_chars(buf, buf + sizeof buf, x).ptr));
    }
}

TEST(TextParsing, IndexFastPath) {
    long long v = -1;
    EXPECT_TRUE(detail::parseIndex("0", 5, v));
    EXPECT_EQ(v, 0);
    EXPECT_TRUE(detail::parseIndex("4", 5, v));
    EXPECT_EQ(v, 4);
    EXPECT_FALSE(detail::parseIndex("5", 5, v));
    EXPECT_TRUE(detail::parseIndex("+3", 5, v));
    EXPECT_EQ(v, 3);
    EXPECT_TRUE(detail::parseIndex("0000000000000000000000000000000003", 5, v));
    EXPECT_EQ(v, 3);
    EXPECT_FALSE(detail::parseIndex("-1", 5, v));
    EXPECT_FALSE(detail::parseIndex("", 5, v));
    EXPECT_FALSE(detail::parseIndex("3x", 5, v));
    EXPECT_FALSE(detail::parseIndex("99999999999999999999999", 5, v));
    EXPECT_TRUE(detail::parseIndex("999999999999999999", 1000000000000000000LL, v));
    EXPECT_EQ(v, 999999999999999999LL);
}
