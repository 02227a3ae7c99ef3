#pragma once
/// @file PlacementStage.hh
/// @ingroup pipeline
/// Pipeline stage "vertices": the 3D geometry of the surviving darts (position of each
/// dart's grid point in its tet, its boundary faces, the frame's handedness), input of the
/// vertex merging (paper 4.4.2) in the assembly.

#include "../Extraction/DartExtraction.hh"
#include "../Postprocessing/HexMeshAssembly.hh"

#include <utility>
#include <vector>

namespace HexEx {

/// Input of placementStage().
struct PlacementInput {
    const TetMesh* mesh = nullptr;              ///< the tet mesh
    const std::vector<TetSoS>* tets = nullptr;  ///< per-tet predicates
    const DartSet* darts = nullptr;             ///< the extracted darts
    const std::vector<char>* alive = nullptr;   ///< per dart: survived annihilation
    const std::vector<int>* new_index = nullptr;///< per dart: index among the survivors
    int n_alive = 0;                            ///< survivors
    int threads = 1;                            ///< worker threads (resolved, >= 1)
    /// (removed dart, heir) pairs (AnnihilateOutput::heir); null or empty: no extra candidates.
    const std::vector<std::pair<int, int>>* heir = nullptr;
};

/// Places the surviving darts. A run of darts at the same (tet, grid point) shares one
/// placed point, computed once. With @p in.heir, every removed dart whose h-vertex a
/// survivor inherited adds its own placed point to that survivor
/// (DartPlacement::extra_dart / extra_point, extra_flipped for anti darts): another
/// preimage of the same grid point, a candidate for the vertex position. The result does not depend on the thread count.
DartGeometry placementStage(const PlacementInput& in);

} // namespace HexEx
