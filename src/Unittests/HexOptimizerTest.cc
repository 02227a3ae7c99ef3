/// @file HexOptimizerTest.cc
/// optimizeHexMesh(): the worst scaled Jacobian rises on perturbed cubes, never decreases,
/// every hex stays certified valid, the boundary stays on the surface (a cube's feature
/// edges and corners exactly, a curved surface read from OBJ), thread-count independence,
/// refusal of inverted input; readTriangleSurface() errors; `hexex optimize --json` and its usage errors.

#include "ToolPath.hh"

#include <HexEx/Core/Error.hh>
#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/IO/HexMeshWriters.hh>
#include <HexEx/Mesh/HexMeshQuality.hh>
#include <HexEx/Untangling/HexOptimizer.hh>
#include <HexEx/Untangling/LocalSurfaceProjection.hh>
#include <HexEx/Untangling/TriangleSurfaceReader.hh>

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>

#include "TestMeshChecks.hh"

using namespace HexEx;

namespace {

/// n^3 grid hexes; vertex (i, j, k) at index (k (n+1) + j) (n+1) + i, position from @p place.
HexMesh gridMesh(int n, const std::function<Vec3d(int, int, int)>& place) {
    HexMesh m;
    auto id = [n](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) m.vertices.push_back(place(i, j, k));
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                m.hexes.push_back({{id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                                    id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)}});
    return m;
}

/// Deterministic pseudo-random numbers in [-1, 1].
struct Lcg {
    std::uint64_t s;
    double next() {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(s >> 11) / static_cast<double>(1ull << 53) * 2.0 - 1.0;
    }
};

/// Unit cube, n^3 hexes; every coordinate strictly inside (0, 1) is moved by up to a / n,
/// so interior vertices move in 3D, face vertices in their face, edge vertices along their edge.
HexMesh perturbedCube(int n, double a, std::uint64_t seed) {
    Lcg r{seed};
    return gridMesh(n, [&](int i, int j, int k) {
        const int c[3] = {i, j, k};
        Vec3d p;
        for (int d = 0; d < 3; ++d) {
            p[d] = static_cast<double>(c[d]) / n;
            const double x = r.next();
            if (c[d] > 0 && c[d] < n) p[d] += a * x / n;
        }
        return p;
    });
}

} // namespace

TEST(HexOptimizer, PerturbedCubeWithFixedBoundaryRisesAboveBound) {
    HexMesh m = perturbedCube(6, 0.22, 7);
    const HexMesh before = m;
    const QualityStats q0 = computeQuality(m, 1);
    ASSERT_EQ(q0.inverted_hexes, 0);
    ASSERT_LT(q0.min_scaled_jacobian, 0.45);
    OptimizeOptions o;
    o.boundary = BoundaryMode::Fixed;
    o.threads = 1;
    const OptimizeReport r = optimizeHexMesh(m, o);
    ASSERT_TRUE(r.success) << r.message;
    EXPECT_DOUBLE_EQ(r.min_scaled_jacobian_before, q0.min_scaled_jacobian);
    EXPECT_GT(r.min_scaled_jacobian_after, 0.65);  // 0.687 measured; the fixed boundary limits it
    EXPECT_DOUBLE_EQ(r.min_scaled_jacobian_after, computeQuality(m, 1).min_scaled_jacobian);
    EXPECT_EQ(HexExTest::notCertifiedValid(m), 0);
    EXPECT_EQ(r.fixed_vertices, 7 * 7 * 7 - 5 * 5 * 5);
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
        const Vec3d& p = before.vertices[v];
        const bool boundary = p[0] == 0 || p[0] == 1 || p[1] == 0 || p[1] == 1 || p[2] == 0 || p[2] == 1;
        if (boundary) {
            EXPECT_EQ(m.vertices[v], p) << "boundary vertex " << v << " moved";
        }
    }
    long total = 0;
    for (const long c : r.histogram_after) total += c;
    EXPECT_EQ(r.histogram_after.size(), 20u);
    EXPECT_EQ(total, 216);
}

TEST(HexOptimizer, CubeFeatureEdgesAndCornersAreKept) {
    const int n = 5;
    HexMesh m = perturbedCube(n, 0.22, 11);
    ASSERT_EQ(computeQuality(m, 1).inverted_hexes, 0);
    const HexMesh before = m;
    OptimizeOptions o;
    o.threads = 1;
    const OptimizeReport r = optimizeHexMesh(m, o);  // surface: the mesh's own boundary (the cube)
    ASSERT_TRUE(r.success) << r.message;
    EXPECT_EQ(r.feature_curves, 12);
    EXPECT_EQ(r.feature_corners, 8);
    EXPECT_EQ(r.corner_vertices, 8);
    EXPECT_EQ(r.curve_vertices, 12 * (n - 1));
    EXPECT_EQ(r.surface_vertices, 6 * (n - 1) * (n - 1));
    EXPECT_GT(r.min_scaled_jacobian_after, r.min_scaled_jacobian_before + 0.2);
    EXPECT_EQ(HexExTest::notCertifiedValid(m), 0);
    const double diag = std::sqrt(3.0), tol = 1e-9 * diag;
    long moved_on_edges = 0;
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
        const Vec3d& p0 = before.vertices[v];
        const Vec3d& p = m.vertices[v];
        int on0 = 0;
        for (int d = 0; d < 3; ++d) {
            if (p0[d] == 0 || p0[d] == 1) {
                ++on0;
                EXPECT_NEAR(p[d], p0[d], tol) << "vertex " << v << " left its face/edge/corner";
            }
            EXPECT_GE(p[d], -tol);
            EXPECT_LE(p[d], 1 + tol);
        }
        if (on0 == 3) {
            EXPECT_EQ(p, p0) << "corner " << v << " moved";
        }
        if (on0 == 2 && (p - p0).norm() > 1e-3) ++moved_on_edges;
    }
    EXPECT_GT(moved_on_edges, 4);  // the edge vertices did slide along their edges
    EXPECT_LE(r.max_feature_distance, tol);
    EXPECT_LE(r.max_surface_distance, tol);
}

TEST(HexOptimizer, BoundaryStaysOnCurvedSurfaceFromObj) {
    // A quarter of a thick cylinder (r in [1, 2], theta in [0, pi/2], z in [0, 1]) as 4^3
    // hexes; the surface file triangulates its boundary 4 times finer in theta, so hex
    // boundary vertices start on it; interior and boundary vertices are then moved in
    // parameter space (boundary ones along the surface in theta, z).
    const int n = 4, fine = 16;
    auto at = [](double r, double t, double z) {
        const double th = t * M_PI / 2;
        return Vec3d(r * std::cos(th), r * std::sin(th), z);
    };
    Lcg rng{5};
    HexMesh m = gridMesh(n, [&](int i, int j, int k) {
        double r = 1 + static_cast<double>(i) / n, t = static_cast<double>(j) / n, z = static_cast<double>(k) / n;
        if (i > 0 && i < n) r += 0.3 * rng.next() / n;
        if (j > 0 && j < n && (i == n || i == 0)) t += 0.3 * rng.next() / n;
        if (k > 0 && k < n && i > 0 && i < n && j > 0 && j < n) z += 0.3 * rng.next() / n;
        return at(r, t, z);
    });
    ASSERT_EQ(computeQuality(m, 1).inverted_hexes, 0);
    // The surface: the 6 sides of the parameter box, each a grid of fine x fine quads.
    const std::string path = (std::filesystem::temp_directory_path() / "hexex_optimizer_wedge.obj").string();
    TriangleSurface expected;
    {
        std::ofstream f(path);
        int base = 1;
        auto side = [&](const std::function<Vec3d(double, double)>& g) {
            for (int b = 0; b <= fine; ++b)
                for (int a = 0; a <= fine; ++a) {
                    const Vec3d p = g(static_cast<double>(a) / fine, static_cast<double>(b) / fine);
                    f.precision(17);
                    f << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
                    expected.points.push_back(p);
                }
            for (int b = 0; b < fine; ++b)
                for (int a = 0; a < fine; ++a) {
                    const int v0 = base + b * (fine + 1) + a, v1 = v0 + 1, v2 = v0 + fine + 2, v3 = v0 + fine + 1;
                    f << "f " << v0 << " " << v1 << " " << v2 << " " << v3 << "\n";
                    expected.triangles.push_back({{v0 - 1, v1 - 1, v2 - 1}});
                    expected.triangles.push_back({{v0 - 1, v2 - 1, v3 - 1}});
                }
            base += (fine + 1) * (fine + 1);
        };
        side([&](double a, double b) { return at(1 + a, b, 0); });
        side([&](double a, double b) { return at(1 + a, b, 1); });
        side([&](double a, double b) { return at(1, a, b); });
        side([&](double a, double b) { return at(2, a, b); });
        side([&](double a, double b) { return at(1 + a, 0, b); });
        side([&](double a, double b) { return at(1 + a, 1, b); });
    }
    const TriangleSurface surface = readTriangleSurface(path);
    std::filesystem::remove(path);
    ASSERT_EQ(surface.triangles.size(), 6u * 2 * fine * fine);
    const HexMesh before = m;
    OptimizeOptions o;
    o.threads = 1;
    const OptimizeReport r = optimizeHexMesh(m, o, &surface);
    ASSERT_TRUE(r.success) << r.message;
    EXPECT_EQ(r.unprojected_vertices, 0);
    EXPECT_GT(r.min_scaled_jacobian_after, r.min_scaled_jacobian_before + 0.05);
    EXPECT_EQ(HexExTest::notCertifiedValid(m), 0);
    // Independent distance check against the triangles as written (brute force).
    const TriangleSurface hb = hexMeshBoundary(before);
    std::vector<char> on(m.vertices.size(), 0);
    for (const auto& t : hb.triangles)
        for (const int v : t) on[static_cast<std::size_t>(v)] = 1;
    const double diag = r.diagonal;
    double worst = 0;
    long moved_outer = 0;
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
        if (!on[v]) continue;
        const Vec3d& p = m.vertices[v];
        double d = 1e300;
        for (const auto& t : expected.triangles)
            d = std::min(d, (closestPointOnTriangle(p, expected.points[static_cast<std::size_t>(t[0])], expected.points[static_cast<std::size_t>(t[1])],
                                                    expected.points[static_cast<std::size_t>(t[2])]) - p).norm());
        worst = std::max(worst, d);
        const double rad = std::hypot(p[0], p[1]);
        if (rad > 1.99 && (p - before.vertices[v]).norm() > 1e-3) ++moved_outer;
    }
    EXPECT_LE(worst, 1e-6 * diag);
    EXPECT_LE(r.max_surface_distance, 1e-6 * diag);
    EXPECT_GT(moved_outer, 0);  // vertices on the curved side did move (along it)
}

TEST(HexOptimizer, SameResultForOneAndTwoThreads) {
    const HexMesh input = perturbedCube(14, 0.2, 3);  // 2,744 hexes: the energy runs in parallel
    ASSERT_EQ(computeQuality(input, 1).inverted_hexes, 0);
    OptimizeOptions o;
    o.max_global_blocks = 4;
    o.max_local_passes = 2;
    HexMesh a = input, b = input;
    o.threads = 1;
    const OptimizeReport ra = optimizeHexMesh(a, o);
    o.threads = 2;
    const OptimizeReport rb = optimizeHexMesh(b, o);
    EXPECT_GT(ra.accepted_blocks, 0);
    EXPECT_GT(ra.min_scaled_jacobian_after, ra.min_scaled_jacobian_before);
    EXPECT_EQ(ra.min_scaled_jacobian_after, rb.min_scaled_jacobian_after);
    EXPECT_EQ(ra.lbfgs_iterations, rb.lbfgs_iterations);
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    for (std::size_t v = 0; v < a.vertices.size(); ++v) ASSERT_EQ(a.vertices[v], b.vertices[v]) << "vertex " << v;
}

TEST(HexOptimizer, WorstNeverDecreasesAndEveryStepStaysValid) {
    // The optimiser is deterministic, so stopping after 0, 1, 2, ... blocks (then passes)
    // shows the state after each step: all certified valid, worst SJ non-decreasing.
    const HexMesh input = perturbedCube(5, 0.25, 23);
    ASSERT_EQ(computeQuality(input, 1).inverted_hexes, 0);
    double last = -2;
    int checked = 0;
    for (int blocks = 0; blocks <= 6; ++blocks)
        for (int passes : {0, 1, 3}) {
            if (passes > 0 && blocks != 6) continue;
            HexMesh m = input;
            OptimizeOptions o;
            o.threads = 1;
            o.max_global_blocks = blocks;
            o.max_local_passes = passes;
            const OptimizeReport r = optimizeHexMesh(m, o);
            ASSERT_TRUE(r.success);
            EXPECT_EQ(HexExTest::notCertifiedValid(m), 0) << blocks << " blocks, " << passes << " passes";
            const double now = computeQuality(m, 1).min_scaled_jacobian;
            EXPECT_GE(now, last) << blocks << " blocks, " << passes << " passes";
            EXPECT_GE(now, r.min_scaled_jacobian_projected);
            last = now;
            ++checked;
        }
    EXPECT_EQ(checked, 9);
    EXPECT_GT(last, 0.5);
}

TEST(HexOptimizer, RefusesInvertedInput) {
    HexMesh m = gridMesh(2, [](int i, int j, int k) { return Vec3d(i, j, k); });
    m.vertices[13] = Vec3d(2.5, 1, 1);  // the centre vertex outside: hexes invert
    const HexMesh before = m;
    const OptimizeReport r = optimizeHexMesh(m);
    EXPECT_FALSE(r.success);
    EXPECT_NE(r.message.find("hexes are inverted (a corner Jacobian <= 0); untangle the mesh first"), std::string::npos)
        << r.message;
    EXPECT_EQ(m.vertices, before.vertices);
    HexMesh bad = before;
    bad.hexes[0][3] = 99;
    EXPECT_THROW(optimizeHexMesh(bad), std::invalid_argument);
}

TEST(HexOptimizer, ReadTriangleSurfaceErrors) {
    EXPECT_THROW(readTriangleSurface("surface.xyz"), InputError);
    try {
        readTriangleSurface("/nonexistent/dir/s.obj");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/s.obj: cannot open"), std::string::npos) << e.what();
    }
}

TEST(HexOptimizer, CommandLineWritesReportAndChecksUsage) {
    const std::string tool = HexExTest::hexexBinary();
    if (tool.empty()) GTEST_SKIP() << "hexex tool not found next to the test binary";
    const auto dir = std::filesystem::temp_directory_path() / "hexex_optimize_cli";
    std::filesystem::create_directories(dir);
    const std::string in = (dir / "in.vtu").string(), out = (dir / "out.vtu").string(), js = (dir / "r.json").string();
    writeHexMesh(in, perturbedCube(4, 0.22, 5));
    auto run = [&](const std::string& args) {
        const int st = std::system((tool + " " + args + " > " + js + " 2> " + (dir / "err.txt").string()).c_str());
        return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    };
    auto slurp = [](const std::string& p) {
        std::ifstream f(p);
        return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    };
    ASSERT_EQ(run("optimize " + in + " -o " + out + " --json --threads 2"), 0) << slurp((dir / "err.txt").string());
    const std::string json = slurp(js);
    EXPECT_NE(json.find("\"histogram_after\": ["), std::string::npos) << json;
    EXPECT_NE(json.find("\"feature_corners\": 8"), std::string::npos) << json;
    EXPECT_NE(json.find("\"invalid_after\": 0"), std::string::npos) << json;
    const HexMesh result = readHexMesh(out);
    EXPECT_EQ(result.hexes.size(), 64u);
    EXPECT_GT(computeQuality(result, 1).min_scaled_jacobian, computeQuality(readHexMesh(in), 1).min_scaled_jacobian);
    EXPECT_EQ(run("optimize " + in + " -o " + out + " --fixed-boundary --surface s.obj"), 2);
    EXPECT_NE(slurp((dir / "err.txt").string()).find("--surface, --surface-from and --fixed-boundary exclude each other"),
              std::string::npos);
    EXPECT_EQ(run("optimize " + in + " -o " + out + " --surface " + (dir / "missing.obj").string()), 2);
    EXPECT_NE(slurp((dir / "err.txt").string()).find("missing.obj: cannot open"), std::string::npos);
    std::filesystem::remove_all(dir);
}
