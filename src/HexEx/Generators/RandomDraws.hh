#pragma once
/// @file RandomDraws.hh
/// @ingroup io
/// Platform-independent draws from std::mt19937 (the standard distributions are not
/// specified bit for bit, so generators that must give the same output everywhere map the
/// raw 32-bit words by hand).

#include <cstdint>
#include <random>

namespace HexEx {

/// Uniform integer in [0, @p n) from raw 32-bit draws (rejection sampling; @p n > 0).
inline std::uint32_t uniformBelow(std::mt19937& gen, std::uint32_t n) {
    const std::uint64_t range = std::uint64_t(1) << 32;
    const std::uint64_t limit = range - range % n;
    for (;;) {
        const std::uint64_t x = static_cast<std::uint32_t>(gen());
        if (x < limit) return static_cast<std::uint32_t>(x % n);
    }
}

/// Uniform double in [0, 1) with 53 random bits from two 32-bit draws.
inline double uniform01(std::mt19937& gen) {
    const std::uint64_t hi = static_cast<std::uint32_t>(gen()) >> 5;  // 27 bits
    const std::uint64_t lo = static_cast<std::uint32_t>(gen()) >> 6;  // 26 bits
    return static_cast<double>((hi << 26) | lo) * (1.0 / 9007199254740992.0);
}

} // namespace HexEx
