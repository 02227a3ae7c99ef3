#pragma once
/// @file PointPairs.hh
/// @ingroup quality
/// Two points in the two lanes of SSE2 registers: the quality pass measures two hexes at
/// once (hexScaledJacobianPair(), classifyHexValidityPair()) with the same floating-point
/// operations per lane as the one-hex functions.

#include "../Core/Vec.hh"

#include <array>

#if defined(__SSE2__)
#include <emmintrin.h>

namespace HexEx {

/// Point or vector of two hexes: lane 0 belongs to the first, lane 1 to the second.
struct PointPair {
    __m128d x;  ///< x of both
    __m128d y;  ///< y of both
    __m128d z;  ///< z of both
};

/// The pair (@p a, @p b).
inline PointPair loadPointPair(const Vec3d& a, const Vec3d& b) {
    return {_mm_set_pd(b[0], a[0]), _mm_set_pd(b[1], a[1]), _mm_set_pd(b[2], a[2])};
}

/// Componentwise difference, lane by lane.
inline PointPair operator-(const PointPair& a, const PointPair& b) {
    return {_mm_sub_pd(a.x, b.x), _mm_sub_pd(a.y, b.y), _mm_sub_pd(a.z, b.z)};
}

/// The 8 corners of the hexes @p a and @p b, corner by corner.
inline void loadHexPair(const std::array<Vec3d, 8>& a, const std::array<Vec3d, 8>& b, PointPair p[8]) {
    for (std::size_t i = 0; i < 8; ++i) p[i] = loadPointPair(a[i], b[i]);
}

/// |x| in both lanes (the sign bit cleared).
inline __m128d absPair(__m128d x) {
    return _mm_and_pd(x, _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL)));
}

} // namespace HexEx

#endif
