#pragma once
/// @file BitCount.hh
/// @ingroup kernel
/// Population count of 32- and 64-bit words, inline.

#include <cstdint>

namespace HexEx {

/// Number of set bits of @p x. Inline: without the popcnt instruction in the target
/// (the default x86-64 build), __builtin_popcountll is a call into the compiler's runtime
/// library, and the rank look-ups of the assembly call it per dart and per corner.
inline int bitCount64(std::uint64_t x) {
    x = x - ((x >> 1) & 0x5555555555555555ull);
    x = (x & 0x3333333333333333ull) + ((x >> 2) & 0x3333333333333333ull);
    x = (x + (x >> 4)) & 0x0F0F0F0F0F0F0F0Full;
    return static_cast<int>((x * 0x0101010101010101ull) >> 56);
}

/// Number of set bits of @p x (32 bits; as bitCount64(), without a library call).
inline int bitCount32(std::uint32_t x) {
    x = x - ((x >> 1) & 0x55555555u);
    x = (x & 0x33333333u) + ((x >> 2) & 0x33333333u);
    return static_cast<int>((((x + (x >> 4)) & 0x0F0F0F0Fu) * 0x01010101u) >> 24);
}

} // namespace HexEx
