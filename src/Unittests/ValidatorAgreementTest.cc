// The independent hex mesh check (hexex validate) agrees with the extractor's own report on
// every generated case, after a round trip through the .vtu and .ovm writers and readers.

#include "../TestSupport/HexGMapFixtures.hh"

#include <HexEx/GMap/GMapValidator.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/Generators/Perturbation.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/IO/HexMeshWriters.hh>
#include <HexEx/Mesh/HexMeshCheck.hh>

#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <string>
#include <unistd.h>

using namespace HexEx;

namespace {
void expectAgreement(ParametrizedTetMesh pm, const std::string& name) {
    SCOPED_TRACE(name);
    pm.mesh.build_adjacency();
    HexMesh hm;
    const auto r = extractHexMesh(pm, hm);
    for (const char* ext : {".vtu", ".ovm"}) {
        SCOPED_TRACE(ext);
        const std::string path = ::testing::TempDir() + "agree_" + std::to_string(::getpid()) + ext;
        writeHexMesh(path, hm);
        const HexMeshCheckResult c = checkHexMesh(readHexMesh(path));
        std::remove(path.c_str());
        EXPECT_EQ(c.hexes, r.output.hexes);
        EXPECT_EQ(c.non_hex_cells, r.output.non_hex_cells);
        EXPECT_EQ(c.vertices, r.output.vertices);
        EXPECT_EQ(c.quads, r.output.quads);
        EXPECT_EQ(c.boundary_quads, r.output.boundary_quads);
        EXPECT_EQ(c.valid_all_hex, r.valid_all_hex);
        EXPECT_EQ(c.quads_shared_by_more_than_two, 0);
        EXPECT_EQ(c.nonmanifold_boundary_edges, 0);
    }
}
} // namespace

TEST(ValidatorAgreement, GeneratedCases) {
    expectAgreement(generateCube(3, 4), "cube");
    expectAgreement(generateCube(1, 3), "coarse cube");
    for (int k : {3, 4, 5, 6}) expectAgreement(generateCylinder(k, 2, 2, 2, 1), "cylinder " + std::to_string(k));
    expectAgreement(generateRing(6, 2, 2, 6, 2, 2), "ring");
    expectAgreement(generateTwistedRing(4, 2, 4, 2), "twisted ring");
    auto c = generateCube(3, 3);
    applyRandomChartTransforms(c, 3);
    applyParameterNoise(c, 1e-11, 3);
    expectAgreement(c, "cube with random charts and noise");
    auto p = generateCube(4, 4);
    perturbParameters(p, 1.0, 2);
    expectAgreement(p, "perturbed cube");
}

// The work validateHexGMap() runs beside its cell search (the assembly's occurrence ranks):
// called once, with the checks' threads (all but the cell search's one when they overlap,
// on maps of at least 65536 darts), and the validation and labels are the same as without.
TEST(ValidatorAgreement, WorkBesideTheCellSearchRunsOnceAndChangesNothing) {
    for (const int hexes : {2, 1400}) {  // 96 darts (no overlap) and 67200 darts
        GMap<3> g = HexExTestSupport::makeHexGMaps(hexes);
        if (hexes == 2) g.link(DartHandle(0), DartHandle(0), 2);  // one broken link: not valid
        HexOrbitLabels plain;
        const GMapValidation expected = validateHexGMap(g, &plain, 1);
        for (const int threads : {1, 2, 3}) {
            SCOPED_TRACE(std::to_string(hexes) + " hexes, " + std::to_string(threads) + " threads");
            int calls = 0, given = 0;
            HexOrbitLabels labels;
            const GMapValidation v = validateHexGMap(g, &labels, threads, [&](int t) {
                ++calls;
                given = t;
            });
            EXPECT_EQ(calls, 1);
            EXPECT_EQ(given, hexes > 1000 && threads >= 2 ? threads - 1 : threads);
            EXPECT_EQ(v.summary(), expected.summary());
            EXPECT_EQ(v.valid(), hexes > 1000);
            EXPECT_EQ(labels.cell, plain.cell);
            EXPECT_EQ(labels.face, plain.face);
            EXPECT_EQ(labels.corner, plain.corner);
            EXPECT_EQ(labels.cell_darts, plain.cell_darts);
        }
    }
}
