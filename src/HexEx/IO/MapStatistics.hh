#pragma once
/// @file MapStatistics.hh
/// @ingroup io
/// Summary statistics of a tet mesh with its integer-grid map (used by `hexex info` and by
/// the extractor report).

#include "../Mesh/ParametrizedTetMesh.hh"

#include <cstddef>

namespace HexEx {

/// Counts and measures of a parametrized tet mesh.
struct MapStatistics {
    std::size_t vertices = 0;        ///< number of vertices
    std::size_t tets = 0;            ///< number of tets
    std::size_t boundary_faces = 0;  ///< faces with only one incident tet
    std::size_t flipped_tets = 0;    ///< tets whose parameter image is negatively oriented (exact)
    std::size_t degenerate_tets = 0; ///< tets whose parameter image has zero volume (exact)
    double parametric_volume = 0;    ///< sum over tets of the signed parameter-space volume det/6
    Vec3d param_bbox_min = Vec3d(0, 0, 0);  ///< componentwise minimum over all corner parameters
    Vec3d param_bbox_max = Vec3d(0, 0, 0);  ///< componentwise maximum over all corner parameters
};

/// Computes the statistics of @p pm. Uses the mesh adjacency for the boundary face count if
/// it was built, and counts unpaired faces itself otherwise. Orientation signs are exact
/// (orient3d); the volume is summed in floating point. Empty meshes give zero counts and
/// a zero bounding box.
MapStatistics computeMapStatistics(const ParametrizedTetMesh& pm);

} // namespace HexEx
