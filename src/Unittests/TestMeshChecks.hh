#pragma once
// Mesh checks shared by the extraction tests.

#include <HexEx/HexEx.hh>
#include <HexEx/Mesh/HexMesh.hh>

#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace HexExTest {

/// The hex mesh extracted from @p pm with default options (adjacency built here).
inline HexEx::HexMesh extracted(HexEx::ParametrizedTetMesh pm) {
    pm.mesh.build_adjacency();
    HexEx::HexMesh hm;
    HexEx::extractHexMesh(pm, hm);
    return hm;
}

/// Number of hexes around each hex edge that lies on the cylinder axis (3D x = y = 0),
/// one entry per such edge.
inline std::vector<int> axisEdgeValences(const HexEx::HexMesh& hm) {
    static const int kEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                      {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    auto onAxis = [&](int v) { return std::hypot(hm.vertices[v][0], hm.vertices[v][1]) < 1e-9; };
    std::map<std::pair<int, int>, int> count;
    for (const auto& h : hm.hexes)
        for (const auto& e : kEdges) {
            int a = h[e[0]], b = h[e[1]];
            if (!onAxis(a) || !onAxis(b)) continue;
            if (a > b) std::swap(a, b);
            ++count[{a, b}];
        }
    std::vector<int> out;
    for (const auto& [e, n] : count) out.push_back(n);
    return out;
}

} // namespace HexExTest
