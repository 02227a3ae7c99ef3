// With AnnihilationRetry::threads >= 2 the phase-by-phase retry runs on a second thread beside
// the first pass, on copies of the links, and is taken over when the first pass leaves a
// broken cell. The result must be exactly that of one thread: links, survivors, heirs and
// every counter, for every way the retries can end (kept at once, repaired, compared with
// later orders that restore the darts both runs changed, the first pass kept after all).
#include "../TestSupport/RandomAnnihilationMaps.hh"

#include <HexEx/Pipeline/AnnihilateStage.hh>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <vector>

using namespace HexEx;
using namespace HexExTestSupport;

namespace {

AnnihilationOutcome annihilate(const RandomDartMap& m, const RetrySetup& s, int threads) {
    AnnihilationRetry retry = retryOptions(s);
    retry.threads = threads;
    return runAnnihilation(m, retry, true);
}

} // namespace

TEST(AnnihilationBeside, SameResultAsOneThreadOnRandomMaps) {
    long taken = 0, dropped = 0, laterOrders = 0, firstKeptAfterAll = 0;
    for (unsigned seed = 1; seed <= 80; ++seed) {
        const RandomDartMap m = randomMutualDartMap(250 + static_cast<int>(seed % 5) * 60, seed);
        for (const RetrySetup& s : retrySetups()) {
            const AnnihilationOutcome one = annihilate(m, s, 1);
            EXPECT_FALSE(one.stats.phased_beside) << "seed " << seed;
            for (const int threads : {2, 3}) {
                const AnnihilationOutcome two = annihilate(m, s, threads);
                expectSameAnnihilation(one, two, seed, true);
                if (two.stats.phased_beside) {
                    ++taken;
                    if (two.stats.retry_runs > 1) ++laterOrders;
                    if (two.stats.reordered == 0) ++firstKeptAfterAll;
                } else if (two.stats.pairs > 0) {
                    EXPECT_EQ(two.stats.retry_runs, 0) << "seed " << seed;  // the first pass was kept
                    ++dropped;
                }
            }
        }
    }
    // Every way is exercised: taken and kept, taken and followed by other orders (which
    // restore the darts of both runs), the first pass kept after those. (Random maps have no
    // hex cells, so their first pass always leaves broken ones: never dropped here.)
    EXPECT_GT(taken, 100);
    EXPECT_GT(laterOrders, 20);
    EXPECT_GT(firstKeptAfterAll, 5);
    EXPECT_EQ(dropped, 0);
}

TEST(AnnihilationBeside, DroppedWhenTheFirstPassLeavesNoBrokenCell) {
    // Pairs linked by alpha_0 only, every other link free: the first pass removes every
    // dart, so no changed dart is left alive, no cell is broken and the first pass is kept.
    // The twin is stopped (it checks the request every 1,024 steps) or has finished, and is
    // dropped; the regular darts without a partner survive.
    RandomDartMap m;
    const int n = 100000;
    m.alpha.resize(n);
    m.sign.resize(n);
    for (int d = 0; d < n; ++d) {
        m.alpha[static_cast<std::size_t>(d)] = {d, d, d, d};
        m.sign[static_cast<std::size_t>(d)] = 1;
    }
    for (int d = 0; d + 1 < 80000; d += 2) {  // (regular, anti) pairs by alpha_0
        m.alpha[static_cast<std::size_t>(d)][0] = d + 1;
        m.alpha[static_cast<std::size_t>(d) + 1][0] = d;
        m.sign[static_cast<std::size_t>(d) + 1] = -1;
    }
    AnnihilationRetry retry;
    retry.enabled = true;
    const AnnihilationOutcome one = runAnnihilation(m, retry, true);
    retry.threads = 2;
    const AnnihilationOutcome two = runAnnihilation(m, retry, true);
    expectSameAnnihilation(one, two, 0, true);
    EXPECT_EQ(two.stats.pairs, 40000);
    EXPECT_EQ(two.stats.retry_runs, 0);
    EXPECT_FALSE(two.stats.phased_beside);
    EXPECT_EQ(std::count(two.alive.begin(), two.alive.end(), 1), 20000);
}

TEST(AnnihilationBeside, TheStageRunsItOnlyWhenAskedAndWithTheSameResult) {
    // annihilateStage() passes its thread count on unless AnnihilateInput::phased_beside is
    // off (callers short of memory); either way the survivors, heirs and counters are the same.
    int taken = 0;
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const RandomDartMap m = randomMutualDartMap(400, seed);
        long anti = 0;
        for (const signed char s : m.sign) anti += s < 0 ? 1 : 0;
        AnnihilateOutput out[2];
        AnnihilationLinks links[2];
        for (int beside = 0; beside < 2; ++beside) {
            links[beside] = m.alpha;
            AnnihilateInput in;
            in.alpha = &links[beside];
            in.sign = &m.sign;
            in.anti = anti;
            in.threads = 2;
            in.retry.enabled = true;
            in.mutual_links = true;
            in.phased_beside = beside == 1;
            out[beside] = annihilateStage(in);
        }
        EXPECT_FALSE(out[0].stats.phased_beside) << "seed " << seed;
        taken += out[1].stats.phased_beside ? 1 : 0;
        EXPECT_EQ(links[0], links[1]) << "seed " << seed;
        EXPECT_EQ(out[0].alive, out[1].alive) << "seed " << seed;
        EXPECT_EQ(out[0].heir, out[1].heir) << "seed " << seed;
        EXPECT_EQ(out[0].new_index, out[1].new_index) << "seed " << seed;
        EXPECT_EQ(out[0].stats.reordered, out[1].stats.reordered) << "seed " << seed;
        EXPECT_EQ(out[0].stats.broken_cells_after, out[1].stats.broken_cells_after) << "seed " << seed;
    }
    EXPECT_GT(taken, 10);
}
