/// @file BoundaryPillowingTest.cc
/// pillowBoundary(): exact counts on a 2x2x2 grid (8 + 24 hexes, 27 + 26 vertices), boundary
/// vertices bit for bit, every hex certified valid, the boundary quads are the new hexes'
/// outer quads; a hex with two boundary faces at 170 degrees (worst SJ <= sin 170 with its
/// topology) above a stated bound after OptimizeOptions::pillow; 1 and 2 threads identical;
/// clear errors on polyhedra and non-manifold boundaries; `hexex optimize --pillow`.

#include "ToolPath.hh"

#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/IO/HexMeshWriters.hh>
#include <HexEx/Mesh/HexMeshCheck.hh>
#include <HexEx/Mesh/HexMeshQuality.hh>
#include <HexEx/Untangling/BoundaryPillowing.hh>
#include <HexEx/Untangling/HexOptimizer.hh>

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <stdexcept>
#include <string>

#include "TestMeshChecks.hh"

using namespace HexEx;

namespace {

/// n^3 unit-cube grid, vertex (i, j, k) at index (k (n+1) + j) (n+1) + i.
HexMesh grid(int n, int ox = 0) {
    HexMesh m;
    auto id = [n](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) m.vertices.emplace_back(i + ox, j, k);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                m.hexes.push_back({{id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                                    id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)}});
    return m;
}

/// Boundary quads of @p m as sorted vertex sets.
std::set<std::array<int, 4>> boundaryQuadSet(const HexMesh& m) {
    std::multiset<std::array<int, 4>> all;
    for (const auto& h : m.hexes)
        for (const auto& f : kHexFaces) {
            std::array<int, 4> q{{h[static_cast<std::size_t>(f[0])], h[static_cast<std::size_t>(f[1])],
                                  h[static_cast<std::size_t>(f[2])], h[static_cast<std::size_t>(f[3])]}};
            std::sort(q.begin(), q.end());
            all.insert(q);
        }
    std::set<std::array<int, 4>> b;
    for (const auto& q : all)
        if (all.count(q) == 1) b.insert(q);
    return b;
}

/// One hex, extruded in z from a quad whose corner B has 170 degrees: the side faces on AB and
/// BC meet at a dihedral angle of 170 degrees, so the corner at B has SJ = sin 170.
HexMesh flatCornerHex() {
    const double a = 10.0 * M_PI / 180.0;
    const Vec3d A(-1, 0, 0), B(0, 0, 0), C(std::cos(a), std::sin(a), 0), D(-0.3, 1.2, 0), up(0, 0, 1);
    HexMesh m;
    m.vertices = {A, B, C, D, A + up, B + up, C + up, D + up};
    // Bottom loop counter-clockwise seen from the top: A B C D.
    m.hexes.push_back({{0, 1, 2, 3, 4, 5, 6, 7}});
    return m;
}

double minSJ(const HexMesh& m) {
    const auto sj = scaledJacobians(m);
    return *std::min_element(sj.begin(), sj.end());
}

} // namespace

TEST(BoundaryPillowingTest, GridGetsOneHexPerBoundaryQuad) {
    HexMesh m = grid(2);
    const HexMesh before = m;
    const auto old_boundary = boundaryQuadSet(m);
    ASSERT_EQ(old_boundary.size(), 24u);
    const PillowReport r = pillowBoundary(m);
    ASSERT_TRUE(r.success) << r.message;
    EXPECT_EQ(r.hexes_added, 24);
    EXPECT_EQ(r.vertices_added, 26);
    EXPECT_EQ(r.skipped_patches, 0);
    EXPECT_EQ(r.boundary_patches, 6);
    ASSERT_EQ(m.hexes.size(), 8u + 24u);
    ASSERT_EQ(m.vertices.size(), 27u + 26u);
    // Every old vertex keeps its position bit for bit (the 26 boundary ones and the centre).
    for (std::size_t v = 0; v < 27; ++v)
        for (int d = 0; d < 3; ++d) EXPECT_EQ(m.vertices[v][d], before.vertices[v][d]) << "vertex " << v;
    EXPECT_EQ(HexExTest::notCertifiedValid(m), 0);
    EXPECT_EQ(r.invalid_after, 0);
    // The boundary is the old one, and each boundary quad is the outer quad of a new hex.
    const auto new_boundary = boundaryQuadSet(m);
    EXPECT_EQ(new_boundary, old_boundary);
    std::set<std::array<int, 4>> outer;
    for (std::size_t c = 8; c < m.hexes.size(); ++c) {
        std::array<int, 4> q{{m.hexes[c][4], m.hexes[c][5], m.hexes[c][6], m.hexes[c][7]}};
        std::sort(q.begin(), q.end());
        outer.insert(q);
    }
    EXPECT_EQ(outer, new_boundary);
    // The old hexes use no boundary vertex any more.
    for (std::size_t c = 0; c < 8; ++c)
        for (const int v : m.hexes[c]) EXPECT_TRUE(v == 13 || v >= 27) << "hex " << c << " vertex " << v;
}

TEST(BoundaryPillowingTest, FlatCornerIsLiftedByPillowAndOptimisation) {
    const HexMesh input = flatCornerHex();
    const double bound = std::sin(170.0 * M_PI / 180.0);
    EXPECT_LE(minSJ(input), bound + 1e-12);
    // Without pillowing the optimiser cannot pass the bound (its boundary faces stay).
    {
        HexMesh m = input;
        OptimizeOptions o;
        o.threads = 1;
        optimizeHexMesh(m, o);
        EXPECT_LE(minSJ(m), bound + 1e-9);
    }
    HexMesh m = input;
    OptimizeOptions o;
    o.threads = 1;
    o.pillow = true;
    const OptimizeReport r = optimizeHexMesh(m, o);
    ASSERT_TRUE(r.success) << r.message;
    EXPECT_GT(r.pillowed_hexes, 0);
    EXPECT_EQ(static_cast<long>(m.hexes.size()), 1 + r.pillowed_hexes);
    EXPECT_EQ(r.hexes, static_cast<long>(m.hexes.size()));
    EXPECT_GE(r.min_scaled_jacobian_after, 0.3);  // 0.354 measured; sin 170 = 0.174
    EXPECT_EQ(r.min_scaled_jacobian_after, minSJ(m));
    EXPECT_EQ(HexExTest::notCertifiedValid(m), 0);
    EXPECT_NEAR(r.min_scaled_jacobian_before, minSJ(input), 1e-15);
    // The feature corners A, C, D (bottom and top) stay; B slides along its rim curve A-B-C.
    for (const std::size_t v : {0u, 2u, 3u, 4u, 6u, 7u})
        EXPECT_LE((m.vertices[v] - input.vertices[v]).norm(), 1e-12) << "vertex " << v;
    for (const std::size_t v : {1u, 5u}) {
        const Vec3d p = m.vertices[v];
        EXPECT_EQ(p[2], input.vertices[v][2]);
        const Vec3d c = input.vertices[2];
        const double off_ab = std::abs(p[1]), off_bc = std::abs(p[0] * c[1] - p[1] * c[0]);
        EXPECT_LE(std::min(off_ab, off_bc), 1e-12) << "vertex " << v;
    }
}

TEST(BoundaryPillowingTest, ThreadCountDoesNotChangeTheResult) {
    HexMesh g = grid(3);
    // A bent grid: the top layer's vertices lifted towards the middle so faces meet flat.
    for (auto& p : g.vertices) p[2] += 0.15 * std::sin(p[0] * 1.1) * p[2];
    HexMesh m1 = g, m2 = g;
    OptimizeOptions o;
    o.pillow = true;
    o.threads = 1;
    const OptimizeReport r1 = optimizeHexMesh(m1, o);
    o.threads = 2;
    const OptimizeReport r2 = optimizeHexMesh(m2, o);
    ASSERT_EQ(m1.vertices.size(), m2.vertices.size());
    ASSERT_EQ(m1.hexes, m2.hexes);
    for (std::size_t v = 0; v < m1.vertices.size(); ++v)
        for (int d = 0; d < 3; ++d) ASSERT_EQ(m1.vertices[v][d], m2.vertices[v][d]) << "vertex " << v;
    EXPECT_EQ(r1.pillowed_hexes, r2.pillowed_hexes);
    EXPECT_EQ(r1.min_scaled_jacobian_after, r2.min_scaled_jacobian_after);
}

TEST(BoundaryPillowingTest, BadInputGivesClearErrors) {
    auto message = [](HexMesh m) {
        try {
            pillowBoundary(m);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    HexMesh poly = grid(1);
    poly.polyhedra.push_back(Polyhedron{{{0, 1, 2}}});
    EXPECT_EQ(message(poly), "pillowing needs an all-hex mesh: the mesh has 1 polyhedra");
    EXPECT_EQ(message(HexMesh{}), "pillowing: the mesh has no hexes");
    // Two cubes sharing one edge: the edge is in four boundary quads.
    HexMesh edge = grid(1);
    const HexMesh b = grid(1);
    // Second cube at x in [1, 2], y in [1, 2]: shares the edge x = 1, y = 1.
    std::array<int, 8> map;
    for (std::size_t v = 0; v < 8; ++v) {
        const Vec3d p = b.vertices[v] + Vec3d(1, 1, 0);
        int found = -1;
        for (std::size_t w = 0; w < edge.vertices.size(); ++w)
            if ((edge.vertices[w] - p).norm() == 0) found = static_cast<int>(w);
        if (found < 0) {
            found = static_cast<int>(edge.vertices.size());
            edge.vertices.push_back(p);
        }
        map[v] = found;
    }
    std::array<int, 8> h2;
    for (std::size_t k = 0; k < 8; ++k) h2[k] = map[static_cast<std::size_t>(b.hexes[0][k])];
    edge.hexes.push_back(h2);
    EXPECT_NE(message(edge).find("non-manifold boundary: the edge ("), std::string::npos) << message(edge);
    EXPECT_NE(message(edge).find(") is in 4 boundary quads (expected 2)"), std::string::npos) << message(edge);
    // Two cubes sharing one vertex: two sheets of the boundary meet there.
    HexMesh vert = grid(1);
    const int n0 = static_cast<int>(vert.vertices.size());
    for (std::size_t v = 1; v < 8; ++v) vert.vertices.push_back(b.vertices[v] + Vec3d(1, 1, 1));
    std::array<int, 8> h3;
    for (std::size_t k = 0; k < 8; ++k) {
        const int v = b.hexes[0][k];
        h3[k] = v == 0 ? 7 : n0 + v - 1;  // corner 0 of the second cube is corner 7 (1, 1, 1) of the first
    }
    vert.hexes.push_back(h3);
    EXPECT_EQ(message(vert), "pillowing: non-manifold boundary: 2 separate sheets of the boundary meet at vertex 7");
    HexMesh rep = grid(1);
    rep.hexes[0][3] = rep.hexes[0][0];
    EXPECT_EQ(message(rep), "pillowing: hex 0 has the vertex 0 twice");
}

TEST(BoundaryPillowingTest, FlatFeatureCornerGetsAStripAndOptionallyASecondLayer) {
    // The hex of FlatCornerIsLifted...: its top and bottom quads have the 170-degree corner
    // between two feature edges, so those two patches get no layer but a strip: 4 side quads
    // -> 4 new hexes, 8 copies (all 8 vertices are rim vertices).
    HexMesh m = flatCornerHex();
    const PillowReport r = pillowBoundary(m);
    ASSERT_TRUE(r.success) << r.message;
    EXPECT_EQ(r.boundary_patches, 5);  // top, bottom, the sides AB+BC (170 degrees apart), CD, DA
    EXPECT_EQ(r.skipped_patches, 2);
    EXPECT_EQ(r.hexes_added, 4);
    EXPECT_EQ(r.vertices_added, 8);
    EXPECT_EQ(HexExTest::notCertifiedValid(m), 0);
    // With the second pass the two disks (each now the old quad plus its strip of 4) get a
    // layer of 5 hexes each.
    HexMesh m2 = flatCornerHex();
    PillowOptions o;
    o.second_layer = true;
    const PillowReport r2 = pillowBoundary(m2, o);
    ASSERT_TRUE(r2.success) << r2.message;
    EXPECT_EQ(r2.second_layer_hexes, 10);
    EXPECT_EQ(r2.hexes_added, 14);
    EXPECT_EQ(static_cast<long>(m2.hexes.size()), 15);
    EXPECT_EQ(HexExTest::notCertifiedValid(m2), 0);
}

TEST(BoundaryPillowingTest, CommandLineOptimizePillow) {
    const std::string tool = HexExTest::hexexBinary();
    if (tool.empty()) GTEST_SKIP() << "hexex tool not found next to the test binary";
    const auto dir = std::filesystem::temp_directory_path() / "hexex_pillow_cli";
    std::filesystem::create_directories(dir);
    const std::string in = (dir / "in.vtu").string(), out = (dir / "out.vtu").string(), js = (dir / "r.json").string();
    const std::string err = (dir / "err.txt").string();
    writeHexMesh(in, grid(2));
    auto run = [&](const std::string& args) {
        const int st = std::system((tool + " " + args + " > " + js + " 2> " + err).c_str());
        return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    };
    auto slurp = [](const std::string& p) {
        std::ifstream f(p);
        return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    };
    ASSERT_EQ(run("optimize " + in + " -o " + out + " --pillow --json --threads 2"), 0) << slurp(err);
    const std::string json = slurp(js);
    EXPECT_NE(json.find("\"pillowed_hexes\": 24"), std::string::npos) << json;
    EXPECT_NE(json.find("\"pillow_vertices\": 26"), std::string::npos) << json;
    EXPECT_NE(json.find("\"hexes\": 32"), std::string::npos) << json;
    EXPECT_NE(slurp(err).find("optimize: pillowed: 24 hexes and 26 vertices added along the boundary"), std::string::npos)
        << slurp(err);
    const HexMesh result = readHexMesh(out);
    EXPECT_EQ(result.hexes.size(), 32u);
    EXPECT_EQ(result.vertices.size(), 53u);
    // Two cubes sharing an edge: a clear error, exit status 2.
    HexMesh two = grid(1);
    for (std::size_t v = 0; v < 8; ++v) two.vertices.push_back(two.vertices[v] + Vec3d(1, 1, 0));
    two.hexes.push_back({{8, 9, 10, 11, 12, 13, 14, 15}});
    // Glue: the second cube's corners (0,0,z) are the first cube's (1,1,z).
    for (auto& v : two.hexes[1]) {
        if (v == 8) v = 2;
        if (v == 12) v = 6;
    }
    two.vertices.resize(16);
    writeHexMesh(in, two);
    EXPECT_EQ(run("optimize " + in + " -o " + out + " --pillow"), 2);
    EXPECT_NE(slurp(err).find(") is in 4 boundary quads (expected 2)"), std::string::npos) << slurp(err);
    std::filesystem::remove_all(dir);
}
