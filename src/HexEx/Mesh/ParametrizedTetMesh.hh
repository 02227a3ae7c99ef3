#pragma once
/// @file ParametrizedTetMesh.hh
/// @ingroup kernel
/// A tet mesh together with its integer-grid map given per tet corner.

#include "TetMesh.hh"

#include <array>
#include <vector>

namespace HexEx {

/// Parameters of the four corners of every tet, each in that tet's own chart:
/// `params[c][i]` is the parameter of corner i of cell c.
using CornerParams = std::vector<std::array<Vec3d, 4>>;

/// Input of the extractor: a tet mesh plus its map.
struct ParametrizedTetMesh {
    TetMesh mesh;         ///< the tet mesh (positively oriented tets)
    CornerParams params;  ///< per-tet corner parameters, same order as the tet corners
};

} // namespace HexEx
