#pragma once
/// @file HexProvenance.hh
/// @ingroup kernel
/// Where each extracted hex and hex vertex comes from in the input (ExtractionOptions::provenance):
/// per hex its source tet and integer grid cell, per vertex a tet and its grid coordinates.

#include <array>
#include <vector>

namespace HexEx {

/// Per-hex and per-vertex provenance of an extracted hex mesh, filled by extractHexMesh()
/// when ExtractionOptions::provenance points to it. Entries are indexed like HexMesh::hexes
/// and HexMesh::vertices; the result does not depend on the thread count.
struct HexProvenance {
    /// Per hex: the input tet whose parameter image contains the hex's centre (found by a
    /// straight walk from the hex's corner-0 dart to the centre through the transitions,
    /// crossing tets of zero parametric volume; ties broken by the symbolic perturbation of
    /// the dart ownership). If the walk fails (it meets the boundary or runs out of steps:
    /// seen only next to flipped tets), the tet of the corner-0 dart.
    std::vector<int> hex_source_tet;
    /// Per hex: the integer grid cell of the hex in the chart of its source tet, as its
    /// smallest corner `c` (the cell is `[c, c + (1,1,1)]`).
    std::vector<std::array<int, 3>> hex_grid_cell;
    /// Per vertex: a tet whose closed parameter image contains the vertex's grid point, or -1
    /// for a vertex of no hex (a vertex only of polyhedra).
    std::vector<int> vertex_source_tet;
    /// Per vertex: its integer grid coordinates in the chart of vertex_source_tet (0 when that
    /// is -1). Taken from the first hex corner (hexes in order, corners in VTK order) at the vertex.
    std::vector<std::array<int, 3>> vertex_grid_coords;
};

} // namespace HexEx
