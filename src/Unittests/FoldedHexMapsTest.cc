// Maps built from hex meshes (mapFromHexMesh) with heavy folds: the extraction must give the
// source mesh back (issue 10).

#include "FromHexChecks.hh"
#include "TestMeshChecks.hh"

#include <HexEx/Core/Error.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/Generators/MapFromHexMesh.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/IO/HexExFile.hh>
#include <HexEx/IO/HexMeshReaders.hh>

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

using namespace HexEx;

namespace {

/// Extracts @p pm (a copy; adjacency built here) with @p threads threads.
ExtractionReport extractWith(ParametrizedTetMesh pm, HexMesh& out, int threads) {
    pm.mesh.build_adjacency();
    ExtractionOptions o;
    o.threads = threads;
    return extractHexMesh(pm, out, o);
}

/// Source meshes of the tests: extractions of generated maps.
HexMesh sourceMesh(const std::string& name) {
    if (name == "cube") return HexExTest::extracted(generateCube(2, 3));
    if (name == "cylinder3") return HexExTest::extracted(generateCylinder(3, 2, 2, 2, 2));
    if (name == "cylinder5") return HexExTest::extracted(generateCylinder(5, 2, 1, 2, 1));
    if (name == "twisted") return HexExTest::extracted(generateTwistedRing(6, 2, 6, 2));
    if (name == "sphere") {
        std::ifstream probe("Examples/data/sphere.hexex");
        if (!probe) return HexMesh();
        return HexExTest::extracted(readHexExFile("Examples/data/sphere.hexex"));
    }
    const std::string path = name;
    return readHexMesh(path);
}

/// Runs one case; returns the check.
HexExTest::FromHexCheck runCase(const HexMesh& src, double a, unsigned seed, int scale, int threads) {
    MapFromHexOptions o;
    o.scale = scale;
    o.seed = seed;
    const MapFromHexResult exact = mapFromHexMesh(src, o);
    o.perturb = a;
    const MapFromHexResult gen = mapFromHexMesh(src, o);
    HexMesh expected = src;
    if (scale != 1) extractWith(exact.map, expected, 1);
    HexMesh out;
    const ExtractionReport rep = extractWith(gen.map, out, threads);
    return HexExTest::checkFromHex(src, exact, gen, expected, out, rep);
}

} // namespace

TEST(MapFromHexMesh, SplitsEveryHexIntoTwentyFourTetsWithOwnCharts) {
    const HexMesh src = sourceMesh("cube");
    ASSERT_EQ(src.hexes.size(), 27u);
    MapFromHexOptions o;
    o.seed = 7;
    const MapFromHexResult r = mapFromHexMesh(src, o);
    EXPECT_EQ(r.map.mesh.n_cells(), 27u * 24u);
    EXPECT_EQ(r.faces, 108u);          // 3 * 4 * 3 * 3 faces of a 3x3x3 grid
    EXPECT_EQ(r.boundary_faces, 54u);
    EXPECT_EQ(r.map.mesh.n_vertices(), 64u + 108u + 27u);
    EXPECT_EQ(r.negative_tets_3d, 0u);
    EXPECT_NEAR(totalParametricVolume(r.map), 27.0, 1e-12);
    std::size_t nonIdentity = 0;
    for (const auto& g : r.charts) nonIdentity += g.is_identity() ? 0 : 1;
    EXPECT_GE(nonIdentity, 20u);
}

TEST(MapFromHexMesh, RejectsNonHexAndBadOptions) {
    HexMesh m = sourceMesh("cube");
    EXPECT_THROW(mapFromHexMesh(m, MapFromHexOptions{2.5, 1, 1}), std::invalid_argument);
    EXPECT_THROW(mapFromHexMesh(m, MapFromHexOptions{0.0, 1, 0}), std::invalid_argument);
    HexMesh flipped = m;
    std::swap(flipped.hexes[0][1], flipped.hexes[0][3]);  // mirrored: orientation disagrees with its neighbours
    std::swap(flipped.hexes[0][5], flipped.hexes[0][7]);
    EXPECT_THROW(mapFromHexMesh(flipped, MapFromHexOptions{}), InputError);
    m.polyhedra.push_back(Polyhedron{});
    EXPECT_THROW(mapFromHexMesh(m, MapFromHexOptions{}), InputError);
}

TEST(MapFromHexMesh, ExactMapsGiveTheSourceMesh) {
    for (const char* name : {"cube", "cylinder3", "cylinder5", "twisted"}) {
        const HexMesh src = sourceMesh(name);
        for (unsigned seed = 1; seed <= 2; ++seed) {
            const auto c = runCase(src, 0.0, seed, 1, 1);
            EXPECT_TRUE(c.ok()) << name << " seed " << seed << ": " << c.summary();
            EXPECT_EQ(c.off_position, 0u) << name;
        }
    }
    const auto c2 = runCase(sourceMesh("cylinder3"), 0.0, 3, 2, 2);
    EXPECT_TRUE(c2.ok()) << c2.summary();
}

// The issue-10 class: face and cell centres moved by up to a grid units (from a = 0.6 on,
// a centre can pass a face edge or corner, so folds cover hex corners). Before the fix,
// vertices were placed at the average of several preimages or on a fold copy (cube seeds
// 1, 2, 3, 7 and 19 of 20 sphere seeds failed at a = 0.6). Every case must now give the
// source mesh back with 1 and 2 threads.
TEST(FoldedHexMaps, SourceMeshBackUnderFolds) {
    std::vector<std::string> names = {"cube", "cylinder3", "cylinder5", "twisted", "sphere"};
    int cases = 0;
    for (const std::string& name : names) {
        const HexMesh src = sourceMesh(name);
        if (src.hexes.empty()) {
            std::cout << "skipping " << name << ": Examples/data/sphere.hexex not found\n";
            continue;
        }
        for (double a : {0.3, 0.5, 0.6, 0.7})
            for (unsigned seed = 1; seed <= 8; ++seed)
                for (int threads : {1, 2}) {
                    const auto c = runCase(src, a, seed, 1, threads);
                    EXPECT_TRUE(c.ok()) << name << " a=" << a << " seed=" << seed << " threads=" << threads << ": "
                                        << c.summary();
                    ++cases;
                }
    }
    EXPECT_GE(cases, 4 * 4 * 8 * 2);
}

// Cases where the proper preimage of a vertex survives only in removed darts: the cube at
// a = 0.6, seed 15 (a boundary vertex whose only surviving h-vertices were fold copies
// until the positions of annihilated anti darts became last-resort candidates), and 0.8.
TEST(FoldedHexMaps, ProperPreimageOnlyInRemovedDarts) {
    const HexMesh cube = sourceMesh("cube");
    for (int threads : {1, 2}) {
        const auto c = runCase(cube, 0.6, 15, 1, threads);
        EXPECT_TRUE(c.ok()) << c.summary();
        EXPECT_EQ(c.off_position, 0u);
    }
    for (const char* name : {"cylinder3", "cylinder5", "sphere"}) {
        const HexMesh src = sourceMesh(name);
        if (src.hexes.empty()) continue;
        for (unsigned seed : {2u, 4u, 9u, 11u, 15u, 18u}) {
            const auto c = runCase(src, 0.8, seed, 1, 1);
            EXPECT_TRUE(c.ok()) << name << " a=0.8 seed=" << seed << ": " << c.summary();
        }
    }
}

// Same output for 1 and 2 threads, bit for bit, on a heavily folded map.
TEST(FoldedHexMaps, OutputIndependentOfThreads) {
    const HexMesh src = sourceMesh("cylinder5");
    MapFromHexOptions o;
    o.perturb = 0.7;
    o.seed = 3;
    const MapFromHexResult gen = mapFromHexMesh(src, o);
    HexMesh one, two;
    const ExtractionReport r1 = extractWith(gen.map, one, 1);
    const ExtractionReport r2 = extractWith(gen.map, two, 2);
    EXPECT_GT(r1.input.flipped_tets, 0);
    EXPECT_EQ(one.hexes, two.hexes);
    ASSERT_EQ(one.vertices.size(), two.vertices.size());
    for (std::size_t v = 0; v < one.vertices.size(); ++v) EXPECT_EQ(one.vertices[v], two.vertices[v]) << v;
}

// Scaled maps: each source hex becomes K^3 hexes; the source vertices stay in place.
TEST(FoldedHexMaps, ScaledMapsGiveTheRefinedMesh) {
    const HexMesh src = sourceMesh("cylinder3");
    MapFromHexOptions o;
    o.scale = 2;
    o.seed = 5;
    HexMesh out;
    const ExtractionReport rep = extractWith(mapFromHexMesh(src, o).map, out, 2);
    EXPECT_TRUE(rep.valid_all_hex);
    EXPECT_EQ(out.hexes.size(), 8 * src.hexes.size());
    for (double a : {0.3, 0.6}) {
        const auto c = runCase(src, a, 2, 2, 1);
        EXPECT_TRUE(c.ok()) << "a=" << a << ": " << c.summary();
    }
}

// Sweep for measurements: HEXEX_FOLD_MESHES (comma-separated names or files),
// HEXEX_FOLD_A, HEXEX_FOLD_SEEDS, HEXEX_FOLD_THREADS. Prints one line per failure.
TEST(FoldedHexMapsSweep, DISABLED_Sweep) {
    const char* meshes = std::getenv("HEXEX_FOLD_MESHES");
    const double a = std::atof(std::getenv("HEXEX_FOLD_A") ? std::getenv("HEXEX_FOLD_A") : "0.6");
    const int seeds = std::atoi(std::getenv("HEXEX_FOLD_SEEDS") ? std::getenv("HEXEX_FOLD_SEEDS") : "20");
    const int threads = std::atoi(std::getenv("HEXEX_FOLD_THREADS") ? std::getenv("HEXEX_FOLD_THREADS") : "1");
    const int scale = std::atoi(std::getenv("HEXEX_FOLD_SCALE") ? std::getenv("HEXEX_FOLD_SCALE") : "1");
    std::string list = meshes ? meshes : "cube,cylinder3,cylinder5,twisted,sphere";
    int total = 0, good = 0;
    std::size_t pos = 0;
    while (pos <= list.size()) {
        const std::size_t comma = std::min(list.find(',', pos), list.size());
        const std::string name = list.substr(pos, comma - pos);
        pos = comma + 1;
        if (name.empty()) continue;
        const HexMesh src = sourceMesh(name);
        if (src.hexes.empty()) continue;
        int ok = 0;
        for (int s = 1; s <= seeds; ++s) {
            const auto c = runCase(src, a, static_cast<unsigned>(s), scale, threads);
            ++total;
            if (c.ok()) {
                ++ok;
                ++good;
            } else {
                std::cout << name << " a=" << a << " seed=" << s << ": " << c.summary() << "\n";
            }
        }
        std::cout << name << " (" << src.hexes.size() << " hexes): " << ok << "/" << seeds << " ok at a=" << a << "\n";
    }
    std::cout << "TOTAL " << good << "/" << total << "\n";
    EXPECT_GT(total, 0);
}
