/// @file CheapFoldsTest.cc
/// Tests of the cheap folds (ExtractionOptions::cheap_folds, FoldCancellation.hh): grid
/// points where every frame has one regular and one anti owner get no darts, and the
/// alpha_0 tracing walks through them. The mesh must be the one of the full annihilation,
/// bit for bit, and the darts must not grow with the fold.

#include <HexEx/Extraction/FoldCancellation.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/Generators/Perturbation.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/Mesh/HexArcs.hh>

#include <gtest/gtest.h>

#include <string>

#include "TestMeshChecks.hh"

using namespace HexEx;
using HexExTest::expectSameMesh;

namespace {

/// Extraction of @p pm with @p threads threads, cheap folds on or off.
struct FoldRun {
    HexMesh mesh;
    ExtractionReport report;
};
FoldRun extractWith(const ParametrizedTetMesh& pm, bool cheap, int threads = 2) {
    FoldRun r;
    ExtractionOptions opt;
    opt.threads = threads;
    opt.cheap_folds = cheap;
    r.report = extractHexMesh(pm, r.mesh, opt);
    return r;
}

/// Cheap folds on and off give the same mesh and counts; returns the run with them on.
FoldRun expectSameAsFullAnnihilation(const ParametrizedTetMesh& pm, int threads = 2) {
    const FoldRun full = extractWith(pm, false, threads);
    FoldRun cheap = extractWith(pm, true, threads);
    expectSameMesh(cheap.mesh, full.mesh);
    EXPECT_EQ(cheap.report.valid_all_hex, full.report.valid_all_hex);
    EXPECT_EQ(cheap.report.darts.remaining_anti, full.report.darts.remaining_anti);
    EXPECT_EQ(cheap.report.output.unconnected_darts, full.report.output.unconnected_darts);
    EXPECT_EQ(full.report.darts.cancelled_fold_points, 0);
    // Every cancelled point took at least one dart with it.
    EXPECT_LE(cheap.report.darts.extracted + cheap.report.darts.cancelled_fold_points, full.report.darts.extracted);
    return cheap;
}

} // namespace

TEST(CheapFolds, NeedleGivesTheCleanMeshWithDartsIndependentOfItsLength) {
    long darts = -1;
    for (const double shift : {37.25, 300.0, 2000.0}) {
        SCOPED_TRACE("shift " + std::to_string(shift));
        ParametrizedTetMesh pm;
        if (!HexExTest::sphereWithNeedle(shift, pm)) GTEST_SKIP() << "Examples/data/sphere.hexex not present";
        const FoldRun r = expectSameAsFullAnnihilation(pm);
        EXPECT_EQ(r.mesh.hexes.size(), 216u);
        EXPECT_EQ(r.mesh.vertices.size(), 343u);
        EXPECT_TRUE(r.report.valid_all_hex);
        EXPECT_GT(r.report.darts.cancelled_fold_points, 0);
        // The fold's inside costs no darts: the same number for any length of the needle.
        if (darts >= 0) {
            EXPECT_EQ(r.report.darts.extracted, darts);
        }
        darts = r.report.darts.extracted;
    }
}

TEST(CheapFolds, NeedleIsTheSameForAnyThreadCount) {
    ParametrizedTetMesh pm;
    if (!HexExTest::sphereWithNeedle(-450, pm)) GTEST_SKIP() << "Examples/data/sphere.hexex not present";
    const FoldRun ref = expectSameAsFullAnnihilation(pm, 1);
    EXPECT_GT(ref.report.darts.cancelled_fold_points, 0);
    for (int threads : {2, 3}) {
        const FoldRun r = extractWith(pm, true, threads);
        expectSameMesh(r.mesh, ref.mesh);
        EXPECT_EQ(r.report.darts.cancelled_fold_points, ref.report.darts.cancelled_fold_points);
        EXPECT_EQ(r.report.darts.extracted, ref.report.darts.extracted);
    }
}

TEST(CheapFolds, LargeFoldedTetsOfACubeGiveTheSameMesh) {
    // The centre of a 2x2x2-box cube of scale 9 pushed through the top: large flipped tets
    // over large proper ones.
    for (const double top : {13.25, 20.5}) {
        ParametrizedTetMesh pm = generateCube(2, 9);
        for (auto& corners : pm.params)
            for (auto& p : corners)
                if (p[0] == 4.5 && p[1] == 4.5 && p[2] == 4.5) p[2] = top;
        pm.mesh.build_adjacency();
        const FoldRun r = expectSameAsFullAnnihilation(pm);
        EXPECT_GT(r.report.input.flipped_tets, 0);
        EXPECT_GT(r.report.darts.cancelled_fold_points, 0) << "top " << top;
    }
}

TEST(CheapFolds, SmallTetsAndOtherChartsAreLeftToTheAnnihilation) {
    // A perturbed cube has small tets only: nothing is cancelled, the mesh is unchanged.
    ParametrizedTetMesh pm = generateCube(6, 3);
    perturbParameters(pm, 1.0, 1);
    pm.mesh.build_adjacency();
    const FoldRun r = expectSameAsFullAnnihilation(pm);
    EXPECT_GT(r.report.input.flipped_tets, 0);
    EXPECT_EQ(r.report.darts.cancelled_fold_points, 0);
    // A needle whose tets are each in a chart of their own: no two of them share a chart
    // component, so no point is cancelled.
    ParametrizedTetMesh needle;
    if (!HexExTest::sphereWithNeedle(300, needle)) GTEST_SKIP() << "Examples/data/sphere.hexex not present";
    applyRandomChartTransforms(needle, 7);
    needle.mesh.build_adjacency();
    const FoldRun charts = expectSameAsFullAnnihilation(needle);
    EXPECT_EQ(charts.report.darts.cancelled_fold_points, 0);
    EXPECT_EQ(charts.mesh.hexes.size(), 216u);
}

TEST(CheapFolds, ChartComponentsJoinTetsAcrossIdentityTransitions) {
    ParametrizedTetMesh pm = generateCube(2, 3);
    pm.mesh.build_adjacency();
    Transitions tr = computeTransitions(pm.mesh, pm.params);
    std::vector<int> comp = identityChartComponents(pm.mesh, tr);
    for (int c : comp) EXPECT_EQ(c, 0);  // one chart: one component, named by its smallest tet
    applyRandomChartTransforms(pm, 3);
    tr = computeTransitions(pm.mesh, pm.params);
    comp = identityChartComponents(pm.mesh, tr);
    long own = 0;
    for (std::size_t c = 0; c < comp.size(); ++c) own += comp[c] == static_cast<int>(c);
    EXPECT_GT(own, 1);
}

TEST(CheapFolds, OffWithArcs) {
    ParametrizedTetMesh pm;
    if (!HexExTest::sphereWithNeedle(300, pm)) GTEST_SKIP() << "Examples/data/sphere.hexex not present";
    HexArcs arcs;
    ExtractionOptions opt;
    opt.threads = 2;
    opt.arcs = &arcs;
    HexMesh hm;
    const ExtractionReport rep = extractHexMesh(pm, hm, opt);
    EXPECT_EQ(rep.darts.cancelled_fold_points, 0);
    EXPECT_EQ(hm.hexes.size(), 216u);
}
