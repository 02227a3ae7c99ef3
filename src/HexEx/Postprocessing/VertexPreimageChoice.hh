#pragma once
/// @file VertexPreimageChoice.hh
/// @ingroup pipeline
/// Where a vertex's grid point has several preimages among its h-vertices (a fold covers
/// it more than once), choose the one that gives the incident hexes the best shape.

#include "../Mesh/HexMesh.hh"
#include "VertexMerging.hh"

namespace HexEx {

/// Smallest scaled corner Jacobian of the VTK hex @p h of @p mesh: over the eight corners,
/// det(e1, e2, e3) / (|e1| |e2| |e3|) of the three edges leaving the corner in right-handed
/// order. 1 for a cube, <= 0 for an inverted corner (-2 if an edge has zero length).
double minScaledJacobian(const HexMesh& mesh, const std::array<int, 8>& h);

/// Sets the position of every vertex listed in @p candidates to one of its candidates.
/// Listed vertices that share a hex form a cluster and are chosen together: the
/// combination of preferred candidates (VertexCandidates::preferred) whose hexes (those
/// incident to the cluster) are best: fewest inverted hexes (minScaledJacobian() <= 0),
/// then the values compared as a list sorted ascending (the worst hex decides, then the
/// next worst, ...; ties: the first combination in lexicographic order); only if the best
/// such combination still inverts a hex are the other candidates considered too. Clusters
/// with more than 65536 combinations are chosen one vertex at a time by the same measure
/// over the vertex's own hexes (sweeps in ascending order until nothing changes, at most 8). Clusters are independent of the
/// order of the hexes. Vertices are visited in ascending order, twice, so that neighbouring
/// ambiguous vertices see each other's choice. Returns the number of vertices whose
/// position changed from the first candidate.
long chooseVertexPreimages(HexMesh& mesh, const VertexCandidates& candidates);

} // namespace HexEx
