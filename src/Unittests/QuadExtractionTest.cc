/// @file QuadExtractionTest.cc
/// End-to-end tests of the 2D pipeline (extractQuadMesh) on the 2D generators: exact quad
/// and vertex counts, validity, cones, random charts, noise and perturbed maps.

#include <HexEx/Core/Error.hh>
#include <HexEx/Quad/QuadExtraction.hh>
#include <HexEx/Quad/QuadGenerators.hh>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

using namespace HexEx;

namespace {

/// Extracts @p m with @p threads threads; expects no exception.
QuadExtractionReport run(const ParametrizedTriMesh& m, QuadMesh& out, int threads = 1) {
    QuadExtractionOptions opt;
    opt.threads = threads;
    opt.min_triangles_per_thread = 1;  // small maps: really use the threads
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
    EXPECT_GT(r.input.flipped_triangles, 5);
    EXPECT_EQ(r.darts.annihilated_pairs, r.darts.anti);
    EXPECT_EQ(r.darts.extracted - 2 * r.darts.anti, 8L * 80);
    EXPECT_EQ(r.output.quads, 80);
    EXPECT_EQ(r.output.vertices, 101);
}

TEST(QuadExtraction, HeavilyDegenerateMapsKeepExactCounts) {
    // Perturbation rounded to multiples of 1/2 on a mesh of spacing 3/8: many triangles
    // collapse to segments or points (zero-length edges, ambiguous transitions) and fold.
    long degenerate = 0, ambiguous = 0;
    for (unsigned seed = 1; seed <= 6; ++seed) {
        ParametrizedTriMesh m = generateSquare(16, 6);
        perturbTriParameters(m, 0.5, seed);
        for (auto& t : m.params)
            for (auto& p : t) p = Vec2d(std::round(2 * p[0]) / 2, std::round(2 * p[1]) / 2);
        applyRandomTriCharts(m, seed);
        QuadMesh qm;
        const QuadExtractionReport r = run(m, qm);
        degenerate += r.input.degenerate_triangles;
        ambiguous += r.input.ambiguous_transitions;
        EXPECT_TRUE(r.valid_all_quad) << "seed " << seed << ": " << r.validation.summary();
        EXPECT_EQ(r.output.quads, 36) << "seed " << seed;
        EXPECT_EQ(r.output.vertices, 49) << "seed " << seed;
    }
    EXPECT_GT(degenerate, 300);
    EXPECT_GT(ambiguous, 100);
}

TEST(QuadExtraction, GivenRotationsAreUsedAndChecked) {
    const ParametrizedTriMesh m = generateQuarterTurnSeam(4, 4);
    const TriAdjacency adj = buildTriAdjacency(m);
    // True rotations: the right half's chart is the left's turned by one quarter turn.
    std::vector<int> given(adj.opposite.size(), 0);
    auto right = [&](std::size_t f) { return static_cast<int>(f / 2) % 4 >= 2; };
    for (std::size_t h = 0; h < given.size(); ++h) {
        const int o = adj.opposite[h];
        if (o < 0) continue;
        const int from = right(h / 3), to = right(static_cast<std::size_t>(o) / 3);
        given[h] = ((to - from) % 4 + 4) % 4;
    }
    QuadExtractionOptions opt;
    opt.given_quarter_turns = &given;
    QuadMesh qm;
    const QuadExtractionReport r = extractQuadMesh(m, qm, opt);
    EXPECT_TRUE(r.valid_all_quad);
    EXPECT_EQ(r.output.quads, 16);
    given[static_cast<std::size_t>(std::find_if(adj.opposite.begin(), adj.opposite.end(), [](int o) { return o >= 0; }) -
                                   adj.opposite.begin())] = 1;  // no longer inverse to its opposite
    EXPECT_THROW(extractQuadMesh(m, qm, opt), InputError);
}

TEST(QuadExtraction, UnalignedBoundaryIsReportedNotAllQuad) {
    ParametrizedTriMesh m = generateSquare(4, 1);
    for (auto& t : m.params)
        for (auto& p : t) p *= 2.5;  // boundary at u, v = 2.5: partial squares along two sides
    QuadMesh qm;
    const QuadExtractionReport r = run(m, qm);
    EXPECT_FALSE(r.valid_all_quad);
    EXPECT_EQ(r.output.quads, 4);
    EXPECT_GT(r.output.unconnected_darts, 0);
    EXPECT_FALSE(r.validation.valid());
    EXPECT_FALSE(r.warnings.empty());
}

TEST(QuadExtraction, BadInputThrowsWithReason) {
    auto expectError = [](const ParametrizedTriMesh& m, const std::string& part) {
        QuadMesh qm;
        try {
            extractQuadMesh(m, qm);
            ADD_FAILURE() << "no error, expected '" << part << "'";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
        }
    };
    ParametrizedTriMesh m = generateSquare(2, 2);
    ParametrizedTriMesh bad = m;
    bad.triangles[3][1] = 99;
    expectError(bad, "triangle 3: vertex index 99 out of range");
    bad = m;
    bad.triangles[2] = {bad.triangles[2][0], bad.triangles[2][0], bad.triangles[2][2]};
    expectError(bad, "triangle 2: repeated vertex");
    bad = m;
    std::swap(bad.triangles[5][1], bad.triangles[5][2]);  // flips one triangle's orientation
    expectError(bad, "same direction");
    bad = m;
    bad.params[1][2][0] = std::nan("");
    expectError(bad, "triangle 1: parameter of corner 2 is not finite");
    bad = m;
    bad.params[0][0][1] = 1e12;
    expectError(bad, "larger than 2^28");
    bad = m;
    bad.params.pop_back();
    expectError(bad, "parameter triples");
    bad = m;
    bad.triangles.push_back(m.triangles[0]);
    bad.params.push_back(m.params[0]);
    expectError(bad, "same direction");
}

TEST(QuadExtraction, FirstInputErrorIsReportedForAnyThreadCount) {
    // Defects in several triangles (checked in parallel chunks): the message is always the
    // one a scan in triangle order meets first.
    ParametrizedTriMesh bad = generateSquare(3, 3);  // 18 triangles
    bad.params[14][1][0] = std::nan("");
    bad.triangles[9][2] = 1000;
    bad.triangles[4] = {bad.triangles[4][1], bad.triangles[4][1], bad.triangles[4][2]};
    bad.params[16][0][1] = 1e12;
    for (int threads : {1, 2, 3, 5, 18}) {
        QuadMesh qm;
        QuadExtractionOptions opt;
        opt.threads = threads;
        opt.min_triangles_per_thread = 1;  // small maps: really use the threads
        try {
            extractQuadMesh(bad, qm, opt);
            ADD_FAILURE() << "no error with " << threads << " threads";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()), "triangle mesh: triangle 4: repeated vertex") << threads;
        }
    }
    bad.triangles[4] = generateSquare(3, 3).triangles[4];  // next: the index out of range
    bad.triangles[9][2] = 1000;
    for (int threads : {1, 2, 18}) {
        QuadMesh qm;
        QuadExtractionOptions opt;
        opt.threads = threads;
        opt.min_triangles_per_thread = 1;  // small maps: really use the threads
        EXPECT_THROW(
            {
                try {
                    extractQuadMesh(bad, qm, opt);
                } catch (const InputError& e) {
                    EXPECT_EQ(std::string(e.what()), "triangle mesh: triangle 9: vertex index 1000 out of range (16 vertices)")
                        << threads;
                    throw;
                }
            },
            InputError);
    }
}

TEST(QuadExtraction, NonManifoldEdgesAreNamedForAnyThreadCount) {
    // Three triangles on edge (0, 1): one runs 0 -> 1, two run 1 -> 0. The first triangle
    // finds two opposite partners; the fast pairing must hand over to the full scan, which
    // reports exactly this, whatever the number of threads (one triangle per thread at 3).
    ParametrizedTriMesh m;
    m.points = {Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, -1, 0), Vec3d(0, -1, 1)};
    m.triangles = {{0, 1, 2}, {1, 0, 3}, {1, 0, 4}};
    m.params = {{Vec2d(0, 0), Vec2d(1, 0), Vec2d(0, 1)}, {Vec2d(1, 0), Vec2d(0, 0), Vec2d(0, -1)},
                {Vec2d(1, 0), Vec2d(0, 0), Vec2d(0, -1)}};
    for (int threads : {1, 2, 3}) {
        QuadMesh qm;
        QuadExtractionOptions opt;
        opt.threads = threads;
        opt.min_triangles_per_thread = 1;  // small maps: really use the threads
        try {
            extractQuadMesh(m, qm, opt);
            ADD_FAILURE() << "no error with " << threads << " threads";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()), "triangle mesh: edge (0, 1) is shared by more than two triangles") << threads;
        }
    }
    // Two triangles running the same way on a boundary edge (no opposite partner at all):
    // not a boundary, an orientation error.
    m.triangles = {{0, 1, 2}, {0, 1, 3}};
    m.params.pop_back();
    for (int threads : {1, 2}) {
        QuadMesh qm;
        QuadExtractionOptions opt;
        opt.threads = threads;
        opt.min_triangles_per_thread = 1;  // small maps: really use the threads
        try {
            extractQuadMesh(m, qm, opt);
            ADD_FAILURE() << "no error with " << threads << " threads";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()), "triangle mesh: triangles 0 and 1 use edge (0, 1) in the same direction "
                                             "(inconsistent orientation or non-manifold edge)") << threads;
        }
    }
}

TEST(QuadExtraction, SmallMapsRunOnOneThread) {
    // At most one thread per QuadExtractionOptions::min_triangles_per_thread triangles
    // (10,000 by default): thread start-up would cost more than the work it shares.
    QuadExtractionOptions opt;
    opt.threads = 8;
    QuadMesh small, large;
    EXPECT_EQ(extractQuadMesh(generateSquare(20, 4), small, opt).threads, 1);      // 800 triangles
    const QuadExtractionReport r = extractQuadMesh(generateSquare(100, 10), large, opt);  // 20,000 triangles
    EXPECT_EQ(r.threads, 2);
    EXPECT_EQ(r.output.quads, 100);
    opt.min_triangles_per_thread = 1;
    EXPECT_EQ(extractQuadMesh(generateSquare(20, 4), small, opt).threads, 8);
    EXPECT_EQ(small.quads.size(), 16u);
}
