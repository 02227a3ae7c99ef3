#pragma once
/// @file VertexPreimageChoice.hh
/// Where a vertex's grid point has several preimages among its h-vertices (a fold covers
/// it more than once), choose the one that gives the incident hexes the best shape.

#include "../Mesh/HexMesh.hh"
#include "VertexMerging.hh"

namespace HexEx {

/// Smallest scaled corner Jacobian of the VTK hex @p h of @p mesh: over the eight corners,
/// det(e1, e2, e3) / (|e1| |e2| |e3|) of the three edges leaving the corner in right-handed
/// order. 1 for a cube, <= 0 for an inverted corner (-2 if an edge has zero length).
double minScaledJacobian(const HexMesh& mesh, const std::array<int, 8>& h);

/// For every vertex listed in @p candidates, sets its position to the preferred candidate
/// (VertexCandidates::preferred) that maximizes the smallest minScaledJacobian() of its
/// incident hexes (other vertices at their current positions); ties keep the earlier
/// candidate. Only if every preferred candidate inverts a hex (value <= 0) are the other
/// candidates considered too. Vertices are visited in ascending order, twice, so that neighbouring
/// ambiguous vertices see each other's choice. Returns the number of vertices whose
/// position changed from the first candidate.
long chooseVertexPreimages(HexMesh& mesh, const VertexCandidates& candidates);

} // namespace HexEx
