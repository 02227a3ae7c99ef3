#pragma once
/// @file ProvenanceStage.hh
/// @ingroup pipeline
/// Optional pipeline stage "provenance" (ExtractionOptions::provenance): per hex its source tet
/// and integer grid cell, per hex vertex a tet and its grid coordinates, read from the darts
/// of the hexes built from darts and from the occurrences of the implicit cells.

#include "ArcStage.hh"
#include "../Extraction/DartExtraction.hh"
#include "../Extraction/TetSoS.hh"
#include "../GMap/GMap.hh"
#include "../Mesh/HexMesh.hh"
#include "../Mesh/HexProvenance.hh"
#include "../Postprocessing/HexMeshAssembly.hh"
#include "../Preprocessing/Transitions.hh"

#include <vector>

namespace HexEx {

/// Input of provenanceStage(): the same views of the assembled map and its darts as arcStage()'s.
using ProvenanceInput = ArcInput;

/// Runs the stage. Never throws for defective maps (a failed walk keeps the corner-0 dart's
/// tet, see HexProvenance::hex_source_tet). The result does not depend on the thread count.
HexProvenance provenanceStage(const ProvenanceInput& in);

} // namespace HexEx
