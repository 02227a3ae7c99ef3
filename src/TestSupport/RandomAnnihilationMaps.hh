/// @file RandomAnnihilationMaps.hh
/// Test support (not installed): random dart maps with mutual links for annihilateDarts(),
/// and what a run leaves, for the tests that compare two ways of running it (the mutual-link
/// promise, the first pass's lazy broken-cell count). Shared so that both draw the same maps.
#pragma once

#include <HexEx/Postprocessing/DartAnnihilation.hh>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

namespace HexExTestSupport {

/// Links per dart, as annihilateDarts() takes them.
using AnnihilationLinks = std::vector<std::array<int, 4>>;

/// A dart map for annihilateDarts(): links and signs.
struct RandomDartMap {
    AnnihilationLinks alpha;        ///< alpha_0..alpha_3 per dart
    std::vector<signed char> sign;  ///< +1 regular, -1 anti
};

/// A random map of @p n darts with mutual links: for each alpha_i the darts are shuffled and
/// taken two by two as partners (one pair in 8 left as two free links, one in 16 as two
/// unconnected ones); about 40 % anti darts. The same @p seed gives the same map.
inline RandomDartMap randomMutualDartMap(int n, unsigned seed) {
    std::mt19937 rng(seed);
    RandomDartMap m;
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
struct AnnihilationOutcome {
    AnnihilationLinks alpha;                  ///< the links after the run
    std::vector<char> alive;                  ///< survivors
    std::vector<std::pair<int, int>> heirs;   ///< (removed dart, heir) pairs
    HexEx::AnnihilationStats stats;           ///< the run's counters
};

/// Runs annihilateDarts() on a copy of @p m with @p retry and @p mutual_links.
inline AnnihilationOutcome runAnnihilation(const RandomDartMap& m, const HexEx::AnnihilationRetry& retry,
                                           bool mutual_links) {
    AnnihilationOutcome o;
    o.alpha = m.alpha;
    o.alive.assign(m.sign.size(), 1);
    o.stats = HexEx::annihilateDarts(o.alpha, m.sign, o.alive, &o.heirs, {}, retry, mutual_links);
    return o;
}

/// One way the retries can be set up; @p repairAt > 0: a repair callback that "succeeds"
/// (without changing anything) when the phase-by-phase run leaves at most that many
/// broken-cell darts, so that some runs are kept without a comparison.
struct RetrySetup {
    int orders, patience;
    bool alpha3Only;
    std::size_t repairAt;
};

/// The setups the comparison tests run every map with: many and few orders, every way a
/// retry can end (kept at once, repaired, compared with later orders).
inline const std::vector<RetrySetup>& retrySetups() {
    static const std::vector<RetrySetup> setups = {{16, 6, true, 0},   {16, 6, false, 0},  {3, 1, false, 0},
                                                   {1, 6, true, 0},    {16, 6, true, 200}, {4, 2, false, 400}};
    return setups;
}

/// The retry options of @p s (enabled; the other options at their defaults).
inline HexEx::AnnihilationRetry retryOptions(const RetrySetup& s) {
    HexEx::AnnihilationRetry retry;
    retry.enabled = true;
    retry.orders = s.orders;
    retry.patience = s.patience;
    retry.keep_alpha3_only = s.alpha3Only;
    const std::size_t repairAt = s.repairAt;
    if (repairAt > 0) retry.repair = [repairAt](const std::vector<int>& broken) { return broken.size() <= repairAt; };
    return retry;
}

/// Expects the same links, survivors, heirs and counters of @p a and @p b (map @p seed in the
/// messages); AnnihilationStats::broken_cells_before only if @p with_first_count.
inline void expectSameAnnihilation(const AnnihilationOutcome& a, const AnnihilationOutcome& b, unsigned seed,
                                   bool with_first_count) {
    EXPECT_EQ(a.alpha, b.alpha) << "seed " << seed;
    EXPECT_EQ(a.alive, b.alive) << "seed " << seed;
    EXPECT_EQ(a.heirs, b.heirs) << "seed " << seed;
    EXPECT_EQ(a.stats.pairs, b.stats.pairs) << "seed " << seed;
    EXPECT_EQ(a.stats.remaining_anti, b.stats.remaining_anti) << "seed " << seed;
    if (with_first_count) {
        EXPECT_EQ(a.stats.broken_cells_before, b.stats.broken_cells_before) << "seed " << seed;
    }
    EXPECT_EQ(a.stats.broken_cells_after, b.stats.broken_cells_after) << "seed " << seed;
    EXPECT_EQ(a.stats.retry_runs, b.stats.retry_runs) << "seed " << seed;
    EXPECT_EQ(a.stats.reordered, b.stats.reordered) << "seed " << seed;
    EXPECT_EQ(a.stats.merged_vertex_runs, b.stats.merged_vertex_runs) << "seed " << seed;
    EXPECT_EQ(a.stats.repaired, b.stats.repaired) << "seed " << seed;
    EXPECT_EQ(a.stats.alpha3_only_kept, b.stats.alpha3_only_kept) << "seed " << seed;
}

} // namespace HexExTestSupport
