#pragma once
/// @file FeatureCorners.hh
/// The feature edges of a boundary quad surface and the corner angles between them, as used by
/// the boundary layer (BoundaryPillowing.cc: patches to skip) and the flat-corner splits
/// (FlatCornerSplitting.cc: corners to split).
#include <HexEx/Mesh/HexMesh.hh>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace HexEx {

/// Feature edges of a quad surface as sorted (smaller vertex, larger vertex) pairs.
struct FeatureEdges {
    std::vector<std::pair<int, int>> sorted;  ///< (min, max) per feature edge, sorted; fill, then look up

    /// True if the edge between vertices @p a and @p b (either order) is a feature edge.
    bool contains(int a, int b) const {
        return std::binary_search(sorted.begin(), sorted.end(), std::make_pair(std::min(a, b), std::max(a, b)));
    }
};

/// The cosine of the angle of quad @p q (vertex indices into @p mesh) at its corner @p k, if
/// both of its edges there are in @p features and neither has length 0; then it is stored in
/// @p cosine and the result is true. Otherwise false and @p cosine is unchanged.
inline bool featureCornerCosine(const HexMesh& mesh, const std::array<int, 4>& q, std::size_t k,
                                const FeatureEdges& features, double& cosine) {
    const int v = q[k], a = q[(k + 1) % 4], b = q[(k + 3) % 4];
    if (!features.contains(v, a) || !features.contains(v, b)) return false;
    const Vec3d& P = mesh.vertices[static_cast<std::size_t>(v)];
    const Vec3d ea = mesh.vertices[static_cast<std::size_t>(a)] - P, eb = mesh.vertices[static_cast<std::size_t>(b)] - P;
    const double la = ea.norm(), lb = eb.norm();
    if (!(la > 0 && lb > 0)) return false;
    cosine = (ea | eb) / (la * lb);
    return true;
}

} // namespace HexEx
