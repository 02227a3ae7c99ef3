#pragma once
/// @file AssembleStage.hh
/// @ingroup pipeline
/// Pipeline stage "assemble": validates the final generalized map (paper 3.1) and builds
/// the hex mesh (vertex merging 4.4.2, hexes, polyhedra for other cells).

#include "../Mesh/HexFaceNeighbours.hh"
#include "../Postprocessing/HexMeshAssembly.hh"

#include <string>
#include <vector>

namespace HexEx {

/// Input of assembleStage().
struct AssembleInput {
    const GMap<3>* map = nullptr;              ///< the final map
    const DartGeometry* geometry = nullptr;    ///< placement of its darts
    const ImplicitCells* implicit = nullptr;   ///< implicit cells, or null when the fast path is off
    int threads = 1;                           ///< worker threads (resolved, >= 1)
    bool want_hex_darts = false;               ///< fill AssembleOutput::hex_darts (for the arcs stage)
    bool want_face_neighbours = false;         ///< fill AssembleOutput::face_neighbours (for the OVM writers)
};

/// Output of assembleStage().
struct AssembleOutput {
    HexMesh mesh;                       ///< the extracted mesh
    GMapValidation validation;          ///< validator result on the map
    AssemblyStats stats;                ///< counts of the assembly
    std::vector<std::string> warnings;  ///< warnings of this stage
    /// False if the map is valid and all-hex but the assembled mesh is not what it describes
    /// (checkAssembledHexes(): vertex identification merged distinct quads or corners);
    /// a warning then names what is wrong.
    bool mesh_agrees = true;
    /// With AssembleInput::want_hex_darts: per hex built from darts, its dart at corner 0
    /// whose frame points to corners 1, 3 and 4 (see assembleHexMesh()).
    std::vector<int> hex_darts;
    /// With AssembleInput::want_face_neighbours: the hexes' face neighbours found by the mesh
    /// check (empty if it did not run or did not pass, e.g. with polyhedra).
    HexFaceNeighbours face_neighbours;
};

/// Runs the stage. The result does not depend on the thread count.
AssembleOutput assembleStage(const AssembleInput& in);

} // namespace HexEx
