#pragma once
/// @file QuadGMapValidator.hh
/// @ingroup quad
/// The validator of paper section 3.1 in 2D, for generalized maps of quad meshes (GMap<2>):
/// involutions, closed faces, edges connected as a whole (the 2D form of equation 1) and
/// quad faces (equation 3); the 3D-only equations (2, 4-6) have no 2D counterpart.

#include "../Core/DefaultInitAllocator.hh"
#include "../GMap/GMap.hh"

#include <array>

#include <string>
#include <vector>

namespace HexEx {

/// Violations found by validateQuadGMap(), counted per dart.
struct QuadGMapValidation {
    long darts = 0;                ///< alive darts checked
    long not_involution = 0;       ///< darts with alpha_i(alpha_i(d)) != d or linked to an erased dart
    long open_links = 0;           ///< darts with a free alpha_0 or alpha_1 (face not closed)
    long eq1_edge_connection = 0;  ///< (alpha_0 alpha_2)^2 != id where alpha_2 is not free
    long eq3_quad = 0;             ///< darts whose <alpha_0, alpha_1> orbit does not have 8 darts
    long boundary_darts = 0;       ///< darts with free alpha_2 (on the boundary)
    /// True if no violation was found.
    bool valid() const { return not_involution == 0 && open_links == 0 && eq1_edge_connection == 0 && eq3_quad == 0; }
    /// One-line human-readable summary.
    std::string summary() const;
};

/// An int array that resize() does not zero (filled by parallel passes).
using QuadLabelVector = std::vector<int, DefaultInitAllocator<int>>;

/// The links of a 2D map as the extractor builds it, alpha_0 .. alpha_2 per dart (every
/// dart alive, a free link is the dart itself), sized without zeroing.
using QuadLinks = std::vector<std::array<int, 3>, DefaultInitAllocator<std::array<int, 3>>>;

/// Orbit labels of a GMap<2>, numbered 0.. in order of their smallest dart (-1 for erased
/// darts). An orbit is the set of darts reachable by the two involutions (for a map whose
/// links are not involutions: reachable from the smallest dart not yet labelled).
struct QuadOrbitLabels {
    QuadLabelVector face;    ///< <alpha_0, alpha_1> orbit per dart
    QuadLabelVector vertex;  ///< <alpha_1, alpha_2> orbit per dart
    QuadLabelVector edge;    ///< <alpha_0, alpha_2> orbit per dart
    QuadLabelVector face_first;    ///< smallest dart of each face orbit
    QuadLabelVector vertex_first;  ///< smallest dart of each vertex orbit
    QuadLabelVector edge_first;    ///< smallest dart of each edge orbit
    int n_faces = 0;          ///< number of face orbits
    int n_vertices = 0;       ///< number of vertex orbits
    int n_edges = 0;          ///< number of edge orbits
};

/// Checks every alive dart of @p g; fills @p labels if given. Linear time. With
/// @p threads > 1 the checks and, when every link is an involution, the orbit labelling
/// run in parallel; the result does not depend on @p threads.
QuadGMapValidation validateQuadGMap(const GMap<2>& g, QuadOrbitLabels* labels = nullptr, int threads = 1);

/// validateQuadGMap() for the map whose links are @p links, every dart alive (what the
/// extractor builds): the same checks and labels, without a GMap.
QuadGMapValidation validateQuadLinks(const QuadLinks& links, QuadOrbitLabels* labels = nullptr, int threads = 1);

} // namespace HexEx
