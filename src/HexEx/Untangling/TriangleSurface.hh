#pragma once
/// @file TriangleSurface.hh
/// @ingroup quality
/// A triangle soup with shared vertices: the surface the boundary vertices of an untangled
/// hex mesh must stay on (the boundary of the input tet mesh, or of the hex mesh itself).

#include "../Core/Vec.hh"
#include "../Mesh/HexMesh.hh"

#include <array>
#include <vector>

namespace HexEx {

class TetMesh;

/// Triangles over a shared vertex array.
struct TriangleSurface {
    std::vector<Vec3d> points;                   ///< vertex positions
    std::vector<std::array<int, 3>> triangles;   ///< vertex indices, outward orientation where known
};

/// The boundary triangles of @p mesh (faces that belong to one tet only). Uses the mesh's
/// adjacency if it is built, otherwise finds the faces by sorting their vertex triples.
TriangleSurface tetMeshBoundary(const TetMesh& mesh);

/// The boundary of the hexes of @p mesh as triangles: every quad used by exactly one hex
/// is split into two triangles along its diagonal 0-2. Polyhedra are ignored. Points are
/// all mesh vertices (unreferenced ones are harmless).
TriangleSurface hexMeshBoundary(const HexMesh& mesh);

} // namespace HexEx
