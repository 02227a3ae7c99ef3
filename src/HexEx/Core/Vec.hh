#pragma once
/// @file Vec.hh
/// @ingroup kernel
/// Vector types: OpenMesh's Vec3d for points and parameters, Vec3i for integer grid points.

#include <OpenMesh/Core/Geometry/VectorT.hh>

namespace HexEx {

/// A point or parameter in R^3 (the vector type OpenVolumeMesh's kernels use).
using Vec3d = OpenMesh::Vec3d;
/// An integer grid point.
using Vec3i = OpenMesh::Vec3i;

/// The integer grid point as a double vector (exact for |x| < 2^53).
inline Vec3d toVec3d(const Vec3i& v) { return Vec3d(v[0], v[1], v[2]); }

/// Six times the signed volume of the tet (@p a, @p b, @p c, @p d): (b - a) x (c - a) . (d - a),
/// positive for a positively oriented tet.
inline double tetVolume6(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& d) {
    return ((b - a) % (c - a)) | (d - a);
}

} // namespace HexEx
