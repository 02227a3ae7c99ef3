#pragma once
/// @file DecimalFormat.hh
/// @ingroup io
/// Decimal text of numbers for the text writers, faster than std::to_chars and with the same
/// bytes: formatUnsigned() for non-negative integers below 2^32 (digit pairs from a table,
/// no division loop), formatReal17() for doubles as printf's "%.17g" (exact 128-bit integer
/// arithmetic for magnitudes in [1e-6, 2^52), std::to_chars for everything else).

#include <charconv>
#include <cstdint>
#include <cstring>

/// Marks the small digit helpers below to be inlined always (GCC and Clang chose to call
/// putFour() out of line inside the writers' loops).
#if defined(__GNUC__)
#define HEXEX_FORMAT_INLINE inline __attribute__((always_inline))
#else
#define HEXEX_FORMAT_INLINE inline
#endif

namespace HexEx {
namespace detail {

/// The two-digit strings "00" to "99", back to back.
inline constexpr char kDigitPairs[201] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

/// Writes exactly 2 decimal digits of @p v (< 100) at @p p.
HEXEX_FORMAT_INLINE void putPair(char* p, std::uint32_t v) { std::memcpy(p, kDigitPairs + 2 * v, 2); }

/// Writes exactly 4 decimal digits of @p v (< 10^4) at @p p.
HEXEX_FORMAT_INLINE void putFour(char* p, std::uint32_t v) {
    putPair(p, v / 100);
    putPair(p + 2, v % 100);
}

/// Writes exactly 8 decimal digits of @p v (< 10^8) at @p p, leading zeros included.
HEXEX_FORMAT_INLINE void putEight(char* p, std::uint32_t v) {
    putFour(p, v / 10000);
    putFour(p + 4, v % 10000);
}

/// Writes @p v (< 10^4) at @p p without leading zeros; @return one past the last character.
HEXEX_FORMAT_INLINE char* putUpToFour(char* p, std::uint32_t v) {
    if (v < 10) {
        *p = static_cast<char>('0' + v);
        return p + 1;
    }
    if (v < 100) {
        putPair(p, v);
        return p + 2;
    }
    if (v < 1000) {
        *p = static_cast<char>('0' + v / 100);
        putPair(p + 1, v % 100);
        return p + 3;
    }
    putFour(p, v);
    return p + 4;
}

/// Writes @p v in decimal at @p p (no sign, no leading zeros; at most 10 characters);
/// @return one past the last character. Same bytes as std::to_chars.
HEXEX_FORMAT_INLINE char* formatUnsigned(char* p, std::uint32_t v) {
    if (v < 10000) return putUpToFour(p, v);
    if (v < 100000000) {
        p = putUpToFour(p, v / 10000);
        putFour(p, v % 10000);
        return p + 4;
    }
    p = putUpToFour(p, v / 100000000);  // 1 or 2 digits
    putEight(p, v % 100000000);
    return p + 8;
}

/// Writes @p x as printf("%.17g") (and std::to_chars(..., general, 17)) does, at @p p, which
/// must have room for 32 characters; @return one past the last character. Finite values of
/// magnitude in [1e-6, 2^52) take the fast path: the 17 significant digits are the mantissa
/// times a power of ten, shifted and rounded half to even, exactly, in 128-bit integers.
inline char* formatReal17(char* p, double x) {
    __extension__ typedef unsigned __int128 U128;
    static constexpr std::uint64_t kPow10[23] = {1ull,
                                                10ull,
                                                100ull,
                                                1000ull,
                                                10000ull,
                                                100000ull,
                                                1000000ull,
                                                10000000ull,
                                                100000000ull,
                                                1000000000ull,
                                                10000000000ull,
                                                100000000000ull,
                                                1000000000000ull,
                                                10000000000000ull,
                                                100000000000000ull,
                                                1000000000000000ull,
                                                10000000000000000ull,
                                                100000000000000000ull,
                                                1000000000000000000ull,
                                                10000000000000000000ull,
                                                0, 0, 0};  // 10^20..10^22 do not fit: built below
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, 8);
    const int biased = static_cast<int>((bits >> 52) & 0x7ff);
    const int e = biased - 1075;  // |x| = m 2^e with a 53-bit m
    // Fast range: 2^-20 <= |x| < 2^52, i.e. e + 52 in [-20, 51] (then -e is 1 to 72).
    if (biased == 0 || e + 52 < -20 || e >= 0)
        return std::to_chars(p, p + 32, x, std::chars_format::general, 17).ptr;
    const std::uint64_t m = (bits & ((std::uint64_t(1) << 52) - 1)) | (std::uint64_t(1) << 52);
    // floor(log10 |x|) is est or est + 1, est = floor((e + 52) log10 2).
    int exp10 = ((e + 52) * 78913) >> 18;
    std::uint64_t q = 0;
    for (;;) {
        const int p10 = 16 - exp10;  // 17 digits: q = round(|x| 10^p10)
        if (p10 > 22) return std::to_chars(p, p + 32, x, std::chars_format::general, 17).ptr;
        const U128 scale = p10 <= 19 ? U128(kPow10[p10]) : U128(kPow10[19]) * kPow10[p10 - 19];
        const U128 n = U128(m) * scale;  // < 2^53 10^22 < 2^127
        const int s = -e;
        q = static_cast<std::uint64_t>(n >> s);
        const U128 rem = n & ((U128(1) << s) - 1), half = U128(1) << (s - 1);
        if (rem > half || (rem == half && (q & 1))) ++q;
        if (q < kPow10[17]) break;
        if (q == kPow10[17]) {  // |x| 10^(p10-1) rounds to 10^16 too (rounded up, or exact)
            q = kPow10[16];
            ++exp10;
            break;
        }
        ++exp10;  // the estimate was one too low: redo with one digit less
    }
    if (bits >> 63) *p++ = '-';
    char d[17];
    putEight(d + 9, static_cast<std::uint32_t>(q % 100000000));
    const std::uint32_t top = static_cast<std::uint32_t>(q / 100000000);  // 9 digits
    d[0] = static_cast<char>('0' + top / 100000000);
    putEight(d + 1, top % 100000000);
    int last = 16;  // last digit kept: trailing zeros are dropped
    while (last > 0 && d[last] == '0') --last;
    if (exp10 < -4) {  // scientific: d.ddd e-0X (exp10 is -5 or -6 here)
        *p++ = d[0];
        if (last > 0) {
            *p++ = '.';
            std::memcpy(p, d + 1, static_cast<std::size_t>(last));
            p += last;
        }
        std::memcpy(p, "e-0", 3);
        p[3] = static_cast<char>('0' - exp10);
        return p + 4;
    }
    if (exp10 < 0) {  // 0.000ddd
        std::memcpy(p, "0.0000", static_cast<std::size_t>(1 - exp10));
        p += 1 - exp10;
        std::memcpy(p, d, static_cast<std::size_t>(last + 1));
        return p + last + 1;
    }
    std::memcpy(p, d, static_cast<std::size_t>(exp10 + 1));  // integer part
    p += exp10 + 1;
    if (last > exp10) {
        *p++ = '.';
        std::memcpy(p, d + exp10 + 1, static_cast<std::size_t>(last - exp10));
        p += last - exp10;
    }
    return p;
}

} // namespace detail
} // namespace HexEx
