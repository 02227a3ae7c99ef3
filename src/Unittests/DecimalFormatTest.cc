/// @file DecimalFormatTest.cc
/// formatReal17() gives printf's "%.17g" bytes and formatUnsigned() std::to_chars' bytes, on
/// the fast path's edges (powers of ten and their neighbours, exact ties at the 18th digit,
/// 1e-6 and 2^52) and on random values, and both fall back correctly outside it.

#include <HexEx/IO/BlockOutput.hh>
#include <HexEx/IO/DecimalFormat.hh>
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace HexEx;

namespace {

/// printf("%.17g", x).
std::string printf17(double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}

/// formatReal17(x).
std::string fast17(double x) {
    char buf[64];
    return std::string(buf, detail::formatReal17(buf, x));
}

/// formatUnsigned(v).
std::string fastUnsigned(std::uint32_t v) {
    char buf[16];
    return std::string(buf, detail::formatUnsigned(buf, v));
}

/// std::to_chars(v).
std::string toChars(std::uint32_t v) {
    char buf[16];
    return std::string(buf, std::to_chars(buf, buf + 16, v).ptr);
}

} // namespace

TEST(DecimalFormat, Real17EdgesMatchPrintf) {
    std::vector<double> xs = {0.0, -0.0, 1.0, -1.0, 0.1, 0.5, 2.5, 1e-6, 9.9999999999999995e-7, 1e-5, 1e-4, 1e-3,
                              64.0, -63.999999999999993, 1.0 / 3, 2.0 / 3, 4503599627370495.5, 4503599627370496.0,
                              9007199254740993.0, 1e15, 1e16, 1e17, std::numeric_limits<double>::min(),
                              std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::max(),
                              std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                              std::ldexp(1.0, -20), std::ldexp(1.0, -21), std::ldexp(1.0, 51), std::ldexp(1.0, 52)};
    for (int k = -8; k <= 17; ++k) {  // powers of ten and 40 neighbours on each side
        double up = std::pow(10.0, k), down = up;
        for (int j = 0; j < 40; ++j) {
            xs.push_back(up);
            xs.push_back(-down);
            up = std::nextafter(up, 1e300);
            down = std::nextafter(down, 0.0);
        }
        xs.push_back(9.99999999999999999 * std::pow(10.0, k));
    }
    // Few significant bits: many have exactly 18 significant digits ending in 5 (a tie at
    // the 17th digit, rounded to even).
    for (int k = 1; k < 60; ++k)
        for (std::uint64_t m = 1; m < 4096; m += 2) xs.push_back(std::ldexp(static_cast<double>(m), -k));
    for (int i = 0; i <= 20000; ++i) xs.push_back(i / 1024.0 - 9.0);
    for (const double x : xs) ASSERT_EQ(fast17(x), printf17(x)) << std::hexfloat << x;
    EXPECT_EQ(fast17(0.1), "0.10000000000000001");
    EXPECT_EQ(fast17(-2.5e-5), "-2.5000000000000001e-05");
    EXPECT_EQ(fast17(1234.5), "1234.5");
}

TEST(DecimalFormat, Real17RandomMatchesPrintf) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.5, 1.0);
    std::uniform_int_distribution<int> exponent(-24, 55);  // around the fast range [2^-20, 2^52)
    for (int i = 0; i < 100000; ++i) {
        const double x = std::ldexp(unit(rng), exponent(rng)) * (i % 2 ? -1 : 1);
        ASSERT_EQ(fast17(x), printf17(x)) << std::hexfloat << x;
        const std::uint64_t bits = rng();  // any finite bit pattern (subnormals included)
        double y = 0;
        std::memcpy(&y, &bits, 8);
        if (std::isfinite(y)) {
            ASSERT_EQ(fast17(y), printf17(y)) << std::hexfloat << y;
        }
    }
}

TEST(DecimalFormat, UnsignedMatchesToChars) {
    std::vector<std::uint32_t> vs = {0, 4294967295u, 4294967294u, 2147483647u, 2147483648u};
    for (std::uint64_t p = 1; p <= 1000000000ull; p *= 10)
        for (const std::uint64_t v : {p - 1, p, p + 1, 2 * p - 1, 5 * p, 9 * p + 9}) vs.push_back(static_cast<std::uint32_t>(v));
    for (std::uint32_t v = 0; v < 200000; ++v) vs.push_back(v);
    std::mt19937 rng(3);
    for (int i = 0; i < 200000; ++i) vs.push_back(static_cast<std::uint32_t>(rng()));
    for (const std::uint32_t v : vs) ASSERT_EQ(fastUnsigned(v), toChars(v)) << v;
}

TEST(DecimalFormat, BlockOutputIntegersOfEveryType) {
    detail::BlockOutput o(nullptr, 16);
    o << -1 << ' ' << 0 << ' ' << 4294967295u << ' ' << 4294967296ll << ' ' << -2147483647 - 1 << ' '
      << std::uint64_t(18446744073709551615ull) << ' ' << static_cast<short>(-7) << ' ' << std::size_t(12);
    EXPECT_EQ(o.take(), "-1 0 4294967295 4294967296 -2147483648 18446744073709551615 -7 12");
}
