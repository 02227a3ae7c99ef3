#pragma once
/// @file OvmHexFaces.hh
/// Faces and edges of the OpenVolumeMesh model of an all-hex mesh, found in small buckets of
/// quads and edges filed by their smallest vertex: a face is a quad shared by two hexes (or a
/// boundary quad), an edge a hex edge's vertex pair. The numbering is the one of
/// buildOvmFaces() (OvmFaces.hh) on the hexes' quads: faces and edges in order of first use,
/// the same halfface and halfedge orientations, so the files' bytes do not change; it needs no
/// copy of the loops and no sequential numbering pass.

#include "../Mesh/HexFaceNeighbours.hh"
#include "../Mesh/HexMesh.hh"
#include "OvmFaces.hh"

#include <array>
#include <vector>

namespace HexEx {

namespace detail {
/// Quads of a VTK-ordered hex, outward, in the order OpenVolumeMesh's hexahedral kernel
/// creates them (bottom, top, then the sides around the bottom); loop 6h + i of hex h is quad i.
constexpr int kOvmHexFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                    {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
/// The kernel's halfface order of a cell (pairs of opposite quads) as indices into kOvmHexFaces.
constexpr int kOvmHexOrder[6] = {0, 1, 5, 3, 4, 2};
} // namespace detail

/// Numbers the faces and edges of the hexes of @p mesh (no polyhedra; vertex indices
/// checked by the caller) as buildOvmFaces() numbers the hexes' quads in loop order (loop
/// 6h + i is quad detail::kOvmHexFaces[i] of hex h): per loop its halfface, per face its four
/// halfedges, the edges' end points. Matches quads and finds edge owners in per-vertex
/// buckets of records, then fills the halfedges hex by hex, in parallel.
/// Same result for any @p threads.
/// With @p neighbours (a table that fits @p mesh: hexFaceNeighboursFit() without the vertex
/// comparison, checked by the caller) the quads are not matched: its items are taken over
/// (left empty) as every face's neighbour, and the pairs' vertex cycles are compared while the
/// halffaces are oriented.
/// @return false (and @p out unspecified) if the mesh is outside what it covers: a hex with a
/// repeated vertex, a quad whose vertices bound quads of more than two hexes, more than
/// 2^27 hexes, or a pair of @p neighbours whose quads differ; buildOvmFaces() must be used then.
bool ovmHexFaces(const HexMesh& mesh, int threads, OvmFaces& out, HexFaceNeighbours* neighbours = nullptr);

} // namespace HexEx
