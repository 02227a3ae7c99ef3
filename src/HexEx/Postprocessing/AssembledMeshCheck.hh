#pragma once
/// @file AssembledMeshCheck.hh
/// @ingroup pipeline
/// Linear check of an assembled all-hex mesh against what checkHexMesh() demands of it:
/// the dart-level validation (validateHexGMap()) cannot see that the vertex identification
/// (vertices = <alpha_1, alpha_2, alpha_3> orbits) gave two distinct quads the same four
/// vertices, or a hex two equal corners. The report must not call such a mesh valid.

#include "../Core/DefaultInitAllocator.hh"
#include "../Mesh/HexFaceNeighbours.hh"
#include "../Mesh/HexMesh.hh"

#include <array>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

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
/// Optional @p twin_faces (per hex from @p first_twin_hex on, e.g. the implicit cells):
/// bit f set if face f (kHexFaces order) is, with the same four vertex indices, the
/// opposite face (0-1, 2-4, 3-5) of another of these hexes whose bit for that face is set
/// (ImplicitCells::twin_faces). Such a pair is filed once, as two occurrences of its quad
/// (the same counts with fewer records); if a hex has a repeated corner the check runs
/// again without them, so the result is the same as without @p twin_faces.
/// With @p neighbours, the quads matched on the way give its face-neighbour table (every face
/// of a hex the other hex's face with the same vertices, or -1), with the mesh's digest; the
/// table is left empty unless every hex is valid and no quad is in more than two hexes. With
/// @p twin_faces the twins are paired through @p twin_corners (per hex from @p first_twin_hex
/// its corner occurrences, ImplicitCells::cells: unit cells of boxes in increasing corner 0);
/// without @p twin_corners there is no table then.
/// Optional @p private_vertices (with @p twin_faces; one bit per vertex, bit v % 64 of word
/// v / 64): vertex v is private if the only hexes with corner v are these twin-bit hexes with
/// one fixed corner occurrence (@p twin_corners) there, i.e. the vertex is that one grid
/// point of one unit-cell box (HexMeshAssembly's private vertices). A twin pair whose four
/// vertices are private is one quad in exactly these two hexes and in no other (any hex
/// with those vertices is a unit cell of that box with those four corners): it is counted
/// as one interior quad without being filed. The result is the same as without it.
AssembledMeshCheck checkAssembledHexes(const HexMesh& mesh, int threads = 1,
                                       const std::vector<unsigned char>* twin_faces = nullptr, std::size_t first_twin_hex = 0,
                                       HexFaceNeighbours* neighbours = nullptr,
                                       const DefaultInitVector<std::array<int, 8>>* twin_corners = nullptr,
                                       const std::vector<std::uint64_t>* private_vertices = nullptr);

} // namespace HexEx
