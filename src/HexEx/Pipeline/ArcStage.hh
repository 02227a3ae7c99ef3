#pragma once
/// @file ArcStage.hh
/// @ingroup pipeline
/// Optional pipeline stage "arcs" (ExtractionOptions::arcs): the exact image of every hex
/// edge (a polyline through the tets) and hex face (a triangulated patch), traced from the
/// darts of the hexes through the halfface transitions (Extraction/ArcTracing.hh).

#include "../Extraction/ArcTracing.hh"
#include "../Extraction/DartExtraction.hh"
#include "../GMap/GMap.hh"
#include "../Mesh/HexArcs.hh"
#include "../Mesh/HexMesh.hh"
#include "../Postprocessing/HexMeshAssembly.hh"

#include <vector>

namespace HexEx {

/// Input of arcStage() and provenanceStage(): views of the assembled map and its darts.
struct ArcInput {
    const TetMesh* mesh = nullptr;                ///< the tet mesh
    const Transitions* transitions = nullptr;     ///< transition per halfface
    const std::vector<TetSoS>* tets = nullptr;    ///< per-tet predicates (sanitized parameters)
    const HexMesh* hexes = nullptr;               ///< the assembled mesh
    const GMap<3>* map = nullptr;                 ///< the final map
    /// Per explicit hex (the first hex_darts->size() hexes): its map dart at corner 0 with
    /// frame (corner 1, corner 3, corner 4) (AssembleOutput::hex_darts).
    const std::vector<int>* hex_darts = nullptr;
    const DartSet* darts = nullptr;               ///< the extracted darts
    const std::vector<int>* map_dart_origin = nullptr;  ///< per map dart: its index in darts
    const ImplicitCells* implicit = nullptr;      ///< implicit cells (the hexes after the explicit ones), or null
    int threads = 1;                              ///< worker threads (resolved, >= 1)
};

/// Runs the stage. Never throws for defective maps: edges and faces whose arcs or patches
/// cannot be formed (walk failed, patch area not 1) are listed in HexArcs::failed_edges and
/// HexArcs::failed_faces. The result does not depend on the thread count.
HexArcs arcStage(const ArcInput& in);

/// Per map dart: its index among the extracted darts (inverse of the survivors' new index).
std::vector<int> mapDartOrigins(const std::vector<int>& new_index, int n_alive);

} // namespace HexEx
