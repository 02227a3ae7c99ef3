#pragma once
/// @file HexMeshQuality.hh
/// @ingroup quality
/// Element quality of hex meshes: the scaled Jacobian per hexahedron and summary statistics.

#include "HexMesh.hh"
#include "HexValidity.hh"

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

/// hexScaledJacobian() of the hexes @p a and @p b into @p out[0] and @p out[1], one in each
/// lane of SSE2 registers: the same operations, hence the same bits (without SSE2: two calls).
void hexScaledJacobianPair(const std::array<Vec3d, 8>& a, const std::array<Vec3d, 8>& b, double out[2]);

/// Scaled Jacobian of every hex of @p mesh, in hex order. Hexes that reference a vertex
/// index out of range get 0 (they count as degenerate).
std::vector<double> scaledJacobians(const HexMesh& mesh);

/// Certified validity (classifyHexValidity()) of every hex of @p mesh, in hex order, on
/// @p threads threads (0 = all; the result does not depend on it). Hexes that reference a
/// vertex index out of range are Invalid.
std::vector<HexValidity> hexValidities(const HexMesh& mesh, int threads = 0);

/// Summary of the hex quality of a mesh (polyhedra are not measured).
///
/// Two validity figures: `inverted_hexes` counts hexes with a corner Jacobian <= 0 (the
/// classical 8-corner test); `invalid_hexes` counts hexes whose Jacobian is proved <= 0
/// somewhere in the element (every inverted hex, plus hexes positive at all 8 corners but
/// negative inside), and `undecided_hexes` those the exact test could not decide. A mesh
/// is certified valid when invalid_hexes + undecided_hexes == 0.
struct QualityStats {
    double min_scaled_jacobian = 0;   ///< minimum over all hexes (0 if there are none)
    double mean_scaled_jacobian = 0;  ///< mean over all hexes (0 if there are none)
    long inverted_hexes = 0;          ///< hexes with a corner Jacobian <= 0 (inverted or degenerate)
    long invalid_hexes = 0;           ///< hexes certified to have J <= 0 somewhere (HexValidity::Invalid)
    long undecided_hexes = 0;         ///< hexes the certified test left undecided (HexValidity::Undecided)
    long first_invalid_hex = -1;      ///< index of the first invalid hex (-1: none)
};

/// Computes QualityStats from scaledJacobians() and hexValidities() on @p threads threads
/// (0 = all); the result does not depend on the thread count.
QualityStats computeQuality(const HexMesh& mesh, int threads = 0);

} // namespace HexEx
