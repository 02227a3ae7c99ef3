#pragma once
/// @file HexMeshQuality.hh
/// Element quality of hex meshes: the scaled Jacobian per hexahedron and summary statistics.

#include "HexMesh.hh"

#include <array>
#include <vector>

namespace HexEx {

/// The three edges leaving each corner of a hexahedron in VTK order, as (corner, a, b, c):
/// the corner Jacobian is det(p[a]-p[corner], p[b]-p[corner], p[c]-p[corner]), positive for
/// a positively oriented hex (corner 0 uses the edges 0->1, 0->3, 0->4).
extern const std::array<std::array<int, 4>, 8> kHexCornerFrames;

/// Scaled Jacobian of one corner: det(a, b, c) / (|a| |b| |c|), in [-1, 1]; 0 if an edge
/// has zero length.
double cornerScaledJacobian(const Vec3d& a, const Vec3d& b, const Vec3d& c);

/// Scaled Jacobian of the hex with corners @p p (VTK order): the minimum over its 8 corners.
/// A unit cube gives 1; a hex with an inverted (or degenerate) corner gives a value <= 0.
double hexScaledJacobian(const std::array<Vec3d, 8>& p);

/// Scaled Jacobian of every hex of @p mesh, in hex order. Hexes that reference a vertex
/// index out of range get 0 (they count as degenerate).
std::vector<double> scaledJacobians(const HexMesh& mesh);

/// Summary of the hex quality of a mesh (polyhedra are not measured).
struct QualityStats {
    double min_scaled_jacobian = 0;   ///< minimum over all hexes (0 if there are none)
    double mean_scaled_jacobian = 0;  ///< mean over all hexes (0 if there are none)
    long inverted_hexes = 0;          ///< hexes with a corner Jacobian <= 0 (inverted or degenerate)
};

/// Computes QualityStats from scaledJacobians().
QualityStats computeQuality(const HexMesh& mesh);

} // namespace HexEx
