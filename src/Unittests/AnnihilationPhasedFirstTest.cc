// Heavy folds (AnnihilationRetry::phased_first_share): where the anti darts are at least that
// share of the darts, phase by phase runs before the ascending pass. Kept, it must be the very
// run the retries keep as their first variant after an ascending pass that broke cells (same
// links, survivors, heirs); not kept, every dart is put back and the result must be exactly
// that of the annihilation without it (every counter too).
#include "../TestSupport/RandomAnnihilationMaps.hh"

#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

using namespace HexEx;
using namespace HexExTestSupport;

namespace {

AnnihilationOutcome annihilate(const RandomDartMap& m, const RetrySetup& s, double share, int threads, long min_darts = 0) {
    AnnihilationRetry retry = retryOptions(s);
    retry.phased_first_share = share;
    retry.phased_first_min_darts = min_darts;  // 0: these maps are small
    retry.threads = threads;
    return runAnnihilation(m, retry, true);
}

} // namespace

TEST(AnnihilationPhasedFirst, KeptRunIsThePhasedRetryAndOtherwiseNothingChanges) {
    // Random maps have no hex cells: every run leaves broken cells, so the ascending pass is
    // always undone and phase by phase is the first retry. Phase by phase first is kept only
    // where the setup's repair "succeeds" (repairAt > 0 and few broken-cell darts).
    long kept = 0, fellBack = 0;
    for (unsigned seed = 1; seed <= 60; ++seed) {
        const RandomDartMap m = randomMutualDartMap(250 + static_cast<int>(seed % 5) * 60, seed);
        for (const RetrySetup& s : retrySetups()) {
            const AnnihilationOutcome plain = annihilate(m, s, 0, 1);
            EXPECT_FALSE(plain.stats.phased_first) << "seed " << seed;
            for (const int threads : {1, 2, 3}) {
                const AnnihilationOutcome first = annihilate(m, s, 0.35, threads);
                if (first.stats.phased_first) {
                    ++kept;
                    EXPECT_GT(s.repairAt, 0u) << "seed " << seed;
                    EXPECT_EQ(first.stats.reordered, 1) << "seed " << seed;
                    EXPECT_EQ(first.stats.retry_runs, 1) << "seed " << seed;
                    EXPECT_TRUE(first.stats.repaired) << "seed " << seed;
                    // The retries keep the same run wherever the repair accepts it after the
                    // ascending pass (a repair that accepts every run: no other order runs).
                    RetrySetup always = s;
                    always.repairAt = static_cast<std::size_t>(-1);
                    const AnnihilationOutcome retried = annihilate(m, always, 0, threads);
                    EXPECT_EQ(retried.stats.reordered, 1) << "seed " << seed;
                    EXPECT_EQ(first.alpha, retried.alpha) << "seed " << seed;
                    EXPECT_EQ(first.alive, retried.alive) << "seed " << seed;
                    EXPECT_EQ(first.heirs, retried.heirs) << "seed " << seed;
                    EXPECT_EQ(first.stats.pairs, retried.stats.pairs) << "seed " << seed;
                    EXPECT_EQ(first.stats.remaining_anti, retried.stats.remaining_anti) << "seed " << seed;
                } else {
                    ++fellBack;
                    expectSameAnnihilation(plain, first, seed, true);
                }
            }
        }
    }
    EXPECT_GT(kept, 50);
    EXPECT_GT(fellBack, 500);
}

TEST(AnnihilationPhasedFirst, OnlyFromTheShareAndSizeOn) {
    // A share just above the map's share of anti darts, or a minimum size above its darts,
    // leaves the annihilation as it was (not heavy); the map's own share and size run phase by
    // phase first and keep it (the repair accepts it).
    const RandomDartMap m = randomMutualDartMap(400, 7);
    double anti = 0;
    for (const signed char x : m.sign) anti += x < 0 ? 1 : 0;
    const double share = anti / static_cast<double>(m.sign.size());
    const RetrySetup s{16, 6, true, static_cast<std::size_t>(-1)};
    const AnnihilationOutcome plain = annihilate(m, s, 0, 1);
    const AnnihilationOutcome light = annihilate(m, s, share + 1e-3, 1);
    const AnnihilationOutcome small = annihilate(m, s, share, 1, 401);
    const AnnihilationOutcome heavy = annihilate(m, s, share, 1, 400);
    expectSameAnnihilation(plain, light, 7, true);
    expectSameAnnihilation(plain, small, 7, true);
    EXPECT_FALSE(light.stats.phased_first);
    EXPECT_FALSE(small.stats.phased_first);
    EXPECT_TRUE(heavy.stats.phased_first);
    EXPECT_EQ(heavy.alpha, plain.alpha);
    EXPECT_EQ(heavy.alive, plain.alive);
    EXPECT_EQ(heavy.heirs, plain.heirs);
    EXPECT_EQ(plain.stats.retry_runs, 1);
    EXPECT_EQ(heavy.stats.retry_runs, 1);
}
