#pragma once
/// @file ProvenanceStage.hh
/// @ingroup pipeline
/// Optional pipeline stage "provenance" (ExtractionOptions::provenance): per hex its source tet
/// and integer grid cell, per hex vertex a tet and its grid coordinates, read from the darts
/// of the hexes built from darts and from the occurrences of the implicit cells.

#include "../Extraction/DartExtraction.hh"
#include "../Extraction/TetSoS.hh"
#include "../GMap/GMap.hh"
#include "../Mesh/HexMesh.hh"
#include "../Mesh/HexProvenance.hh"
#include "../Postprocessing/HexMeshAssembly.hh"
#include "../Preprocessing/Transitions.hh"

#include <vector>

namespace HexEx {

/// Input of provenanceStage().
struct ProvenanceInput {
    const TetMesh* mesh = nullptr;                ///< the tet mesh (adjacency built)
    const Transitions* transitions = nullptr;     ///< transition per halfface
    const std::vector<TetSoS>* tets = nullptr;    ///< per-tet predicates (sanitized parameters)
    const HexMesh* hexes = nullptr;               ///< the assembled mesh
    const GMap<3>* map = nullptr;                 ///< the final map
    /// Per hex built from darts (the first hex_darts->size() hexes): its map dart at corner 0
    /// with frame (corner 1, corner 3, corner 4) (AssembleOutput::hex_darts).
    const std::vector<int>* hex_darts = nullptr;
    const DartSet* darts = nullptr;               ///< the extracted darts
    const std::vector<int>* map_dart_origin = nullptr;  ///< per map dart: its index in darts
    const ImplicitCells* implicit = nullptr;      ///< implicit cells (the hexes after the explicit ones), or null
    int threads = 1;                              ///< worker threads (resolved, >= 1)
};

/// Runs the stage. Never throws for defective maps (a failed walk keeps the corner-0 dart's
/// tet, see HexProvenance::hex_source_tet). The result does not depend on the thread count.
HexProvenance provenanceStage(const ProvenanceInput& in);

} // namespace HexEx
