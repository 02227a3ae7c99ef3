#pragma once
/// @file VertexMerging.hh
/// Vertex merging (paper 4.4.2). The equivalence classes are the <alpha_1, alpha_2, alpha_3>
/// orbits of the final map: h-vertices joined by annihilated alpha_0 pairs or by tracing
/// through degenerate tets share an orbit. This file decides the merged positions.

#include "../Mesh/TetMesh.hh"

#include <array>
#include <vector>

namespace HexEx {

/// Geometry the merging needs: the placed points (a grid point in one tet, shared by the
/// darts extracted there) and, per dart, its placed point.
struct DartPlacement {
    std::vector<int> point;                        ///< per dart: index of its placed point
    std::vector<Vec3d> position;                   ///< per placed point: 3D position of the grid point in its tet
    std::vector<std::array<int, 3>> boundary_hf;   ///< per placed point: boundary halffaces of the tet containing it (-1 = none)
};

/// Merged position per class: the centroid of the class's distinct h-vertex positions if
/// none lies on the boundary; otherwise the point closest (least squares, Eigen) to the
/// planes of the boundary faces incident to its boundary h-vertices, replaced by the
/// boundary h-vertex nearest to it so the vertex stays on the input boundary.
/// @p label gives the class of every dart (-1 for none), @p n_classes their number;
/// @p threads positions the classes in parallel (the result does not depend on it).
std::vector<Vec3d> mergedVertexPositions(const TetMesh& mesh, const std::vector<int>& label, int n_classes,
                                         const DartPlacement& darts, int threads = 1);

} // namespace HexEx
