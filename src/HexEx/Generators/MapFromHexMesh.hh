#pragma once
/// @file MapFromHexMesh.hh
/// @ingroup io
/// Integer-grid maps built from a given hex mesh, so that the expected extraction result is
/// that mesh, vertex for vertex: every hex is split into 24 tets, every hex gets its own
/// random chart, and face and cell centres can be moved in parameter space to create folds.

#include "../Grid/GridTransform.hh"
#include "../Mesh/HexMesh.hh"
#include "../Mesh/ParametrizedTetMesh.hh"

#include <cstddef>
#include <vector>

namespace HexEx {

/// Options of mapFromHexMesh().
struct MapFromHexOptions {
    /// Face and cell centres are moved in parameter space by up to this many grid units per
    /// coordinate (uniform noise, quantized to multiples of 2^-20); boundary face centres
    /// only within their face's plane. 0 keeps the map exact. Must lie in [0, 2] (from 1 on a
    /// centre can pass a whole grid unit, so folds cover neighbouring hexes' corners).
    double perturb = 0.0;
    /// Seed of the chart choice and of the perturbation (std::mt19937, same on every platform).
    unsigned seed = 1;
    /// Each source hex becomes a K x K x K block of grid cells (K = scale >= 1).
    int scale = 1;
};

/// Result of mapFromHexMesh().
struct MapFromHexResult {
    /// The tet mesh with its map. Vertices: first the source vertices (same indices), then
    /// one per distinct quad face (its centre), then one per hex (its centre). Tet
    /// `24 h + 4 j + k` belongs to hex h (face j in VTK face order, edge k of that face).
    ParametrizedTetMesh map;
    /// Per source hex, the chart: local lattice coordinates (corner i of the hex in VTK order
    /// at scale * (x_i, y_i, z_i), x_i, y_i, z_i in {0, 1}) to its tets' parameters.
    std::vector<GridTransform> charts;
    std::size_t faces = 0;           ///< distinct quad faces (= face centre vertices)
    std::size_t boundary_faces = 0;  ///< faces with one incident hex
    std::size_t negative_tets_3d = 0;  ///< tets not positively oriented in 3D (source hex inverted or warped)
};

/// Local lattice corner of VTK hex corner @p i (0..7): components in {0, 1}.
Vec3i hexCornerLattice(int i);

/// Builds the map described in MapFromHexMesh.hh from the all-hex mesh @p hexes.
/// Parameters of hex h are `charts[h]` applied to its local lattice coordinates: corners
/// at integer points, face centres at the face's middle and the cell centre at
/// (K/2, K/2, K/2), both plus their perturbation; a face centre is moved consistently in
/// both incident hexes' charts. Every interior face therefore carries a transition that is
/// a random grid automorphism. 3D positions: source vertices as given, centres at the
/// average of their corners.
/// @throws InputError if the mesh has polyhedra, a hex with repeated or out-of-range
///         vertices, a quad shared by more than two hexes or by two hexes with the same
///         orientation; std::invalid_argument for options out of range.
MapFromHexResult mapFromHexMesh(const HexMesh& hexes, const MapFromHexOptions& options);

} // namespace HexEx
