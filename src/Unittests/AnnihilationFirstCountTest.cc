// The first pass's broken cells are counted only up to the first one, and all of them only
// where a retry is compared with that count (AnnihilationRetry::exact_first_count off, the
// default). The result must be exactly that of counting them all at once: links, survivors,
// heirs, the order kept and its broken cells, for every way the retries can end.
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

/// A random map of @p n darts with mutual links (each alpha_i pairs the shuffled darts two by
/// two; one pair in 8 free, one in 16 unconnected) and about 40 % anti darts.
struct RandomMap {
    Links alpha;
    std::vector<signed char> sign;
};

RandomMap randomMap(int n, unsigned seed) {
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
            m.alpha[static_cast<std::size_t>(x)][i] = r == 2 ? -1 : r < 2 ? x : y;
            m.alpha[static_cast<std::size_t>(y)][i] = r == 2 ? -1 : r < 2 ? y : x;
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

/// One way the retries can be set up; @p repairAt > 0: a repair callback that "succeeds"
/// (without changing anything) when the phase-by-phase run leaves at most that many
/// broken-cell darts, so that some runs are kept without a comparison.
struct RetrySetup {
    int orders, patience;
    bool alpha3Only;
    std::size_t repairAt;
};

Outcome annihilate(const RandomMap& m, const RetrySetup& s, bool exact) {
    Outcome o;
    o.alpha = m.alpha;
    o.alive.assign(m.sign.size(), 1);
    AnnihilationRetry retry;
    retry.enabled = true;
    retry.orders = s.orders;
    retry.patience = s.patience;
    retry.keep_alpha3_only = s.alpha3Only;
    retry.exact_first_count = exact;
    if (s.repairAt > 0) retry.repair = [&s](const std::vector<int>& broken) { return broken.size() <= s.repairAt; };
    o.stats = annihilateDarts(o.alpha, m.sign, o.alive, &o.heirs, {}, retry, true);
    return o;
}

} // namespace

TEST(AnnihilationFirstCount, SameResultAsCountingEveryBrokenCellAtOnce) {
    const RetrySetup setups[] = {{16, 6, true, 0}, {16, 6, false, 0}, {3, 1, false, 0}, {1, 6, true, 0}, {16, 6, true, 200}, {4, 2, false, 400}};
    long stoppedEarly = 0, countedLater = 0, firstKept = 0, othersKept = 0;
    for (unsigned seed = 1; seed <= 120; ++seed) {
        const RandomMap m = randomMap(250 + static_cast<int>(seed % 5) * 60, seed);
        for (const RetrySetup& s : setups) {
            const Outcome exact = annihilate(m, s, true);
            const Outcome lazy = annihilate(m, s, false);
            EXPECT_EQ(exact.alpha, lazy.alpha) << "seed " << seed;
            EXPECT_EQ(exact.alive, lazy.alive) << "seed " << seed;
            EXPECT_EQ(exact.heirs, lazy.heirs) << "seed " << seed;
            EXPECT_EQ(exact.stats.pairs, lazy.stats.pairs) << "seed " << seed;
            EXPECT_EQ(exact.stats.remaining_anti, lazy.stats.remaining_anti) << "seed " << seed;
            EXPECT_EQ(exact.stats.broken_cells_after, lazy.stats.broken_cells_after) << "seed " << seed;
            EXPECT_EQ(exact.stats.reordered, lazy.stats.reordered) << "seed " << seed;
            EXPECT_EQ(exact.stats.retry_runs, lazy.stats.retry_runs) << "seed " << seed;
            EXPECT_EQ(exact.stats.merged_vertex_runs, lazy.stats.merged_vertex_runs) << "seed " << seed;
            EXPECT_EQ(exact.stats.repaired, lazy.stats.repaired) << "seed " << seed;
            EXPECT_EQ(exact.stats.alpha3_only_kept, lazy.stats.alpha3_only_kept) << "seed " << seed;
            // Counted before: 0 or exact; otherwise stopped at the first broken cell.
            if (lazy.stats.broken_cells_before == exact.stats.broken_cells_before) {
                if (exact.stats.broken_cells_before > 1) ++countedLater;
            } else {
                EXPECT_EQ(lazy.stats.broken_cells_before, 1) << "seed " << seed;
                EXPECT_GT(exact.stats.broken_cells_before, 1) << "seed " << seed;
                ++stoppedEarly;
            }
            if (exact.stats.retry_runs > 0) ++(exact.stats.reordered == 0 ? firstKept : othersKept);
        }
    }
    // Every way out is exercised: kept at once without the count (repair or quads only),
    // compared and counted later, the first pass kept after all (run again and counted).
    EXPECT_GT(stoppedEarly, 20);
    EXPECT_GT(countedLater, 20);
    EXPECT_GT(firstKept, 10);
    EXPECT_GT(othersKept, 10);
}
