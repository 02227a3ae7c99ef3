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

AnnihilationOutcome annihilate(const RandomDartMap& m, const RetrySetup& s, bool exact) {
    AnnihilationRetry retry = retryOptions(s);
    retry.exact_first_count = exact;
    return runAnnihilation(m, retry, true);
}

} // namespace

TEST(AnnihilationFirstCount, SameResultAsCountingEveryBrokenCellAtOnce) {
    long stoppedEarly = 0, countedLater = 0, firstKept = 0, othersKept = 0;
    for (unsigned seed = 1; seed <= 120; ++seed) {
        const RandomDartMap m = randomMutualDartMap(250 + static_cast<int>(seed % 5) * 60, seed);
        for (const RetrySetup& s : retrySetups()) {
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
