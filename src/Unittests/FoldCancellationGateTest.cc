// mayCancelFoldPoints(): the dart stage computes the chart components for the cheap folds only
// where some flipped tet gets a dense index (grid box of at least kDenseIndexMinPoints points).
#include <HexEx/Extraction/DartExtraction.hh>
#include <HexEx/Extraction/FoldCancellation.hh>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

using namespace HexEx;

namespace {

/// A tet with corners 0, s e_x, s e_y, s e_z shifted by @p o (proper), or with two corners
/// swapped (flipped).
std::array<Vec3d, 4> corners(double s, const Vec3d& o, bool flipped) {
    std::array<Vec3d, 4> c = {o, o + Vec3d(s, 0, 0), o + Vec3d(0, s, 0), o + Vec3d(0, 0, s)};
    if (flipped) std::swap(c[1], c[2]);
    return c;
}

} // namespace

TEST(FoldCancellationGate, OnlyALargeFlippedTetCanCancel) {
    // Corner tet of side s at the origin: grid points (i, j, k) >= 0 with i + j + k <= s, but
    // the grid box counts (s + 1)^3 points: s = 3 gives 64, s = 2 gives 27.
    const auto big = corners(3, Vec3d(0, 0, 0), true), small = corners(2, Vec3d(0, 0, 0), true);
    const auto bigProper = corners(3, Vec3d(0, 0, 0), false);
    // Shifted by a half: the box of side 3 then holds only 3^3 = 27 points.
    const auto bigShifted = corners(3, Vec3d(0.5, 0.5, 0.5), true);
    const std::vector<TetSoS> smallOnly = {TetSoS(small), TetSoS(bigProper)};
    EXPECT_EQ(TetSoS(big).vol, -1);
    EXPECT_EQ(TetSoS(bigProper).vol, 1);
    EXPECT_FALSE(mayCancelFoldPoints(smallOnly));
    EXPECT_FALSE(mayCancelFoldPoints({TetSoS(bigShifted), TetSoS(bigProper)}));
    EXPECT_TRUE(mayCancelFoldPoints({TetSoS(bigProper), TetSoS(big)}));
    EXPECT_GE(gridBox(TetSoS(big), 0).points, kDenseIndexMinPoints);
    EXPECT_LT(gridBox(TetSoS(small), 0).points, kDenseIndexMinPoints);
    EXPECT_LT(gridBox(TetSoS(bigShifted), 0).points, kDenseIndexMinPoints);
    // A parameter the extraction refuses: left to it (gridBox() throws there).
    const auto absurd = corners(1, Vec3d(2e9, 0, 0), true);
    EXPECT_TRUE(mayCancelFoldPoints({TetSoS(absurd)}));
    EXPECT_FALSE(mayCancelFoldPoints({}));
}
