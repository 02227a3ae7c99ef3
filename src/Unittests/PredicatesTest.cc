// Exact predicates, point classification (including flat tets) and the symbolic perturbation.

#include <HexEx/Extraction/FacePlanes.hh>
#include <HexEx/Extraction/TetSoS.hh>
#include <HexEx/Predicates/ExactPredicates.hh>

#include <gtest/gtest.h>

#include <array>
#include <random>
#include <vector>

using namespace HexEx;

TEST(Predicates, Orient3dSignsAndExactZero) {
    const Vec3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    EXPECT_EQ(orient3d(a, b, c, Vec3d(0, 0, 1)), 1);
    EXPECT_EQ(orient3d(a, b, c, Vec3d(0, 0, -1)), -1);
    EXPECT_EQ(orient3d(a, b, c, Vec3d(0.3, 0.7, 0)), 0);
    // Nearly coplanar: a double evaluation of the determinant would round to the wrong sign or zero.
    const Vec3d p(0.1, 0.1, 0.1), q(0.2, 0.2, 0.2), r(0.3, 0.3, 0.3 + 1e-17 * 0 + 5.551115123125783e-17);
    EXPECT_EQ(orient3d(a, p, q, r), 0);  // p, q, a collinear: any r gives zero
    const Vec3d s(1e-30, 1, 1), t(1, 1e-30, 1), u(1, 1, 1e-30);
    EXPECT_EQ(orient3d(a, s, t, u), -orient3d(a, t, s, u));
}

TEST(Predicates, Orient2dAxisProjections) {
    const Vec3d a(0, 0, 0), b(0, 1, 0), c(0, 0, 1);
    EXPECT_EQ(orient2dAxis(a, b, c, 0), 1);   // (y, z) plane: counter-clockwise
    EXPECT_EQ(orient2dAxis(a, c, b, 0), -1);
    EXPECT_EQ(orient2dAxis(a, b, c, 1), 0);   // projected onto (z, x): collinear
    // Values whose products cancel catastrophically in doubles.
    const double e = 1.0 / (1 << 30);
    const Vec3d p(0, 1 + e, 1 + 2 * e), q(0, 1 + 2 * e, 1 + 4 * e), r(0, 1 + 3 * e, 1 + 6 * e);
    EXPECT_EQ(orient2dAxis(p, q, r, 0), 0);
}

namespace {
const std::array<Vec3d, 4> kUnit = {Vec3d(0, 0, 0), Vec3d(2, 0, 0), Vec3d(0, 2, 0), Vec3d(0, 0, 2)};
}

TEST(Predicates, ClassifyPointInProperTet) {
    const Vec3d* p = kUnit.data();
    EXPECT_EQ(classifyPoint(p, Vec3d(0, 0, 0)).location, PointLocation::AtVertex);
    EXPECT_EQ(classifyPoint(p, Vec3d(0, 0, 0)).corners, 1u);
    EXPECT_EQ(classifyPoint(p, Vec3d(1, 0, 0)).location, PointLocation::OnEdge);
    EXPECT_EQ(classifyPoint(p, Vec3d(1, 0, 0)).corners, 0b0011u);
    EXPECT_EQ(classifyPoint(p, Vec3d(1, 1, 0)).location, PointLocation::OnEdge);  // edge 1-2
    EXPECT_EQ(classifyPoint(p, Vec3d(1, 1, 0)).corners, 0b0110u);
    const auto f = classifyPoint(p, Vec3d(0.5, 0.5, 0));
    EXPECT_EQ(f.location, PointLocation::OnFace);
    EXPECT_EQ(f.corners, 0b0111u);
    EXPECT_EQ(classifyPoint(p, Vec3d(0.5, 0.5, 0.5)).location, PointLocation::Inside);
    EXPECT_EQ(classifyPoint(p, Vec3d(1, 1, 1)).location, PointLocation::Outside);
    EXPECT_EQ(classifyPoint(p, Vec3d(-1, 0, 0)).location, PointLocation::Outside);
    // Flipped tet: same classification.
    const Vec3d flipped[4] = {kUnit[0], kUnit[2], kUnit[1], kUnit[3]};
    EXPECT_EQ(classifyPoint(flipped, Vec3d(0.5, 0.5, 0.5)).location, PointLocation::Inside);
    EXPECT_EQ(classifyPoint(flipped, Vec3d(1, 0, 0)).location, PointLocation::OnEdge);
}

TEST(Predicates, ClassifyPointInFlatTets) {
    // Four coplanar corners (z = 0): a flat quad region.
    const Vec3d flat[4] = {Vec3d(0, 0, 0), Vec3d(2, 0, 0), Vec3d(2, 2, 0), Vec3d(0, 2, 0)};
    EXPECT_EQ(classifyPoint(flat, Vec3d(1, 0.5, 0)).location, PointLocation::OnFace);
    EXPECT_EQ(classifyPoint(flat, Vec3d(1, 1, 0)).location, PointLocation::OnEdge);  // on the diagonal 0-2
    EXPECT_EQ(classifyPoint(flat, Vec3d(1, 0, 0)).location, PointLocation::OnEdge);
    EXPECT_EQ(classifyPoint(flat, Vec3d(2, 2, 0)).location, PointLocation::AtVertex);
    EXPECT_EQ(classifyPoint(flat, Vec3d(1, 1, 1)).location, PointLocation::Outside);
    EXPECT_EQ(classifyPoint(flat, Vec3d(3, 1, 0)).location, PointLocation::Outside);
    // Three collinear corners plus one off the line (the sphere data has such tets).
    const Vec3d sliver[4] = {Vec3d(6, 2.5, 0), Vec3d(3, 3, -3), Vec3d(6, 3.5, 0), Vec3d(6, 6, 0)};
    EXPECT_EQ(classifyPoint(sliver, Vec3d(6, 3, 0)).location, PointLocation::OnEdge);
    EXPECT_EQ(classifyPoint(sliver, Vec3d(6, 5, 0)).location, PointLocation::OnEdge);
    EXPECT_EQ(classifyPoint(sliver, Vec3d(6, 7, 0)).location, PointLocation::Outside);
    // Collapsed to a segment and to a point.
    const Vec3d seg[4] = {Vec3d(0, 0, 0), Vec3d(1, 1, 1), Vec3d(2, 2, 2), Vec3d(3, 3, 3)};
    EXPECT_EQ(classifyPoint(seg, Vec3d(1, 1, 1)).location, PointLocation::AtVertex);
    EXPECT_EQ(classifyPoint(seg, Vec3d(2, 2, 2)).location, PointLocation::AtVertex);
    EXPECT_EQ(classifyPoint(seg, Vec3d(1, 1, 0)).location, PointLocation::Outside);
    const Vec3d pt[4] = {Vec3d(1, 1, 1), Vec3d(1, 1, 1), Vec3d(1, 1, 1), Vec3d(1, 1, 1)};
    EXPECT_EQ(classifyPoint(pt, Vec3d(1, 1, 1)).location, PointLocation::AtVertex);
    EXPECT_EQ(classifyPoint(pt, Vec3d(0, 1, 1)).location, PointLocation::Outside);
}

TEST(SymbolicPerturbation, DartsOfATetCornerFollowItsCone) {
    // At the corner (0,0,0) of the axis-aligned unit tet, exactly the 6 frames whose three
    // directions are all positive lie inside: z + e d1 + e^2 d2 + e^3 d3 with d_k >= 0.
    const TetSoS T(kUnit);
    ASSERT_EQ(T.vol, 1);
    const auto oz = T.sides(Vec3d(0, 0, 0));
    int inside = 0;
    for (int a = 0; a < 6; ++a)
        for (int b = 0; b < 6; ++b)
            for (int c = 0; c < 6; ++c) {
                if (a / 2 == b / 2 || b / 2 == c / 2 || a / 2 == c / 2) continue;
                const bool in = T.contains(oz, AxisDir(a), AxisDir(b), AxisDir(c));
                const bool allPositive = !(a & 1) && !(b & 1) && !(c & 1);
                EXPECT_EQ(in, allPositive) << a << " " << b << " " << c;
                inside += in;
            }
    EXPECT_EQ(inside, 6);
}

TEST(SymbolicPerturbation, EveryFrameHasExactlyOneOwnerAroundAnEdge) {
    // The cube [0,2]^3 split into 6 Kuhn tets around its diagonal: at the grid point (1,1,1)
    // on that diagonal every one of the 48 frames is owned by exactly one tet.
    const Vec3d c[8] = {Vec3d(0, 0, 0), Vec3d(2, 0, 0), Vec3d(0, 2, 0), Vec3d(2, 2, 0),
                        Vec3d(0, 0, 2), Vec3d(2, 0, 2), Vec3d(0, 2, 2), Vec3d(2, 2, 2)};
    const int paths[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};
    std::vector<std::array<Vec3d, 4>> corners;  // TetSoS refers to these: keep them alive
    for (const auto& p : paths) {
        std::array<Vec3d, 4> q = {c[p[0]], c[p[1]], c[p[2]], c[p[3]]};
        if (orient3d(q[0], q[1], q[2], q[3]) < 0) std::swap(q[2], q[3]);
        corners.push_back(q);
    }
    std::vector<TetSoS> tets;
    for (const auto& q : corners) tets.emplace_back(q);
    const Vec3d z(1, 1, 1);
    for (int a = 0; a < 6; ++a)
        for (int b = 0; b < 6; ++b)
            for (int cc = 0; cc < 6; ++cc) {
                if (a / 2 == b / 2 || b / 2 == cc / 2 || a / 2 == cc / 2) continue;
                int owners = 0;
                for (const auto& T : tets) owners += T.contains(T.sides(z), AxisDir(a), AxisDir(b), AxisDir(cc));
                EXPECT_EQ(owners, 1) << a << " " << b << " " << cc;
            }
}

TEST(SymbolicPerturbation, DegenerateTetOwnsNothing) {
    const std::array<Vec3d, 4> flat = {Vec3d(0, 0, 0), Vec3d(2, 0, 0), Vec3d(2, 2, 0), Vec3d(0, 2, 0)};
    const TetSoS T(flat);
    EXPECT_EQ(T.vol, 0);
    EXPECT_FALSE(T.contains(T.sides(Vec3d(1, 1, 0)), 0, 2, 4));
}

// FacePlanes::side() (one cross product per face, a filter per point) and TetSoS::sides()
// (with its shortcut at corners) must give exactly TetSoS::side(): on small integer tets
// (many exact zeros, flat tets, repeated corners), on nearly flat tets whose filter fails,
// and on large random coordinates, at every grid point of the box and at the corners.
TEST(SymbolicPerturbation, FacePlanesAndSidesAgreeWithSide) {
    std::mt19937 rng(23);
    std::uniform_int_distribution<int> small(-3, 3);
    std::uniform_real_distribution<double> real(-40.0, 40.0);
    long checked = 0, zeros = 0;
    auto check = [&](const std::array<Vec3d, 4>& corners) {
        const TetSoS T(corners);
        const FacePlanes F(T);
        std::vector<Vec3d> points(corners.begin(), corners.end());
        Vec3d lo = corners[0], hi = corners[0];
        for (const Vec3d& c : corners) {
            lo.minimize(c);
            hi.maximize(c);
        }
        for (int x = static_cast<int>(std::floor(lo[0])) - 1; x <= static_cast<int>(std::ceil(hi[0])) + 1; ++x)
            for (int y = static_cast<int>(std::floor(lo[1])) - 1; y <= static_cast<int>(std::ceil(hi[1])) + 1; ++y)
                for (int z = static_cast<int>(std::floor(lo[2])) - 1; z <= static_cast<int>(std::ceil(hi[2])) + 1; ++z)
                    points.emplace_back(x, y, z);
        for (const Vec3d& q : points) {
            const std::array<int, 4> all = T.sides(q);
            for (int j = 0; j < 4; ++j) {
                const int want = T.side(j, q);
                ASSERT_EQ(F.side(j, q), want) << "face " << j << " at " << q;
                ASSERT_EQ(all[static_cast<std::size_t>(j)], want) << "face " << j << " at " << q;
                ++checked;
                zeros += want == 0;
            }
        }
    };
    for (int n = 0; n < 400; ++n) {  // small integers: exact zeros, flat tets, repeated corners
        std::array<Vec3d, 4> c;
        for (auto& v : c) v = Vec3d(small(rng), small(rng), small(rng));
        check(c);
    }
    for (int n = 0; n < 200; ++n) {  // nearly flat: the fourth corner a hair off the plane of the others
        std::array<Vec3d, 4> c;
        for (int k = 0; k < 3; ++k) c[static_cast<std::size_t>(k)] = Vec3d(small(rng), small(rng), small(rng));
        const double t = std::uniform_real_distribution<double>(0.1, 0.9)(rng);
        c[3] = c[0] + t * (c[1] - c[0]) + (1 - t) * (c[2] - c[0]);
        c[3][n % 3] = std::nextafter(c[3][n % 3], n % 2 ? 1e9 : -1e9);
        check(c);
    }
    for (int n = 0; n < 50; ++n) {  // general position, larger boxes
        std::array<Vec3d, 4> c;
        for (auto& v : c) v = Vec3d(real(rng) / 4, real(rng) / 4, real(rng) / 4);
        check(c);
    }
    EXPECT_GT(checked, 100000);
    EXPECT_GT(zeros, 10000);
}
