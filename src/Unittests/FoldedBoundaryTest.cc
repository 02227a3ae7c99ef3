/// @file FoldedBoundaryTest.cc
/// boundaryDoublets() and hexesOutsideSurface() (FoldedBoundary.hh): exact results on a
/// two-hex slab whose middle vertices are boundary doublets, on a grid without doublets, and
/// on a row of four cubes against a box that holds the first two.

#include <HexEx/Untangling/FoldedBoundary.hh>

#include <gtest/gtest.h>

#include <vector>

using namespace HexEx;

namespace {

/// A unit square split along its diagonal by the middle vertex v into two quads
/// (v, a, x, b) and (v, b, y, a) that share both edges at v, extruded to two hexes: v (index
/// 4) and its copy on the top (index 9) are boundary doublets.
HexMesh doubletSlab() {
    HexMesh m;
    for (int z = 0; z < 2; ++z) {
        m.vertices.emplace_back(0, 0, z);      // a
        m.vertices.emplace_back(1, 0, z);      // x
        m.vertices.emplace_back(1, 1, z);      // b
        m.vertices.emplace_back(0, 1, z);      // y
        m.vertices.emplace_back(0.5, 0.5, z);  // v
    }
    const int a = 0, x = 1, b = 2, y = 3, v = 4, t = 5;
    m.hexes.push_back({{v, a, x, b, v + t, a + t, x + t, b + t}});
    m.hexes.push_back({{v, b, y, a, v + t, b + t, y + t, a + t}});
    return m;
}

/// Four unit cubes in a row along x, from x = 0 to 4.
HexMesh cubeRow() {
    HexMesh m;
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 5; ++i) m.vertices.emplace_back(i, j, k);
    auto id = [](int i, int j, int k) { return (k * 2 + j) * 5 + i; };
    for (int i = 0; i < 4; ++i)
        m.hexes.push_back({{id(i, 0, 0), id(i + 1, 0, 0), id(i + 1, 1, 0), id(i, 1, 0), id(i, 0, 1), id(i + 1, 0, 1),
                            id(i + 1, 1, 1), id(i, 1, 1)}});
    return m;
}

/// The boundary of the box [0, 2] x [0, 1] x [0, 1], 12 triangles oriented outward.
TriangleSurface box() {
    TriangleSurface s;
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) s.points.emplace_back(2 * i, j, k);
    auto id = [](int i, int j, int k) { return (k * 2 + j) * 2 + i; };
    auto quad = [&](int p, int q, int r, int u) {  // counter-clockwise seen from outside
        s.triangles.push_back({{p, q, r}});
        s.triangles.push_back({{p, r, u}});
    };
    quad(id(0, 0, 0), id(0, 1, 0), id(1, 1, 0), id(1, 0, 0));  // z = 0
    quad(id(0, 0, 1), id(1, 0, 1), id(1, 1, 1), id(0, 1, 1));  // z = 1
    quad(id(0, 0, 0), id(1, 0, 0), id(1, 0, 1), id(0, 0, 1));  // y = 0
    quad(id(0, 1, 0), id(0, 1, 1), id(1, 1, 1), id(1, 1, 0));  // y = 1
    quad(id(0, 0, 0), id(0, 0, 1), id(0, 1, 1), id(0, 1, 0));  // x = 0
    quad(id(1, 0, 0), id(1, 1, 0), id(1, 1, 1), id(1, 0, 1));  // x = 2
    return s;
}

} // namespace

TEST(FoldedBoundary, DoubletsOfTheSplitSquareSlab) {
    EXPECT_EQ(boundaryDoublets(doubletSlab()), (std::vector<int>{4, 9}));
}

TEST(FoldedBoundary, NoDoubletsOnAGridOrARow) {
    HexMesh grid = cubeRow();
    EXPECT_TRUE(boundaryDoublets(grid).empty());
    // One cube: every boundary vertex is in three quads.
    grid.hexes.resize(1);
    EXPECT_TRUE(boundaryDoublets(grid).empty());
}

TEST(FoldedBoundary, WindingNumberInsideAndOutsideTheBox) {
    const TriangleSurface s = box();
    EXPECT_NEAR(windingNumber(s, Vec3d(1, 0.5, 0.5)), 1.0, 1e-12);
    EXPECT_NEAR(windingNumber(s, Vec3d(0.2, 0.9, 0.1)), 1.0, 1e-12);
    EXPECT_NEAR(windingNumber(s, Vec3d(3, 0.5, 0.5)), 0.0, 1e-12);
    EXPECT_NEAR(windingNumber(s, Vec3d(-1, 2, 3)), 0.0, 1e-12);
}

TEST(FoldedBoundary, OutsideHexesConnectedToTheSeeds) {
    const HexMesh row = cubeRow();  // hexes 0 and 1 inside the box, 2 and 3 outside
    const TriangleSurface s = box();
    EXPECT_EQ(hexesOutsideSurface(row, s, {3}), (std::vector<int>{2, 3}));
    EXPECT_EQ(hexesOutsideSurface(row, s, {2}), (std::vector<int>{2, 3}));
    EXPECT_TRUE(hexesOutsideSurface(row, s, {1}).empty());    // inside: not flooded from
    EXPECT_TRUE(hexesOutsideSurface(row, s, {}).empty());
    EXPECT_EQ(hexesOutsideSurface(row, s, {0, 3, 99, -1}), (std::vector<int>{2, 3}));  // out of range ignored
}
