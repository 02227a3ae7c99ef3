// Robust extraction of defective maps: flipped and degenerate tets (paper 4.4 and 5).

#include "SharedData.hh"

#include <HexEx/Generators/Generators.hh>
#include <HexEx/Generators/Perturbation.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/IO/HexExFile.hh>

#include <gtest/gtest.h>

#include "TestMeshChecks.hh"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

using namespace HexEx;

namespace {
ExtractionReport run(ParametrizedTetMesh& pm, HexMesh& hm, int threads = 1) {
    pm.mesh.build_adjacency();
    ExtractionOptions o;
    o.threads = threads;
    return extractHexMesh(pm, hm, o);
}
} // namespace

// Paper 5.1 stress test on a polycube-like map: the unperturbed hex and vertex counts survive.
TEST(DefectiveMaps, PerturbedCubeKeepsHexAndVertexCounts) {
    long withFlips = 0;
    for (double a : {0.2, 0.5, 1.0, 2.0})
        for (unsigned seed = 1; seed <= 5; ++seed) {
            SCOPED_TRACE("a = " + std::to_string(a) + ", seed = " + std::to_string(seed));
            auto pm = generateCube(4, 4);
            perturbParameters(pm, a, seed);
            HexMesh hm;
            const auto r = run(pm, hm);
            if (r.input.flipped_tets > 0) ++withFlips;
            EXPECT_EQ(r.output.hexes, 64);
            EXPECT_EQ(r.output.vertices, 125);
            EXPECT_EQ(r.output.non_hex_cells, 0);
            EXPECT_EQ(r.darts.remaining_anti, 0);
            EXPECT_EQ(r.darts.annihilated_pairs, r.darts.anti);
            EXPECT_TRUE(r.valid_all_hex) << r.validation.summary();
        }
    EXPECT_GT(withFlips, 10);  // the test must actually exercise flipped tets
}

TEST(DefectiveMaps, PerturbedCubeIsThreadIndependent) {
    auto pm = generateCube(3, 3);
    perturbParameters(pm, 1.0, 42);
    HexMesh h1, h2;
    run(pm, h1, 1);
    run(pm, h2, 2);
    EXPECT_EQ(h1.hexes, h2.hexes);
    EXPECT_TRUE(std::equal(h1.vertices.begin(), h1.vertices.end(), h2.vertices.begin(), h2.vertices.end()));
}

TEST(DefectiveMaps, PerturbedCylinderKeepsValence) {
    for (int k : {3, 5})
        for (unsigned seed = 1; seed <= 3; ++seed) {
            SCOPED_TRACE("k = " + std::to_string(k) + ", seed = " + std::to_string(seed));
            auto pm = generateCylinder(k, 3, 2, 3, 2);
            perturbParameters(pm, 0.3, seed);
            HexMesh hm;
            const auto r = run(pm, hm);
            EXPECT_EQ(r.output.hexes, k * 9 * 2);
            EXPECT_EQ(r.input.singular_edges, k == 4 ? 0 : 2);
            // The singular axis keeps its valence in the output: k hexes around each of its
            // H = 2 hex edges (its vertices stay on the axis line under the perturbation).
            const auto val = HexExTest::axisEdgeValences(hm);
            EXPECT_EQ(val.size(), 2u);
            for (int v : val) EXPECT_EQ(v, k);
            EXPECT_TRUE(r.valid_all_hex) << r.validation.summary();
        }
}

// A sub-block of the cube squashed flat in parameter space: the rest is still a valid mesh.
TEST(DefectiveMaps, SquashedSubBlock) {
    auto pm = generateCube(4, 4);
    // The slab 1 <= u <= 3 collapses onto the plane u = 1; the part beyond moves down by 2.
    for (auto& tet : pm.params)
        for (auto& p : tet) p[0] = p[0] <= 1 ? p[0] : p[0] <= 3 ? 1 : p[0] - 2;
    HexMesh hm;
    const auto r = run(pm, hm);
    EXPECT_EQ(r.input.degenerate_tets, 2 * 6 * 16);
    EXPECT_EQ(r.output.hexes, 32);  // the slabs [0,1] and [3,4] survive, glued along the collapsed slab
    EXPECT_EQ(r.output.vertices, 75);
    EXPECT_EQ(r.output.non_hex_cells, 0);
    EXPECT_TRUE(r.valid_all_hex) << r.validation.summary();
}

// Hand-built flip in the style of paper figure 5/6: one vertex pushed across a grid plane
// flips its tets; annihilation removes exactly the anti darts and their partners.
TEST(DefectiveMaps, AnnihilationOfASingleFold) {
    auto pm = generateCube(4, 4);
    // The interior vertex with parameter (2,2,2) is moved across two grid planes, past the
    // opposite sides of some of its tets, which flips them: grid points near it are covered
    // three times (regular, anti, regular) and annihilation must leave one vertex each.
    for (auto& tet : pm.params)
        for (auto& p : tet)
            if (p == Vec3d(2, 2, 2)) p = Vec3d(3.5, 1.4, 2.6);
    HexMesh hm;
    const auto r = run(pm, hm);
    EXPECT_GT(r.input.flipped_tets, 0);
    EXPECT_GT(r.darts.anti, 0);
    EXPECT_EQ(r.darts.annihilated_pairs, r.darts.anti);
    EXPECT_EQ(r.output.hexes, 64);
    EXPECT_EQ(r.output.vertices, 125);
    EXPECT_EQ(r.darts.remaining_anti, 0);
    EXPECT_TRUE(r.valid_all_hex) << r.validation.summary();
}

TEST(DefectiveMaps, S1PolycubeScale1) {
    const std::string text = HexExTest::readSharedXz("S1_polycube_scale1.hexex.xz");
    if (text.empty()) GTEST_SKIP() << "../shared/data/S1_polycube_scale1.hexex.xz not available (or no xz)";
    auto pm = readHexExBuffer(text, "S1_polycube_scale1.hexex");
    HexMesh hm;
    ExtractionOptions o;
    const auto r = extractHexMesh(pm, hm, o);
    EXPECT_EQ(r.input.flipped_tets, 23);
    EXPECT_EQ(r.input.degenerate_tets, 35);
    EXPECT_EQ(r.output.hexes, 10288);
    EXPECT_EQ(r.output.vertices, 13274);
    EXPECT_EQ(r.output.non_hex_cells, 0);
    EXPECT_TRUE(r.valid_all_hex) << r.validation.summary();
}

// Noise that breaks the charts' consistency across faces gives non-hex cells and boundary
// vertices whose darts disagree; with thousands of cells the validator, the cell assembly
// and the vertex merging run in several chunks: the output must not depend on the threads.
TEST(DefectiveMaps, NoisyCubeIsThreadIndependentWithPolyhedra) {
    auto pm = generateCube(16, 16);
    applyParameterNoise(pm, 0.2, 7);
    HexMesh h1;
    const auto r1 = run(pm, h1, 1);
    EXPECT_GT(h1.polyhedra.size(), 0u);  // the test must exercise non-hex cells
    EXPECT_GT(h1.hexes.size(), 3000u);   // and enough cells for several chunks
    EXPECT_GT(r1.darts.asymmetric_links, 0);  // and one-sided links (partners found by several darts)
    for (int threads : {2, 3, 4}) {
        SCOPED_TRACE("threads = " + std::to_string(threads));
        HexMesh h;
        const auto r = run(pm, h, threads);
        EXPECT_EQ(h.hexes, h1.hexes);
        ASSERT_EQ(h.vertices.size(), h1.vertices.size());
        EXPECT_TRUE(std::equal(h.vertices.begin(), h.vertices.end(), h1.vertices.begin()));
        ASSERT_EQ(h.polyhedra.size(), h1.polyhedra.size());
        for (std::size_t p = 0; p < h.polyhedra.size(); ++p) EXPECT_EQ(h.polyhedra[p].faces, h1.polyhedra[p].faces);
        EXPECT_EQ(r.output.quads, r1.output.quads);
        EXPECT_EQ(r.output.non_hex_cells, r1.output.non_hex_cells);
        EXPECT_EQ(r.validation.summary(), r1.validation.summary());
        EXPECT_EQ(r.darts.asymmetric_links, r1.darts.asymmetric_links);
        EXPECT_EQ(r.output.unconnected_darts, r1.output.unconnected_darts);
    }
}
