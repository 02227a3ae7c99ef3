#pragma once
/// @file ExtractionReport.hh
/// Options and report of the one-call extraction API.

#include "../GMap/GMapValidator.hh"

#include <functional>
#include <string>
#include <vector>

namespace HexEx {

/// Options of extractHexMesh().
struct ExtractionOptions {
    /// Worker threads (0 = all hardware threads). The output is identical for any value.
    int threads = 0;
    /// Sanitization tolerance: parameter coordinates this close to an integer are snapped.
    double epsilon = 1e-6;
    /// Annihilate regular/anti dart pairs and so merge the vertices they duplicate (4.4).
    bool merge = true;
    /// Optional rotation index (0..23) per halfface instead of inferring transitions.
    const std::vector<int>* given_rotations = nullptr;
    /// Optional progress callback: (phase name, fraction done in [0, 1]).
    std::function<void(const std::string&, double)> progress;
};

/// Everything the extractor measured and decided; filled as data flows.
struct ExtractionReport {
    /// Input statistics.
    struct Input {
        long vertices = 0, tets = 0, boundary_faces = 0;  ///< mesh size
        long flipped_tets = 0, degenerate_tets = 0;       ///< parameter-space defects after sanitization
        long singular_edges = 0, singular_vertices = 0;   ///< singularities found from the transitions
        double parametric_volume = 0;                     ///< sum of signed parametric tet volumes
        long ambiguous_transitions = 0;                   ///< faces whose rotation was resolved from neighbours
        long unresolved_transitions = 0;                  ///< of those, not resolvable by edge consistency
        long snapped_coordinates = 0;                     ///< coordinates snapped to integers
    } input;  ///< input statistics
    /// Output statistics.
    struct Output {
        long vertices = 0, hexes = 0, non_hex_cells = 0;       ///< mesh size
        long quads = 0, boundary_quads = 0;                    ///< faces
        long unconnected_darts = 0;                            ///< darts with an alpha_0..alpha_2 link missing
        long repaired_face_connections = 0;                    ///< partially connected quads completed
    } output;  ///< output statistics
    /// Dart statistics.
    struct Darts {
        long extracted = 0, anti = 0, annihilated_pairs = 0, remaining_anti = 0;  ///< counts
        long asymmetric_links = 0;  ///< traced links whose partner traced elsewhere (dropped)
    } darts;  ///< dart statistics
    /// Timings in seconds per stage.
    struct Timings {
        double preprocess = 0, vertices = 0, darts = 0, connect = 0, postprocess = 0, assemble = 0;  ///< stages
    } timings_s;  ///< timings
    GMapValidation validation;           ///< validator result on the final map
    bool valid_all_hex = false;          ///< every cell a hex and the map valid
    int threads = 1;                     ///< threads used
    std::vector<std::string> warnings;   ///< human-readable warnings
};

} // namespace HexEx
