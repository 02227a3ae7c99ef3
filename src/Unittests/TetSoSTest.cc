/// @file TetSoSTest.cc
/// Tests of TetSoS::side(): the sign of o_j(x) equals orient3d() of the tet with corner j
/// replaced by x, on every path side() takes (the floating-point filter, the small dyadic
/// doubles, the 128-bit fixed-point integers, orient3d() for anything else), for points on,
/// next to and away from the faces' planes.

#include <HexEx/Extraction/TetSoS.hh>
#include <HexEx/Predicates/ExactPredicates.hh>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

using namespace HexEx;

namespace {

/// How the coordinates of one test case are drawn.
enum class Coords {
    SmallDyadic,  ///< multiples of 1/64 below 8 (FacePlanes::smallDyadic())
    Fixed20,      ///< integers below 1000 plus multiples of 2^-20 (the perturbed maps)
    Edge16,       ///< multiples of 2^-24 close to +-2^16, where the fixed-point range ends
    Large,        ///< multiples of 1/4 up to 1e7 (beyond the fixed-point range)
    Arbitrary     ///< any doubles in [-10, 10] (mostly not fixed-point)
};

double draw(Coords kind, std::mt19937& rng) {
    std::uniform_int_distribution<int> small(-512, 512), whole(-1000, 1000), frac(0, (1 << 20) - 1), edge(-64, 64);
    std::uniform_real_distribution<double> any(-10.0, 10.0), big(-1e7, 1e7);
    switch (kind) {
    case Coords::SmallDyadic: return small(rng) / 64.0;
    case Coords::Fixed20: return whole(rng) + std::ldexp(frac(rng), -20);
    case Coords::Edge16: return (small(rng) < 0 ? -1 : 1) * (65536.0 + std::ldexp(edge(rng), -24));
    case Coords::Large: return std::round(big(rng) * 4.0) / 4.0;
    case Coords::Arbitrary: return any(rng);
    }
    return 0;
}

/// orient3d() of @p T's corners with corner @p j replaced by @p x: the definition of o_j(x).
int reference(const TetSoS& T, int j, const Vec3d& x) {
    Vec3d q[4] = {T.p[0], T.p[1], T.p[2], T.p[3]};
    q[j] = x;
    return orient3d(q[0], q[1], q[2], q[3]);
}

} // namespace

TEST(TetSoS, SideEqualsOrient3dOnAndNextToEveryFacePlane) {
    std::mt19937 rng(7);
    const Coords kinds[] = {Coords::SmallDyadic, Coords::Fixed20, Coords::Edge16, Coords::Large, Coords::Arbitrary};
    std::uniform_int_distribution<int> weight(-4, 4), pick(0, 3);
    long zeros = 0, nonzeros = 0, compared = 0;
    for (Coords kind : kinds) {
        for (int trial = 0; trial < 400; ++trial) {
            std::array<Vec3d, 4> corners;
            for (auto& c : corners) c = Vec3d(draw(kind, rng), draw(kind, rng), draw(kind, rng));
            const TetSoS T(corners);
            for (int j = 0; j < 4; ++j) {
                // The corners of face j, in index order.
                int o[3], m = 0;
                for (int k = 0; k < 4; ++k)
                    if (k != j) o[m++] = k;
                const Vec3d& a = corners[static_cast<std::size_t>(o[0])];
                const Vec3d& b = corners[static_cast<std::size_t>(o[1])];
                const Vec3d& c = corners[static_cast<std::size_t>(o[2])];
                std::vector<Vec3d> points{a, b, c, corners[static_cast<std::size_t>(j)]};
                // On the plane (exactly, for the grid-like kinds: small dyadic weights), and
                // nudged off it by one unit of the coordinates' grid along each axis.
                const double s = weight(rng) / 4.0, t = weight(rng) / 4.0;
                const Vec3d on = a + (b - a) * s + (c - a) * t;
                points.push_back(on);
                points.push_back((a + b) * 0.5);
                for (double unit : {1.0 / 64, std::ldexp(1.0, -20), std::ldexp(1.0, -24), 1e-13}) {
                    Vec3d off = on;
                    off[pick(rng) % 3] += (weight(rng) < 0 ? -unit : unit);
                    points.push_back(off);
                }
                points.emplace_back(draw(kind, rng), draw(kind, rng), draw(kind, rng));
                for (const Vec3d& x : points) {
                    const int want = reference(T, j, x);
                    ASSERT_EQ(T.side(j, x), want) << "kind " << static_cast<int>(kind) << " trial " << trial << " face " << j;
                    (want == 0 ? zeros : nonzeros) += 1;
                    ++compared;
                }
            }
        }
    }
    // Both outcomes occur often: the exact paths (zero and tiny determinants) are exercised.
    EXPECT_EQ(compared, 5L * 400 * 4 * 11);
    EXPECT_GT(zeros, 20000);
    EXPECT_GT(nonzeros, 20000);
}

TEST(TetSoS, SidesAtACornerAndInsideFollowTheVolume) {
    const std::array<Vec3d, 4> corners{Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, 0, std::ldexp(1.0, -20))};
    const TetSoS T(corners);
    ASSERT_EQ(T.vol, 1);
    EXPECT_EQ(T.sides(corners[2]), (std::array<int, 4>{0, 0, 1, 0}));
    const Vec3d inside(0.25, 0.25, std::ldexp(1.0, -23));
    EXPECT_EQ(T.sides(inside), (std::array<int, 4>{1, 1, 1, 1}));
    // On face 3 (z = 0) and just below it: o_3 is zero, then opposite to the volume.
    EXPECT_EQ(T.side(3, Vec3d(0.25, 0.25, 0)), 0);
    EXPECT_EQ(T.side(3, Vec3d(0.25, 0.25, -std::ldexp(1.0, -24))), -1);
}
