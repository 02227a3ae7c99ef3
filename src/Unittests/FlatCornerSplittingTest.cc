/// @file FlatCornerSplittingTest.cc
/// splitFlatFeatureCorners(): a hex whose top and bottom quads have a 175-degree corner
/// between two feature edges, with a layer on its whole boundary: the two layer hexes on
/// those quads are split (exact counts, boundary quads, old vertices bit for bit, every hex
/// certified valid, no flat feature corner left); hexes with more than one boundary face are
/// not split; OptimizeOptions::pillow passes the bound sin 175 that the layer alone keeps;
/// out-of-range vertices give a clear error.

#include <HexEx/Mesh/HexArcs.hh>
#include <HexEx/Mesh/HexMeshQuality.hh>
#include <HexEx/Untangling/BoundaryPillowing.hh>
#include <HexEx/Untangling/FlatCornerSplitting.hh>
#include <HexEx/Untangling/HexOptimizer.hh>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "TestMeshChecks.hh"

using namespace HexEx;

namespace {

/// One hex extruded in z from the quad A B C D whose corner at B has 175 degrees.
HexMesh flatHex() {
    const double a = 5.0 * M_PI / 180.0;
    const Vec3d A(-1, 0, 0), B(0, 0, 0), C(std::cos(a), std::sin(a), 0), D(-0.2, 1.1, 0), up(0, 0, 1);
    HexMesh m;
    m.vertices = {A, B, C, D, A + up, B + up, C + up, D + up};
    m.hexes.push_back({{0, 1, 2, 3, 4, 5, 6, 7}});
    return m;
}

/// The hex of flatHex() with a layer on its whole boundary (7 hexes, 16 vertices).
HexMesh layeredFlatHex() {
    HexMesh m = flatHex();
    PillowOptions o;
    o.skip_patch_angle_deg = 180;
    o.threads = 1;
    const PillowReport r = pillowBoundary(m, o);
    EXPECT_TRUE(r.success) << r.message;
    return m;
}

/// Number of boundary quads of @p m.
std::size_t boundaryQuads(const HexMesh& m) {
    std::map<std::array<int, 4>, int> count;
    for (const auto& h : m.hexes)
        for (const auto& f : HexArcs::kHexFaces) {
            std::array<int, 4> q{{h[static_cast<std::size_t>(f[0])], h[static_cast<std::size_t>(f[1])],
                                  h[static_cast<std::size_t>(f[2])], h[static_cast<std::size_t>(f[3])]}};
            std::sort(q.begin(), q.end());
            ++count[q];
        }
    return static_cast<std::size_t>(std::count_if(count.begin(), count.end(), [](const auto& e) { return e.second == 1; }));
}

double minSJ(const HexMesh& m) {
    const auto sj = scaledJacobians(m);
    return *std::min_element(sj.begin(), sj.end());
}

} // namespace

TEST(FlatCornerSplittingTest, LayerHexesOnTheFlatQuadsAreSplit) {
    HexMesh m = layeredFlatHex();
    ASSERT_EQ(m.hexes.size(), 7u);
    ASSERT_EQ(m.vertices.size(), 16u);
    ASSERT_EQ(boundaryQuads(m), 6u);
    EXPECT_LE(minSJ(m), std::sin(175.0 * M_PI / 180.0) + 1e-12);
    const HexMesh before = m;
    const FlatCornerReport r = splitFlatFeatureCorners(m);
    EXPECT_EQ(r.flat_corners, 2);  // B on the bottom quad, B + up on the top quad
    EXPECT_EQ(r.split_hexes, 2);
    EXPECT_EQ(r.hexes_added, 10);
    EXPECT_EQ(r.vertices_added, 16);
    EXPECT_EQ(r.skipped_hexes, 0);
    ASSERT_EQ(m.hexes.size(), 17u);
    ASSERT_EQ(m.vertices.size(), 32u);
    // Each flat quad becomes its copy and a ring of four quads.
    EXPECT_EQ(boundaryQuads(m), 6u + 2 * 4);
    for (std::size_t v = 0; v < 16; ++v)
        for (int d = 0; d < 3; ++d) EXPECT_EQ(m.vertices[v][d], before.vertices[v][d]) << "vertex " << v;
    // Bottom quad first (boundary quads in hex, face order): its copies 16-19 stay in the
    // plane z = 0, the inner copies 20-23 lie above it; the top quad's copies 24-27 stay at
    // z = 1, its inner copies 28-31 lie below.
    for (std::size_t v = 16; v < 32; ++v) {
        const double z = m.vertices[v][2];
        if (v < 20) EXPECT_EQ(z, 0.0) << "vertex " << v;
        else if (v < 24) EXPECT_GT(z, 0.0) << "vertex " << v;
        else if (v < 28) EXPECT_EQ(z, 1.0) << "vertex " << v;
        else EXPECT_LT(z, 1.0) << "vertex " << v;
    }
    EXPECT_EQ(HexExTest::notCertifiedValid(m), 0);
    // No flat corner between feature edges is left (the copy's flat corner is inside its patch).
    HexMesh again = m;
    const FlatCornerReport r2 = splitFlatFeatureCorners(again);
    EXPECT_EQ(r2.flat_corners, 0);
    EXPECT_EQ(r2.split_hexes, 0);
    EXPECT_EQ(again.hexes.size(), m.hexes.size());
}

TEST(FlatCornerSplittingTest, HexWithSeveralBoundaryFacesIsNotSplit) {
    HexMesh m = flatHex();
    const FlatCornerReport r = splitFlatFeatureCorners(m);
    EXPECT_EQ(r.flat_corners, 2);
    EXPECT_EQ(r.split_hexes, 0);
    EXPECT_EQ(r.skipped_hexes, 2);
    EXPECT_EQ(m.hexes.size(), 1u);
    EXPECT_EQ(m.vertices.size(), 8u);
}

TEST(FlatCornerSplittingTest, OptimiserPassesTheBoundThatTheLayerKeeps) {
    const double bound = std::sin(175.0 * M_PI / 180.0);
    OptimizeOptions o;
    o.threads = 1;
    o.pillow = true;
    o.pillow_skip_patch_angle_deg = 180;  // a layer on the whole boundary, no strips
    o.pillow_flat_corners = false;
    HexMesh layer_only = flatHex();
    const OptimizeReport r0 = optimizeHexMesh(layer_only, o);
    ASSERT_TRUE(r0.success) << r0.message;
    EXPECT_EQ(r0.pillowed_hexes, 6);
    EXPECT_LE(r0.min_scaled_jacobian_after, bound + 1e-9);
    o.pillow_flat_corners = true;
    HexMesh m = flatHex();
    const OptimizeReport r = optimizeHexMesh(m, o);
    ASSERT_TRUE(r.success) << r.message;
    EXPECT_EQ(r.pillowed_hexes, 16);  // 6 layer hexes, 2 x 5 from the splits
    EXPECT_EQ(r.pillow_vertices, 8 + 16);
    EXPECT_EQ(static_cast<long>(m.hexes.size()), 17);
    EXPECT_GT(r.min_scaled_jacobian_after, 0.25);  // 0.271 measured; sin 175 = 0.087
    EXPECT_EQ(r.min_scaled_jacobian_after, minSJ(m));
    EXPECT_EQ(HexExTest::notCertifiedValid(m), 0);
    HexMesh m2 = flatHex();
    o.threads = 2;
    optimizeHexMesh(m2, o);
    ASSERT_EQ(m2.vertices.size(), m.vertices.size());
    for (std::size_t v = 0; v < m.vertices.size(); ++v)
        for (int d = 0; d < 3; ++d) EXPECT_EQ(m2.vertices[v][d], m.vertices[v][d]) << "vertex " << v;
}

TEST(FlatCornerSplittingTest, VertexOutOfRangeIsAnError) {
    HexMesh m = flatHex();
    m.hexes[0][3] = 8;
    try {
        splitFlatFeatureCorners(m);
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()), "flat corner splitting: hex 0 references vertex 8 of 8");
    }
}
