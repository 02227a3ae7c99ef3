#pragma once
/// @file AssembledMeshCheck.hh
/// @ingroup pipeline
/// Linear check of an assembled all-hex mesh against what checkHexMesh() demands of it:
/// the dart-level validation (validateHexGMap()) cannot see that the vertex identification
/// (vertices = <alpha_1, alpha_2, alpha_3> orbits) gave two distinct quads the same four
/// vertices, or a hex two equal corners. The report must not call such a mesh valid.

#include "../Mesh/HexMesh.hh"

#include <string>

namespace HexEx {

/// Result of checkAssembledHexes(): what the vertex indices of the hexes say.
struct AssembledMeshCheck {
    long repeated_corner_hexes = 0;          ///< hexes with an out-of-range or repeated vertex index
    long quads = 0;                          ///< distinct quads (vertex sets) of the valid hexes
    long boundary_quads = 0;                 ///< of those, in exactly one hex
    long quads_shared_by_more_than_two = 0;  ///< quads in three or more hexes
    long nonmanifold_boundary_edges = 0;     ///< boundary-quad edges not in exactly two boundary quads
    long nonmanifold_boundary_vertices = 0;  ///< boundary vertices whose boundary quads form more than one fan

    /// True if nothing above is wrong and the quad counts equal the dart-level ones
    /// (@p dart_quads, @p dart_boundary_quads: <alpha_0, alpha_1, alpha_3> orbits).
    bool agrees(long dart_quads, long dart_boundary_quads) const;
    /// One warning naming what is wrong (empty if agrees()).
    std::string warning(long dart_quads, long dart_boundary_quads) const;
};

/// Checks the hexes of @p mesh (its polyhedra are ignored) in time linear in its size:
/// quads are bucketed by their smallest vertex, boundary edges and corners likewise. The
/// hex, quad and per-vertex boundary passes run on @p threads threads (>= 1); the result
/// does not depend on it.
AssembledMeshCheck checkAssembledHexes(const HexMesh& mesh, int threads = 1);

} // namespace HexEx
