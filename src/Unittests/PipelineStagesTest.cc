// The pipeline stages of src/HexEx/Pipeline run one by one give the same mesh and report
// counts as extractHexMesh(), and each stage's output has the expected sizes.

#include <HexEx/Generators/Generators.hh>
#include <HexEx/Generators/Perturbation.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/IO/HexExFile.hh>
#include <HexEx/Pipeline/AnnihilateStage.hh>
#include <HexEx/Pipeline/AssembleStage.hh>
#include <HexEx/Pipeline/ConnectStage.hh>
#include <HexEx/Pipeline/DartStage.hh>
#include <HexEx/Pipeline/ImplicitCellPath.hh>
#include <HexEx/Pipeline/PlacementStage.hh>
#include <HexEx/Pipeline/PreprocessStage.hh>
#include <HexEx/Pipeline/ReportStage.hh>

#include <gtest/gtest.h>

#include "TestMeshChecks.hh"

#include <fstream>

using namespace HexEx;
using HexExTest::expectSameMesh;

namespace {

/// Result of running the stages by hand.
struct ManualRun {
    HexMesh mesh;
    ExtractionReport report;
    long preprocess_tets = 0, darts = 0, anti = 0, survivors = 0, map_darts = 0, placed_points = 0, heirs = 0;
};

/// Runs every stage in pipeline order, as extractHexMesh() does (without timing or freeing).
/// With @p oneHeirPerPoint the annihilation gets the darts (as in extractHexMesh()) and lists
/// one heir entry per grid point; without, one per removed dart.
ManualRun runStages(const ParametrizedTetMesh& pm, int threads, bool implicitRequested = true, bool oneHeirPerPoint = false) {
    ManualRun r;
    r.report.threads = threads;
    const PreprocessOutput pre = preprocess({&pm, nullptr, 1e-6, 4e7, threads});
    addToReport(pre, r.report);
    r.preprocess_tets = static_cast<long>(pre.tets.size());
    const bool implicit = useImplicitCells(implicitRequested, pre.stats.flipped_tets);
    DartStageOutput darts = extractDartStage({&pm.mesh, &pre.tets, pre.abs_volume, implicit, threads});
    addToReport(darts, r.report);
    r.darts = static_cast<long>(darts.darts.darts.size());
    r.anti = darts.anti;
    ConnectOutput links = connectStage({&pm.mesh, &pre.transitions, &pre.tets, &darts.darts, threads, {}});
    addToReport(links, r.report);
    // The retry and link settings of extractHexMesh(), so that the run stays the same as the
    // extractor's whichever annihilation path (ascending first, phase by phase first) a map takes.
    AnnihilateInput annihilateIn{&links.alpha, &darts.sign, true, darts.anti, oneHeirPerPoint ? &darts.darts : nullptr, 1, {}, {}};
    annihilateIn.retry.enabled = !implicit;
    annihilateIn.mutual_links = true;
    const AnnihilateOutput survivors = annihilateStage(annihilateIn);
    addToReport(survivors, r.report);
    r.heirs = static_cast<long>(survivors.heir.size());
    r.survivors = survivors.n_alive;
    ImplicitCells cells;
    if (implicit)
        cells.alpha3_occurrence = implicitAlpha3Occurrences(links.alpha, survivors.alive, survivors.new_index, survivors.n_alive, threads);
    const MapOutput map = buildMapStage({std::move(links.alpha), &survivors, true, threads});
    addToReport(map, r.report);
    r.map_darts = static_cast<long>(map.map.n_darts());
    const DartGeometry geo =
        placementStage({&pm.mesh, &pre.tets, &darts.darts, &survivors.alive, &survivors.new_index, survivors.n_alive, threads,
                        &survivors.heir});
    r.placed_points = static_cast<long>(geo.placement.position.size());
    if (implicit) {
        cells.dart_occurrence = implicitDartOccurrences(darts.darts, survivors.alive, survivors.new_index, survivors.n_alive, threads);
        buildImplicitCells(pm.mesh, pre.transitions, pre.tets, darts.darts, threads, cells);
        addToReport(cells, r.report);
    }
    AssembleOutput out = assembleStage({&map.map, &geo, implicit ? &cells : nullptr, threads});
    addToReport(out, r.report);
    r.mesh = std::move(out.mesh);
    return r;
}

/// The manual run equals extractHexMesh() in mesh and report counts; returns the manual run.
ManualRun expectSameAsExtractor(ParametrizedTetMesh pm, int threads) {
    pm.mesh.build_adjacency();
    ExtractionOptions opt;
    opt.threads = threads;
    HexMesh expected;
    const ExtractionReport rep = extractHexMesh(pm, expected, opt);
    ManualRun r = runStages(pm, threads);
    expectSameMesh(r.mesh, expected);
    EXPECT_EQ(r.report.output.vertices, rep.output.vertices);
    EXPECT_EQ(r.report.output.hexes, rep.output.hexes);
    EXPECT_EQ(r.report.output.quads, rep.output.quads);
    EXPECT_EQ(r.report.output.boundary_quads, rep.output.boundary_quads);
    EXPECT_EQ(r.report.output.unconnected_darts, rep.output.unconnected_darts);
    EXPECT_EQ(r.report.darts.extracted, rep.darts.extracted);
    EXPECT_EQ(r.report.darts.anti, rep.darts.anti);
    EXPECT_EQ(r.report.darts.annihilated_pairs, rep.darts.annihilated_pairs);
    EXPECT_EQ(r.report.darts.implicit_cells, rep.darts.implicit_cells);
    EXPECT_EQ(r.report.input.flipped_tets, rep.input.flipped_tets);
    EXPECT_EQ(r.report.warnings, rep.warnings);
    EXPECT_EQ(r.report.valid_all_hex, rep.valid_all_hex);
    return r;
}

} // namespace

TEST(PipelineStages, CubeWithoutImplicitCellsHas48DartsPerHex) {
    ParametrizedTetMesh pm = generateCube(2, 3);
    pm.mesh.build_adjacency();
    const ManualRun r = runStages(pm, 1, false);
    EXPECT_EQ(r.preprocess_tets, 48);  // 6 * 2^3
    EXPECT_EQ(r.darts, 48 * 27);
    EXPECT_EQ(r.anti, 0);
    EXPECT_EQ(r.survivors, 48 * 27);
    EXPECT_EQ(r.map_darts, 48 * 27);
    EXPECT_EQ(r.mesh.hexes.size(), 27u);
    EXPECT_EQ(r.mesh.vertices.size(), 64u);
    EXPECT_TRUE(r.report.valid_all_hex);
}

TEST(PipelineStages, SameAsExtractorOnCylinderWithImplicitCells) {
    for (int threads : {1, 2}) {
        const ManualRun r = expectSameAsExtractor(generateCylinder(5, 6, 4, 1, 1), threads);
        EXPECT_EQ(r.mesh.hexes.size(), 5u * 6 * 6 * 4);
        EXPECT_GT(r.report.darts.implicit_cells, 0);
        EXPECT_TRUE(r.report.valid_all_hex);
    }
}

TEST(PipelineStages, SameAsExtractorOnPerturbedCubeWithFolds) {
    ParametrizedTetMesh pm = generateCube(6, 3);
    perturbParameters(pm, 1.0, 1);
    for (int threads : {1, 2}) {
        const ManualRun r = expectSameAsExtractor(pm, threads);
        EXPECT_GT(r.report.input.flipped_tets, 0);
        EXPECT_GT(r.report.darts.annihilated_pairs, 0);
        EXPECT_EQ(r.survivors, r.darts - 2 * r.report.darts.annihilated_pairs);
    }
}

TEST(PipelineStages, OneHeirPerGridPointGivesTheSameMesh) {
    // Removed darts at the same grid point of the same tet with the same heir add the same
    // vertex candidate: listing one of them must not change a bit of the mesh, and on a
    // fold-heavy map it must shorten the list by far (48 darts per interior grid point).
    ParametrizedTetMesh pm = generateCube(6, 3);
    perturbParameters(pm, 1.0, 1);
    pm.mesh.build_adjacency();
    for (int threads : {1, 2}) {
        const ManualRun all = runStages(pm, threads, true, false);
        const ManualRun one = runStages(pm, threads, true, true);
        expectSameMesh(one.mesh, all.mesh);
        EXPECT_EQ(one.placed_points, all.placed_points);
        EXPECT_GT(one.heirs, 0);
        EXPECT_LT(one.heirs * 4, all.heirs);
    }
}

TEST(PipelineStages, SameAsExtractorOnSphere) {
    const std::string path = "Examples/data/sphere.hexex";
    if (!std::ifstream(path)) GTEST_SKIP() << path << " not present";
    expectSameAsExtractor(readHexExFile(path), 2);
}
