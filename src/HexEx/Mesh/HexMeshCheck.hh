#pragma once
/// @file HexMeshCheck.hh
/// @ingroup quality
/// The one validator of output meshes (paper section 3.1, mesh level): all cells hexes,
/// every face shared by at most two cells, boundary faces forming a closed 2-manifold,
/// Euler characteristic, plus hex quality. Used by the tests, `hexex validate` and the
/// benchmarks.

#include "HexMesh.hh"
#include "HexMeshQuality.hh"

namespace HexEx {

/// Result of checkHexMesh().
///
/// Faces are identified by their vertex sets (orientation and starting vertex do not
/// matter); faces of hexes and of polyhedra are pooled, so a quad shared by a hex and a
/// polyhedron is an interior face.
struct HexMeshCheckResult {
    long cells = 0;                          ///< hexes + polyhedra
    long hexes = 0;                          ///< hexahedra
    long non_hex_cells = 0;                  ///< polyhedra (cells that are not hexahedra)
    long vertices = 0;                       ///< all vertices, referenced or not
    long edges = 0;                          ///< distinct edges of all cell faces
    long faces = 0;                          ///< distinct faces of all cells
    long quads = 0;                          ///< distinct faces with four vertices
    long boundary_quads = 0;                 ///< quads incident to exactly one cell
    long boundary_faces = 0;                 ///< faces of any size incident to exactly one cell
    long quads_shared_by_more_than_two = 0;  ///< faces (of any size) incident to three or more cells
    long nonmanifold_boundary_edges = 0;     ///< boundary-face edges not in exactly two boundary faces
    long nonmanifold_boundary_vertices = 0;  ///< boundary vertices whose boundary faces form more than one fan (pinched)
    long invalid_cells = 0;                  ///< cells with an out-of-range or repeated vertex index, or a face with < 3 vertices (skipped)
    long euler_characteristic = 0;           ///< V - E + F - C (C without the invalid cells)
    QualityStats quality;                    ///< hex quality (scaled Jacobians)
    /// True if there is at least one cell, every cell is a valid hex, no face is shared by
    /// more than two cells and the boundary is a closed 2-manifold (every boundary edge in
    /// exactly two boundary quads, one fan of boundary quads around every boundary vertex).
    /// Element quality (inverted hexes) does not affect it.
    bool valid_all_hex = false;
};

/// Checks @p mesh (never throws for bad indices: such cells are counted in invalid_cells).
HexMeshCheckResult checkHexMesh(const HexMesh& mesh);

/// The six faces of a hex in VTK order, each a vertex loop (local indices 0..7) oriented
/// outward for a positively oriented hex (counter-clockwise seen from outside): bottom,
/// top, front (0 1 5 4), right, back, left.
extern const int kHexFaces[6][4];

} // namespace HexEx
