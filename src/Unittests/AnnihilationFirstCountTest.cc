// The first pass's broken cells are counted only up to the first one, and all of them only
// where a retry is compared with that count (AnnihilationRetry::exact_first_count off, the
// default). The result must be exactly that of counting them all at once: links, survivors,
// heirs, the order kept and its broken cells, for every way the retries can end.
#include "../TestSupport/RandomAnnihilationMaps.hh"

#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

using namespace HexEx;
using namespace HexExTestSupport;

namespace {

/// One way the retries can be set up; @p repairAt > 0: a repair callback that "succeeds"
/// (without changing anything) when the phase-by-phase run leaves at most that many
/// broken-cell darts, so that some runs are kept without a comparison.
struct RetrySetup {
    int orders, patience;
    bool alpha3Only;
    std::size_t repairAt;
};

AnnihilationOutcome annihilate(const RandomDartMap& m, const RetrySetup& s, bool exact) {
    AnnihilationRetry retry;
    retry.enabled = true;
    retry.orders = s.orders;
    retry.patience = s.patience;
    retry.keep_alpha3_only = s.alpha3Only;
    retry.exact_first_count = exact;
    if (s.repairAt > 0) retry.repair = [&s](const std::vector<int>& broken) { return broken.size() <= s.repairAt; };
    return runAnnihilation(m, retry, true);
}

} // namespace

TEST(AnnihilationFirstCount, SameResultAsCountingEveryBrokenCellAtOnce) {
    const RetrySetup setups[] = {{16, 6, true, 0}, {16, 6, false, 0}, {3, 1, false, 0}, {1, 6, true, 0}, {16, 6, true, 200}, {4, 2, false, 400}};
    long stoppedEarly = 0, countedLater = 0, firstKept = 0, othersKept = 0;
    for (unsigned seed = 1; seed <= 120; ++seed) {
        const RandomDartMap m = randomMutualDartMap(250 + static_cast<int>(seed % 5) * 60, seed);
        for (const RetrySetup& s : setups) {
            const AnnihilationOutcome exact = annihilate(m, s, true);
            const AnnihilationOutcome lazy = annihilate(m, s, false);
            expectSameAnnihilation(exact, lazy, seed, false);
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
