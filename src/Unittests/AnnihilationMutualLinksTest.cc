// annihilateDarts() with mutual_links (the connect stage's links are always mutual): the work
// list skips the checks that cannot queue a dart, and the result must be exactly that of the
// run without the promise (links, survivors, heirs, counters), in every order the retries try.
#include <HexEx/Postprocessing/DartAnnihilation.hh>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

using namespace HexEx;

namespace {

using Links = std::vector<std::array<int, 4>>;

/// A random map of @p n darts with mutual links: for each alpha_i, the darts are shuffled and
/// taken two by two as partners (one pair in 8 left as two free links, one in 16 as two
/// unconnected ones); about 40 % anti darts.
struct RandomMap {
    Links alpha;
    std::vector<signed char> sign;
};

RandomMap randomMutualMap(int n, unsigned seed) {
    std::mt19937 rng(seed);
    RandomMap m;
    m.alpha.assign(static_cast<std::size_t>(n), {-1, -1, -1, -1});
    std::vector<int> order(static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < 4; ++i) {
        std::iota(order.begin(), order.end(), 0);
        std::shuffle(order.begin(), order.end(), rng);
        for (std::size_t k = 0; k + 1 < order.size(); k += 2) {
            const int x = order[k], y = order[k + 1];
            const unsigned r = rng() % 16;
            const bool freeLinks = r < 2, unconnected = r == 2;
            m.alpha[static_cast<std::size_t>(x)][i] = unconnected ? -1 : freeLinks ? x : y;
            m.alpha[static_cast<std::size_t>(y)][i] = unconnected ? -1 : freeLinks ? y : x;
        }
        if (order.size() % 2) m.alpha[static_cast<std::size_t>(order.back())][i] = order.back();
    }
    m.sign.resize(static_cast<std::size_t>(n));
    for (auto& s : m.sign) s = (rng() % 10 < 4) ? -1 : 1;
    return m;
}

/// Everything annihilateDarts() leaves.
struct Outcome {
    Links alpha;
    std::vector<char> alive;
    std::vector<std::pair<int, int>> heirs;
    AnnihilationStats stats;
};

Outcome annihilate(const RandomMap& m, bool retries, bool mutual) {
    Outcome o;
    o.alpha = m.alpha;
    o.alive.assign(m.sign.size(), 1);
    AnnihilationRetry retry;
    retry.enabled = retries;
    o.stats = annihilateDarts(o.alpha, m.sign, o.alive, &o.heirs, {}, retry, mutual);
    return o;
}

void expectSame(const Outcome& a, const Outcome& b, unsigned seed) {
    EXPECT_EQ(a.alpha, b.alpha) << "seed " << seed;
    EXPECT_EQ(a.alive, b.alive) << "seed " << seed;
    EXPECT_EQ(a.heirs, b.heirs) << "seed " << seed;
    EXPECT_EQ(a.stats.pairs, b.stats.pairs) << "seed " << seed;
    EXPECT_EQ(a.stats.remaining_anti, b.stats.remaining_anti) << "seed " << seed;
    EXPECT_EQ(a.stats.broken_cells_before, b.stats.broken_cells_before) << "seed " << seed;
    EXPECT_EQ(a.stats.broken_cells_after, b.stats.broken_cells_after) << "seed " << seed;
    EXPECT_EQ(a.stats.retry_runs, b.stats.retry_runs) << "seed " << seed;
    EXPECT_EQ(a.stats.reordered, b.stats.reordered) << "seed " << seed;
    EXPECT_EQ(a.stats.merged_vertex_runs, b.stats.merged_vertex_runs) << "seed " << seed;
}

} // namespace

TEST(AnnihilationMutualLinks, SameResultAsWithoutThePromiseOnRandomMaps) {
    long pairs = 0, retried = 0, phaseByPhaseKept = 0, left = 0;
    for (unsigned seed = 1; seed <= 300; ++seed) {
        const RandomMap m = randomMutualMap(300 + static_cast<int>(seed % 7) * 50, seed);
        for (const bool retries : {false, true}) {
            const Outcome plain = annihilate(m, retries, false);
            const Outcome fast = annihilate(m, retries, true);
            expectSame(plain, fast, seed);
            pairs += plain.stats.pairs;
            left += plain.stats.remaining_anti;
            if (retries) {
                retried += plain.stats.retry_runs > 0 ? 1 : 0;
                phaseByPhaseKept += plain.stats.reordered == 1 ? 1 : 0;
            }
        }
    }
    // The maps exercise what the promise changes: many pairs, anti darts left over (the
    // work list's checks that fail), the retries and the phase-by-phase run.
    EXPECT_GT(pairs, 10000);
    EXPECT_GT(left, 1000);
    EXPECT_GT(retried, 100);
    EXPECT_GT(phaseByPhaseKept, 0);
}

TEST(AnnihilationMutualLinks, ResultDependsOnTheOrderSoTheComparisonCanFail) {
    // The random maps are order-sensitive: a run in another order (what a wrongly skipped
    // queue entry amounts to) gives other links on some of them. Checked with the retries'
    // own orders: the kept order differs from the first pass's on some maps and then the
    // links differ from a run without retries.
    int differ = 0;
    for (unsigned seed = 1; seed <= 100; ++seed) {
        const RandomMap m = randomMutualMap(400, seed);
        const Outcome first = annihilate(m, false, true);
        const Outcome kept = annihilate(m, true, true);
        if (kept.stats.reordered != 0 && kept.alpha != first.alpha) ++differ;
    }
    EXPECT_GT(differ, 10);
}
