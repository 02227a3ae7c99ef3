#pragma once
/// @file QuadMesh.hh
/// @ingroup quad
/// Output of the 2D pipeline: quads plus the polygons whose dart orbits are not quads.

#include "../Core/Vec.hh"

#include <array>
#include <vector>

namespace HexEx {

/// A polygon mesh: quads (counter-clockwise in parameter space, i.e. oriented like the
/// input triangles) and, never dropped, faces that are not quads.
struct QuadMesh {
    std::vector<Vec3d> vertices;               ///< vertex positions
    std::vector<std::array<int, 4>> quads;     ///< quads, vertex loops
    std::vector<std::vector<int>> polygons;    ///< faces that are not quads, vertex loops
};

} // namespace HexEx
