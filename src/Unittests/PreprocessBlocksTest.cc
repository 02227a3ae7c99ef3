/// @file PreprocessBlocksTest.cc
/// Tests of parallelBlocks() (every index once, the lowest failing block's exception) and
/// of the transitions and the sanitization, which hand out blocks of faces and vertices to
/// the threads as they finish: on a map with a random chart per hex (dense translations,
/// every vertex walked) plus noise and corrupted corners, 2 and 3 threads give exactly the
/// transitions, parameters and statistics of 1 thread.

#include <HexEx/Core/Parallel.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/Generators/MapFromHexMesh.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/Preprocessing/Sanitization.hh>

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

using namespace HexEx;

TEST(PreprocessBlocks, ParallelBlocksVisitsEveryIndexOnce) {
    for (std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(7), std::size_t(1000), std::size_t(1001)})
        for (int threads : {1, 2, 3, 8}) {
            std::vector<std::atomic<int>> seen(n);
            std::vector<std::atomic<int>> blocks((n + 99) / 100);
            parallelBlocks(n, 100, threads, [&](int t, std::size_t k, std::size_t b, std::size_t e) {
                EXPECT_GE(t, 0);
                EXPECT_LT(t, threads);
                EXPECT_EQ(b, 100 * k);
                EXPECT_EQ(e, std::min(n, 100 * (k + 1)));
                ++blocks[k];
                for (std::size_t i = b; i < e; ++i) ++seen[i];
            });
            for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(seen[i].load(), 1) << "n " << n << " index " << i;
            for (std::size_t k = 0; k < blocks.size(); ++k) EXPECT_EQ(blocks[k].load(), 1) << "n " << n << " block " << k;
        }
}

TEST(PreprocessBlocks, ParallelBlocksRethrowsTheLowestFailingBlock) {
    for (int threads : {1, 2, 3}) {
        try {
            parallelBlocks(1000, 10, threads, [&](int, std::size_t k, std::size_t, std::size_t) {
                if (k == 37 || k == 38 || k == 90) throw std::runtime_error(std::to_string(k));
            });
            ADD_FAILURE() << "no exception at " << threads << " threads";
        } catch (const std::runtime_error& e) {
            EXPECT_EQ(std::string(e.what()), "37") << threads << " threads";
        }
    }
}

TEST(PreprocessBlocks, TransitionsAndSanitizationDoNotDependOnThreads) {
    // A hex mesh (the extraction of a cube), remapped with a random chart per hex and noise
    // on the face and cell centres: 24,000 tets, 96,000 halffaces (6 fit blocks), 5,000+
    // vertices (5 vertex blocks); two corrupted corners to repair.
    ParametrizedTetMesh cube = generateCube(2, 10);
    cube.mesh.build_adjacency();
    HexMesh hexes;
    extractHexMesh(cube, hexes);
    ASSERT_EQ(hexes.hexes.size(), 1000u);
    MapFromHexOptions mo;
    mo.perturb = 0.3;
    mo.seed = 5;
    ParametrizedTetMesh pm = mapFromHexMesh(hexes, mo).map;
    pm.mesh.build_adjacency();
    ASSERT_EQ(pm.mesh.n_cells(), 24000u);
    ASSERT_GT(pm.mesh.n_vertices(), 2 * 1024u);
    pm.params[100][1][0] += 1000;
    pm.params[23000][3][2] = -5e4;

    const Transitions ref = computeTransitions(pm.mesh, pm.params, nullptr, 1);
    std::size_t translated = 0;
    for (std::size_t h = 0; h < ref.halfface.size(); ++h) translated += ref.halfface[h].t == Vec3i(0, 0, 0) ? 0 : 1;
    EXPECT_GT(8 * translated, ref.halfface.size()) << "the translations must be dense";
    EXPECT_EQ(ref.n_inconsistent, 6);  // the three faces of each corrupted corner
    CornerParams refParams = pm.params;
    SanitizeOptions so;
    const SanitizeStats refStats = sanitizeParameters(pm.mesh, refParams, ref, so);
    EXPECT_EQ(refStats.repaired_corners, 2);

    for (int threads : {2, 3}) {
        SCOPED_TRACE(std::to_string(threads) + " threads");
        const Transitions tr = computeTransitions(pm.mesh, pm.params, nullptr, threads);
        EXPECT_EQ(tr.n_ambiguous, ref.n_ambiguous);
        EXPECT_EQ(tr.n_unresolved, ref.n_unresolved);
        EXPECT_EQ(tr.n_inconsistent, ref.n_inconsistent);
        ASSERT_EQ(tr.halfface.size(), ref.halfface.size());
        for (std::size_t h = 0; h < ref.halfface.size(); ++h) ASSERT_EQ(tr.halfface[h], ref.halfface[h]) << "halfface " << h;
        CornerParams params = pm.params;
        so.threads = threads;
        const SanitizeStats stats = sanitizeParameters(pm.mesh, params, tr, so);
        EXPECT_EQ(stats.snapped_coordinates, refStats.snapped_coordinates);
        EXPECT_EQ(stats.repaired_corners, refStats.repaired_corners);
        ASSERT_EQ(stats.repairs.size(), refStats.repairs.size());
        for (std::size_t k = 0; k < stats.repairs.size(); ++k) {
            EXPECT_EQ(stats.repairs[k].tet, refStats.repairs[k].tet);
            EXPECT_EQ(stats.repairs[k].corner, refStats.repairs[k].corner);
            EXPECT_EQ(stats.repairs[k].vertex, refStats.repairs[k].vertex);
            EXPECT_EQ(stats.repairs[k].original, refStats.repairs[k].original);
            EXPECT_EQ(stats.repairs[k].repaired, refStats.repairs[k].repaired);
        }
        EXPECT_TRUE(params == refParams) << "sanitized parameters differ";
    }
}
