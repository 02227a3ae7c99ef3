#pragma once
/// @file GridPointPosition.hh
/// @ingroup pipeline
/// 3D position of an integer grid point seen from one tet (barycentric interpolation of
/// the tet's corner positions), shared by the vertex placement and the implicit cells.

#include "../Extraction/DartExtraction.hh"
#include "../Mesh/TetMesh.hh"

#include <array>
#include <vector>

namespace HexEx {

/// Position of grid point @p z of tet @p t's chart, by barycentric coordinates with exact
/// zeros where a predicate (or the implicit-cell flags of @p darts) puts @p z on a face.
/// If @p boundary_hf is given it receives the boundary halffaces of @p t through @p z
/// (at most 3; the caller initializes it to -1).
Vec3d gridPointPosition(const TetMesh& mesh, const std::vector<TetSoS>& tets, const DartSet& darts, int t,
                        const Vec3i& z, std::array<int, 3>* boundary_hf);

} // namespace HexEx
