#pragma once
/// @file HexFaceRecords.hh
/// The 6 faces of every hex of a HexMesh, keyed by their sorted vertices: equal keys are
/// the same quad seen from two hexes (an inner face), a key seen once is a boundary quad.

#include "HexMesh.hh"

#include <array>
#include <vector>

namespace HexEx {

/// One face of one hex: its vertices sorted (the key), the hex and the face number
/// (HexArcs::kHexFaces).
struct HexFaceRecord {
    std::array<int, 4> key;  ///< the face's four vertices, ascending
    int hex;                 ///< the hex the face belongs to
    int face;                ///< the face number within the hex (0-5)
};

/// Every face of every hex of @p mesh, sorted by key, then hex, then face number, so that
/// the records of one quad are adjacent and their order does not depend on anything else.
/// The vertex indices are not checked: validate them before if the mesh is user input.
std::vector<HexFaceRecord> sortedHexFaces(const HexMesh& mesh);

} // namespace HexEx
