// checkAssembledHexes(): the linear check of an assembled all-hex mesh that keeps the report
// from calling a mesh valid that checkHexMesh() rejects (vertex identification merging
// distinct quads or corners of a valid map).

#include <HexEx/Mesh/HexMeshCheck.hh>
#include <HexEx/Postprocessing/AssembledMeshCheck.hh>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

using namespace HexEx;

namespace {

/// A column of @p n unit hexes along z (vertices 4k..4k+3 at height k).
HexMesh column(int n) {
    HexMesh m;
    for (int k = 0; k <= n; ++k)
        for (auto xy : {std::array<double, 2>{0, 0}, {1, 0}, {1, 1}, {0, 1}}) m.vertices.push_back(Vec3d(xy[0], xy[1], k));
    for (int k = 0; k < n; ++k) m.hexes.push_back({4 * k, 4 * k + 1, 4 * k + 2, 4 * k + 3, 4 * k + 4, 4 * k + 5, 4 * k + 6, 4 * k + 7});
    return m;
}

/// Every count of two checks is equal.
void expectSameCheck(const AssembledMeshCheck& a, const AssembledMeshCheck& b) {
    EXPECT_EQ(a.repeated_corner_hexes, b.repeated_corner_hexes);
    EXPECT_EQ(a.quads, b.quads);
    EXPECT_EQ(a.boundary_quads, b.boundary_quads);
    EXPECT_EQ(a.quads_shared_by_more_than_two, b.quads_shared_by_more_than_two);
    EXPECT_EQ(a.nonmanifold_boundary_edges, b.nonmanifold_boundary_edges);
    EXPECT_EQ(a.nonmanifold_boundary_vertices, b.nonmanifold_boundary_vertices);
}
} // namespace

TEST(AssembledMeshCheck, AValidColumnAgreesWithItsQuadCounts) {
    const AssembledMeshCheck c = checkAssembledHexes(column(3));
    EXPECT_EQ(c.quads, 16);
    EXPECT_EQ(c.boundary_quads, 14);
    EXPECT_EQ(c.repeated_corner_hexes, 0);
    EXPECT_EQ(c.quads_shared_by_more_than_two, 0);
    EXPECT_EQ(c.nonmanifold_boundary_edges, 0);
    EXPECT_EQ(c.nonmanifold_boundary_vertices, 0);
    EXPECT_TRUE(c.agrees(16, 14));
    EXPECT_EQ(c.warning(16, 14), "");
    EXPECT_FALSE(c.agrees(17, 14));  // a map with one quad more: two of its quads were merged
    EXPECT_EQ(c.warning(17, 14), "the vertex identification broke the mesh the valid map describes: 16 distinct quads (14 on the "
                                 "boundary) where the map has 17 (14) (distinct vertices of the map were merged)");
}

TEST(AssembledMeshCheck, AgreesWithCheckHexMeshOnAQuadInThreeHexes) {
    HexMesh m = column(2);
    // A third hex on the top of the first one (vertices 4..7), going down through new vertices.
    for (auto xy : {std::array<double, 2>{0, 0}, {1, 0}, {1, 1}, {0, 1}}) m.vertices.push_back(Vec3d(xy[0] + 3, xy[1], 0));
    m.hexes.push_back({12, 13, 14, 15, 4, 5, 6, 7});
    const AssembledMeshCheck c = checkAssembledHexes(m);
    const HexMeshCheckResult w = checkHexMesh(m);
    EXPECT_EQ(c.quads_shared_by_more_than_two, 1);
    EXPECT_EQ(w.quads_shared_by_more_than_two, 1);
    EXPECT_EQ(c.quads, w.quads);
    EXPECT_EQ(c.boundary_quads, w.boundary_quads);
    EXPECT_EQ(c.nonmanifold_boundary_edges, w.nonmanifold_boundary_edges);
    EXPECT_EQ(c.nonmanifold_boundary_vertices, w.nonmanifold_boundary_vertices);
    EXPECT_FALSE(c.agrees(c.quads, c.boundary_quads));
    EXPECT_FALSE(w.valid_all_hex);
}

TEST(AssembledMeshCheck, FindsRepeatedCornersAndPinchedBoundaries) {
    HexMesh m = column(1);
    m.hexes[0][6] = 5;
    EXPECT_EQ(checkAssembledHexes(m).repeated_corner_hexes, 1);
    EXPECT_EQ(checkAssembledHexes(HexMesh{m.vertices, {{0, 1, 2, 3, 4, 5, 6, 99}}, {}}).repeated_corner_hexes, 1);
    // Negative corners are out of range too, -1 included (in any of the eight places).
    for (int i = 0; i < 8; ++i)
        for (int bad : {-1, -2}) {
            HexMesh n = column(1);
            n.hexes[0][static_cast<std::size_t>(i)] = bad;
            EXPECT_EQ(checkAssembledHexes(n).repeated_corner_hexes, 1) << "corner " << i << " = " << bad;
        }
    // Two hexes touching in one vertex (vertex 6 of the first is vertex 0 of the second).
    HexMesh p = column(1);
    for (int k = 0; k < 2; ++k)
        for (auto xy : {std::array<double, 2>{1, 1}, {2, 1}, {2, 2}, {1, 2}}) p.vertices.push_back(Vec3d(xy[0], xy[1], 1 + k));
    p.hexes.push_back({8, 9, 10, 11, 12, 13, 14, 15});
    p.hexes[1][0] = 6;
    const AssembledMeshCheck c = checkAssembledHexes(p);
    EXPECT_EQ(c.nonmanifold_boundary_vertices, checkHexMesh(p).nonmanifold_boundary_vertices);
    EXPECT_EQ(c.nonmanifold_boundary_vertices, 1);
    EXPECT_EQ(c.nonmanifold_boundary_edges, 0);
    EXPECT_EQ(c.quads, 12);
    EXPECT_FALSE(c.agrees(12, 12));
}

TEST(AssembledMeshCheck, SameCountsOnAnyThreadCount) {
    // 12,000 columns of two hexes side by side (24,000 hexes: the parallel path), the first
    // hex with a repeated corner, and a third hex on the middle quad of column 7.
    HexMesh m;
    const int columns = 12000;
    for (int c = 0; c < columns; ++c) {
        HexMesh col = column(2);
        const int base = static_cast<int>(m.vertices.size());
        for (const auto& p : col.vertices) m.vertices.push_back(p + Vec3d(2.0 * c, 0, 0));
        for (auto h : col.hexes) {
            for (int& v : h) v += base;
            m.hexes.push_back(h);
        }
    }
    m.hexes[0][6] = m.hexes[0][5];
    const int top = 12 * 7 + 4;  // vertices 4..7 of column 7: its middle quad
    for (int k = 0; k < 4; ++k) m.vertices.push_back(Vec3d(100.0 + k, 0, 0));
    const int nv = static_cast<int>(m.vertices.size());
    m.hexes.push_back({nv - 4, nv - 3, nv - 2, nv - 1, top, top + 1, top + 2, top + 3});  // a third hex on it
    const AssembledMeshCheck one = checkAssembledHexes(m, 1);
    EXPECT_EQ(one.repeated_corner_hexes, 1);
    EXPECT_EQ(one.quads_shared_by_more_than_two, 1);
    EXPECT_EQ(one.quads, 11 * (columns - 1) + 6 + 5);  // 11 per column, the bad hex's column has one hex, plus the extra hex's 5 own quads
    for (const int threads : {2, 3}) {
        expectSameCheck(checkAssembledHexes(m, threads), one);
    }
}

TEST(AssembledMeshCheck, CountsTheQuadsAroundAVertexOfManyHexes) {
    // A 2x2x2 block whose centre vertex has index 0: the smallest vertex of its 12 inner
    // quads, each in two hexes (24 quads filed under one vertex, more than the small-bucket
    // sort handles). Then the same block with one inner quad in a third hex.
    HexMesh m;
    auto id = [](int i, int j, int k) { return i == 1 && j == 1 && k == 1 ? 0 : 1 + i + 3 * j + 9 * k - (i + 3 * j + 9 * k > 13 ? 1 : 0); };
    m.vertices.resize(27);
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) m.vertices[static_cast<std::size_t>(id(i, j, k))] = Vec3d(i, j, k);
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i)
                m.hexes.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                                   id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
    const AssembledMeshCheck c = checkAssembledHexes(m);
    EXPECT_EQ(c.quads, 36);
    EXPECT_EQ(c.boundary_quads, 24);
    EXPECT_TRUE(c.agrees(36, 24));
    // A third hex on the inner quad x = 1, 0 <= y, z <= 1 (through the centre), outside the block.
    for (int k = 0; k < 4; ++k) m.vertices.push_back(Vec3d(10, k % 2, k / 2));
    m.hexes.push_back({27, 28, 30, 29, id(1, 0, 0), id(1, 1, 0), id(1, 1, 1), id(1, 0, 1)});
    const AssembledMeshCheck d = checkAssembledHexes(m);
    const HexMeshCheckResult w = checkHexMesh(m);
    EXPECT_EQ(d.quads_shared_by_more_than_two, 1);
    EXPECT_EQ(d.quads, w.quads);
    EXPECT_EQ(d.boundary_quads, w.boundary_quads);
    EXPECT_EQ(d.quads, 36 + 5);
}

TEST(AssembledMeshCheck, CountsTheQuadsOfALargeGrid) {
    // 57^3 = 185,193 hexes: more than 2^20 quads, which are matched in two parts of the vertices.
    const int n = 57;
    HexMesh m;
    auto id = [&](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) m.vertices.push_back(Vec3d(i, j, k));
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                m.hexes.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                                   id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
    for (const int threads : {1, 2}) {
        const AssembledMeshCheck c = checkAssembledHexes(m, threads);
        EXPECT_EQ(c.quads, 3L * n * n * (n + 1));
        EXPECT_EQ(c.boundary_quads, 6L * n * n);
        EXPECT_TRUE(c.agrees(3L * n * n * (n + 1), 6L * n * n));
    }
}

TEST(AssembledMeshCheck, BoundaryEdgesAndFansAsCheckHexMeshOnManyHexes) {
    // 6,000 separate unit hexes in a row (24,000 boundary quads: the boundary items are sorted
    // and checked in chunks); every 3rd hex shares one vertex with the hex before it (a pinched
    // vertex), every 5th one (not a multiple of 3) an edge (four boundary quads at it).
    HexMesh m;
    const int n = 6000;
    long pinched = 0, sharedEdges = 0;
    for (int c = 0; c < n; ++c) {
        HexMesh h = column(1);
        const int base = static_cast<int>(m.vertices.size());
        for (const auto& p : h.vertices) m.vertices.push_back(p + Vec3d(2.0 * c, 0, 0));
        std::array<int, 8> hex = h.hexes[0];
        for (int& v : hex) v += base;
        if (c > 0 && c % 3 == 0) {
            hex[0] = m.hexes.back()[1];  // vertex 1 of the hex before
            ++pinched;
        } else if (c > 0 && c % 5 == 0) {
            hex[0] = m.hexes.back()[1];  // edge 1-5 of the hex before as the edge 0-4
            hex[4] = m.hexes.back()[5];
            ++sharedEdges;
        }
        m.hexes.push_back(hex);
    }
    const HexMeshCheckResult w = checkHexMesh(m);
    EXPECT_EQ(w.nonmanifold_boundary_edges, sharedEdges);
    EXPECT_EQ(w.nonmanifold_boundary_vertices, pinched);  // the ends of a shared edge keep one fan each
    EXPECT_EQ(pinched, 1999);
    EXPECT_EQ(sharedEdges, 800);
    for (const int threads : {1, 2, 3}) {
        const AssembledMeshCheck c = checkAssembledHexes(m, threads);
        EXPECT_EQ(c.boundary_quads, 6L * n);
        EXPECT_EQ(c.nonmanifold_boundary_edges, w.nonmanifold_boundary_edges);
        EXPECT_EQ(c.nonmanifold_boundary_vertices, w.nonmanifold_boundary_vertices);
    }
}

namespace {
/// An n^3 grid of unit hexes after @p lead hexes of a column elsewhere, with the twin-face
/// bits the implicit cells get (bit f: the neighbour across face f is a grid hex too).
struct TwinGrid {
    HexMesh mesh;
    std::vector<unsigned char> twins;  ///< per grid hex
    std::size_t first = 0;             ///< index of the first grid hex
};
TwinGrid twinGrid(int n, int lead) {
    TwinGrid g;
    g.mesh = column(lead);
    for (auto& p : g.mesh.vertices) p += Vec3d(-10, 0, 0);
    const int base = static_cast<int>(g.mesh.vertices.size());
    auto id = [&](int i, int j, int k) { return base + i + (n + 1) * (j + (n + 1) * k); };
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) g.mesh.vertices.push_back(Vec3d(i, j, k));
    g.first = g.mesh.hexes.size();
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                g.mesh.hexes.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                                        id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
                // kHexFaces: 0 z = 0, 1 z = 1, 2 y = 0, 3 x = 1, 4 y = 1, 5 x = 0.
                unsigned t = 0;
                if (k > 0) t |= 1u << 0;
                if (k + 1 < n) t |= 1u << 1;
                if (j > 0) t |= 1u << 2;
                if (i + 1 < n) t |= 1u << 3;
                if (j + 1 < n) t |= 1u << 4;
                if (i > 0) t |= 1u << 5;
                g.twins.push_back(static_cast<unsigned char>(t));
            }
    return g;
}
} // namespace

TEST(AssembledMeshCheck, TwinFacesGiveTheSameCounts) {
    // 2 column hexes + a 30^3 grid (27,002 hexes, the parallel path), twin pairs filed once.
    const int n = 30;
    TwinGrid g = twinGrid(n, 2);
    const long quads = 11 + 3L * n * n * (n + 1), boundary = 10 + 6L * n * n;
    for (const int threads : {1, 2}) {
        const AssembledMeshCheck plain = checkAssembledHexes(g.mesh, threads);
        const AssembledMeshCheck twin = checkAssembledHexes(g.mesh, threads, &g.twins, g.first);
        EXPECT_EQ(twin.quads, quads);
        EXPECT_EQ(twin.boundary_quads, boundary);
        EXPECT_TRUE(twin.agrees(quads, boundary));
        expectSameCheck(twin, plain);
    }
    // A third hex on an inner twin quad (x = 1 between grid hexes (0,0,0) and (1,0,0)): in
    // three hexes, found through the twin pair's two occurrences.
    const int nv = static_cast<int>(g.mesh.vertices.size());
    for (int k = 0; k < 4; ++k) g.mesh.vertices.push_back(Vec3d(100, k % 2, k / 2));
    const auto& h0 = g.mesh.hexes[g.first];
    g.mesh.hexes.push_back({nv, nv + 1, nv + 3, nv + 2, h0[1], h0[2], h0[6], h0[5]});
    const AssembledMeshCheck plain = checkAssembledHexes(g.mesh, 2);
    const AssembledMeshCheck twin = checkAssembledHexes(g.mesh, 2, &g.twins, g.first);
    EXPECT_EQ(twin.quads_shared_by_more_than_two, 1);
    EXPECT_EQ(twin.quads, quads + 5);
    expectSameCheck(twin, plain);
}

TEST(AssembledMeshCheck, TwinFacesOfAHexWithARepeatedCornerAreCheckedWithoutThem) {
    // A grid hex with a repeated corner: not counted, so its twins' faces are single
    // occurrences (boundary quads) as without the twin bits.
    TwinGrid g = twinGrid(6, 1);
    auto& h = g.mesh.hexes[g.first + 6 * 6 + 6 + 1];  // grid hex (1, 1, 1), inside
    h[6] = h[0];
    const AssembledMeshCheck plain = checkAssembledHexes(g.mesh, 1);
    const AssembledMeshCheck twin = checkAssembledHexes(g.mesh, 1, &g.twins, g.first);
    EXPECT_EQ(twin.repeated_corner_hexes, 1);
    EXPECT_EQ(twin.boundary_quads, 6 + 6L * 6 * 6 + 6);
    expectSameCheck(twin, plain);
}

TEST(AssembledMeshCheck, PrivateTwinPairsGiveTheSameCountsAndTable) {
    // The grid's vertices are in grid hexes only (private): its twin pairs are not filed.
    const int n = 30;
    TwinGrid g = twinGrid(n, 2);
    const auto base = static_cast<std::size_t>(g.mesh.hexes[g.first][0]);
    auto privateBits = [&](const std::vector<int>& except) {
        std::vector<std::uint64_t> bits((g.mesh.vertices.size() + 63) / 64, 0);
        for (std::size_t v = base; v < g.mesh.vertices.size(); ++v)
            if (std::find(except.begin(), except.end(), static_cast<int>(v)) == except.end()) bits[v / 64] |= std::uint64_t(1) << (v % 64);
        return bits;
    };
    // The grid hexes' corners as occurrences (unit cells in increasing corner 0).
    DefaultInitVector<std::array<int, 8>> corners(g.mesh.hexes.begin() + static_cast<long>(g.first), g.mesh.hexes.end());
    const std::vector<std::uint64_t> all = privateBits({});
    for (const int threads : {1, 2}) {
        HexFaceNeighbours table;
        const AssembledMeshCheck plain = checkAssembledHexes(g.mesh, threads);
        const AssembledMeshCheck priv = checkAssembledHexes(g.mesh, threads, &g.twins, g.first, &table, &corners, &all);
        EXPECT_TRUE(priv.agrees(11 + 3L * n * n * (n + 1), 10 + 6L * n * n));
        expectSameCheck(priv, plain);
        HexFaceNeighbours matched;
        checkAssembledHexes(g.mesh, threads, nullptr, 0, &matched);
        ASSERT_FALSE(table.items.empty());
        EXPECT_EQ(table.items, matched.items);
    }
    // A third hex on an inner twin quad: its four vertices are not private then (another hex
    // has them), so the quad is filed and found in three hexes.
    const int nv = static_cast<int>(g.mesh.vertices.size());
    for (int k = 0; k < 4; ++k) g.mesh.vertices.push_back(Vec3d(100, k % 2, k / 2));
    const auto h0 = g.mesh.hexes[g.first];
    g.mesh.hexes.push_back({nv, nv + 1, nv + 3, nv + 2, h0[1], h0[2], h0[6], h0[5]});
    const std::vector<std::uint64_t> some = privateBits({h0[1], h0[2], h0[6], h0[5]});
    const AssembledMeshCheck plain = checkAssembledHexes(g.mesh, 2);
    const AssembledMeshCheck priv = checkAssembledHexes(g.mesh, 2, &g.twins, g.first, nullptr, nullptr, &some);
    EXPECT_EQ(priv.quads_shared_by_more_than_two, 1);
    expectSameCheck(priv, plain);
}
