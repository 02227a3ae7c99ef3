#pragma once
/// @file SingularityGraph.hh
/// The singularity graph of a parametrized tet mesh: its singular edges (interior edges
/// whose transitions around them do not compose to the identity) as 3D line segments with
/// their valences, ready to be drawn or written (writeSingularEdgesVtk(), `hexex extract
/// --singularities`) or attached to the user's mesh.

#include "../Core/Handles.hh"
#include "../Core/Vec.hh"
#include "../Mesh/ParametrizedTetMesh.hh"

#include <array>
#include <vector>

namespace HexEx {

/// Singular edges as a graph on the vertices they touch.
struct SingularityGraph {
    std::vector<Vec3d> points;                 ///< positions of the graph's vertices
    std::vector<VertexHandle> point_vertices;  ///< the tet-mesh vertex of each point
    std::vector<std::array<int, 2>> segments;  ///< per singular edge: its two points
    std::vector<EdgeHandle> edges;             ///< per singular edge: the tet-mesh edge (TetMesh::edge_vertices())
    std::vector<int> valences;                 ///< per singular edge: quarter turns around it (4 = regular)
};

/// Computes the singularity graph of @p pm (adjacency must be built): transitions inferred
/// from the corner parameters (computeTransitions(), with @p givenRotations if non-null),
/// singular edges and their valences (findSingularities()). Edges come in edge-index order,
/// points in the order the edges first meet them. @p threads parallelizes the transitions
/// and the edge walk; the result does not depend on it.
SingularityGraph singularityGraph(const ParametrizedTetMesh& pm, const std::vector<int>* givenRotations = nullptr,
                                  int threads = 1);

} // namespace HexEx
