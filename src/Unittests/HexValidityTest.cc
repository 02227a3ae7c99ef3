/// @file HexValidityTest.cc
/// The certified validity test of trilinear hexes (HexValidity.hh) and its use in
/// computeQuality().

#include "HexEx/Mesh/HexMeshQuality.hh"
#include "HexEx/Mesh/HexValidity.hh"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using namespace HexEx;

namespace {

using Hex = std::array<Vec3d, 8>;

Hex unitCube(double scale = 1, const Vec3d& offset = Vec3d(0, 0, 0)) {
    const double c[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    Hex h;
    for (int i = 0; i < 8; ++i) h[i] = Vec3d(c[i][0], c[i][1], c[i][2]) * scale + offset;
    return h;
}

/// A hex found by a random search (perturbed unit cube): J > 0 at all 8 corners, but
/// J(0.25, 1, 0) < 0 (checked below from the trilinear map itself).
Hex positiveCornersNegativeInside() {
    return {{{0.34903947519629847, -0.040657101802294204, -0.14580526119256942},
             {1.3158235993425553, -0.22753776138255985, -0.32283547238959748},
             {0.66302905271037815, 0.96539898402132385, -0.21103170472141899},
             {0.38309908700906353, 1.3863647837410384, 0.3657617023242497},
             {-0.26060920847350455, -0.27169702399717743, 0.61007095309834447},
             {1.21923850574767, -0.22315681136377602, 0.88364110018111863},
             {0.63601846817499119, 1.4113433695468787, 0.7938652942780513},
             {-0.3339704468756034, 1.045714042671493, 1.3534283884624589}}};
}

Hex randomHex(std::mt19937_64& rng, double amplitude) {
    std::uniform_real_distribution<double> d(-amplitude, amplitude);
    Hex h = unitCube();
    for (auto& p : h) p += Vec3d(d(rng), d(rng), d(rng));
    return h;
}

double minSampledJacobian(const Hex& h, int n) {
    double mn = std::numeric_limits<double>::infinity();
    for (int a = 0; a <= n; ++a)
        for (int b = 0; b <= n; ++b)
            for (int c = 0; c <= n; ++c)
                mn = std::min(mn, jacobianDeterminant(h, double(a) / n, double(b) / n, double(c) / n));
    return mn;
}

} // namespace

TEST(HexValidity, UnitCubeCoefficientsAreAllOne) {
    const auto b = jacobianBernsteinCoefficients(unitCube(2.0));
    for (double x : b) EXPECT_DOUBLE_EQ(x, 8.0);
    EXPECT_EQ(classifyHexValidity(unitCube()), HexValidity::Valid);
    EXPECT_EQ(classifyHexValidity(unitCube(1e-3, Vec3d(1e4, -2e4, 3e4))), HexValidity::Valid);
}

TEST(HexValidity, BernsteinCoefficientsEqualTheDeterminantAtSamplePoints) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> t(0, 1);
    for (int n = 0; n < 200; ++n) {
        const Hex h = randomHex(rng, 0.4);
        const auto b = jacobianBernsteinCoefficients(h);
        for (int s = 0; s < 10; ++s) {
            const double u = t(rng), v = t(rng), w = t(rng);
            const double direct = jacobianDeterminant(h, u, v, w);
            EXPECT_NEAR(evaluateBernstein(b, u, v, w), direct, 1e-12 * (1 + std::abs(direct)));
        }
        // The corner coefficients are J at the corners.
        EXPECT_NEAR(b[0], jacobianDeterminant(h, 0, 0, 0), 1e-12);
        EXPECT_NEAR(b[26], jacobianDeterminant(h, 1, 1, 1), 1e-12);
        EXPECT_NEAR(b[2 + 3 * 2], jacobianDeterminant(h, 1, 1, 0), 1e-12);
    }
}

TEST(HexValidity, PositiveCornersButNegativeInsideIsInvalid) {
    const Hex h = positiveCornersNegativeInside();
    EXPECT_GT(hexScaledJacobian(h), 0.0);                 // the 8-corner test passes ...
    EXPECT_LT(jacobianDeterminant(h, 0.25, 1.0, 0.0), 0.0);  // ... but J < 0 at a point of the hex
    EXPECT_EQ(classifyHexValidity(h), HexValidity::Invalid);

    HexMesh mesh;
    mesh.vertices.assign(h.begin(), h.end());
    mesh.hexes.push_back({0, 1, 2, 3, 4, 5, 6, 7});
    const QualityStats q = computeQuality(mesh);
    EXPECT_EQ(q.inverted_hexes, 0);
    EXPECT_EQ(q.invalid_hexes, 1);
    EXPECT_EQ(q.undecided_hexes, 0);
    EXPECT_EQ(q.first_invalid_hex, 0);
}

TEST(HexValidity, AgreesWithDenseSamplingOnRandomHexes) {
    std::mt19937_64 rng(5);
    int valid = 0, invalid = 0, invalid_with_positive_corners = 0;
    for (int n = 0; n < 3000; ++n) {
        const Hex h = randomHex(rng, 0.45);
        const HexValidity v = classifyHexValidity(h);
        ASSERT_NE(v, HexValidity::Undecided) << "hex " << n;
        const double sampled = minSampledJacobian(h, 8);
        if (sampled <= 0) {
            EXPECT_EQ(v, HexValidity::Invalid) << "hex " << n << " sampled J " << sampled;
        }
        if (v == HexValidity::Valid) {
            ++valid;
            EXPECT_GT(sampled, 0.0) << "hex " << n;
        } else {
            ++invalid;
            if (hexScaledJacobian(h) > 0) ++invalid_with_positive_corners;
        }
    }
    EXPECT_GT(valid, 1000);
    EXPECT_GT(invalid, 100);
    // The classifier finds hexes that the corner test misses (about 1 in 600-900 of these).
    EXPECT_GE(invalid_with_positive_corners, 1);
}

TEST(HexValidity, DegenerateAndNonFiniteHexesAreInvalid) {
    Hex flat = unitCube();
    for (int i = 4; i < 8; ++i) flat[i][2] = 0;  // top face on the bottom face
    EXPECT_EQ(classifyHexValidity(flat), HexValidity::Invalid);

    Hex collapsed_edge = unitCube();
    collapsed_edge[1] = collapsed_edge[0];  // J = 0 at corner 0
    EXPECT_EQ(classifyHexValidity(collapsed_edge), HexValidity::Invalid);

    Hex point = unitCube(0.0);
    EXPECT_EQ(classifyHexValidity(point), HexValidity::Invalid);

    Hex nan = unitCube();
    nan[6][1] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(classifyHexValidity(nan), HexValidity::Invalid);
    nan[6][1] = std::numeric_limits<double>::infinity();
    EXPECT_EQ(classifyHexValidity(nan), HexValidity::Invalid);

    Hex mirrored = unitCube();
    for (auto& p : mirrored) p[0] = -p[0];
    EXPECT_EQ(classifyHexValidity(mirrored), HexValidity::Invalid);
}

TEST(HexValidity, ComputeQualityDoesNotDependOnThreads) {
    std::mt19937_64 rng(3);
    HexMesh mesh;
    for (int n = 0; n < 5000; ++n) {
        const Hex h = randomHex(rng, 0.45);
        const int base = static_cast<int>(mesh.vertices.size());
        mesh.vertices.insert(mesh.vertices.end(), h.begin(), h.end());
        mesh.hexes.push_back({base, base + 1, base + 2, base + 3, base + 4, base + 5, base + 6, base + 7});
    }
    mesh.hexes.push_back({0, 1, 2, 3, 4, 5, 6, 1 << 30});  // index out of range: invalid
    const QualityStats one = computeQuality(mesh, 1), two = computeQuality(mesh, 2);
    EXPECT_EQ(one.invalid_hexes, two.invalid_hexes);
    EXPECT_EQ(one.undecided_hexes, two.undecided_hexes);
    EXPECT_EQ(one.first_invalid_hex, two.first_invalid_hex);
    EXPECT_EQ(one.mean_scaled_jacobian, two.mean_scaled_jacobian);
    EXPECT_GE(one.invalid_hexes, one.inverted_hexes);
    EXPECT_EQ(hexValidities(mesh, 2).back(), HexValidity::Invalid);
}

namespace {

/// Hexes for the pair functions: random ones from nearly cubes to heavily tangled, nearly
/// flat and nearly collapsed ones (values close to the rounding bound), and special ones
/// (zero edges, signed zeros, NaN, infinity, overflowing and underflowing coordinates).
std::vector<Hex> pairTestHexes() {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<Hex> hexes;
    for (const double amplitude : {0.05, 0.3, 0.45, 0.6, 1.0})
        for (int n = 0; n < 600; ++n) hexes.push_back(randomHex(rng, amplitude));
    for (int n = 0; n < 400; ++n) {
        Hex flat = randomHex(rng, 0.02);
        const double thickness = std::ldexp(unit(rng), -20 - static_cast<int>(unit(rng) * 30));
        for (int i = 4; i < 8; ++i) flat[static_cast<std::size_t>(i)][2] = flat[static_cast<std::size_t>(i - 4)][2] + thickness;
        hexes.push_back(flat);
        Hex pinched = randomHex(rng, 0.02);
        const std::size_t c = static_cast<std::size_t>(unit(rng) * 8) % 8;
        pinched[c] = pinched[(c + 1) % 8] + Vec3d(unit(rng), unit(rng), unit(rng)) * std::ldexp(1.0, -40);
        hexes.push_back(pinched);
    }
    // Collinear and coplanar corners of small integers: corner Jacobians of +0 and -0.
    std::uniform_int_distribution<int> small(-2, 2);
    for (int n = 0; n < 400; ++n) {
        Hex h;
        for (auto& p : h) p = Vec3d(small(rng), n % 2 ? small(rng) : 0, 0);
        hexes.push_back(h);
    }
    hexes.push_back(positiveCornersNegativeInside());
    hexes.push_back(unitCube(0.0));
    hexes.push_back(unitCube(-0.0));
    hexes.push_back(unitCube(1e150));    // rounding bound overflows: undecided
    hexes.push_back(unitCube(1e-160));   // Jacobians underflow
    hexes.push_back(unitCube(1e300));    // edge lengths overflow
    Hex mirrored = unitCube();
    for (auto& p : mirrored) p[0] = -p[0];
    hexes.push_back(mirrored);
    Hex flat = unitCube();
    for (int i = 4; i < 8; ++i) flat[static_cast<std::size_t>(i)][2] = -0.0;
    hexes.push_back(flat);
    for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity()}) {
        Hex h = unitCube();
        h[6][1] = bad;
        hexes.push_back(h);
    }
    return hexes;
}

std::uint64_t bitsOf(double x) {
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

} // namespace

TEST(HexValidity, PairsGiveTheSameValuesAsOneAtATime) {
    const std::vector<Hex> hexes = pairTestHexes();
    int verdicts[3] = {0, 0, 0};
    int zeros = 0, negative_zeros = 0;
    for (std::size_t i = 0; i < hexes.size(); ++i) {
        const Hex& a = hexes[i];
        const double sj_a = hexScaledJacobian(a);
        const HexValidity v_a = classifyHexValidity(a);
        ++verdicts[static_cast<int>(v_a)];
        zeros += sj_a == 0;
        negative_zeros += sj_a == 0 && std::signbit(sj_a);
        // a in both lanes, beside its neighbour and beside a far one.
        for (const std::size_t j : {(i + 1) % hexes.size(), (i * 7919 + 13) % hexes.size()}) {
            const Hex& b = hexes[j];
            double sj[2];
            HexValidity v[2];
            hexScaledJacobianPair(a, b, sj);
            classifyHexValidityPair(a, b, v);
            EXPECT_EQ(bitsOf(sj[0]), bitsOf(sj_a)) << i;
            EXPECT_EQ(bitsOf(sj[1]), bitsOf(hexScaledJacobian(b))) << j;
            EXPECT_EQ(v[0], v_a) << i;
            EXPECT_EQ(v[1], classifyHexValidity(b)) << j;
            hexScaledJacobianPair(b, a, sj);
            classifyHexValidityPair(b, a, v);
            EXPECT_EQ(bitsOf(sj[1]), bitsOf(sj_a)) << i;
            EXPECT_EQ(v[1], v_a) << i;
        }
    }
    // Every verdict and degenerate values occur, so the test covers both ways.
    EXPECT_GE(verdicts[static_cast<int>(HexValidity::Valid)], 1000);
    EXPECT_GE(verdicts[static_cast<int>(HexValidity::Invalid)], 500);
    EXPECT_GE(verdicts[static_cast<int>(HexValidity::Undecided)], 1);
    EXPECT_GE(zeros, 4);
    EXPECT_GE(negative_zeros, 1);
}

TEST(HexValidity, ComputeQualityEqualsOneHexAtATime) {
    // An odd number of hexes: chunks of odd and even length at 1, 2, 3 threads.
    const std::vector<Hex> hexes = pairTestHexes();
    HexMesh mesh;
    for (int round = 0; round < 2; ++round)
        for (const Hex& h : hexes) {
            const int base = static_cast<int>(mesh.vertices.size());
            mesh.vertices.insert(mesh.vertices.end(), h.begin(), h.end());
            mesh.hexes.push_back({base, base + 1, base + 2, base + 3, base + 4, base + 5, base + 6, base + 7});
        }
    mesh.hexes.insert(mesh.hexes.begin() + 1001, {0, 1, 2, 3, 4, 5, 6, -1});  // out of range: invalid
    if (mesh.hexes.size() % 2 == 0) mesh.hexes.push_back(mesh.hexes.front());
    ASSERT_GE(mesh.hexes.size(), 4096u);
    // The reference: one hex at a time, summed in hex order.
    double sum = 0, mn = 0;
    long inverted = 0, invalid = 0, undecided = 0, first_invalid = -1;
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
        double sj = 0;
        HexValidity v = HexValidity::Invalid;
        if (mesh.hexes[h][7] >= 0) {
            Hex p;
            for (std::size_t i = 0; i < 8; ++i) p[i] = mesh.vertices[static_cast<std::size_t>(mesh.hexes[h][i])];
            sj = hexScaledJacobian(p);
            v = classifyHexValidity(p);
        }
        sum += sj;
        mn = h == 0 ? sj : std::min(mn, sj);
        inverted += sj <= 0;
        if (v == HexValidity::Invalid && first_invalid < 0) first_invalid = static_cast<long>(h);
        invalid += v == HexValidity::Invalid;
        undecided += v == HexValidity::Undecided;
    }
    for (const int threads : {1, 2, 3}) {
        const QualityStats q = computeQuality(mesh, threads);
        EXPECT_EQ(bitsOf(q.mean_scaled_jacobian), bitsOf(sum / static_cast<double>(mesh.hexes.size()))) << threads;
        EXPECT_EQ(bitsOf(q.min_scaled_jacobian), bitsOf(mn)) << threads;
        EXPECT_EQ(q.inverted_hexes, inverted) << threads;
        EXPECT_EQ(q.invalid_hexes, invalid) << threads;
        EXPECT_EQ(q.undecided_hexes, undecided) << threads;
        EXPECT_EQ(q.first_invalid_hex, first_invalid) << threads;
    }
}
