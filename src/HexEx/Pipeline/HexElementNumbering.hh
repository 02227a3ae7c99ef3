#pragma once
/// @file HexElementNumbering.hh
/// @ingroup pipeline
/// Ids of the edges and faces of the hexes of a hex mesh by first appearance (the numbering
/// of HexArcs), computed in parallel by grouping the occurrences by their smallest vertex.

#include "../Mesh/HexArcs.hh"
#include "../Mesh/HexMesh.hh"

#include <utility>
#include <vector>

namespace HexEx {

/// Per edge or face id: the hex that has it first and its local index there.
using HexElementOwners = std::vector<std::pair<int, int>>;

/// Fills HexArcs::edges, faces, hex_edges, hex_faces and hex_face_sign of @p out for the
/// hexes of @p hm (edges and faces are equal if their vertex sets are; ids in order of the
/// first occurrence, hexes in order, local indices in order) and returns the owner of every
/// edge and face id in @p edge_owner / @p face_owner. Same result for any @p threads.
void numberHexEdgesAndFaces(const HexMesh& hm, int threads, HexArcs& out, HexElementOwners& edge_owner,
                            HexElementOwners& face_owner);

} // namespace HexEx
