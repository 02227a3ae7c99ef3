#pragma once
/// @file HexMesh.hh
/// @ingroup kernel
/// The extractor's output: hexahedra (VTK vertex order) plus polyhedra for cells whose
/// dart orbits are not hexahedra.

#include "../Core/Vec.hh"

#include <array>
#include <vector>

namespace HexEx {

/// A polyhedral cell given by its faces; each face is a vertex loop oriented outward.
struct Polyhedron {
    std::vector<std::vector<int>> faces;  ///< vertex indices per face
};

/// Output mesh: vertices, hexes as 8 vertex indices in VTK order (bottom quad 0-1-2-3
/// counter-clockwise seen from the top quad 4-5-6-7, vertex 4 above 0), and non-hex cells.
struct HexMesh {
    std::vector<Vec3d> vertices;              ///< vertex positions
    std::vector<std::array<int, 8>> hexes;    ///< hexahedra, VTK order
    std::vector<Polyhedron> polyhedra;        ///< cells that are not hexahedra, never dropped
};

} // namespace HexEx
