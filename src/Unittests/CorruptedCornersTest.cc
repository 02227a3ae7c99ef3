// One corrupted number in a map (a typo in one corner parameter of one tet) must not break
// the extraction: the transitions are fitted to the two agreeing corners of each face and
// the sanitization takes the value most tets agree on, so the clean mesh comes back and
// the repair is reported.

#include <HexEx/Generators/Generators.hh>
#include <HexEx/Generators/Perturbation.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/IO/HexExFile.hh>
#include <HexEx/IO/ReportJson.hh>

#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <string>
#include <vector>

using namespace HexEx;

namespace {

const char* const kSphere = "Examples/data/sphere.hexex";

/// The bundled sphere map with its adjacency; false if the file is absent.
bool readSphere(ParametrizedTetMesh& pm) {
    if (!std::ifstream(kSphere)) return false;
    pm = readHexExFile(kSphere);
    pm.mesh.build_adjacency();
    return true;
}

/// Number of tets at every vertex.
std::vector<int> tetsPerVertex(const ParametrizedTetMesh& pm) {
    std::vector<int> n(pm.mesh.n_vertices(), 0);
    for (std::size_t c = 0; c < pm.params.size(); ++c)
        for (int k = 0; k < 4; ++k) ++n[pm.mesh.cell_vertex(CellHandle(static_cast<int>(c)), k).uidx()];
    return n;
}

/// Extracts @p pm and checks that the result is @p clean, bit for bit.
void expectCleanMesh(const ParametrizedTetMesh& pm, const HexMesh& clean, ExtractionReport& rep, int threads = 1) {
    HexMesh hm;
    ExtractionOptions opt;
    opt.threads = threads;
    rep = extractHexMesh(pm, hm, opt);
    EXPECT_TRUE(rep.valid_all_hex);
    EXPECT_EQ(hm.hexes, clean.hexes);
    ASSERT_EQ(hm.vertices.size(), clean.vertices.size());
    for (std::size_t v = 0; v < hm.vertices.size(); ++v) EXPECT_EQ(hm.vertices[v], clean.vertices[v]) << "vertex " << v;
}

} // namespace

TEST(CorruptedCorners, EveryCornerOfTheSphereIsRepaired) {
    ParametrizedTetMesh pm;
    if (!readSphere(pm)) GTEST_SKIP() << kSphere << " not present";
    HexMesh clean;
    const ExtractionReport cleanRep = extractHexMesh(pm, clean);
    ASSERT_EQ(clean.hexes.size(), 216u);
    ASSERT_EQ(clean.vertices.size(), 343u);
    EXPECT_EQ(cleanRep.input.repaired_corners, 0);
    EXPECT_EQ(cleanRep.input.inconsistent_transitions, 0);
    const std::vector<int> valence = tetsPerVertex(pm);
    int cases = 0;
    for (std::size_t c = 0; c < pm.params.size(); ++c)
        for (int k = 0; k < 4; ++k) {
            const int v = pm.mesh.cell_vertex(CellHandle(static_cast<int>(c)), k).idx();
            for (int axis = 0; axis < 3; ++axis)
                for (double value : {1e3, -37.25, 1e7}) {
                    SCOPED_TRACE("tet " + std::to_string(c) + " corner " + std::to_string(k) + " axis " +
                                 std::to_string(axis) + " value " + std::to_string(value) + " (vertex " +
                                 std::to_string(v) + ", " + std::to_string(valence[static_cast<std::size_t>(v)]) +
                                 " tets)");
                    ParametrizedTetMesh bad = pm;
                    const double original = bad.params[c][k][axis];
                    bad.params[c][k][axis] = value;
                    ExtractionReport rep;
                    expectCleanMesh(bad, clean, rep);
                    EXPECT_EQ(rep.input.repaired_corners, 1);
                    ASSERT_EQ(rep.input.repairs.size(), 1u);
                    EXPECT_EQ(rep.input.repairs[0].tet, static_cast<int>(c));
                    EXPECT_EQ(rep.input.repairs[0].corner, k);
                    EXPECT_EQ(rep.input.repairs[0].vertex, v);
                    EXPECT_EQ(rep.input.repairs[0].original[axis], value);
                    EXPECT_EQ(rep.input.repairs[0].repaired[axis], original);
                    ++cases;
                }
        }
    EXPECT_EQ(cases, 76 * 4 * 3 * 3);
}

TEST(CorruptedCorners, SeveralTyposAtDifferentVerticesAreAllRepairedForAnyThreadCount) {
    ParametrizedTetMesh pm;
    if (!readSphere(pm)) GTEST_SKIP() << kSphere << " not present";
    HexMesh clean;
    extractHexMesh(pm, clean);
    ParametrizedTetMesh bad = pm;
    // Three corners of three different vertices (checked below), one of them the interior one.
    bad.params[10][2][1] = 1e5;
    bad.params[40][0][0] = -250;
    int interiorTet = -1, interiorCorner = -1;
    for (std::size_t c = 0; c < pm.params.size() && interiorTet < 0; ++c)
        for (int k = 0; k < 4; ++k)
            if (pm.mesh.cell_vertex(CellHandle(static_cast<int>(c)), k).idx() == 40 && c != 10 && c != 40) {
                interiorTet = static_cast<int>(c);
                interiorCorner = k;
                break;
            }
    ASSERT_GE(interiorTet, 0);
    bad.params[static_cast<std::size_t>(interiorTet)][interiorCorner][2] += 3e4;
    const int v1 = pm.mesh.cell_vertex(CellHandle(10), 2).idx(), v2 = pm.mesh.cell_vertex(CellHandle(40), 0).idx();
    ASSERT_NE(v1, v2);
    ASSERT_NE(v1, 40);
    ASSERT_NE(v2, 40);
    for (int threads : {1, 2, 3}) {
        SCOPED_TRACE("threads " + std::to_string(threads));
        ExtractionReport rep;
        expectCleanMesh(bad, clean, rep, threads);
        EXPECT_EQ(rep.input.repaired_corners, 3);
        ASSERT_EQ(rep.input.repairs.size(), 3u);
        // Listed by vertex.
        EXPECT_LT(rep.input.repairs[0].vertex, rep.input.repairs[1].vertex);
        EXPECT_LT(rep.input.repairs[1].vertex, rep.input.repairs[2].vertex);
    }
}

TEST(CorruptedCorners, RepairIsReportedInJsonAndAsAWarning) {
    ParametrizedTetMesh pm;
    if (!readSphere(pm)) GTEST_SKIP() << kSphere << " not present";
    pm.params[10][2][1] = 1e5;
    HexMesh hm;
    const ExtractionReport rep = extractHexMesh(pm, hm);
    EXPECT_EQ(rep.input.inconsistent_transitions, 2);  // the two interior faces of tet 10 at that corner
    ASSERT_EQ(rep.warnings.size(), 1u);
    EXPECT_EQ(rep.warnings[0], "1 corner parameter disagreed with the majority of the tets at its vertex and was "
                               "replaced by the majority value (a corrupted number in the input?): tet 10 corner 2 "
                               "(vertex 27) (6 100000 0) -> (6 6 0)");
    const std::string json = reportToJson(rep, ReportExtras());
    EXPECT_NE(json.find("\"repaired_corners\": 1"), std::string::npos) << json;
    EXPECT_NE(json.find("\"inconsistent_transitions\": 2"), std::string::npos) << json;
    EXPECT_NE(json.find("{\"tet\": 10, \"corner\": 2, \"vertex\": 27, \"original\": [6, 1e+05, 0], \"repaired\": [6, 6, 0]}"),
              std::string::npos)
        << json;
}

TEST(CorruptedCorners, ATypoBeyondTheVolumeLimitIsRepairedNotRefused) {
    ParametrizedTetMesh pm;
    if (!readSphere(pm)) GTEST_SKIP() << kSphere << " not present";
    HexMesh clean;
    extractHexMesh(pm, clean);
    pm.params[10][2][1] = 1e8;  // raw parametric volume far above max_hexes (4e7)
    ExtractionReport rep;
    expectCleanMesh(pm, clean, rep);
    EXPECT_EQ(rep.input.repaired_corners, 1);
}

TEST(CorruptedCorners, ConsistentMapsAreNotTouched) {
    // The interior vertex moved consistently in all its tets (flipped tets, a fold): nothing to repair.
    ParametrizedTetMesh pm;
    if (!readSphere(pm)) GTEST_SKIP() << kSphere << " not present";
    for (std::size_t c = 0; c < pm.params.size(); ++c)
        for (int k = 0; k < 4; ++k)
            if (pm.mesh.cell_vertex(CellHandle(static_cast<int>(c)), k).idx() == 40) pm.params[c][k][1] += 1e3;
    HexMesh hm;
    const ExtractionReport rep = extractHexMesh(pm, hm);  // a genuine needle fold: it cancels
    EXPECT_EQ(rep.input.repaired_corners, 0);
    EXPECT_EQ(rep.input.inconsistent_transitions, 0);
    EXPECT_GT(rep.input.flipped_tets, 0);
    EXPECT_EQ(hm.hexes.size(), 216u);
    EXPECT_TRUE(rep.valid_all_hex);
}

namespace {
/// @p count typos of size ±1 or ±0.7 grid units at random corners of @p pm (seeded).
void addSmallTypos(ParametrizedTetMesh& pm, unsigned seed, int count) {
    std::mt19937 rng(seed);
    const double sizes[4] = {1.0, -1.0, 0.7, -0.7};
    for (int i = 0; i < count; ++i) {
        const std::size_t c = rng() % pm.params.size();
        const int k = static_cast<int>(rng() % 4), axis = static_cast<int>(rng() % 3);
        pm.params[c][k][axis] += sizes[rng() % 4];
    }
}
} // namespace

TEST(CorruptedCorners, SmallTyposOnAFoldedRandomChartCube) {
    // Small faces (6 grid cells over 8 boxes), random charts, folds: a typo of one grid unit
    // can make a wrong rotation's residuals round alike; the exact-pair check catches it.
    ParametrizedTetMesh pm = generateCube(8, 6);
    applyRandomChartTransforms(pm, 3);
    perturbParameters(pm, 0.7, 1);
    pm.mesh.build_adjacency();
    HexMesh clean;
    const ExtractionReport cleanRep = extractHexMesh(pm, clean);
    ASSERT_TRUE(cleanRep.valid_all_hex);
    ASSERT_GT(cleanRep.input.flipped_tets, 0);
    int repaired = 0;
    // 40 seeds of three typos each (7 of them failed before the exact-pair check).
    for (unsigned seed = 0; seed < 40; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        ParametrizedTetMesh bad = pm;
        addSmallTypos(bad, seed, 3);
        ExtractionReport rep;
        expectCleanMesh(bad, clean, rep, 2);
        EXPECT_EQ(rep.input.repaired_corners, 3);
        repaired += rep.input.repaired_corners == 3 ? 1 : 0;
    }
    EXPECT_EQ(repaired, 40);
}
