// Heirs of the annihilated darts (annihilateDarts() with a heirs list): the vertex groups are
// joined after the run from the removed pairs' links as they were when each pair was removed.
#include <HexEx/Postprocessing/DartAnnihilation.hh>

#include <gtest/gtest.h>

#include <array>
#include <utility>
#include <vector>

using namespace HexEx;

namespace {

using Links = std::vector<std::array<int, 4>>;
using Heirs = std::vector<std::pair<int, int>>;

/// n darts with every link free (each dart its own alpha_0..alpha_3 partner).
Links freeLinks(int n) {
    Links a(static_cast<std::size_t>(n));
    for (int d = 0; d < n; ++d) a[static_cast<std::size_t>(d)] = {d, d, d, d};
    return a;
}

/// Links darts x and y by alpha_i, both ways.
void sew(Links& a, int x, int y, int i) {
    a[static_cast<std::size_t>(x)][static_cast<std::size_t>(i)] = y;
    a[static_cast<std::size_t>(y)][static_cast<std::size_t>(i)] = x;
}

/// What one annihilation run with a heirs list leaves.
struct HeirsRun {
    int pairs = 0;            ///< pairs removed
    std::vector<char> alive;  ///< per dart: 1 if it survived
    Heirs heirs;              ///< (removed dart, heir) pairs
};

/// Annihilates the darts of @p a (all alive at first) with signs @p sign, keeping the heirs.
HeirsRun annihilateWithHeirs(Links& a, const std::vector<signed char>& sign) {
    HeirsRun r;
    r.alive.assign(sign.size(), 1);
    r.pairs = static_cast<int>(annihilateDarts(a, sign, r.alive, &r.heirs).pairs);
    return r;
}

} // namespace

TEST(AnnihilationHeirs, ChainOfTwoPairsLeavesOneGroupWithTheSmallestSurvivor) {
    // Regular 0 and anti 1 share an edge (alpha_0); 0's alpha_1 goes to 2, 1's to 3; regular 3
    // and anti 4 share an edge, 4's alpha_1 goes to 5. The pair (0, 1) joins 0, 1, 2, 3 and
    // re-links alpha_1(2) = 3; the pair (3, 4) then joins 3 with its partner of that moment
    // (2) and 4 with 5. Survivors 2 and 5 are one group: 2 is the heir of every removed dart.
    Links a = freeLinks(6);
    sew(a, 0, 1, 0);
    sew(a, 0, 2, 1);
    sew(a, 1, 3, 1);
    sew(a, 3, 4, 0);
    sew(a, 4, 5, 1);
    const std::vector<signed char> sign = {1, -1, 1, 1, -1, 1};
    const HeirsRun r = annihilateWithHeirs(a, sign);
    EXPECT_EQ(r.pairs, 2);
    EXPECT_EQ(r.alive, (std::vector<char>{0, 0, 1, 0, 0, 1}));
    EXPECT_EQ(r.heirs, (Heirs{{0, 2}, {1, 2}, {3, 2}, {4, 2}}));
}

TEST(AnnihilationHeirs, SeparatePairsKeepSeparateHeirs) {
    // Two pairs far apart: (0, 1) next to survivor 2, (3, 4) next to survivor 5.
    Links a = freeLinks(6);
    sew(a, 0, 1, 0);
    sew(a, 0, 2, 2);
    sew(a, 3, 4, 0);
    sew(a, 4, 5, 3);
    const std::vector<signed char> sign = {1, -1, 1, 1, -1, 1};
    const HeirsRun r = annihilateWithHeirs(a, sign);
    EXPECT_EQ(r.pairs, 2);
    EXPECT_EQ(r.heirs, (Heirs{{0, 2}, {1, 2}, {3, 5}, {4, 5}}));
}

TEST(AnnihilationHeirs, OneSidedLinkToARemovedDartStillGivesTheGroupsOfThatMoment) {
    // Not involutive: regular 2's alpha_1 points to 0 (0's alpha_1 is free). The pair (0, 1)
    // goes first; then the pair (2, 3) re-links 2's alpha_1 partner (removed dart 0) to 3's
    // (4), a write into a removed dart's links: the pending pair is joined before it, the
    // rest of the run at once. Groups of the moment: {0, 1}, then {2, 3, 0} and {3, 4}: one
    // group, survivor 4.
    Links a = {{1, 0, 0, 0}, {0, 1, 1, 1}, {3, 0, 2, 2}, {2, 4, 3, 3}, {4, 3, 4, 4}};
    const std::vector<signed char> sign = {1, -1, 1, -1, 1};
    const HeirsRun r = annihilateWithHeirs(a, sign);
    EXPECT_EQ(r.pairs, 2);
    EXPECT_EQ(r.alive, (std::vector<char>{0, 0, 0, 0, 1}));
    EXPECT_EQ(r.heirs, (Heirs{{0, 4}, {1, 4}, {2, 4}, {3, 4}}));
}
