#pragma once
/// @file PlanarOrientation.hh
/// @ingroup quad
/// The exact planar orientation test of the 2D pipeline, orient2dAxis(a, b, c, 2) with its
/// cheap cases inlined. The 2D tracing and dart extraction call it millions of times,
/// mostly with points on grid lines, where the floating-point filter cannot decide.

#include "../Predicates/ExactPredicates.hh"
#include "ParametrizedTriMesh.hh"

#include <cmath>

namespace HexEx {

namespace detail {
/// True if the coordinate, scaled by 64, is an integer of magnitude at most 2^15 (the
/// condition under which orient2dAxis() trusts the plain determinant: no rounding).
inline bool smallDyadicCoord(double x) {
    const double y = x * 64.0;
    return std::fabs(y) <= 32768.0 && y == static_cast<double>(static_cast<int>(y));
}
} // namespace detail

/// Sign of (b - a) x (c - a) in the (u, v) plane for c = (cu, cv): the same value as
/// orient2dAxis((a, 0), (b, 0), (cu, cv, 0), 2), whose steps it repeats inline (floating-point
/// filter, exact zero by equal coordinates, exact determinant of small dyadic inputs);
/// only the remaining cases make the call.
inline int orient2dUV(const Vec2d& a, const Vec2d& b, double cu, double cv) {
    const double t1 = (b[0] - a[0]) * (cv - a[1]), t2 = (b[1] - a[1]) * (cu - a[0]);
    const double det = t1 - t2, bound = 5e-16 * (std::fabs(t1) + std::fabs(t2));
    if (det > bound) return 1;
    if (-det > bound) return -1;
    if ((b[0] == a[0] || cv == a[1]) && (b[1] == a[1] || cu == a[0])) return 0;
    using detail::smallDyadicCoord;
    if (smallDyadicCoord(a[0]) && smallDyadicCoord(a[1]) && smallDyadicCoord(b[0]) && smallDyadicCoord(b[1]) &&
        smallDyadicCoord(cu) && smallDyadicCoord(cv))
        return (det > 0) - (det < 0);
    return orient2dAxis(Vec3d(a[0], a[1], 0), Vec3d(b[0], b[1], 0), Vec3d(cu, cv, 0), 2);
}

} // namespace HexEx
