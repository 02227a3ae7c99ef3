/// @file InfoCommandTest.cc
/// Tests of computeMapStatistics() (the numbers behind `hexex info`) on tiny meshes.

#include <HexEx/IO/HexExFile.hh>
#include <HexEx/IO/MapStatistics.hh>

#include <gtest/gtest.h>

#include <filesystem>

using namespace HexEx;

namespace {

/// Two tets sharing face (1 2 3), built in code; parameters given by the caller.
ParametrizedTetMesh twoTets(const std::array<Vec3d, 4>& params0, const std::array<Vec3d, 4>& params1) {
    ParametrizedTetMesh pm;
    const Vec3d pos[5] = {Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, 0, 1), Vec3d(1, 1, 1)};
    for (const auto& p : pos) pm.mesh.add_vertex(p);
    pm.mesh.add_cell({VertexHandle(0), VertexHandle(1), VertexHandle(2), VertexHandle(3)});
    pm.mesh.add_cell({VertexHandle(1), VertexHandle(2), VertexHandle(3), VertexHandle(4)});
    pm.params = {params0, params1};
    return pm;
}

} // namespace

TEST(MapStatisticsTest, ProperFlippedAndDegenerate) {
    // Tet 0: proper, volume 8/6 (scaled by 2). Tet 1: flipped (corners 2, 3 swapped), volume -2/6.
    auto pm = twoTets({Vec3d(0, 0, 0), Vec3d(2, 0, 0), Vec3d(0, 2, 0), Vec3d(0, 0, 2)},
                      {Vec3d(1, 0, 0), Vec3d(0, 0, 1), Vec3d(0, 1, 0), Vec3d(1, 1, 1)});
    MapStatistics s = computeMapStatistics(pm);  // without adjacency
    EXPECT_EQ(s.vertices, 5u);
    EXPECT_EQ(s.tets, 2u);
    EXPECT_EQ(s.boundary_faces, 6u);
    EXPECT_EQ(s.flipped_tets, 1u);
    EXPECT_EQ(s.degenerate_tets, 0u);
    EXPECT_DOUBLE_EQ(s.parametric_volume, 8.0 / 6.0 - 2.0 / 6.0);
    EXPECT_EQ(s.param_bbox_min, Vec3d(0, 0, 0));
    EXPECT_EQ(s.param_bbox_max, Vec3d(2, 2, 2));

    pm.mesh.build_adjacency();
    EXPECT_EQ(computeMapStatistics(pm).boundary_faces, 6u);  // with adjacency, same answer

    // A flat parameter tet (all corners in the plane w = 0) and a collapsed one.
    pm.params[0] = {Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(1, 1, 0)};
    pm.params[1] = {Vec3d(-1, 5, 3), Vec3d(-1, 5, 3), Vec3d(-1, 5, 3), Vec3d(-1, 5, 3)};
    s = computeMapStatistics(pm);
    EXPECT_EQ(s.flipped_tets, 0u);
    EXPECT_EQ(s.degenerate_tets, 2u);
    EXPECT_EQ(s.parametric_volume, 0.0);
    EXPECT_EQ(s.param_bbox_min, Vec3d(-1, 0, 0));
    EXPECT_EQ(s.param_bbox_max, Vec3d(1, 5, 3));
}

TEST(MapStatisticsTest, EmptyMesh) {
    const MapStatistics s = computeMapStatistics(ParametrizedTetMesh{});
    EXPECT_EQ(s.tets, 0u);
    EXPECT_EQ(s.boundary_faces, 0u);
    EXPECT_EQ(s.parametric_volume, 0.0);
}

TEST(MapStatisticsTest, Sphere) {
    const std::string path = std::string(HEXEX_SOURCE_DIR) + "/Examples/data/sphere.hexex";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "test data not found: " << path;
    const MapStatistics s = computeMapStatistics(readHexExFile(path));
    EXPECT_EQ(s.vertices, 41u);
    EXPECT_EQ(s.tets, 76u);
    EXPECT_EQ(s.boundary_faces, 76u);
    EXPECT_EQ(s.flipped_tets, 0u);
    EXPECT_EQ(s.degenerate_tets, 2u);
    EXPECT_NEAR(s.parametric_volume, 216.0, 1e-9);
}
