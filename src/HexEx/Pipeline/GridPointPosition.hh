#pragma once
/// @file GridPointPosition.hh
/// @ingroup pipeline
/// 3D position of an integer grid point seen from one tet (barycentric interpolation of
/// the tet's corner positions), shared by the vertex placement and the implicit cells.

#include "../Extraction/DartExtraction.hh"
#include "../Mesh/TetMesh.hh"

#include <array>
#include <vector>

namespace HexEx {

/// Positions of grid points of one tet's chart, by barycentric coordinates with exact
/// zeros where a predicate (or the implicit-cell flags of the darts' dense index) puts the
/// point on a face. What does not depend on the point (the tet's corner parameters and
/// positions, its volume, one cross product, its dense index) is taken once, for many
/// points of the tet; every point's value is computed by the same operations in the same
/// order as for a single point, so it is the same double.
class TetPointPositions {
public:
    /// For tet @p t of @p mesh (@p tets: its predicate data; @p darts: its dense index);
    /// the three must outlive this object.
    TetPointPositions(const TetMesh& mesh, const std::vector<TetSoS>& tets, const DartSet& darts, int t);
    /// Position of grid point @p z. If @p boundary_hf is given it receives the boundary
    /// halffaces of the tet through @p z (at most 3; the caller initializes it to -1).
    Vec3d operator()(const Vec3i& z, std::array<int, 3>* boundary_hf = nullptr) const;

private:
    const TetMesh* mesh_;
    const TetSoS* T_;
    const DartSet::DenseIndex* dense_ = nullptr;  // with flags, or null
    int t_;
    Vec3d e1_, e2_, e3_, c12_;                    // corner differences from corner 0, e1 x e2
    double V_;                                    // (e1 x e2) . e3
    std::array<Vec3d, 4> x_;                      // the corners' 3D positions
};

/// Position of grid point @p z of tet @p t's chart (TetPointPositions for one point).
/// If @p boundary_hf is given it receives the boundary halffaces of @p t through @p z
/// (at most 3; the caller initializes it to -1).
Vec3d gridPointPosition(const TetMesh& mesh, const std::vector<TetSoS>& tets, const DartSet& darts, int t,
                        const Vec3i& z, std::array<int, 3>* boundary_hf);

} // namespace HexEx
