#pragma once
// Mesh checks shared by the extraction tests.

#include <HexEx/HexEx.hh>
#include <HexEx/IO/HexExFile.hh>
#include <HexEx/Mesh/HexMesh.hh>
#include <HexEx/Mesh/HexMeshQuality.hh>
#include <HexEx/Mesh/HexValidity.hh>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace HexExTest {

/// Hexes of @p m that classifyHexValidity() does not prove valid (invalid or undecided).
inline long notCertifiedValid(const HexEx::HexMesh& m) {
    long n = 0;
    for (const auto v : HexEx::hexValidities(m, 1)) n += v != HexEx::HexValidity::Valid;
    return n;
}

/// Examples/data/sphere.hexex with its interior vertex 40 moved by @p value along v in
/// every tet: a genuine needle fold (all tets agree, nothing to repair; the fold cancels
/// to the clean sphere's 216 hexes), adjacency built; false if the file is absent.
inline bool sphereWithNeedle(double value, HexEx::ParametrizedTetMesh& pm) {
    const std::string path = "Examples/data/sphere.hexex";
    if (!std::ifstream(path)) return false;
    pm = HexEx::readHexExFile(path);
    for (std::size_t c = 0; c < pm.params.size(); ++c)
        for (int k = 0; k < 4; ++k)
            if (pm.mesh.cell_vertex(HexEx::CellHandle(static_cast<int>(c)), k).idx() == 40) pm.params[c][k][1] += value;
    pm.mesh.build_adjacency();
    return true;
}

/// Bitwise equality of two meshes (positions compared as bytes, hexes, polyhedron faces).
inline void expectSameMesh(const HexEx::HexMesh& a, const HexEx::HexMesh& b) {
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    for (std::size_t v = 0; v < a.vertices.size(); ++v)
        EXPECT_EQ(std::memcmp(a.vertices[v].data(), b.vertices[v].data(), 3 * sizeof(double)), 0) << "vertex " << v;
    EXPECT_EQ(a.hexes, b.hexes);
    ASSERT_EQ(a.polyhedra.size(), b.polyhedra.size());
    for (std::size_t c = 0; c < a.polyhedra.size(); ++c) EXPECT_EQ(a.polyhedra[c].faces, b.polyhedra[c].faces) << "polyhedron " << c;
}

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
