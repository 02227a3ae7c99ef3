// Maps built from the published hex meshes in ../shared/data/hexmeshes with heavy folds
// (issue 22): the report must agree with an independent check of the written mesh, and
// the sampled cases must give the source mesh back. The full sweep is a disabled test:
//   unittests --gtest_also_run_disabled_tests --gtest_filter='SharedHexMeshes.DISABLED_*'

#include "FromHexChecks.hh"
#include "SharedData.hh"
#include "TestMeshChecks.hh"

#include <HexEx/Generators/Generators.hh>
#include <HexEx/Generators/MapFromHexMesh.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/IO/HexMeshWriters.hh>
#include <HexEx/Mesh/HexMeshCheck.hh>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace HexEx;

namespace {

/// Reads ../shared/data/hexmeshes/NAME.vtk.xz, or returns an empty mesh if it (or xz) is missing.
HexMesh sharedHexMesh(const std::string& name) {
    const std::string text = HexExTest::readSharedXz("hexmeshes/" + name + ".vtk.xz");
    if (text.empty()) return {};
    return readHexMeshBuffer(text, HexMeshFormat::Vtk, name);
}

/// One folded case: the map of @p src with chart seed @p seed and centres moved by up to @p a.
struct FoldedCase {
    HexMesh out;                     ///< the extracted mesh
    ExtractionReport report;         ///< its report
    HexExTest::FromHexCheck check;   ///< source mesh back?
};

FoldedCase runFolded(const HexMesh& src, double a, unsigned seed, int threads = 2, bool retries = true) {
    MapFromHexOptions o;
    o.seed = seed;
    const MapFromHexResult exact = mapFromHexMesh(src, o);
    o.perturb = a;
    MapFromHexResult gen = mapFromHexMesh(src, o);
    gen.map.mesh.build_adjacency();
    ExtractionOptions eo;
    eo.threads = threads;
    eo.annihilation_retries = retries;
    FoldedCase c;
    c.report = extractHexMesh(gen.map, c.out, eo);
    c.check = HexExTest::checkFromHex(src, exact, gen, src, c.out, c.report);
    return c;
}

/// The independent check of @p m after writing it to a .vtu file and reading it back.
HexMeshCheckResult checkWritten(const HexMesh& m) {
    const std::string path = ::testing::TempDir() + "sweep_" + std::to_string(::getpid()) + ".vtu";
    writeHexMesh(path, m);
    const HexMeshCheckResult c = checkHexMesh(readHexMesh(path));
    std::remove(path.c_str());
    return c;
}

/// Same hexes, no polyhedra, a valid report, every vertex at its source position (none off).
void expectSourceMeshBack(const FoldedCase& c, const std::string& what) {
    EXPECT_TRUE(c.report.valid_all_hex) << what << ": " << c.report.validation.summary();
    EXPECT_TRUE(c.check.isomorphic) << what << ": " << c.check.summary();
    EXPECT_EQ(c.out.polyhedra.size(), 0u) << what;
    EXPECT_EQ(c.check.not_on_preimage, 0u) << what;
    EXPECT_EQ(c.check.off_position, 0u) << what;
    EXPECT_EQ(c.check.new_inverted, 0u) << what;
}

} // namespace

// The dart-level validation (report.valid_all_hex, validation.violations) against the
// independent check of the written file, on folded maps of generated meshes: they must
// agree on every case, and an invalid report must name its violations.
TEST(ValidatorHonesty, ReportAgreesWithTheWrittenMeshOnFoldedMaps) {
    const HexMesh sources[] = {HexExTest::extracted(generateCube(2, 3)), HexExTest::extracted(generateCylinder(3, 2, 2, 2, 2)),
                               HexExTest::extracted(generateTwistedRing(6, 2, 6, 2))};
    int cases = 0, valid = 0;
    for (const HexMesh& src : sources)
        for (double a : {0.6, 0.7, 0.8, 0.9})
            for (unsigned seed = 1; seed <= 5; ++seed) {
                const FoldedCase c = runFolded(src, a, seed);
                const std::string what = std::to_string(src.hexes.size()) + " hexes, a=" + std::to_string(a) + " seed=" + std::to_string(seed);
                const HexMeshCheckResult w = checkWritten(c.out);
                EXPECT_EQ(w.valid_all_hex, c.report.valid_all_hex) << what << ": " << c.report.validation.summary();
                EXPECT_EQ(w.hexes, c.report.output.hexes) << what;
                EXPECT_EQ(w.non_hex_cells, c.report.output.non_hex_cells) << what;
                if (!c.report.validation.valid()) {
                    EXPECT_FALSE(c.report.validation.examples.empty()) << what;
                }
                ++cases;
                valid += c.report.valid_all_hex ? 1 : 0;
            }
    EXPECT_EQ(cases, 60);
    std::cout << valid << " of " << cases << " folded maps valid\n";
}

// The pig at a = 0.6, seed 1: the first pass of the annihilation left 16 darts whose alpha_3
// links crossed two quads (the report said "INVALID: eq2 16" for the right mesh). Without
// retries, their quads are re-paired by their vertices (4 relinked faces); with them (the
// default), another order leaves no broken cell and nothing needs relinking. Both give
// the source mesh and a valid report that agrees with the written mesh.
TEST(ValidatorHonesty, PigAtSixTenthsIsValidAndTheSourceMesh) {
    const HexMesh pig = sharedHexMesh("sss19_pig_in");
    if (pig.hexes.empty()) GTEST_SKIP() << "../shared/data/hexmeshes/sss19_pig_in.vtk.xz not available (or no xz)";
    ASSERT_EQ(pig.hexes.size(), 13987u);
    for (int threads : {1, 2})
        for (bool retries : {false, true}) {
            const FoldedCase c = runFolded(pig, 0.6, 1, threads, retries);
            expectSourceMeshBack(c, "pig a=0.6 seed=1 threads=" + std::to_string(threads) + " retries=" + std::to_string(retries));
            EXPECT_EQ(c.report.output.relinked_faces, retries ? 0 : 4);
            EXPECT_EQ(c.report.darts.annihilation_order > 0, retries);
            EXPECT_EQ(c.report.darts.broken_cells_after_annihilation, 0);
            EXPECT_TRUE(checkWritten(c.out).valid_all_hex);
        }
}

// The pig at a = 1.0, seed 9: the first pass of the annihilation breaks cells, and the first
// retry (phase by phase) leaves none, but it crosses alpha_3 links around the valence-6 edge
// 2103-10741 of the source so that the interior edge 1877-1904 and the edge 10751-2105 become
// one: every cell a hex, every vertex link a sphere, yet 2 vertices short and a quad in three
// hexes. The retries now rank such a run below every run that merges no vertices
// (countMergedVertexQuads()), keep a later order, and the face relinking finishes it: the
// source mesh back, every vertex in place, and a report that agrees with the written mesh.
TEST(ValidatorHonesty, PigAtOneSeedNineGivesTheSourceMesh) {
    const HexMesh pig = sharedHexMesh("sss19_pig_in");
    if (pig.hexes.empty()) GTEST_SKIP() << "../shared/data/hexmeshes/sss19_pig_in.vtk.xz not available (or no xz)";
    const FoldedCase c = runFolded(pig, 1.0, 9);
    expectSourceMeshBack(c, "pig a=1.0 seed=9");
    EXPECT_EQ(c.out.vertices.size(), 16389u);
    EXPECT_GT(c.report.darts.annihilation_order, 1);
    EXPECT_TRUE(checkWritten(c.out).valid_all_hex);
}

// A sampled subset of the sweep (both meshes, a = 0.6 to 0.8): the source mesh back, with a
// report that agrees with the written mesh. Pig 0.7 seed 1 needs both vertex rules of issue
// 22's second round (an inherited boundary dart no longer pulls an interior vertex onto
// another vertex's position; the majority of a vertex's darts beats a fold copy), cfpc16 0.8
// seed 2 the second (it had 17 vertices on fold copies and 8 inverted hexes), pig 0.8 seeds 1
// and 3 the majority of placed points (where the darts have none, or the wrong one);
// cfpc16 0.7 seed 8 and pig 0.6 seed 7 the boundary vertex of the tet mesh among a boundary
// vertex's candidates (each had one boundary vertex on a fold copy in a boundary face, the
// cfpc16 one inverting a hex), pig 0.8 seeds 12 and 18 the vertex of the tet mesh among an
// interior vertex's candidates (each had two interior vertices on fold copies and one
// inverted hex). Skipped without ../shared.
TEST(SharedHexMeshes, SampledFoldsGiveTheSourceMesh) {
    const HexMesh pig = sharedHexMesh("sss19_pig_in"), cf = sharedHexMesh("cfpc16_hollow8");
    if (pig.hexes.empty() || cf.hexes.empty()) GTEST_SKIP() << "../shared/data/hexmeshes not available (or no xz)";
    ASSERT_EQ(cf.hexes.size(), 8813u);
    const struct {
        const HexMesh* src;
        const char* name;
        double a;
        unsigned seed;
    } cases[] = {{&pig, "pig", 0.7, 1}, {&pig, "pig", 0.7, 2}, {&cf, "cfpc16", 0.6, 2}, {&cf, "cfpc16", 0.7, 3},
                 {&cf, "cfpc16", 0.8, 2}, {&pig, "pig", 0.8, 1}, {&pig, "pig", 0.8, 3}, {&cf, "cfpc16", 0.7, 8},
                 {&pig, "pig", 0.6, 7}, {&pig, "pig", 0.8, 12}, {&pig, "pig", 0.8, 18}};
    for (const auto& k : cases) {
        const std::string what = std::string(k.name) + " a=" + std::to_string(k.a) + " seed=" + std::to_string(k.seed);
        const FoldedCase c = runFolded(*k.src, k.a, k.seed);
        expectSourceMeshBack(c, what);
        EXPECT_EQ(checkWritten(c.out).valid_all_hex, c.report.valid_all_hex) << what;
    }
}

// The annihilation's retries in other orders (AnnihilationRetry): on cfpc16 at 0.6, seed 1
// the first order glues a cell to itself. Before the relinking's last pass that gave 3
// polyhedra; the last pass cuts the two quads crossed the same way too and pairs all four (4
// relinked): a valid all-hex mesh with the source's counts, but not the source: two of its
// vertices sit at source vertex 9005 (the four quads paired the other way round). A known
// limit of pairing by vertices; another order gives the source mesh with nothing to relink; on
// the pig at 0.7, seed 4 the first order crosses alpha_1/alpha_2 links (two cells merged into
// a polyhedron). The kept order, and so the mesh, is the same for any thread count.
TEST(SharedHexMeshes, AnnihilationRetriesGiveTheSourceMeshWhereTheFirstOrderBreaksCells) {
    const HexMesh pig = sharedHexMesh("sss19_pig_in"), cf = sharedHexMesh("cfpc16_hollow8");
    if (pig.hexes.empty() || cf.hexes.empty()) GTEST_SKIP() << "../shared/data/hexmeshes not available (or no xz)";
    const FoldedCase first = runFolded(cf, 0.6, 1, 2, false);
    EXPECT_TRUE(first.report.valid_all_hex);
    EXPECT_EQ(first.out.polyhedra.size(), 0u);
    EXPECT_EQ(first.report.output.relinked_faces, 4);
    EXPECT_FALSE(first.check.isomorphic);
    EXPECT_NE(first.check.summary().find("two vertices map to expected vertex 9005"), std::string::npos) << first.check.summary();
    EXPECT_EQ(first.report.darts.annihilation_order, 0);
    const FoldedCase retried = runFolded(cf, 0.6, 1, 2, true);
    expectSourceMeshBack(retried, "cfpc16 a=0.6 seed=1");
    EXPECT_GT(retried.report.darts.annihilation_order, 0);
    EXPECT_EQ(retried.report.darts.broken_cells_after_annihilation, 0);
    const FoldedCase one = runFolded(pig, 0.7, 4, 1), two = runFolded(pig, 0.7, 4, 2);
    expectSourceMeshBack(one, "pig a=0.7 seed=4 threads=1");
    EXPECT_GT(one.report.darts.annihilation_order, 0);
    EXPECT_EQ(one.report.darts.annihilation_order, two.report.darts.annihilation_order);
    EXPECT_EQ(one.out.hexes, two.out.hexes);
    EXPECT_EQ(one.out.vertices, two.out.vertices);
}

// The fold around a singular edge (pig 0.8, seed 7): every order of the annihilation leaves
// one 96-dart polyhedron (two cells merged, eq4 24, eq5 32, eq6 96; two of its darts sit on
// the corner of the wrong cube, a split vertex). The reconnection re-links its darts into
// the two source hexes: the source mesh back, every vertex in place, for 1 and 2 threads.
TEST(SharedHexMeshes, FoldAroundASingularEdgeIsReconnectedIntoTheSourceHexes) {
    const HexMesh pig = sharedHexMesh("sss19_pig_in");
    if (pig.hexes.empty()) GTEST_SKIP() << "../shared/data/hexmeshes/sss19_pig_in.vtk.xz not available (or no xz)";
    HexMesh first;
    for (int threads : {1, 2}) {
        const FoldedCase c = runFolded(pig, 0.8, 7, threads);
        expectSourceMeshBack(c, "pig a=0.8 seed=7 threads=" + std::to_string(threads));
        EXPECT_EQ(c.report.darts.broken_cells_after_annihilation, 1);
        EXPECT_EQ(c.report.darts.reconnected_cells, 2);
        EXPECT_EQ(c.report.darts.unreconnected_cells, 0);
        EXPECT_EQ(c.out.hexes.size(), 13987u);
        if (threads == 1) first = c.out;
        else {
            EXPECT_EQ(first.hexes, c.out.hexes);
            EXPECT_EQ(first.vertices, c.out.vertices);
        }
    }
}

// Pig 1.5 seed 2: the kept annihilation order leaves 6 cells whose quads only are crossed
// (8 quads cut by the relinking). Paired by their vertices taken with the crossed links,
// 4 of them found no partner (those links merged two vertices, so several cut quads had
// one key) and 2 interior quads stayed open: the written mesh was the source, but the map
// was not, and the report said so. The leftovers are now paired once more by the vertices
// of the map with the cut quads open: all 8 sewn, the source mesh back.
TEST(SharedHexMeshes, CutQuadsLeftByMergedLabelsAreSewnByTheVerticesAfterTheCut) {
    const HexMesh pig = sharedHexMesh("sss19_pig_in");
    if (pig.hexes.empty()) GTEST_SKIP() << "../shared/data/hexmeshes/sss19_pig_in.vtk.xz not available (or no xz)";
    const FoldedCase c = runFolded(pig, 1.5, 2);
    expectSourceMeshBack(c, "pig a=1.5 seed=2");
    EXPECT_EQ(c.report.output.relinked_faces, 8);
    EXPECT_EQ(c.report.output.boundary_quads, 4540);
    EXPECT_TRUE(checkWritten(c.out).valid_all_hex);
}

// Pig 1.5 seed 16: after the phase-by-phase run two groups of 96 darts are left (two cells
// merged into one polyhedron each). One chart component of the second group reaches around
// a singular edge and holds 32 darts of one cube and 8 of another, so placed whole it filled
// three cubes ("the darts do not fill whole cubes"). Split by cube, its parts are placed
// on their own: 50 + 46 darts, a split vertex, re-linked into the two source hexes.
TEST(SharedHexMeshes, ChartComponentAroundASingularEdgeIsSplitByCube) {
    const HexMesh pig = sharedHexMesh("sss19_pig_in");
    if (pig.hexes.empty()) GTEST_SKIP() << "../shared/data/hexmeshes/sss19_pig_in.vtk.xz not available (or no xz)";
    const FoldedCase c = runFolded(pig, 1.5, 16);
    expectSourceMeshBack(c, "pig a=1.5 seed=16");
    EXPECT_EQ(c.report.darts.annihilation_order, 1);
    EXPECT_EQ(c.report.darts.reconnected_cells, 4);
    EXPECT_EQ(c.report.darts.unreconnected_cells, 0);
    EXPECT_EQ(c.out.hexes.size(), 13987u);
}

// Pig 1.5 seed 21: besides a reconnected group, one cell is glued to itself by two of its
// own quads, and two quads of other cells are linked to each other the same crossed way
// (equation 2 holds there, so they were not cut): the vertices of the self-glued cell's two
// quads stay one set and the relinking found no partner (3 polyhedra, 2 vertices short).
// The last pass cuts the sewn quads with those vertices too and pairs all four: 16 relinked,
// the source mesh back.
TEST(SharedHexMeshes, QuadsCrossedLikeASelfGluedCellAreCutAndPairedToo) {
    const HexMesh pig = sharedHexMesh("sss19_pig_in");
    if (pig.hexes.empty()) GTEST_SKIP() << "../shared/data/hexmeshes/sss19_pig_in.vtk.xz not available (or no xz)";
    const FoldedCase c = runFolded(pig, 1.5, 21);
    expectSourceMeshBack(c, "pig a=1.5 seed=21");
    EXPECT_EQ(c.report.output.relinked_faces, 16);
    EXPECT_EQ(c.report.output.boundary_quads, 4540);
    EXPECT_EQ(c.report.darts.reconnected_cells, 2);
    EXPECT_TRUE(checkWritten(c.out).valid_all_hex);
}

// Pig 1.2 seed 29: every tet at the source position of one boundary vertex (source vertex
// 11822) is flipped, so its darts there were all annihilated (10 anti darts at that boundary
// vertex of the tet mesh) and only fold copies survived; the vertex was placed on one of them,
// 0.59 % of the diagonal off. The tet-mesh vertex rule now also looks at the anti darts'
// positions where no other candidate is a vertex of the tet mesh: the source mesh back.
TEST(SharedHexMeshes, BoundaryVertexSeenOnlyByAnnihilatedAntiDartsIsPutAtTheTetMeshVertex) {
    const HexMesh pig = sharedHexMesh("sss19_pig_in");
    if (pig.hexes.empty()) GTEST_SKIP() << "../shared/data/hexmeshes/sss19_pig_in.vtk.xz not available (or no xz)";
    const FoldedCase c = runFolded(pig, 1.2, 29);
    expectSourceMeshBack(c, "pig a=1.2 seed=29");
    EXPECT_EQ(c.report.darts.broken_cells_after_annihilation, 0);
    EXPECT_EQ(c.out.vertices.size(), 16389u);
}

namespace {

/// Comma-separated numbers (or ranges of integers "1-40") of the environment variable @p var, or @p dflt if unset.
std::vector<double> envList(const char* var, std::vector<double> dflt) {
    const char* v = std::getenv(var);
    if (!v || !*v) return dflt;
    std::vector<double> out;
    std::stringstream ss(v);
    std::string item;
    while (std::getline(ss, item, ',')) {
        const std::size_t dash = item.find('-', 1);
        if (dash != std::string::npos) {  // a range of seeds "1-40"
            for (int k = std::stoi(item.substr(0, dash)); k <= std::stoi(item.substr(dash + 1)); ++k) out.push_back(k);
        } else if (!item.empty()) {
            out.push_back(std::stod(item));
        }
    }
    return out;
}

} // namespace

// The full sweep: both meshes, a = 0.6, 0.7, 0.8, seeds 1-4 (about 40 s). Prints one
// line per case; Documentation/algorithm.md (#algorithm_from_hex) has the figures. The
// report must agree with the written mesh on every case, and all 24 cases give the source
// mesh back with every vertex at its source position (19 before the annihilation's
// retries; 2 had a boundary vertex on a fold copy before the tet-mesh vertex rule).
// Other sweeps (scripts/fold-sweep.sh): HEXEX_SWEEP_A="1.0,1.5", HEXEX_SWEEP_SEEDS="1-40",
// HEXEX_SWEEP_MESHES="pig,cfpc16" (either); then only the agreement of report and written
// mesh is asserted, and the count of exact cases is printed. A case is exact (OK) if the
// written mesh is valid all-hex, the report says so, the hexes are the source's under a
// vertex bijection, there are no polyhedra, every vertex is within 1e-9 of the diagonal of
// its source position and no hex is inverted that is not in the source. Issue 35's sweep:
// HEXEX_SWEEP_A="0.8,1.0,1.2,1.5" HEXEX_SWEEP_SEEDS="1-40" (320 cases; Documentation/algorithm.md
// has the table).
TEST(SharedHexMeshes, DISABLED_FullSweep) {
    const std::vector<double> amplitudes = envList("HEXEX_SWEEP_A", {0.6, 0.7, 0.8});
    const std::vector<double> seeds = envList("HEXEX_SWEEP_SEEDS", {1, 2, 3, 4});
    const char* meshesVar = std::getenv("HEXEX_SWEEP_MESHES");
    const std::string meshes = meshesVar && *meshesVar ? meshesVar : "pig,cfpc16";
    const bool standard = !std::getenv("HEXEX_SWEEP_A") && !std::getenv("HEXEX_SWEEP_SEEDS") && !meshesVar;
    int ok = 0, total = 0;
    for (const char* name : {"sss19_pig_in", "cfpc16_hollow8"}) {
        if (meshes.find(std::string(name).substr(0, 3) == "sss" ? "pig" : "cfpc16") == std::string::npos) continue;
        const HexMesh src = sharedHexMesh(name);
        if (src.hexes.empty()) GTEST_SKIP() << "../shared/data/hexmeshes not available (or no xz)";
        for (double a : amplitudes)
            for (double s : seeds) {
                const unsigned seed = static_cast<unsigned>(s);
                const auto t0 = std::chrono::steady_clock::now();
                const FoldedCase c = runFolded(src, a, seed);
                const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
                const bool written = checkWritten(c.out).valid_all_hex;
                EXPECT_EQ(written, c.report.valid_all_hex) << name << " a=" << a << " seed=" << seed;
                const bool good = written && c.check.ok() && c.out.polyhedra.empty() && c.check.new_inverted == 0 && c.check.off_position == 0;
                const auto& t = c.report.timings_s;
                std::cout << name << " a=" << a << " seed=" << seed << " hexes=" << c.out.hexes.size()
                          << " polyhedra=" << c.out.polyhedra.size() << " report_valid=" << c.report.valid_all_hex
                          << " written_valid=" << written << " order=" << c.report.darts.annihilation_order
                          << " broken=" << c.report.darts.broken_cells_after_annihilation
                          << " relinked=" << c.report.output.relinked_faces << " extract_s="
                          << (t.preprocess + t.vertices + t.darts + t.connect + t.postprocess + t.assemble)
                          << " case_s=" << secs << " | " << c.check.summary() << (good ? " OK" : " FAIL") << std::endl;  // flushed: long sweeps show progress through a pipe
                ok += good ? 1 : 0;
                ++total;
            }
    }
    std::cout << ok << " of " << total << " cases give the source mesh back\n";
    if (standard) {
        EXPECT_EQ(total, 24);
        EXPECT_EQ(ok, 24);
    }
}
