#include <HexEx/Grid/GridTransform.hh>

#include <gtest/gtest.h>

using namespace HexEx;

TEST(Rotation, GroupAxioms) {
    for (int a = 0; a < 24; ++a) {
        Rotation ra(a);
        EXPECT_EQ((ra * ra.inverse()).index(), 0);
        EXPECT_EQ((Rotation(0) * ra).index(), a);
        for (int b = 0; b < 24; ++b)
            for (int c = 0; c < 24; ++c)
                EXPECT_EQ(((ra * Rotation(b)) * Rotation(c)).index(), (ra * (Rotation(b) * Rotation(c))).index());
    }
}

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <random>
#include <set>

namespace {

/// Determinant of a rotation's matrix.
int determinant(const Rotation& R) {
    auto m = [&](int r, int c) { return R.matrix(r, c); };
    return m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) - m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
           m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
}

/// Integer cross product.
Vec3i crossI(const Vec3i& a, const Vec3i& b) {
    return Vec3i(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}

/// A random dyadic double k / 2^20 with |k| < 2^30: adding small integers to it is exact.
double randomDyadic(std::mt19937& gen) {
    const std::int64_t k = static_cast<std::int64_t>(gen() % (1u << 31)) - (std::int64_t(1) << 30);
    return static_cast<double>(k) / static_cast<double>(1 << 20);
}

/// A random grid transform with translation in [-8, 8]^3 (modulo bias is irrelevant for tests).
GridTransform randomTransform(std::mt19937& gen) {
    Vec3i t;
    for (int d = 0; d < 3; ++d) t[d] = static_cast<int>(gen() % 17) - 8;
    return GridTransform(Rotation(static_cast<int>(gen() % 24)), t);
}

} // namespace

TEST(Rotation, MatricesAreSignedPermutationsWithDeterminantOne) {
    std::set<std::array<int, 9>> seen;
    for (int a = 0; a < Rotation::kCount; ++a) {
        const Rotation R(a);
        std::array<int, 9> m{};
        for (int r = 0; r < 3; ++r) {
            int rowNonZero = 0, colNonZero = 0;
            for (int c = 0; c < 3; ++c) {
                m[3 * r + c] = R.matrix(r, c);
                EXPECT_LE(std::abs(R.matrix(r, c)), 1);
                rowNonZero += R.matrix(r, c) != 0;
                colNonZero += R.matrix(c, r) != 0;
            }
            EXPECT_EQ(rowNonZero, 1);
            EXPECT_EQ(colNonZero, 1);
        }
        EXPECT_EQ(determinant(R), 1) << "rotation " << a;
        seen.insert(m);
        EXPECT_EQ(R.is_identity(), a == 0);
    }
    EXPECT_EQ(seen.size(), 24u) << "the 24 rotations must be distinct";
    // The identity is index 0.
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(Rotation(0).matrix(r, c), r == c ? 1 : 0);
}

TEST(Rotation, CompositionTableIsMatrixProduct) {
    for (int a = 0; a < 24; ++a)
        for (int b = 0; b < 24; ++b) {
            const Rotation ab = Rotation(a) * Rotation(b);
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) {
                    int sum = 0;
                    for (int k = 0; k < 3; ++k) sum += Rotation(a).matrix(r, k) * Rotation(b).matrix(k, c);
                    EXPECT_EQ(ab.matrix(r, c), sum) << "a=" << a << " b=" << b << " entry " << r << "," << c;
                }
        }
}

TEST(Rotation, InverseTableIsTranspose) {
    for (int a = 0; a < 24; ++a) {
        const Rotation R(a), Ri = Rotation(a).inverse();
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) EXPECT_EQ(Ri.matrix(r, c), R.matrix(c, r));
        EXPECT_TRUE((R * Ri).is_identity());
        EXPECT_TRUE((Ri * R).is_identity());
        EXPECT_EQ(Ri.inverse(), R);
    }
}

TEST(Rotation, ApplyMatchesMatrix) {
    const Vec3i u(3, -7, 11);
    const Vec3d ud(0.5, -2.25, 1e-300);
    for (int a = 0; a < 24; ++a) {
        const Rotation R(a);
        const Vec3i ri = R.apply(u);
        const Vec3d rd = R.apply(ud);
        for (int r = 0; r < 3; ++r) {
            int si = 0;
            double sd = 0.0;
            for (int c = 0; c < 3; ++c) {
                si += R.matrix(r, c) * u[c];
                if (R.matrix(r, c) != 0) sd = R.matrix(r, c) * ud[c];
            }
            EXPECT_EQ(ri[r], si);
            EXPECT_EQ(rd[r], sd);  // bit-exact: only permutes and negates
        }
        for (AxisDir d = 0; d < 6; ++d) EXPECT_EQ(dirVec(R.apply(d)), R.apply(dirVec(d)));
        const std::array<AxisDir, 3> cols = {R.apply(makeDir(0, 1)), R.apply(makeDir(1, 1)), R.apply(makeDir(2, 1))};
        EXPECT_EQ(Rotation::fromColumns(cols), a);
    }
    EXPECT_EQ(Rotation::fromColumns({makeDir(0, 1), makeDir(1, 1), makeDir(2, -1)}), -1) << "reflection";
    EXPECT_EQ(Rotation::fromColumns({makeDir(0, 1), makeDir(0, 1), makeDir(2, 1)}), -1) << "repeated axis";
}

TEST(Rotation, AngleClasses) {
    int count[4] = {0, 0, 0, 0};
    for (int a = 0; a < 24; ++a) {
        const Rotation R(a);
        const int cls = R.angleClass();
        ASSERT_GE(cls, 0);
        ASSERT_LE(cls, 3);
        ++count[cls];
        // Order of the rotation: 1, 4, 2, 3 for the classes 0..3.
        const int order[4] = {1, 4, 2, 3};
        Rotation p = R;
        int k = 1;
        while (!p.is_identity()) {
            p = p * R;
            ++k;
        }
        EXPECT_EQ(k, order[cls]) << "rotation " << a;
    }
    EXPECT_EQ(count[0], 1);
    EXPECT_EQ(count[1], 6);
    EXPECT_EQ(count[2], 9);
    EXPECT_EQ(count[3], 8);
}

TEST(AxisDir, EncodingHelpers) {
    for (AxisDir d = 0; d < 6; ++d) {
        EXPECT_EQ(makeDir(dirAxis(d), dirSign(d)), d);
        EXPECT_EQ(dirAxis(dirNeg(d)), dirAxis(d));
        EXPECT_EQ(dirSign(dirNeg(d)), -dirSign(d));
        EXPECT_EQ(dirVec(dirNeg(d)), -dirVec(d));
        EXPECT_EQ(dirVec(d)[dirAxis(d)], dirSign(d));
    }
}

TEST(AxisDir, FrameHandednessAndCross) {
    for (AxisDir a = 0; a < 6; ++a)
        for (AxisDir b = 0; b < 6; ++b) {
            if (dirAxis(a) != dirAxis(b)) {
                EXPECT_EQ(dirVec(dirCross(a, b)), crossI(dirVec(a), dirVec(b)));
            }
            for (AxisDir c = 0; c < 6; ++c) {
                const Vec3i va = dirVec(a), vb = dirVec(b), vc = dirVec(c);
                const int det = crossI(va, vb)[0] * vc[0] + crossI(va, vb)[1] * vc[1] + crossI(va, vb)[2] * vc[2];
                const bool distinct = dirAxis(a) != dirAxis(b) && dirAxis(b) != dirAxis(c) && dirAxis(a) != dirAxis(c);
                EXPECT_EQ(frameHandedness(a, b, c), distinct ? det : 0);
            }
        }
    EXPECT_EQ(frameHandedness(makeDir(0, 1), makeDir(1, 1), makeDir(2, 1)), 1);
    EXPECT_EQ(frameHandedness(makeDir(1, 1), makeDir(0, 1), makeDir(2, 1)), -1);
    // Rotations preserve handedness.
    for (int r = 0; r < 24; ++r)
        for (AxisDir a = 0; a < 6; ++a)
            for (AxisDir b = 0; b < 6; ++b)
                if (dirAxis(a) != dirAxis(b)) {
                    EXPECT_EQ(Rotation(r).apply(dirCross(a, b)), dirCross(Rotation(r).apply(a), Rotation(r).apply(b)));
                }
}

TEST(GridTransform, ComposeInverseApply) {
    std::mt19937 gen(2024);
    for (int trial = 0; trial < 2000; ++trial) {
        const GridTransform f = randomTransform(gen), g = randomTransform(gen);
        const Vec3i z(static_cast<int>(gen() % 41) - 20, static_cast<int>(gen() % 41) - 20,
                      static_cast<int>(gen() % 41) - 20);
        const Vec3d u(randomDyadic(gen), randomDyadic(gen), randomDyadic(gen));
        // Composition applies the right factor first.
        EXPECT_EQ((f * g).apply(z), f.apply(g.apply(z)));
        EXPECT_EQ((f * g).apply(u), f.apply(g.apply(u)));
        // Inverse, bit for bit on doubles.
        const Vec3d back = f.inverse().apply(f.apply(u));
        for (int d = 0; d < 3; ++d) EXPECT_EQ(std::memcmp(&back[d], &u[d], sizeof(double)), 0);
        EXPECT_EQ(f.inverse().apply(f.apply(z)), z);
        EXPECT_TRUE((f * f.inverse()).is_identity());
        EXPECT_TRUE((f.inverse() * f).is_identity());
        EXPECT_EQ((f * g).inverse(), g.inverse() * f.inverse());
        // Directions ignore the translation.
        for (AxisDir d = 0; d < 6; ++d) EXPECT_EQ(toVec3d(dirVec(f.applyDir(d))), f.apply(toVec3d(dirVec(d))) - f.apply(Vec3d(0, 0, 0)));
        // Apply on doubles agrees with apply on integers for integer points.
        EXPECT_EQ(f.apply(toVec3d(z)), toVec3d(f.apply(z)));
    }
    const GridTransform id;
    EXPECT_TRUE(id.is_identity());
    EXPECT_FALSE(GridTransform(Rotation(0), Vec3i(1, 0, 0)).is_identity());
    EXPECT_NE(GridTransform(Rotation(1), Vec3i(0, 0, 0)), id);
}

TEST(GridTransform, AssociativeOnRandomTriples) {
    std::mt19937 gen(7);
    for (int trial = 0; trial < 500; ++trial) {
        const GridTransform f = randomTransform(gen), g = randomTransform(gen), h = randomTransform(gen);
        EXPECT_EQ((f * g) * h, f * (g * h));
    }
}
