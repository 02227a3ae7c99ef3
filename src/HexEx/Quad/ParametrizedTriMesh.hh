#pragma once
/// @file ParametrizedTriMesh.hh
/// @ingroup quad
/// Input of the 2D (quad) pipeline: a triangle mesh with an integer-grid map given per
/// triangle corner, and its halfedge adjacency.

#include "../Core/DefaultInitAllocator.hh"
#include "../Core/Vec.hh"

#include <array>
#include <vector>

namespace HexEx {

/// A 2D parameter (u, v).
using Vec2d = OpenMesh::Vec2d;

/// A triangle mesh (any surface in 3D, with or without boundary, consistently oriented)
/// with a seamless integer-grid map: params[f][k] is the parameter of corner k of triangle f
/// in triangle f's own chart. Across every interior edge the two charts differ by a
/// quarter-turn rotation plus an integer translation; every unit square of the grid becomes
/// one quad.
struct ParametrizedTriMesh {
    std::vector<Vec3d> points;                   ///< vertex positions
    std::vector<std::array<int, 3>> triangles;   ///< vertex indices per triangle
    std::vector<std::array<Vec2d, 3>> params;    ///< per triangle corner (u, v)
};

/// Halfedge adjacency of a ParametrizedTriMesh. Halfedge `3 f + i` is the edge of triangle
/// f opposite its corner i, running from corner (i+1)%3 to corner (i+2)%3 (the 2D analogue
/// of the tet mesh's halfface `4 c + i`). The two per-halfedge arrays are sized without
/// zeroing (buildTriAdjacency() fills them in parallel).
struct TriAdjacency {
    std::vector<int, DefaultInitAllocator<int>> opposite;          ///< per halfedge: the neighbour's halfedge, -1 on the boundary
    std::vector<int> vertex_offset;                                ///< triangles of vertex v: vertex_triangles[vertex_offset[v] .. vertex_offset[v+1])
    std::vector<int, DefaultInitAllocator<int>> vertex_triangles;  ///< see vertex_offset (ascending per vertex)
};

/// Checks @p m (index ranges, repeated corners, finite parameters, one parameter triple
/// per triangle) and builds its adjacency. Throws InputError naming the triangle for bad
/// input, for an edge shared by more than two triangles and for neighbours with opposite
/// orientation (the surface must be an oriented 2-manifold with boundary).
TriAdjacency buildTriAdjacency(const ParametrizedTriMesh& m, int threads = 1);

} // namespace HexEx
