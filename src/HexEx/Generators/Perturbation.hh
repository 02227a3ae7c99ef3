#pragma once
/// @file Perturbation.hh
/// @ingroup io
/// Stress-test perturbation of an integer-grid map after the HexEx paper, section 5.1:
/// every vertex's parameter is moved by uniform noise, consistently in all charts that see
/// the vertex, while boundary planes and singular edges keep their grid alignment.

#include "../Mesh/HexMesh.hh"
#include "../Mesh/ParametrizedTetMesh.hh"

#include <cstddef>

namespace HexEx {

/// What perturbParameters() did.
struct PerturbStats {
    std::size_t vertices = 0;              ///< vertices visited (with at least one tet)
    std::size_t moved_vertices = 0;        ///< vertices displaced by a non-zero vector
    std::size_t boundary_vertices = 0;     ///< vertices constrained by at least one boundary plane
    std::size_t singular_vertices = 0;     ///< vertices constrained by at least one singular edge
    std::size_t fixed_vertices = 0;        ///< vertices whose constraints left no free axis
    double max_displacement = 0;           ///< largest absolute displacement of any coordinate
};

/// Moves the parameter of every vertex of @p pm by noise uniform in [-@p a, @p a] per axis.
///
/// The displacement is drawn in the chart of the vertex's lowest-index tet (the reference
/// chart) and carried into every other incident tet's chart by the rotation part of the
/// transitions (computeTransitions()), propagated breadth-first over the interior faces
/// around the vertex; so the vertex moves consistently in all its charts and transitions
/// stay what they were. Constraints, expressed as axes of the reference chart:
/// - a boundary face of the vertex whose three corner parameters share the same integer
///   value in some coordinate lies in an integer plane: that coordinate stays fixed (one
///   plane leaves two free axes, a boundary edge one, a corner none);
/// - a vertex on a singular edge (findSingularities()) moves only along the edge's axis
///   (not at all if its singular edges run along different axes or are not axis-aligned).
///
/// Three numbers are drawn per vertex in vertex order whatever the constraints, from a
/// std::mt19937 seeded with @p seed and mapped to doubles by hand, so the result is the
/// same on every platform. Builds the adjacency of @p pm if needed.
/// @throws std::invalid_argument if @p a is negative or not finite, or if the parameter
///         count does not match the cell count.
void perturbParameters(ParametrizedTetMesh& pm, double a, unsigned seed, PerturbStats* stats = nullptr);

/// What perturbHexMesh() did.
struct HexPerturbStats {
    std::size_t vertices = 0;           ///< vertices of the mesh
    std::size_t interior_vertices = 0;  ///< vertices that may move (on no boundary quad and no polyhedron)
    std::size_t moved_vertices = 0;     ///< interior vertices displaced by a non-zero vector
    long inverted_before = 0;           ///< hexes with a corner Jacobian <= 0 before
    long inverted_after = 0;            ///< and after
    double max_displacement = 0;        ///< largest displacement length
};

/// Tangles the hex mesh @p mesh for tests of the untangler: every interior vertex moves by
/// a vector uniform in the cube [-d, d]^3 with d = @p fraction times the mean length of the
/// hex edges at the vertex (measured before any vertex moves). Boundary vertices (on a quad
/// used by one hex), vertices of polyhedra and unreferenced vertices keep their positions
/// bit for bit, so the original positions stay a valid placement with the same boundary.
/// With a fraction around 1 most hexes of a regular mesh invert.
///
/// Three numbers are drawn per vertex in vertex order, whether or not the vertex moves,
/// from a std::mt19937 seeded with @p seed and mapped to doubles by hand: the same input,
/// fraction and seed give the same output on every platform.
/// @throws std::invalid_argument if @p fraction is negative or not finite, or a hex
///         references a vertex out of range.
void perturbHexMesh(HexMesh& mesh, double fraction, unsigned seed, HexPerturbStats* stats = nullptr);

} // namespace HexEx
