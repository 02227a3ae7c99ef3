/// @file FoldedBoundaryTest.cc
/// boundaryDoublets(), hexesOutsideSurface() and removeHexes() (FoldedBoundary.hh): exact
/// results on a two-hex slab whose middle vertices are boundary doublets, on a grid without
/// doublets, and on a row of cubes against a box that holds the first two; OptimizeOptions::pillow
/// removes a hex outside the box that is positive at its corners but negative inside, and every
/// hex of the result is certified valid (exact counts, 1 and 2 threads identical).

#include <HexEx/Mesh/HexMeshQuality.hh>
#include <HexEx/Untangling/FoldedBoundary.hh>
#include <HexEx/Untangling/HexOptimizer.hh>
#include <HexEx/Untangling/UntangleWithRepair.hh>

#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "TestMeshChecks.hh"

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

/// The first two cubes of cubeRow() and, on their face x = 2, a hex outside the box [0, 2] x
/// [0, 1] x [0, 1] whose far corners were found by a random search: J > 0 at its 8 corners
/// but negative inside (checked in the test).
HexMesh rowWithInvalidFlap() {
    HexMesh m = cubeRow();
    m.hexes.resize(2);  // x from 0 to 2; vertices (i, j, k) at (k * 2 + j) * 5 + i
    auto id = [](int i, int j, int k) { return (k * 2 + j) * 5 + i; };
    const int far[4] = {static_cast<int>(m.vertices.size()), static_cast<int>(m.vertices.size()) + 1,
                        static_cast<int>(m.vertices.size()) + 2, static_cast<int>(m.vertices.size()) + 3};
    m.vertices.emplace_back(2.7830701737099623, 0.2675202495308675, 0.028419666974264235);
    m.vertices.emplace_back(2.9585594079978104, 0.5418894157777765, 0.45957374984705546);
    m.vertices.emplace_back(3.4496295600277698, 0.32624071263997101, 0.80339082012598906);
    m.vertices.emplace_back(2.842993795455059, 1.3538251488596802, 1.1508942871914223);
    m.hexes.push_back({{id(2, 0, 0), far[0], far[1], id(2, 1, 0), id(2, 0, 1), far[2], far[3], id(2, 1, 1)}});
    return m;
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
    TriangleSurface inward = s;  // the same box with its triangles turned inward
    for (auto& t : inward.triangles) std::swap(t[1], t[2]);
    EXPECT_NEAR(windingNumber(inward, Vec3d(1, 0.5, 0.5)), -1.0, 1e-12);
    EXPECT_EQ(hexesOutsideSurface(row, inward, {1, 3}), (std::vector<int>{2, 3}));
}

TEST(FoldedBoundary, RemoveHexesKeepsOrderAndReportsTheExposedVertices) {
    HexMesh row = cubeRow();
    // Hex 1 (x from 1 to 2): every vertex is still used; the quads x = 1 and x = 2 are exposed.
    EXPECT_EQ(removeHexes(row, {1, 1, 7, -2}), (std::vector<int>{1, 2, 6, 7, 11, 12, 16, 17}));
    ASSERT_EQ(row.hexes.size(), 3u);
    EXPECT_EQ(row.vertices.size(), 20u);
    EXPECT_EQ(row.hexes[1], cubeRow().hexes[2]);
    // The last hex: the 4 vertices at x = 4 go, those at x = 3 are exposed (new indices).
    row = cubeRow();
    EXPECT_EQ(removeHexes(row, {3}), (std::vector<int>{3, 7, 11, 15}));
    EXPECT_EQ(row.hexes.size(), 3u);
    EXPECT_EQ(row.vertices.size(), 16u);
    EXPECT_EQ(row.vertices[15], Vec3d(3, 1, 1));
    EXPECT_EQ(row.hexes[0][7], 12);  // (0, 1, 1): (1 * 2 + 1) * 4 + 0 after the removal
    row.polyhedra.push_back(Polyhedron{});
    EXPECT_THROW(removeHexes(row, {0}), std::invalid_argument);
}

TEST(FoldedBoundary, PillowRemovesAnInvalidFlapOutsideTheSurface) {
    const HexMesh input = rowWithInvalidFlap();
    std::array<Vec3d, 8> flap;
    for (std::size_t k = 0; k < 8; ++k) flap[k] = input.vertices[static_cast<std::size_t>(input.hexes[2][k])];
    ASSERT_GT(hexScaledJacobian(flap), 0.0);                     // positive at the corners,
    ASSERT_EQ(classifyHexValidity(flap), HexValidity::Invalid);  // negative inside
    const TriangleSurface surface = box();
    EXPECT_EQ(hexesOutsideSurface(input, surface, {2}), (std::vector<int>{2}));

    HexMesh results[2];
    for (int threads = 1; threads <= 2; ++threads) {
        HexMesh m = input;
        OptimizeOptions o;
        o.pillow = true;
        o.threads = threads;
        const OptimizeReport r = optimizeHexMesh(m, o, &surface);
        EXPECT_TRUE(r.success) << r.message;
        EXPECT_EQ(r.trimmed_hexes, 1);
        EXPECT_EQ(r.pillowed_hexes, 10);  // the 10 boundary quads of the two cubes
        EXPECT_EQ(r.hexes, 12);
        EXPECT_EQ(m.hexes.size(), 12u);
        EXPECT_EQ(m.vertices.size(), 24u);  // 12 of the cubes and one copy of each
        EXPECT_EQ(r.invalid_before, 1);
        EXPECT_EQ(r.invalid_after, 0);
        EXPECT_EQ(HexExTest::notCertifiedValid(m), 0);
        EXPECT_LE(r.max_surface_distance, 1e-9);
        results[threads - 1] = m;
    }
    EXPECT_EQ(results[0].vertices, results[1].vertices);
    EXPECT_EQ(results[0].hexes, results[1].hexes);
}

// untangleWithRepair() (`hexex extract --untangle`): untangling alone cannot make the flap
// valid (its far vertices are boundary vertices kept on the box's surface planes), so with
// PillowPolicy::IfNeeded the pillowing repair runs and every hex ends certified valid; with
// PillowPolicy::Never the hexes stay as they were and the bad one is reported.
TEST(FoldedBoundary, UntangleFallsBackToPillowingOnlyWhenNeeded) {
    const TriangleSurface surface = box();
    {
        HexMesh m = rowWithInvalidFlap();
        RepairOptions o;
        o.pillow = PillowPolicy::Never;
        const RepairReport r = untangleWithRepair(m, o, &surface);
        EXPECT_EQ(r.untangle.invalid_before, 1);
        EXPECT_EQ(r.untangle.invalid_after + r.untangle.undecided_after, 1);
        EXPECT_FALSE(r.optimized);
        EXPECT_FALSE(r.repaired);
        EXPECT_TRUE(r.note.empty()) << r.note;
        EXPECT_EQ(m.hexes.size(), 3u);
    }
    HexMesh results[2];
    for (int threads = 1; threads <= 2; ++threads) {
        HexMesh m = rowWithInvalidFlap();
        RepairOptions o;
        o.untangle.threads = o.optimize.threads = threads;
        const RepairReport r = untangleWithRepair(m, o, &surface);
        EXPECT_TRUE(r.optimized);
        EXPECT_TRUE(r.repaired);
        EXPECT_EQ(r.optimize.trimmed_hexes, 1);
        EXPECT_EQ(r.optimize.pillowed_hexes, 10);
        EXPECT_EQ(m.hexes.size(), 12u);
        EXPECT_EQ(HexExTest::notCertifiedValid(m), 0);
        EXPECT_EQ(r.note, "untangling alone left 1 hexes not certified valid; repaired as with --pillow: 1 hexes "
                          "outside the surface removed, 10 hexes added along the boundary, then untangled and "
                          "optimised (0 hexes invalid after)");
        results[threads - 1] = m;
    }
    EXPECT_EQ(results[0].vertices, results[1].vertices);
    EXPECT_EQ(results[0].hexes, results[1].hexes);
    // A valid mesh is left as it is (no layer).
    HexMesh row = cubeRow();
    const RepairReport plain = untangleWithRepair(row, RepairOptions{}, nullptr);
    EXPECT_FALSE(plain.optimized);
    EXPECT_EQ(row.hexes.size(), 4u);
}
