/// @file ConnectionTracingTest.cc
/// Tests of traceConnections(): the shared alpha_0 walks (one per tet, grid point and d1)
/// give exactly the links and counters of tracing every dart alone, for any thread count.

#include "SharedData.hh"

#include <HexEx/Extraction/ConnectionTracing.hh>
#include <HexEx/Extraction/DartExtraction.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/Generators/Perturbation.hh>
#include <HexEx/IO/HexExFile.hh>
#include <HexEx/Preprocessing/Sanitization.hh>
#include <HexEx/Preprocessing/Transitions.hh>

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>

using namespace HexEx;

namespace {

/// The tracing of one map with sharing on and off.
struct SharedVsAlone {
    long darts = 0;         ///< number of darts
    long shared = 0;        ///< alpha_0 links from shared walks (1 thread)
    long tied = 0;          ///< darts of shared groups that left the walk at a tie (1 thread)
    long flipped = 0;       ///< flipped tets
    long degenerate = 0;    ///< degenerate tets
};

/// Runs the preprocessing and dart extraction as the extractor does (with or without
/// implicit cells), then compares traceConnections() with sharing on and off on 1, 2 and 3
/// threads: links and all counters but the sharing ones must be identical.
SharedVsAlone compareSharing(ParametrizedTetMesh pm, bool implicit_cells = false) {
    SharedVsAlone out;
    pm.mesh.build_adjacency();
    const TetMesh& mesh = pm.mesh;
    CornerParams params = pm.params;
    const Transitions tr = computeTransitions(mesh, params);
    sanitizeParameters(mesh, params, tr);
    const std::vector<TetSoS> tets = buildTetSoS(params, 1);
    for (const TetSoS& T : tets) {
        out.flipped += T.vol < 0;
        out.degenerate += T.vol == 0;
    }
    const DartSet ds = extractDarts(tets, 1, 1e9, implicit_cells && out.flipped == 0);
    out.darts = static_cast<long>(ds.darts.size());
    TraceStats alone;
    const std::vector<DartLinks> ref = traceConnections(mesh, tr, tets, ds, 1, alone, {}, false);
    EXPECT_EQ(alone.shared_alpha0, 0);
    for (int threads : {1, 2, 3}) {
        SCOPED_TRACE("threads = " + std::to_string(threads));
        TraceStats st;
        const std::vector<DartLinks> links = traceConnections(mesh, tr, tets, ds, threads, st, {}, true);
        EXPECT_EQ(links.size(), ref.size());
        long mismatches = 0;
        for (std::size_t d = 0; d < links.size() && d < ref.size(); ++d)
            if (links[d] != ref[d]) {
                if (++mismatches <= 5)
                    ADD_FAILURE() << "dart " << d << " (tet " << ds.darts[d].tet << "): alpha " << links[d][0] << ' '
                                  << links[d][1] << ' ' << links[d][2] << ' ' << links[d][3] << ", alone "
                                  << ref[d][0] << ' ' << ref[d][1] << ' ' << ref[d][2] << ' ' << ref[d][3];
            }
        EXPECT_EQ(mismatches, 0);
        for (int i = 0; i < 4; ++i) EXPECT_EQ(st.unconnected[i], alone.unconnected[i]) << "i = " << i;
        EXPECT_EQ(st.boundary_alpha3, alone.boundary_alpha3);
        EXPECT_EQ(st.steps, alone.steps);
        if (threads == 1) {
            out.shared = st.shared_alpha0;
            out.tied = st.split_alpha0;
        }
    }
    return out;
}


} // namespace

// An exact cube (grid points on tet faces and edges): nearly every alpha_0 is shared.
TEST(ConnectionTracing, SharedWalksMatchOnExactCube) {
    const SharedVsAlone r = compareSharing(generateCube(4, 3));
    EXPECT_GT(r.shared, r.darts / 4);
}

// Perturbed cubes with flipped and degenerate tets: swaps of start and target, exits from
// degenerate tets, anti darts.
TEST(ConnectionTracing, SharedWalksMatchOnPerturbedCubes) {
    long flipped = 0, tied = 0, shared = 0;
    for (unsigned seed : {1u, 2u, 3u}) {
        for (double a : {0.3, 0.8}) {
            SCOPED_TRACE("seed " + std::to_string(seed) + " amplitude " + std::to_string(a));
            ParametrizedTetMesh pm = generateCube(4, 3);
            perturbParameters(pm, a, seed);
            const SharedVsAlone r = compareSharing(pm);
            flipped += r.flipped;
            tied += r.tied;
            shared += r.shared;
        }
    }
    EXPECT_GT(flipped, 0);  // the test must cover folds
    EXPECT_GT(tied, 0);     // and walks that tie before all partners are found
    EXPECT_GT(shared, 0);
}

// Noise that breaks chart consistency (transitions that are not the identity everywhere,
// failed traces) and implicit cells in large tets.
TEST(ConnectionTracing, SharedWalksMatchOnNoisyAndImplicitCubes) {
    ParametrizedTetMesh noisy = generateCube(5, 4);
    applyParameterNoise(noisy, 0.25, 11);
    EXPECT_GT(compareSharing(noisy).shared, 0);
    const SharedVsAlone big = compareSharing(generateCube(2, 12), true);
    EXPECT_GT(big.shared, 0);
}

// A real map with transitions, singularities, flipped and degenerate tets (if available).
TEST(ConnectionTracing, SharedWalksMatchOnS1) {
    const std::string text = HexExTest::readSharedXz("S1_polycube_scale1.hexex.xz");
    if (text.empty()) GTEST_SKIP() << "../shared/data/S1_polycube_scale1.hexex.xz not available (or no xz)";
    const SharedVsAlone r = compareSharing(readHexExBuffer(text, "S1_polycube_scale1.hexex"));
    EXPECT_GT(r.flipped, 0);
    EXPECT_GT(r.degenerate, 0);
    EXPECT_GT(r.shared, 0);
    EXPECT_GT(r.tied, 0);
}

// A cylinder with a singular axis (transitions between the wedges) and large tets with
// implicit cells, with many more darts than one block of the tracing passes (4096): the
// same links on 1, 2 and 3 threads, and every alpha_1..alpha_3 partner that is an implicit
// cell at the dart's own point is that point's occurrence, for the deferred dart of each
// link as well as for the traced one.
TEST(ConnectionTracing, ImplicitPartnersAcrossBlocksOnCylinder) {
    ParametrizedTetMesh pm = generateCylinder(5, 16, 12, 1, 1);
    const SharedVsAlone r = compareSharing(pm, true);
    ASSERT_GT(r.darts, 8 * 4096) << "the map must span many blocks";
    EXPECT_GT(r.shared, 0);
    pm.mesh.build_adjacency();
    CornerParams params = pm.params;
    const Transitions tr = computeTransitions(pm.mesh, params);
    sanitizeParameters(pm.mesh, params, tr);
    const std::vector<TetSoS> tets = buildTetSoS(params, 1);
    const DartSet ds = extractDarts(tets, 1, 1e9, true);
    TraceStats st;
    const std::vector<DartLinks> links = traceConnections(pm.mesh, tr, tets, ds, 2, st);
    long implicitLinks = 0, wrong = 0;
    for (std::size_t d = 0; d < ds.darts.size(); ++d) {
        const Dart& D = ds.darts[d];
        for (int i = 1; i < 4; ++i) {
            const auto& f = D.d;
            const std::array<AxisDir, 3> want = i == 1   ? std::array<AxisDir, 3>{f[1], f[0], f[2]}
                                                : i == 2 ? std::array<AxisDir, 3>{f[0], f[2], f[1]}
                                                         : std::array<AxisDir, 3>{f[0], f[1], dirNeg(f[2])};
            if (ds.find(D.tet, D.z, want) >= 0 || !ds.implicitCell(D.tet, D.z, want)) continue;
            ++implicitLinks;
            if (implicitPartnerOccurrence(links[d][static_cast<std::size_t>(i)]) != ds.occurrence(D.tet, D.z) && ++wrong <= 5)
                ADD_FAILURE() << "dart " << d << " alpha_" << i << " = " << links[d][static_cast<std::size_t>(i)]
                              << ", expected the implicit partner at occurrence " << ds.occurrence(D.tet, D.z);
        }
    }
    EXPECT_GT(implicitLinks, 1000);
    EXPECT_EQ(wrong, 0);
    for (int i = 0; i < 4; ++i) EXPECT_EQ(st.unconnected[i], 0) << "i = " << i;
}
