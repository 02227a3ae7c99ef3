/// @file UntangleFeatureFoldTest.cc
/// untangleHexMesh() on the fold of S1 x2 (the map `S1_polycube_scale2.hexex.xz`, real solver
/// output): its 3 inverted hexes sit on a feature curve of the boundary and cannot become
/// positive while the vertices on the curve stay on it. By default those vertices are
/// released onto the surface and the count goes to 0; with release_features off the 3 stay
/// and the message names the feature curves. The bundled cut-out always runs; the whole map
/// (extraction plus untangling on the tet mesh's boundary) runs when ../shared is present.

#include "SharedData.hh"

#include <HexEx/HexEx.hh>
#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/IO/HexExFile.hh>
#include <HexEx/Mesh/HexMeshQuality.hh>
#include <HexEx/Untangling/SurfaceProjection.hh>
#include <HexEx/Untangling/Untangler.hh>

#include <gtest/gtest.h>

#include <string>

using namespace HexEx;

namespace {

/// The bundled cut-out around the fold of S1 x2.
HexMesh featureFold() { return readHexMesh(std::string(HEXEX_SOURCE_DIR) + "/src/Unittests/data/untangle/s1x2_feature_fold.vtk"); }

/// Largest distance of a moved vertex of @p before's boundary to @p surface, relative to the
/// bounding-box diagonal of @p before.
double maxMovedBoundaryDistance(const HexMesh& before, const HexMesh& after, const TriangleSurface& surface) {
    const SurfaceProjection proj(surface, 179);
    const TriangleSurface hb = hexMeshBoundary(before);
    std::vector<char> on(before.vertices.size(), 0);
    for (const auto& t : hb.triangles)
        for (const int v : t) on[static_cast<std::size_t>(v)] = 1;
    Vec3d lo(1e300), hi(-1e300);
    for (const auto& p : before.vertices) {
        lo.minimize(p);
        hi.maximize(p);
    }
    double worst = 0;
    for (std::size_t v = 0; v < on.size(); ++v)
        if (on[v] && after.vertices[v] != before.vertices[v])
            worst = std::max(worst, (proj.closestOnSurface(after.vertices[v]) - after.vertices[v]).norm());
    return worst / (hi - lo).norm();
}

} // namespace

TEST(UntangleFeatureFold, ReleasedFeatureVerticesGiveNoInvertedHex) {
    HexMesh m = featureFold();
    ASSERT_EQ(m.hexes.size(), 276u);
    const HexMesh before = m;
    UntangleOptions opt;
    opt.threads = 2;
    const UntangleReport r = untangleHexMesh(m, opt);
    EXPECT_EQ(r.inverted_before, 3);
    EXPECT_EQ(r.inverted_after, 0) << r.message;
    EXPECT_EQ(r.invalid_after, 0) << r.message;  // certified valid, not only at the corners
    EXPECT_TRUE(r.success);
    EXPECT_EQ(computeQuality(m).inverted_hexes, 0);
    EXPECT_EQ(computeQuality(m).invalid_hexes, 0);
    EXPECT_GT(r.released_feature_vertices, 0);
    EXPECT_LE(r.released_feature_vertices, 24);  // only vertices of the inverted hexes
    EXPECT_TRUE(r.message.empty()) << r.message;
    EXPECT_LE(maxMovedBoundaryDistance(before, m, hexMeshBoundary(before)), 1e-9);
}

TEST(UntangleFeatureFold, KeptFeaturesAreReportedAsTheCause) {
    HexMesh m = featureFold();
    ASSERT_EQ(m.hexes.size(), 276u);
    UntangleOptions opt;
    opt.release_features = false;
    const UntangleReport r = untangleHexMesh(m, opt);
    EXPECT_EQ(r.inverted_before, 3);
    EXPECT_EQ(r.inverted_after, 3);
    EXPECT_EQ(r.released_feature_vertices, 0);
    EXPECT_NE(r.message.find("3 hexes remain invalid (3 inverted at a corner, 0 undecided); 3 of them have vertices held on feature curves or corners"),
              std::string::npos)
        << r.message;
}

TEST(UntangleFeatureFold, WholeS1Scale2MapWithItsTetBoundary) {
    const std::string text = HexExTest::readSharedXz("S1_polycube_scale2.hexex.xz");
    if (text.empty()) GTEST_SKIP() << HexExTest::sharedDataPath("S1_polycube_scale2.hexex.xz") << " not found (or xz failed)";
    const ParametrizedTetMesh map = readHexExBuffer(text, "S1_polycube_scale2.hexex");
    HexMesh hm;
    ExtractionOptions eo;
    eo.threads = 2;
    extractHexMesh(map, hm, eo);
    const HexMesh before = hm;
    const TriangleSurface surface = tetMeshBoundary(map.mesh);
    UntangleOptions uo;
    uo.threads = 2;
    const UntangleReport r = untangleHexMesh(hm, uo, &surface);
    EXPECT_EQ(r.hexes, 84347);
    EXPECT_EQ(r.inverted_before, 3);
    EXPECT_EQ(r.inverted_after, 0) << r.message;
    // Certified: 3 hexes invalid before; one hex next to the feature fold stays negative
    // inside (positive at its 8 corners) after the certified phase (issue 32, left open).
    EXPECT_EQ(r.invalid_before, 3);
    EXPECT_LE(r.invalid_after, 1) << r.message;
    // 1 ring (corner criterion), 1 ring again with the feature vertices released, 1 ring
    // certified; the certified 1-ring attempt leaves the count as it was, so no 4-ring one.
    EXPECT_EQ(r.attempts, 3);
    EXPECT_GT(r.released_feature_vertices, 0);
    EXPECT_LE(maxMovedBoundaryDistance(before, hm, surface), 1e-9);
}
