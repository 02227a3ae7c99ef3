/// @file UntanglerTest.cc
/// Tests of untangleHexMesh(): inverted hexes go to 0 on folded extractions and on randomly
/// tangled grids, boundary vertices stay on the input surface, valid meshes are returned
/// unchanged, the result does not depend on the thread count, and a boundary that forces an
/// inversion is reported.

#include <HexEx/Generators/Generators.hh>
#include <HexEx/Generators/Perturbation.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/Mesh/HexMeshQuality.hh>
#include <HexEx/Untangling/Untangler.hh>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <random>

using namespace HexEx;

namespace {

/// The unit cube as an n x n x n grid of hexes.
HexMesh gridCube(int n) {
    HexMesh m;
    auto id = [n](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) m.vertices.push_back(Vec3d(i, j, k) / n);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                m.hexes.push_back({{id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                                    id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)}});
    return m;
}

/// Moves every interior vertex of gridCube(n) by uniform noise of @p amp cells per axis.
HexMesh tangledCube(int n, double amp, unsigned seed) {
    HexMesh m = gridCube(n);
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(-amp, amp);
    for (int k = 1; k < n; ++k)
        for (int j = 1; j < n; ++j)
            for (int i = 1; i < n; ++i) {
                const double dx = u(gen), dy = u(gen), dz = u(gen);
                m.vertices[static_cast<std::size_t>((k * (n + 1) + j) * (n + 1) + i)] += Vec3d(dx, dy, dz) / n;
            }
    return m;
}

/// Closest point to @p p on triangle (a, b, c) (regions of the Voronoi diagram of the
/// triangle's features, written out).
Vec3d closestOnTriangle(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
    const Vec3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab | ap, d2 = ac | ap;
    if (d1 <= 0 && d2 <= 0) return a;
    const Vec3d bp = p - b;
    const double d3 = ab | bp, d4 = ac | bp;
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
    const Vec3d cp = p - c;
    const double d5 = ab | cp, d6 = ac | cp;
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double den = 1.0 / (va + vb + vc);
    return a + ab * (vb * den) + ac * (vc * den);
}

/// Largest distance of a vertex of @p after that moved (compared to @p before) and lies on
/// the boundary of @p before to the surface @p s, by brute force.
double maxBoundaryDistance(const HexMesh& before, const HexMesh& after, const TriangleSurface& s) {
    const TriangleSurface hb = hexMeshBoundary(before);
    std::vector<char> on(before.vertices.size(), 0);
    for (const auto& t : hb.triangles)
        for (const int v : t) on[static_cast<std::size_t>(v)] = 1;
    double worst = 0;
    for (std::size_t v = 0; v < on.size(); ++v) {
        if (!on[v] || after.vertices[v] == before.vertices[v]) continue;
        double best = std::numeric_limits<double>::infinity();
        for (const auto& t : s.triangles) {
            const Vec3d q = closestOnTriangle(after.vertices[v], s.points[static_cast<std::size_t>(t[0])],
                                              s.points[static_cast<std::size_t>(t[1])], s.points[static_cast<std::size_t>(t[2])]);
            best = std::min(best, (q - after.vertices[v]).norm());
        }
        worst = std::max(worst, best);
    }
    return worst;
}

double bboxDiagonal(const HexMesh& m) {
    Vec3d lo(1e300), hi(-1e300);
    for (const auto& p : m.vertices) {
        lo.minimize(p);
        hi.maximize(p);
    }
    return (hi - lo).norm();
}

/// Extraction of @p pm with default options.
HexMesh extract(ParametrizedTetMesh& pm) {
    if (!pm.mesh.has_adjacency()) pm.mesh.build_adjacency();
    HexMesh hm;
    extractHexMesh(pm, hm);
    return hm;
}

} // namespace

TEST(Untangler, ValidMeshIsReturnedUnchanged) {
    ParametrizedTetMesh pm = generateCylinder(5, 2, 2, 2, 2);
    HexMesh m = extract(pm);
    ASSERT_GT(m.hexes.size(), 0u);
    const HexMesh before = m;
    const UntangleReport r = untangleHexMesh(m);
    EXPECT_EQ(r.inverted_before, 0);
    EXPECT_EQ(r.inverted_after, 0);
    EXPECT_EQ(r.moved_vertices, 0);
    EXPECT_EQ(r.outer_iterations, 0);
    EXPECT_TRUE(r.success);
    EXPECT_EQ(m.vertices, before.vertices);
}

TEST(Untangler, RandomlyTangledGridWithFixedBoundary) {
    HexMesh m = tangledCube(6, 0.9, 3);
    const HexMesh before = m;
    UntangleOptions o;
    o.boundary = BoundaryMode::Fixed;
    const UntangleReport r = untangleHexMesh(m, o);
    EXPECT_GE(r.inverted_before, 60) << "the test needs many inverted hexes";
    EXPECT_EQ(r.inverted_after, 0) << r.message;
    EXPECT_EQ(computeQuality(m).inverted_hexes, 0);
    EXPECT_GT(r.min_scaled_jacobian_after, 0.0);
    // Boundary vertices of the cube did not move at all.
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
        const Vec3d& p = before.vertices[v];
        const bool boundary = std::min({p[0], p[1], p[2]}) == 0.0 || std::max({p[0], p[1], p[2]}) == 1.0;
        if (boundary) {
            EXPECT_EQ(m.vertices[v], p) << "vertex " << v;
        }
    }
}

TEST(Untangler, RandomlyTangledGridWithSlidingBoundary) {
    HexMesh m = tangledCube(6, 0.9, 5);
    const HexMesh before = m;
    const TriangleSurface cube = hexMeshBoundary(gridCube(6));
    const UntangleReport r = untangleHexMesh(m, UntangleOptions{}, &cube);
    EXPECT_GE(r.inverted_before, 60);
    EXPECT_EQ(r.inverted_after, 0) << r.message;
    EXPECT_LE(maxBoundaryDistance(before, m, cube), 1e-9 * bboxDiagonal(before));
    // The 8 cube corners are feature corners: fixed. Vertices on cube edges stay on them.
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
        const Vec3d& p = before.vertices[v];
        int on_planes = 0;
        for (int a = 0; a < 3; ++a) on_planes += p[a] == 0.0 || p[a] == 1.0;
        if (on_planes == 3) {
            EXPECT_EQ(m.vertices[v], p);
        }
        if (on_planes >= 2) {
            int still = 0;
            for (int a = 0; a < 3; ++a) still += std::abs(m.vertices[v][a]) < 1e-12 || std::abs(m.vertices[v][a] - 1) < 1e-12;
            EXPECT_GE(still, 2) << "vertex " << v << " left its cube edge";
        }
    }
}

TEST(Untangler, ResultDoesNotDependOnThreadCount) {
    // 17^3 = 4913 hexes, all moving: above the size (4096 hexes) from which threads are used.
    HexMesh a = tangledCube(17, 0.7, 7), b = a, c = a;
    UntangleOptions o;
    o.threads = 1;
    const UntangleReport ra = untangleHexMesh(a, o);
    o.threads = 2;
    untangleHexMesh(b, o);
    o.threads = 5;
    untangleHexMesh(c, o);
    EXPECT_GT(ra.inverted_before, 100);
    EXPECT_EQ(ra.inverted_after, 0);
    EXPECT_GE(ra.free_vertices, 4000) << "the neighbourhood should have more than 4096 hexes";
    EXPECT_EQ(a.vertices, b.vertices);
    EXPECT_EQ(a.vertices, c.vertices);
}

TEST(Untangler, PerturbedCylindersAndCubesOfTheGenerators) {
    // Folded maps: perturbed generator maps whose extraction has inverted hexes.
    long total_before = 0;
    for (unsigned seed = 1; seed <= 6; ++seed) {
        ParametrizedTetMesh pm = seed % 2 ? generateCylinder(5, 3, 2, 3, 2) : generateCube(4, 4);
        perturbParameters(pm, 0.8, seed);
        HexMesh hm = extract(pm);
        const HexMesh before = hm;
        const TriangleSurface surface = tetMeshBoundary(pm.mesh);
        const UntangleReport r = untangleHexMesh(hm, UntangleOptions{}, &surface);
        total_before += r.inverted_before;
        std::printf("seed %u: %ld hexes, %ld inverted -> %ld, min sj %.3f, %d steps\n", seed, r.hexes, r.inverted_before,
                    r.inverted_after, r.min_scaled_jacobian_after, r.outer_iterations);
        EXPECT_EQ(r.inverted_after, 0) << "seed " << seed << ": " << r.message;
        EXPECT_LE(maxBoundaryDistance(before, hm, surface), 1e-9 * bboxDiagonal(before)) << "seed " << seed;
    }
    EXPECT_GT(total_before, 0) << "the perturbed maps should fold";
}

TEST(Untangler, BoundaryThatForcesAnInversionIsReported) {
    // One hex whose top face lies below its bottom face: every vertex is on the boundary.
    HexMesh m = gridCube(1);
    for (int i = 4; i < 8; ++i) m.vertices[static_cast<std::size_t>(i)][2] = -1.0;
    UntangleOptions o;
    o.boundary = BoundaryMode::Fixed;
    const UntangleReport r = untangleHexMesh(m, o);
    EXPECT_EQ(r.inverted_before, 1);
    EXPECT_EQ(r.inverted_after, 1);
    EXPECT_FALSE(r.success);
    EXPECT_NE(r.message.find("1 hexes remain invalid (1 inverted at a corner, 0 undecided); 1 of them have no vertex that may move"), std::string::npos)
        << r.message;
}

TEST(Untangler, RejectsVertexIndicesOutOfRange) {
    HexMesh m = gridCube(1);
    m.hexes[0][3] = 8;
    EXPECT_THROW(untangleHexMesh(m), std::invalid_argument);
}

TEST(Untangler, QualityIterationsRaiseTheWorstScaledJacobian) {
    // The quality rounds keep the placement with the largest worst scaled Jacobian, so they
    // never lower it; on these folded maps they raise it in total.
    double sum_without = 0, sum_with = 0;
    int quality_iterations = 0;
    for (unsigned seed = 1; seed <= 6; ++seed) {
        ParametrizedTetMesh pm = seed % 2 ? generateCylinder(5, 3, 2, 3, 2) : generateCube(4, 4);
        perturbParameters(pm, 0.8, seed);
        const HexMesh extracted = extract(pm);
        const TriangleSurface surface = tetMeshBoundary(pm.mesh);
        UntangleOptions off;
        off.quality_iterations = 0;
        HexMesh a = extracted, b = extracted;
        const UntangleReport ra = untangleHexMesh(a, off, &surface);
        const UntangleReport rb = untangleHexMesh(b, UntangleOptions{}, &surface);
        ASSERT_EQ(ra.inverted_after, 0) << "seed " << seed;
        ASSERT_EQ(rb.inverted_after, 0) << "seed " << seed;
        EXPECT_EQ(ra.quality_iterations, 0);
        quality_iterations += rb.quality_iterations;  // 0 if no moved hex is below quality_threshold
        EXPECT_GE(rb.min_scaled_jacobian_after, ra.min_scaled_jacobian_after) << "seed " << seed;
        sum_without += ra.min_scaled_jacobian_after;
        sum_with += rb.min_scaled_jacobian_after;
    }
    EXPECT_GT(quality_iterations, 0);
    EXPECT_GT(sum_with, sum_without + 0.05);
}
