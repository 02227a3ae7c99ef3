#pragma once
/// @file Extractor.hh
/// @ingroup pipeline
/// The pipeline's driver: runs the stages of this folder in order (Documentation/algorithm.md,
/// "Stages") and fills the report as data flows. Included through HexEx.hh.

#include "../Extraction/ExtractionReport.hh"
#include "../Mesh/HexFaceNeighbours.hh"
#include "../Mesh/HexMesh.hh"
#include "../Mesh/ParametrizedTetMesh.hh"

namespace HexEx {

/// Extracts the hex mesh of @p input (adjacency must be built; see TetMesh::build_adjacency())
/// into @p output. Never throws for defective maps: what could not be resolved is counted
/// in the report and non-hex cells are returned as polyhedra. Throws InputError only for
/// unusable input (e.g. non-finite or absurdly large parameters), and its subclass
/// ResourceError when the map would need more memory than ExtractionOptions::max_memory
/// or an allocation fails (std::bad_alloc never escapes).
ExtractionReport extractHexMesh(const ParametrizedTetMesh& input, HexMesh& output,
                                const ExtractionOptions& options = {});

/// The same, taking the corner parameters of @p input over as the pipeline's working copy
/// instead of copying them (one copy of 96 bytes per tet less in time and peak memory):
/// for an input built only for this call, e.g. read from another mesh kernel. Same result
/// as the overload above; afterwards `input.params` is empty and `input.mesh` unchanged.
ExtractionReport extractHexMesh(ParametrizedTetMesh&& input, HexMesh& output,
                                const ExtractionOptions& options = {});

/// The same, and the hexes' face neighbours as the assembly found them into
/// @p face_neighbours (if not null; empty where the mesh check did not pass or there are
/// polyhedra): writeHexMesh() numbers the `.ovm`/`.ovmb` faces of @p output from them.
ExtractionReport extractHexMesh(ParametrizedTetMesh&& input, HexMesh& output, const ExtractionOptions& options,
                                HexFaceNeighbours* face_neighbours);

} // namespace HexEx
