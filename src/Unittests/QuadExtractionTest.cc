/// @file QuadExtractionTest.cc
/// End-to-end tests of the 2D pipeline (extractQuadMesh) on the 2D generators: exact quad
/// and vertex counts, validity, cones, random charts, noise and perturbed maps.

#include <HexEx/Quad/QuadExtraction.hh>
#include <HexEx/Quad/QuadGenerators.hh>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>

using namespace HexEx;

namespace {

/// Extracts @p m with @p threads threads; expects no exception.
QuadExtractionReport run(const ParametrizedTriMesh& m, QuadMesh& out, int threads = 1) {
    QuadExtractionOptions opt;
    opt.threads = threads;
    return extractQuadMesh(m, out, opt);
}

/// Expects a valid all-quad result with exactly @p quads quads and @p vertices vertices.
void expectGrid(const ParametrizedTriMesh& m, long quads, long vertices, long boundary_edges, const char* what) {
    SCOPED_TRACE(what);
    QuadMesh qm;
    const QuadExtractionReport r = run(m, qm);
    EXPECT_TRUE(r.valid_all_quad) << r.validation.summary();
    EXPECT_EQ(r.output.quads, quads);
    EXPECT_EQ(r.output.vertices, vertices);
    EXPECT_EQ(r.output.boundary_edges, boundary_edges);
    EXPECT_EQ(r.output.non_quad_faces, 0);
    EXPECT_EQ(r.output.unconnected_darts, 0);
    EXPECT_EQ(static_cast<long>(qm.quads.size()), quads);
    EXPECT_EQ(static_cast<long>(qm.vertices.size()), vertices);
    EXPECT_NEAR(r.input.parametric_area, static_cast<double>(quads), 1e-6);
}

/// Number of quads of @p qm that use the vertex at 3D position @p p.
int quadsAround(const QuadMesh& qm, const Vec3d& p) {
    int v = -1;
    for (std::size_t i = 0; i < qm.vertices.size(); ++i)
        if ((qm.vertices[i] - p).norm() < 1e-9) v = static_cast<int>(i);
    if (v < 0) return -1;
    int n = 0;
    for (const auto& q : qm.quads)
        for (int c : q)
            if (c == v) ++n;
    return n;
}

} // namespace

TEST(QuadExtraction, SquareAtSeveralResolutions) {
    for (int n : {1, 3, 4, 7})
        for (int s : {1, 2, 4, 5}) {
            const std::string what = "square n=" + std::to_string(n) + " s=" + std::to_string(s);
            expectGrid(generateSquare(n, s), long(s) * s, long(s + 1) * (s + 1), 4L * s, what.c_str());
        }
}

TEST(QuadExtraction, ConeDisksHaveExactCountsAndValence) {
    for (int k : {3, 4, 5, 6})
        for (int R : {1, 2, 3})
            for (int n : {R, 2 * R + 1}) {
                const std::string what = "cone k=" + std::to_string(k) + " R=" + std::to_string(R) + " n=" + std::to_string(n);
                SCOPED_TRACE(what);
                const ParametrizedTriMesh m = generateConeDisk(k, R, n);
                expectGrid(m, long(k) * R * R, long(k) * R * (R + 1) + 1, 2L * k * R, what.c_str());
                QuadMesh qm;
                const QuadExtractionReport r = run(m, qm);
                EXPECT_EQ(quadsAround(qm, Vec3d(0, 0, 0)), k);
                EXPECT_EQ(r.input.cones, k == 4 ? 0 : 1);
            }
}

TEST(QuadExtraction, TorusAndQuarterTurnSeam) {
    expectGrid(generateTorus(4, 3, 5, 4), 12, 12, 0, "torus 4x3 on 5x4");
    expectGrid(generateTorus(6, 6, 6, 6), 36, 36, 0, "torus 6x6 on 6x6");
    expectGrid(generateTorus(3, 5, 7, 3), 15, 15, 0, "torus 3x5 on 7x3");
    expectGrid(generateQuarterTurnSeam(3, 4), 9, 16, 12, "seam W=3 n=4");
    expectGrid(generateQuarterTurnSeam(4, 6), 16, 25, 16, "seam W=4 n=6");
    expectGrid(generateQuarterTurnSeam(5, 3), 25, 36, 20, "seam W=5 n=3");
}

TEST(QuadExtraction, RandomChartsAndNoiseKeepCounts) {
    struct Case { ParametrizedTriMesh m; long quads, vertices, boundary; };
    std::vector<Case> cases;
    cases.push_back({generateSquare(5, 4), 16, 25, 16});
    cases.push_back({generateConeDisk(5, 2, 3), 20, 31, 20});
    cases.push_back({generateConeDisk(3, 3, 3), 27, 37, 18});
    cases.push_back({generateTorus(4, 4, 5, 6), 16, 16, 0});
    cases.push_back({generateQuarterTurnSeam(4, 4), 16, 25, 16});
    unsigned seed = 1;
    for (auto& c : cases) {
        ParametrizedTriMesh m = c.m;
        applyRandomTriCharts(m, seed);
        expectGrid(m, c.quads, c.vertices, c.boundary, ("random charts " + std::to_string(seed)).c_str());
        applyTriParameterNoise(m, 1e-11, seed + 100);
        expectGrid(m, c.quads, c.vertices, c.boundary, ("charts + noise " + std::to_string(seed)).c_str());
        ++seed;
    }
}

TEST(QuadExtraction, PerturbedSquaresAndDisksKeepExactCounts) {
    long flipped = 0;
    for (unsigned seed : {1u, 2u, 3u, 4u}) {
        ParametrizedTriMesh sq = generateSquare(12, 6);
        perturbTriParameters(sq, 0.5, seed);
        QuadMesh qm;
        QuadExtractionReport r = run(sq, qm);
        flipped += r.input.flipped_triangles;
        EXPECT_TRUE(r.valid_all_quad) << "square seed " << seed << ": " << r.validation.summary();
        EXPECT_EQ(r.output.quads, 36) << "square seed " << seed;
        EXPECT_EQ(r.output.vertices, 49) << "square seed " << seed;

        for (int k : {3, 5, 6}) {
            ParametrizedTriMesh disk = generateConeDisk(k, 4, 8);
            perturbTriParameters(disk, 0.5, seed);
            r = run(disk, qm);
            flipped += r.input.flipped_triangles;
            EXPECT_TRUE(r.valid_all_quad) << "disk k=" << k << " seed " << seed << ": " << r.validation.summary();
            EXPECT_EQ(r.output.quads, 16L * k) << "disk k=" << k << " seed " << seed;
            EXPECT_EQ(r.output.vertices, 20L * k + 1) << "disk k=" << k << " seed " << seed;
        }
    }
    EXPECT_GT(flipped, 200);  // the perturbation really flips many triangles
}

TEST(QuadExtraction, SameOutputForAnyThreadCount) {
    ParametrizedTriMesh m = generateConeDisk(5, 4, 6);
    perturbTriParameters(m, 0.4, 9);
    QuadMesh a, b;
    const QuadExtractionReport ra = run(m, a, 1), rb = run(m, b, 3);
    EXPECT_EQ(ra.darts.extracted, rb.darts.extracted);
    EXPECT_EQ(a.quads, b.quads);
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    for (std::size_t i = 0; i < a.vertices.size(); ++i) EXPECT_EQ(a.vertices[i], b.vertices[i]);
}

TEST(QuadExtraction, PerturbationReallyFlipsAndAnnihilates) {
    ParametrizedTriMesh m = generateConeDisk(5, 4, 8);
    TriPerturbStats st;
    perturbTriParameters(m, 0.5, 2, &st);
    EXPECT_EQ(st.vertices, 361u);
    EXPECT_EQ(st.fixed_vertices, 6u);  // the cone and the 5 outer corners
    QuadMesh qm;
    const QuadExtractionReport r = run(m, qm);
    std::printf("flipped %ld degenerate %ld darts %ld anti %ld pairs %ld asym %ld\n", r.input.flipped_triangles,
                r.input.degenerate_triangles, r.darts.extracted, r.darts.anti, r.darts.annihilated_pairs, r.darts.asymmetric_links);
    EXPECT_GT(r.input.flipped_triangles, 5);
    EXPECT_EQ(r.darts.annihilated_pairs, r.darts.anti);
    EXPECT_EQ(r.darts.extracted - 2 * r.darts.anti, 8L * 80);
    EXPECT_EQ(r.output.quads, 80);
    EXPECT_EQ(r.output.vertices, 101);
}
