#pragma once
/// @file OutputHasher.hh
/// FNV-1a hashing of output data, shared by the bit-identity tools (quad_output_hash,
/// arc_output_hash).

#include <HexEx/Core/Vec.hh>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace HexExBench {

/// FNV-1a over raw bytes: simple, stable across runs and platforms of the same endianness.
struct OutputHasher {
    std::uint64_t h = 1469598103934665603ull;  ///< the running hash
    /// Hashes @p n raw bytes at @p p.
    void bytes(const void* p, std::size_t n) {
        const auto* c = static_cast<const unsigned char*>(p);
        for (std::size_t i = 0; i < n; ++i) h = (h ^ c[i]) * 1099511628211ull;
    }
    /// Hashes the bytes of a trivially copyable value.
    template <class T>
    void add(const T& v) { bytes(&v, sizeof v); }
    /// Hashes a vector's size and elements.
    template <class T>
    void all(const std::vector<T>& v) {
        add(v.size());
        for (const T& x : v) add(x);
    }
    /// Hashes a point list's size and coordinates.
    void points(const std::vector<HexEx::Vec3d>& v) {
        add(v.size());
        for (const auto& p : v)
            for (int k = 0; k < 3; ++k) add(p[k]);
    }
};

} // namespace HexExBench
