#pragma once
/// @file QuadExtraction.hh
/// @ingroup quad
/// The 2D pipeline's one-call API on the built-in types: extract the quad mesh of a
/// triangle mesh with an integer-grid map (ParametrizedTriMesh -> QuadMesh), with its
/// options and report. The templated entry for other kernels (OpenMesh, plain arrays) is
/// in QuadTraits.hh; `#include <HexEx/QuadEx.hh>` brings both.

#include "ParametrizedTriMesh.hh"
#include "QuadGMapValidator.hh"
#include "QuadMesh.hh"

#include <string>
#include <vector>

namespace HexEx {

/// Options of extractQuadMesh().
struct QuadExtractionOptions {
    /// Worker threads (0 = all hardware threads). The output is identical for any value.
    int threads = 0;
    /// At most one thread per this many triangles (at least one thread): below it, starting
    /// threads costs more than they save, so small maps run on one thread. 1 uses every
    /// requested thread (the tests of thread-count independence).
    long min_triangles_per_thread = 10000;
    /// Sanitization tolerance: parameter coordinates this close to an integer are snapped.
    double epsilon = 1e-6;
    /// Annihilate regular/anti dart pairs and so merge the vertices they duplicate (4.4).
    bool merge = true;
    /// Refuse maps whose total unsigned parametric area exceeds this many grid squares.
    double max_quads = 4e7;
    /// Optional rotation per halfedge (0..3 counter-clockwise quarter turns into the
    /// neighbour's chart; halfedge 3 f + i is the edge of triangle f opposite corner i)
    /// instead of inferring them from the parameters.
    const std::vector<int>* given_quarter_turns = nullptr;
};

/// Everything the 2D extractor measured and decided (the same keys as the 3D
/// ExtractionReport where they apply).
struct QuadExtractionReport {
    /// Input statistics.
    struct Input {
        long vertices = 0;                ///< triangle mesh vertices
        long triangles = 0;               ///< triangles
        long boundary_edges = 0;          ///< boundary edges of the surface
        long flipped_triangles = 0;       ///< triangles with negative parametric area after sanitization
        long degenerate_triangles = 0;    ///< triangles with zero parametric area after sanitization
        long cones = 0;                   ///< interior vertices whose transitions around them compose to a rotation (valence not 4 mod 4)
        double parametric_area = 0;       ///< sum of signed parametric triangle areas
        long ambiguous_transitions = 0;   ///< interior edges of (nearly) zero parametric length
        long unresolved_transitions = 0;  ///< of those, not resolvable by vertex consistency
        long snapped_coordinates = 0;     ///< parameter coordinates snapped to integers
    } input;  ///< input statistics
    /// Output statistics.
    struct Output {
        long vertices = 0;            ///< quad mesh vertices
        long quads = 0;               ///< quads
        long non_quad_faces = 0;      ///< faces that are not quads (written as polygons)
        long edges = 0;               ///< edges
        long boundary_edges = 0;      ///< edges on the boundary
        long unconnected_darts = 0;   ///< missing alpha_0..alpha_2 links
        long dropped_faces = 0;       ///< face orbits with fewer than three distinct vertices (not written)
    } output;  ///< output statistics
    /// Dart statistics.
    struct Darts {
        long extracted = 0;          ///< darts extracted (regular and anti)
        long anti = 0;               ///< anti darts (from flipped triangles)
        long annihilated_pairs = 0;  ///< regular/anti pairs removed
        long remaining_anti = 0;     ///< anti darts left after annihilation
        long asymmetric_links = 0;   ///< traced links whose partner traced elsewhere (dropped)
    } darts;  ///< dart statistics
    /// Wall-clock seconds per stage.
    struct Timings {
        double preprocess = 0;   ///< adjacency, transitions, sanitization, classification
        double darts = 0;        ///< dart extraction
        double connect = 0;      ///< tracing of the alpha links
        double postprocess = 0;  ///< annihilation and map construction
        double assemble = 0;     ///< validation, vertex positions and faces
    } timings_s;  ///< timings
    QuadGMapValidation validation;       ///< validator result on the final map
    bool valid_all_quad = false;         ///< every face a quad, no anti dart left, the map valid
    int threads = 1;                     ///< threads used (see QuadExtractionOptions::min_triangles_per_thread)
    std::vector<std::string> warnings;   ///< human-readable warnings
};

/// Extracts the quad mesh of @p input into @p output (cleared first). Never throws for
/// defective maps (flipped or degenerate triangles, noise): what could not be resolved is
/// counted in the report and non-quad faces are returned as polygons. Throws InputError
/// for unusable input (bad indices, non-manifold or inconsistently oriented surface,
/// non-finite or absurdly large parameters).
QuadExtractionReport extractQuadMesh(const ParametrizedTriMesh& input, QuadMesh& output,
                                     const QuadExtractionOptions& options = {});

} // namespace HexEx
