#pragma once
/// @file HexFaceNeighbours.hh
/// @ingroup kernel
/// The face neighbours of the hexes of a hex mesh, as the assembly knows them (the quads it
/// matched for checkAssembledHexes(), the implicit cells' twin faces), handed to the
/// OpenVolumeMesh writers so that they number the faces without matching quads again. The
/// table names the mesh it was built for by a digest: a mesh changed since then is not
/// numbered with it (the writers match the quads themselves then).

#include "../Core/DefaultInitAllocator.hh"
#include "HexMesh.hh"

#include <cstdint>

namespace HexEx {

/// Per face f of hex h (item 6h + f, faces in kHexFaces order: bottom, top, front, right,
/// back, left) the item 6h' + f' of the other hex's face with the same four vertices, or -1
/// for a boundary face; empty if there is no table.
struct HexFaceNeighbours {
    DefaultInitVector<int> items;  ///< per hex face its neighbour face item, or -1
    std::uint64_t digest = 0;      ///< hexMeshDigest() of the mesh the table was built for
};

/// A 64-bit digest of the hexes of @p mesh (their vertex indices in order), of the number of
/// vertices and of the number of polyhedra: equal digests mean, up to a collision, the same
/// hexes. Computed on @p threads threads; the value does not depend on it.
std::uint64_t hexMeshDigest(const HexMesh& mesh, int threads = 1);

/// True if @p table fits @p mesh: 6 entries per hex, its digest is @p digest (the caller's
/// hexMeshDigest() of @p mesh), every entry is -1 or another face whose entry names this one,
/// and, with @p compare_vertices, every pair of faces has the same four vertices as the same
/// cycle (either way round; the OpenVolumeMesh numbering compares them itself while it
/// orients the halffaces). Runs on @p threads threads.
bool hexFaceNeighboursFit(const HexMesh& mesh, const HexFaceNeighbours& table, std::uint64_t digest, int threads = 1,
                          bool compare_vertices = true);

} // namespace HexEx
