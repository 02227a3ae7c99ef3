#pragma once
/// @file FeatureCorners.hh
/// Boundary quad surfaces: quad normals, sorted edges, the feature edges and the corner angles
/// between them, as used by
/// the boundary layer (BoundaryPillowing.cc: patches to skip) and the flat-corner splits
/// (FlatCornerSplitting.cc: corners to split).
#include <HexEx/Mesh/HexMesh.hh>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <utility>
#include <vector>

namespace HexEx {

/// Unit normal of the quad @p q (vertex indices into @p mesh) from its diagonals, or zero if
/// it is degenerate or not finite.
inline Vec3d quadUnitNormal(const HexMesh& mesh, const std::array<int, 4>& q) {
    const auto& P = mesh.vertices;
    const Vec3d n = (P[static_cast<std::size_t>(q[2])] - P[static_cast<std::size_t>(q[0])]) %
                    (P[static_cast<std::size_t>(q[3])] - P[static_cast<std::size_t>(q[1])]);
    const double len = n.norm();
    return len > 0 && std::isfinite(len) ? n / len : Vec3d(0, 0, 0);
}

/// One edge of one quad: its vertices (a < b) and the quad's index.
struct QuadEdge {
    int a;  ///< smaller vertex
    int b;  ///< larger vertex
    int q;  ///< index of the quad
};

/// The 4 edges of every quad of @p quads, sorted by (a, b, q): the quads of an edge are
/// consecutive.
inline std::vector<QuadEdge> sortedQuadEdges(const std::vector<std::array<int, 4>>& quads) {
    std::vector<QuadEdge> edges;
    edges.reserve(quads.size() * 4);
    for (std::size_t i = 0; i < quads.size(); ++i)
        for (std::size_t k = 0; k < 4; ++k) {
            const int a = quads[i][k], b = quads[i][(k + 1) % 4];
            edges.push_back({std::min(a, b), std::max(a, b), static_cast<int>(i)});
        }
    std::sort(edges.begin(), edges.end(), [](const QuadEdge& x, const QuadEdge& y) {
        return std::tie(x.a, x.b, x.q) < std::tie(y.a, y.b, y.q);
    });
    return edges;
}

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
