// Tests of HexMeshQuality (scaled Jacobians) and HexMeshCheck (the mesh validator).

#include <HexEx/Generators/Generators.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/Mesh/HexMeshCheck.hh>
#include <HexEx/Mesh/HexMeshQuality.hh>

#include <gtest/gtest.h>

#include "TestMeshChecks.hh"

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

using namespace HexEx;

namespace {

using HexExTest::extracted;

/// An n x n x n grid of unit hexes in VTK order.
HexMesh gridMesh(int n) {
    HexMesh m;
    auto id = [n](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) m.vertices.emplace_back(i, j, k);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                m.hexes.push_back({{id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                                    id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
                                    id(i, j + 1, k + 1)}});
    return m;
}

} // namespace

TEST(HexMeshQuality, UnitCubeIsOne) {
    const HexMesh m = gridMesh(1);
    const auto sj = scaledJacobians(m);
    ASSERT_EQ(sj.size(), 1u);
    EXPECT_DOUBLE_EQ(sj[0], 1.0);
    const QualityStats q = computeQuality(m);
    EXPECT_DOUBLE_EQ(q.min_scaled_jacobian, 1.0);
    EXPECT_DOUBLE_EQ(q.mean_scaled_jacobian, 1.0);
    EXPECT_EQ(q.inverted_hexes, 0);
}

TEST(HexMeshQuality, ScaledBoxAndShearedHex) {
    HexMesh m = gridMesh(1);
    for (auto& p : m.vertices) p = Vec3d(3 * p[0], 0.5 * p[1], 7 * p[2]);
    EXPECT_NEAR(computeQuality(m).min_scaled_jacobian, 1.0, 1e-15);  // scale invariant
    // Shear the top by one unit in x: corner 0 sees edges (1,0,0), (0,1,0), (1,0,1).
    HexMesh s = gridMesh(1);
    for (int i = 4; i < 8; ++i) s.vertices[i][0] += 1;
    EXPECT_NEAR(computeQuality(s).min_scaled_jacobian, 1 / std::sqrt(2.0), 1e-15);
    EXPECT_EQ(computeQuality(s).inverted_hexes, 0);
}

TEST(HexMeshQuality, MirroredHexIsInverted) {
    HexMesh m = gridMesh(1);
    for (auto& p : m.vertices) p[2] = -p[2];
    const QualityStats q = computeQuality(m);
    EXPECT_EQ(q.inverted_hexes, 1);
    EXPECT_DOUBLE_EQ(q.min_scaled_jacobian, -1.0);
}

TEST(HexMeshQuality, DegenerateAndOutOfRange) {
    HexMesh m = gridMesh(1);
    m.vertices[1] = m.vertices[0];  // zero-length edge
    EXPECT_EQ(computeQuality(m).inverted_hexes, 1);
    HexMesh bad = gridMesh(1);
    bad.hexes[0][5] = 1000;
    EXPECT_EQ(scaledJacobians(bad)[0], 0.0);
    EXPECT_EQ(computeQuality(HexMesh{}).inverted_hexes, 0);
}

TEST(HexMeshCheck, ExtractedCubeIsValid) {
    const HexMesh m = extracted(generateCube(2, 3));
    const HexMeshCheckResult r = checkHexMesh(m);
    EXPECT_TRUE(r.valid_all_hex);
    EXPECT_EQ(r.hexes, 27);
    EXPECT_EQ(r.cells, 27);
    EXPECT_EQ(r.non_hex_cells, 0);
    EXPECT_EQ(r.vertices, 64);
    EXPECT_EQ(r.quads, 108);
    EXPECT_EQ(r.boundary_quads, 54);
    EXPECT_EQ(r.edges, 144);
    EXPECT_EQ(r.quads_shared_by_more_than_two, 0);
    EXPECT_EQ(r.nonmanifold_boundary_edges, 0);
    EXPECT_EQ(r.nonmanifold_boundary_vertices, 0);
    EXPECT_EQ(r.euler_characteristic, 1);
    EXPECT_EQ(r.quality.inverted_hexes, 0);
    EXPECT_NEAR(r.quality.min_scaled_jacobian, 1.0, 1e-12);
}

TEST(HexMeshCheck, ExtractedSingularCylinderIsValid) {
    const HexMesh m = extracted(generateCylinder(3, 2, 2, 1, 1));
    const HexMeshCheckResult r = checkHexMesh(m);
    EXPECT_TRUE(r.valid_all_hex);
    EXPECT_EQ(r.hexes, 24);
    EXPECT_EQ(r.euler_characteristic, 1);
    EXPECT_EQ(r.nonmanifold_boundary_edges, 0);
    EXPECT_EQ(r.quality.inverted_hexes, 0);
    EXPECT_GT(r.quality.min_scaled_jacobian, 0.0);
}

TEST(HexMeshCheck, MissingMiddleHexKeepsClosedBoundary) {
    HexMesh m = gridMesh(3);
    m.hexes.erase(m.hexes.begin() + 13);  // the centre hex (1,1,1)
    const HexMeshCheckResult r = checkHexMesh(m);
    EXPECT_TRUE(r.valid_all_hex);
    EXPECT_EQ(r.boundary_quads, 60);
    EXPECT_EQ(r.nonmanifold_boundary_edges, 0);
    EXPECT_EQ(r.euler_characteristic, 2);  // a thick spherical shell
}

TEST(HexMeshCheck, QuadSharedByThreeHexesIsFlagged) {
    HexMesh m = gridMesh(1);
    // Stack a second hex on top, then a third one on the same top quad of the first.
    const int base = static_cast<int>(m.vertices.size());
    for (int i = 0; i < 4; ++i) m.vertices.push_back(m.vertices[4 + i] + Vec3d(0, 0, 1));
    for (int i = 0; i < 4; ++i) m.vertices.push_back(m.vertices[4 + i] + Vec3d(0.2, 0.1, 2));
    m.hexes.push_back({{4, 5, 6, 7, base, base + 1, base + 2, base + 3}});
    m.hexes.push_back({{4, 5, 6, 7, base + 4, base + 5, base + 6, base + 7}});
    const HexMeshCheckResult r = checkHexMesh(m);
    EXPECT_EQ(r.quads_shared_by_more_than_two, 1);
    EXPECT_FALSE(r.valid_all_hex);
    EXPECT_GT(r.nonmanifold_boundary_edges, 0);
}

TEST(HexMeshCheck, OpenBoundaryAndInvalidCells) {
    // Two hexes sharing only an edge: the boundary is non-manifold along that edge.
    HexMesh m = gridMesh(2);
    m.hexes = {m.hexes[0], m.hexes[7]};  // (0,0,0) and (1,1,1) share vertex only
    HexMeshCheckResult r = checkHexMesh(m);
    EXPECT_EQ(r.nonmanifold_boundary_edges, 0);  // vertex-pinched: every boundary edge still in two quads
    EXPECT_EQ(r.nonmanifold_boundary_vertices, 1);
    EXPECT_FALSE(r.valid_all_hex);
    HexMesh e = gridMesh(2);
    e.hexes = {e.hexes[0], e.hexes[3]};  // (0,0,0) and (1,1,0) share the vertical edge
    r = checkHexMesh(e);
    EXPECT_EQ(r.nonmanifold_boundary_edges, 1);
    EXPECT_FALSE(r.valid_all_hex);

    HexMesh bad = gridMesh(1);
    bad.hexes.push_back({{0, 1, 2, 3, 4, 5, 6, 99}});
    bad.hexes.push_back({{0, 0, 2, 3, 4, 5, 6, 7}});
    r = checkHexMesh(bad);
    EXPECT_EQ(r.invalid_cells, 2);
    EXPECT_FALSE(r.valid_all_hex);

    HexMesh poly = gridMesh(1);
    poly.polyhedra.push_back(Polyhedron{{{0, 1, 2}, {0, 2, 3}}});
    r = checkHexMesh(poly);
    EXPECT_EQ(r.non_hex_cells, 1);
    EXPECT_FALSE(r.valid_all_hex);
    EXPECT_FALSE(checkHexMesh(HexMesh{}).valid_all_hex);
}

// hexScaledJacobian() computes each edge length once; it must give the same doubles (bit for
// bit, sign of zero included) as the minimum of cornerScaledJacobian() over the 8 corners.
TEST(HexMeshQuality, HexScaledJacobianHasTheBitsOfTheCornerFormula) {
    auto reference = [](const std::array<Vec3d, 8>& p) {
        double worst = 1.0;
        for (const auto& f : kHexCornerFrames) {
            const Vec3d& o = p[f[0]];
            worst = std::min(worst, cornerScaledJacobian(p[f[1]] - o, p[f[2]] - o, p[f[3]] - o));
        }
        return worst;
    };
    auto sameBits = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> jitter(-0.45, 0.45);
    std::uniform_int_distribution<int> kind(0, 5);
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    int zeros = 0, negative = 0, distinct = 0;
    const HexMesh unit = gridMesh(1);
    for (int n = 0; n < 200000; ++n) {
        std::array<Vec3d, 8> p;
        for (int i = 0; i < 8; ++i) p[static_cast<std::size_t>(i)] = unit.vertices[static_cast<std::size_t>(i)];
        const int k = kind(rng);
        for (auto& q : p)
            for (int d = 0; d < 3; ++d) {
                if (k == 0) q[d] += jitter(rng);                        // general hexes
                else if (k == 1) q[d] = std::round(3 * jitter(rng));    // integer corners: exact zero determinants
                else if (k == 2) q[d] = 1e-3 * std::round(4 * jitter(rng));  // repeated corners, zero-length edges
                else if (k == 3) q[d] = 4 * jitter(rng);                // tangled
                else if (k == 4) q[d] = 1e200 * jitter(rng);            // overflowing lengths
                else q[d] += jitter(rng) * 1e-300;                      // underflowing differences
            }
        if (n % 997 == 0) p[static_cast<std::size_t>(n % 8)][n % 3] = (n % 2) ? inf : nan;
        const double a = hexScaledJacobian(p), b = reference(p);
        ASSERT_TRUE(sameBits(a, b)) << "hex " << n << ": " << a << " vs " << b;
        if (a == 0) ++zeros;
        if (a < 0) ++negative;
        if (a != 1 && a != 0) ++distinct;
    }
    // The sample reaches the special cases the shortcut must keep.
    EXPECT_GT(zeros, 1000);
    EXPECT_GT(negative, 1000);
    EXPECT_GT(distinct, 100000);
}
