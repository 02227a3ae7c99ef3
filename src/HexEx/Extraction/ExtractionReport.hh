#pragma once
/// @file ExtractionReport.hh
/// @ingroup pipeline
/// Options and report of the one-call extraction API.

#include "../GMap/GMapValidator.hh"
#include "../Preprocessing/CornerRepair.hh"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace HexEx {

/// Name of the optional `int` halfface property holding the given rotation (0..23) of
/// each halfface's transition into its neighbour.
inline constexpr const char* kGivenRotationProperty = "hexex:rotation";

struct HexArcs;  // Mesh/HexArcs.hh
struct HexProvenance;  // Mesh/HexProvenance.hh

/// Options of extractHexMesh().
struct ExtractionOptions {
    /// Worker threads (0 = all hardware threads). The output is identical for any value.
    int threads = 0;
    /// Sanitization tolerance: parameter coordinates this close to an integer are snapped.
    double epsilon = 1e-6;
    /// Annihilate regular/anti dart pairs and so merge the vertices they duplicate (4.4).
    bool merge = true;
    /// Build unit cells that lie strictly inside one large proper tet directly from the grid,
    /// without darts (much less memory for coarse tet meshes). Used only when no tet is
    /// flipped; the output is the same as without it.
    bool implicit_cells = true;
    /// Cheap folds: grid points covered by exactly one proper and one flipped large tet of
    /// one chart (their darts would all annihilate) get no darts, and the tracing walks
    /// through them. Not used with #arcs. Off: every dart is extracted and annihilated.
    bool cheap_folds = true;
    /// Where the annihilation (with #merge) left broken hex cells, put the darts it touched
    /// back and annihilate again, phase by phase and then in other orders, keeping the run
    /// with the fewest broken cells (AnnihilationRetry; Documentation/algorithm.md); cells
    /// still broken then have their darts re-linked into hexes where possible
    /// (reconnectBrokenCells()). Maps without a broken cell are not affected. Off: the
    /// first pass's result is kept.
    bool annihilation_retries = true;
    /// Refuse maps whose total unsigned parametric volume exceeds this many grid cells
    /// (each hex costs 48 darts in memory; the default allows about 2 billion darts).
    double max_hexes = 4e7;
    /// Memory budget in bytes; 0 = automatic: defaultMemoryBudget() at the call (half of
    /// the memory available then). Before allocating per-grid-point and per-dart data the
    /// extractor estimates the memory it needs and throws ResourceError at once, naming the
    /// tets with the largest parametric images, if the estimate exceeds the budget; dart
    /// extraction also stops with ResourceError when the darts themselves exceed it.
    /// std::bad_alloc anywhere in the extraction becomes a ResourceError too.
    std::uint64_t max_memory = 0;
    /// Optional rotation index (0..23) per halfface instead of inferring transitions (the
    /// paper's assumption that matchings are known). If null, an `int` halfface property
    /// named kGivenRotationProperty on the tet mesh is used when present.
    const std::vector<int>* given_rotations = nullptr;
    /// Optional: if set, receives the exact image of every hex edge (a polyline, "arc") and
    /// hex face (a triangulated "patch") in the input (Documentation/arcs.md). Off (null) by
    /// default, and then costs nothing.
    HexArcs* arcs = nullptr;
    /// Optional: if set, receives per hex its source tet and integer grid cell, and per
    /// vertex a tet and its grid coordinates (HexProvenance). Off (null) by default, and then
    /// costs nothing; when set, the darts are kept until the end of the extraction.
    HexProvenance* provenance = nullptr;
    /// Optional progress callback: (phase name, fraction done in [0, 1]).
    std::function<void(const std::string&, double)> progress;
};

/// Everything the extractor measured and decided; filled as data flows.
struct ExtractionReport {
    /// Input statistics.
    struct Input {
        long vertices = 0;                ///< tet mesh vertices
        long tets = 0;                    ///< tets
        long boundary_faces = 0;          ///< boundary triangles
        long flipped_tets = 0;            ///< tets with negative parametric volume after sanitization
        long degenerate_tets = 0;         ///< tets with zero parametric volume after sanitization
        long singular_edges = 0;          ///< interior edges whose holonomy is not the identity
        long singular_vertices = 0;       ///< vertices on a number of singular edges other than 0 or 2
        double parametric_volume = 0;     ///< sum of signed parametric tet volumes
        long ambiguous_transitions = 0;   ///< faces whose rotation was resolved from neighbours
        long unresolved_transitions = 0;  ///< of those, not resolvable by edge consistency
        long snapped_coordinates = 0;     ///< parameter coordinates snapped to integers
        long inconsistent_transitions = 0;  ///< faces whose corners disagreed; transition by consensus
        long repaired_corners = 0;        ///< corner parameters outvoted at their vertex and replaced
        /// The first (by vertex) at most 32 replaced corners.
        std::vector<CornerRepair> repairs;
    } input;  ///< input statistics
    /// Output statistics.
    struct Output {
        long vertices = 0;                   ///< hex mesh vertices
        long hexes = 0;                      ///< hexahedra
        long non_hex_cells = 0;              ///< cells that are not hexahedra (written as polyhedra)
        long quads = 0;                      ///< quads (interior and boundary)
        long boundary_quads = 0;             ///< boundary quads
        long unconnected_darts = 0;          ///< missing alpha_0..alpha_2 links
        long repaired_face_connections = 0;  ///< partially connected quads completed
        long relinked_faces = 0;             ///< quads linked again by their vertices after the annihilation (relinkInconsistentFaces())
    } output;  ///< output statistics
    /// Dart statistics.
    struct Darts {
        long extracted = 0;          ///< darts extracted (regular and anti)
        long anti = 0;               ///< anti darts (from flipped tets)
        long annihilated_pairs = 0;  ///< regular/anti pairs removed
        long remaining_anti = 0;     ///< anti darts left after annihilation
        long asymmetric_links = 0;   ///< traced links whose partner traced elsewhere (dropped)
        long implicit_cells = 0;     ///< hexes built from the grid inside one tet, without darts
        long cancelled_fold_points = 0;  ///< (tet, grid point) occurrences of cancelled fold points (no darts; ExtractionOptions::cheap_folds)
        int annihilation_order = 0;      ///< order of the annihilation kept: 0 the first pass, 1 phase by phase, 2 descending, k > 2 hashed (ExtractionOptions::annihilation_retries)
        long broken_cells_after_annihilation = 0; ///< hex cells the annihilation left broken, after the retries
        long reconnected_cells = 0;   ///< hex cells formed by re-linking the darts of broken cells (reconnectBrokenCells())
        long unreconnected_cells = 0; ///< broken cells whose darts could not be re-linked into hexes (left as they were)
        /// A group of broken cells left as they were (darts joined by any link).
        struct Unreconnected {
            int dart = -1;         ///< its smallest dart
            int tet = -1;          ///< that dart's tet
            long darts = 0;        ///< darts of the group (a multiple of 48 if none is missing)
            long broken_cells = 0; ///< broken cells (<alpha_0, alpha_1, alpha_2> orbits that are not hexes) in it
            std::string reason;    ///< why no reconnection was found
        };
        std::vector<Unreconnected> unreconnected;  ///< the groups left (at most 8, in order of their smallest dart)
    } darts;  ///< dart statistics
    /// Edge arcs and face patches (only with ExtractionOptions::arcs).
    struct Arcs {
        /// At most this many ids are listed in failed_edge_ids / failed_face_ids.
        static constexpr std::size_t kMaxListed = 20;
        long edges = 0;                      ///< hex edges (each has an arc unless it failed)
        long faces = 0;                      ///< hex faces (each has a patch unless it failed)
        long failed_edges = 0;               ///< edges whose arc could not be formed
        long failed_faces = 0;               ///< faces whose patch could not be formed or is incomplete
        std::vector<int> failed_edge_ids;    ///< the first kMaxListed failed edge ids
        std::vector<int> failed_face_ids;    ///< the first kMaxListed failed face ids
    } arcs;  ///< arcs and patches
    /// Wall-clock seconds per stage.
    struct Timings {
        double preprocess = 0;   ///< transitions, sanitization, classification
        double vertices = 0;     ///< positions of the hex vertices
        double darts = 0;        ///< dart extraction
        double connect = 0;      ///< tracing of the alpha links
        double postprocess = 0;  ///< annihilation, face repair, map construction
        double assemble = 0;     ///< validation and hex mesh assembly
        double arcs = 0;         ///< edge arcs and face patches (ExtractionOptions::arcs)
    } timings_s;  ///< timings
    GMapValidation validation;           ///< validator result on the final map
    bool valid_all_hex = false;          ///< every cell a hex and the map valid
    int threads = 1;                     ///< threads used
    std::vector<std::string> warnings;   ///< human-readable warnings
};

} // namespace HexEx
