#pragma once
/// @file VertexMerging.hh
/// @ingroup pipeline
/// Vertex merging (paper 4.4.2). The equivalence classes are the <alpha_1, alpha_2, alpha_3>
/// orbits of the final map: h-vertices joined by annihilated alpha_0 pairs or by tracing
/// through degenerate tets share an orbit. This file decides the merged positions.

#include "../Core/DefaultInitAllocator.hh"
#include "../Mesh/TetMesh.hh"

#include <array>
#include <vector>

namespace HexEx {

/// Geometry the merging needs: the placed points (a grid point in one tet, shared by the
/// darts extracted there) and, per dart, its placed point.
struct DartPlacement {
    DefaultInitVector<int> point;                       ///< per dart: index of its placed point
    std::vector<Vec3d> position;                   ///< per placed point: 3D position of the grid point in its tet
    DefaultInitVector<std::array<int, 3>> boundary_hf;  ///< per placed point: boundary halffaces of the tet containing it (-1 = none)
    /// Extra placed points of removed regular darts (annihilation), each attached to the
    /// surviving dart extra_dart[k] that inherited its h-vertex: another preimage of the
    /// same grid point, used as a position candidate of that dart's vertex.
    std::vector<int> extra_dart;
    std::vector<int> extra_point;  ///< placed point of each extra (index into position)
    /// Per extra: 1 if it comes from an anti dart (a preimage in the flipped part of the
    /// map): such positions are candidates only after all others.
    std::vector<char> extra_flipped;
};

/// Classes whose h-vertices lie at several distinct positions (preimages of one grid point,
/// e.g. a proper one and fold copies), with those positions as candidates.
struct VertexCandidates {
    std::vector<int> vertex;        ///< the classes that have more than one candidate, ascending
    /// Per listed class: how many leading candidates its placement rule rates equally (all
    /// for interior classes; for boundary classes those closest to the boundary planes).
    std::vector<int> preferred;
    std::vector<int> offset;        ///< candidates of vertex[k]: position[offset[k] .. offset[k + 1])
    /// Candidate positions: distinct h-vertex positions, sorted by x, y, z; for boundary
    /// classes the boundary h-vertices, the boundary rule's choice first, then the others
    /// closest to the planes, then the rest.
    std::vector<Vec3d> position;
};

/// Merged position per class, always the position of one of its h-vertices (a true
/// preimage of the class's grid point, never an average). Positions of annihilated anti
/// darts (DartPlacement::extra_flipped) are appended to a class's candidates after all
/// others and never preferred. Interior classes (no h-vertex
/// on the boundary): the only distinct position if there is one; otherwise the first
/// candidate, and the class is listed in @p candidates (if given) so that
/// chooseVertexPreimages() can pick by the quality of the incident hexes. Boundary
/// classes: the point closest (least squares, Eigen) to the planes of the boundary faces
/// incident to its boundary h-vertices, replaced by the boundary h-vertex nearest to it so
/// the vertex stays on the input boundary (paper 4.4.2), among the boundary h-vertices
/// closest to those planes (smallest sum of squared distances, up to rounding); if it has
/// several boundary h-vertices it is listed too, with that choice first.
/// Whether a class is on the boundary is decided by its surviving darts only (a removed
/// dart's boundary h-vertex is then just one more candidate). A position held by more than
/// half of the class's surviving darts is its only preferred candidate (first), for
/// boundary classes only if its distance to the boundary planes is at most a quarter of
/// its distance to the plane rule's choice and it lies on one of those boundary faces or
/// at a boundary vertex of @p mesh. A boundary class one of whose candidates (positions of
/// surviving and removed regular darts) lies at a boundary vertex of @p mesh, and only one,
/// has that candidate as its only preferred one (first; it maps exactly onto the grid point,
/// a fold copy does not). For interior classes, the position with more than half
/// of the class's placed points (surviving and removed regular darts, one per tet and grid
/// point) comes before the majority of darts, and a candidate at a vertex of @p mesh, if
/// exactly one is and the map has annihilated darts, before both (issue 22;
/// Documentation/algorithm.md, "Vertices").
/// @p label gives the class of every dart (-1 for none), @p n_classes their number;
/// @p threads positions the classes in parallel (the result does not depend on it).
std::vector<Vec3d> mergedVertexPositions(const TetMesh& mesh, const std::vector<int>& label, int n_classes,
                                         const DartPlacement& darts, int threads = 1,
                                         VertexCandidates* candidates = nullptr);

} // namespace HexEx
