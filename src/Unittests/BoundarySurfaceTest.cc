/// @file BoundarySurfaceTest.cc
/// Tests of boundarySurface() / writeBoundarySurface() and of `hexex extract --surface`.

// OpenMesh's PropertyT<VectorT>::push_back() default-constructs an uninitialized vector,
// which GCC reports as -Wmaybe-uninitialized inside the standard library once inlined.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include <HexEx/Core/Error.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/Mesh/BoundarySurface.hh>

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

/// Extracts the hex mesh of generateCube(n, s).
HexEx::HexMesh extractCube(int n, int s) {
    HexEx::ParametrizedTetMesh pm = HexEx::generateCube(n, s);
    pm.mesh.build_adjacency();
    HexEx::HexMesh hm;
    const auto rep = HexEx::extractHexMesh(pm, hm);
    EXPECT_EQ(rep.output.hexes, static_cast<decltype(rep.output.hexes)>(s * s * s));
    return hm;
}

/// A fresh temporary directory, removed by the destructor.
class TempDir {
public:
    TempDir() {
        const char* base = std::getenv("TMPDIR");
        std::string templ = std::string(base && *base ? base : "/tmp") + "/hexex-surface-XXXXXX";
        std::vector<char> buf(templ.begin(), templ.end());
        buf.push_back('\0');
        if (!::mkdtemp(buf.data())) throw std::runtime_error("mkdtemp failed");
        dir_ = buf.data();
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    std::string path(const std::string& name) const { return (dir_ / name).string(); }

private:
    fs::path dir_;
};

/// Number of distinct edges of @p m and whether every edge has two faces.
bool closedManifold(const HexEx::SurfaceMesh& m) {
    for (const auto e : m.edges())
        if (m.is_boundary(e)) return false;
    for (const auto v : m.vertices())
        if (!m.is_manifold(v)) return false;
    return true;
}

} // namespace

TEST(BoundarySurfaceTest, CubeHasOuterQuadsOnly) {
    const HexEx::HexMesh hm = extractCube(2, 3);
    ASSERT_EQ(hm.hexes.size(), 27u);
    HexEx::BoundarySurfaceReport rep;
    const HexEx::SurfaceMesh s = HexEx::boundarySurface(hm, &rep);
    EXPECT_EQ(s.n_faces(), 54u);
    EXPECT_EQ(rep.boundary_faces, 54u);
    EXPECT_EQ(rep.boundary_quads, 54u);
    EXPECT_EQ(rep.split_faces, 0u);
    EXPECT_EQ(rep.skipped_faces, 0u);
    EXPECT_EQ(s.n_vertices(), 56u);  // 4^3 - 2^3 interior vertices
    EXPECT_EQ(s.n_edges(), 108u);
    for (const auto f : s.faces()) EXPECT_EQ(s.valence(f), 4u);
    const long euler = static_cast<long>(s.n_vertices()) - static_cast<long>(s.n_edges()) + static_cast<long>(s.n_faces());
    EXPECT_EQ(euler, 2);
    EXPECT_TRUE(closedManifold(s));

    // Every vertex lies on the boundary of the unit cube; every face normal points outward.
    for (const auto v : s.vertices()) {
        const auto p = s.point(v);
        bool onSide = false;
        for (int k = 0; k < 3; ++k) onSide = onSide || p[k] == 0.0 || p[k] == 1.0;
        EXPECT_TRUE(onSide) << p;
    }
    for (const auto f : s.faces()) {
        HexEx::Vec3d c(0, 0, 0);
        std::vector<HexEx::Vec3d> pts;
        for (const auto v : s.fv_range(f)) pts.push_back(s.point(v));
        for (const auto& p : pts) c += p / static_cast<double>(pts.size());
        const HexEx::Vec3d n = (pts[1] - pts[0]) % (pts[2] - pts[1]);
        EXPECT_GT(n | (c - HexEx::Vec3d(0.5, 0.5, 0.5)), 0.0) << "face " << f.idx() << " points inward";
    }
}

TEST(BoundarySurfaceTest, SingleHexAndCompaction) {
    HexEx::HexMesh hm;
    hm.vertices.push_back(HexEx::Vec3d(9, 9, 9));  // unused: must not appear
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x) hm.vertices.push_back(HexEx::Vec3d(x, y, z));
    auto id = [](int x, int y, int z) { return 1 + x + 2 * y + 4 * z; };
    hm.hexes.push_back({id(0, 0, 0), id(1, 0, 0), id(1, 1, 0), id(0, 1, 0), id(0, 0, 1), id(1, 0, 1), id(1, 1, 1),
                        id(0, 1, 1)});
    const HexEx::SurfaceMesh s = HexEx::boundarySurface(hm);
    EXPECT_EQ(s.n_vertices(), 8u);
    EXPECT_EQ(s.n_faces(), 6u);
    EXPECT_TRUE(closedManifold(s));
    EXPECT_EQ(s.point(HexEx::SurfaceMesh::VertexHandle(0)), HexEx::Vec3d(0, 0, 0));  // compacted, ascending
}

namespace {

/// The unit cube as one hex (vertices 0..7, VTK order) plus a square pyramid (apex 8) on
/// its top face, given as a polyhedron with outward faces.
HexEx::HexMesh hexWithPyramid() {
    HexEx::HexMesh hm;
    hm.vertices = {HexEx::Vec3d(0, 0, 0), HexEx::Vec3d(1, 0, 0), HexEx::Vec3d(1, 1, 0), HexEx::Vec3d(0, 1, 0),
                   HexEx::Vec3d(0, 0, 1), HexEx::Vec3d(1, 0, 1), HexEx::Vec3d(1, 1, 1), HexEx::Vec3d(0, 1, 1),
                   HexEx::Vec3d(0.5, 0.5, 2)};
    hm.hexes.push_back({0, 1, 2, 3, 4, 5, 6, 7});
    HexEx::Polyhedron pyr;
    pyr.faces = {{4, 7, 6, 5}, {4, 5, 8}, {5, 6, 8}, {6, 7, 8}, {7, 4, 8}};
    hm.polyhedra.push_back(pyr);
    return hm;
}

} // namespace

TEST(BoundarySurfaceTest, PolyhedronFacesJoinTheSurface) {
    HexEx::BoundarySurfaceReport rep;
    const HexEx::SurfaceMesh s = HexEx::boundarySurface(hexWithPyramid(), &rep);
    EXPECT_EQ(rep.boundary_faces, 9u);  // 5 hex quads + 4 pyramid triangles; the shared quad is interior
    EXPECT_EQ(rep.boundary_quads, 5u);
    EXPECT_EQ(s.n_faces(), 9u);
    EXPECT_EQ(s.n_vertices(), 9u);
    EXPECT_TRUE(closedManifold(s));
    EXPECT_EQ(static_cast<long>(s.n_vertices()) - static_cast<long>(s.n_edges()) + static_cast<long>(s.n_faces()), 2);
}

TEST(BoundarySurfaceTest, NonManifoldBoundaryIsSplitNotLost) {
    // Two unit hexes touching along one edge only: that edge has four boundary quads.
    HexEx::HexMesh hm;
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 3; ++x) hm.vertices.push_back(HexEx::Vec3d(x, y, z));
    auto id = [](int x, int y, int z) { return x + 3 * y + 9 * z; };
    auto hex = [&](int x, int y) {
        return std::array<int, 8>{id(x, y, 0),     id(x + 1, y, 0),     id(x + 1, y + 1, 0), id(x, y + 1, 0),
                                  id(x, y, 1),     id(x + 1, y, 1),     id(x + 1, y + 1, 1), id(x, y + 1, 1)};
    };
    hm.hexes = {hex(0, 0), hex(1, 1)};
    HexEx::BoundarySurfaceReport rep;
    const HexEx::SurfaceMesh s = HexEx::boundarySurface(hm, &rep);
    EXPECT_EQ(rep.boundary_faces, 12u);
    EXPECT_EQ(s.n_faces(), 12u);  // nothing dropped
    EXPECT_GT(rep.split_faces, 0u);
    EXPECT_GT(s.n_vertices(), 14u);  // duplicated vertices for the split faces
}

TEST(BoundarySurfaceTest, DegenerateAndOutOfRange) {
    HexEx::HexMesh hm = hexWithPyramid();
    hm.polyhedra.push_back(HexEx::Polyhedron{{{0, 1}}});  // a two-vertex "face"
    HexEx::BoundarySurfaceReport rep;
    const HexEx::SurfaceMesh s = HexEx::boundarySurface(hm, &rep);
    EXPECT_EQ(rep.skipped_faces, 1u);
    EXPECT_EQ(s.n_faces(), 9u);

    HexEx::HexMesh bad = hexWithPyramid();
    bad.hexes[0][3] = 42;
    EXPECT_THROW(HexEx::boundarySurface(bad), std::invalid_argument);
    EXPECT_TRUE(HexEx::boundarySurface(HexEx::HexMesh()).n_faces() == 0);
}

TEST(BoundarySurfaceTest, WritersRoundTripThroughOpenMesh) {
    const HexEx::HexMesh hm = extractCube(2, 3);
    TempDir dir;
    for (const std::string ext : {"obj", "off", "ply", "stl", "OBJ"}) {
        const std::string path = dir.path("boundary." + ext);
        std::vector<std::string> warnings;
        ASSERT_NO_THROW(warnings = HexEx::writeBoundarySurface(path, hm)) << path;
        EXPECT_TRUE(warnings.empty());
        HexEx::SurfaceMesh back;
        ASSERT_TRUE(OpenMesh::IO::read_mesh(back, path)) << path;
        EXPECT_EQ(back.n_vertices(), 56u) << path;
        const bool stl = ext == "stl";
        EXPECT_EQ(back.n_faces(), stl ? 108u : 54u) << path;
        EXPECT_EQ(back.n_edges(), stl ? 162u : 108u) << path;
        for (const auto f : back.faces()) EXPECT_EQ(back.valence(f), stl ? 3u : 4u) << path;
        EXPECT_TRUE(closedManifold(back)) << path;
    }
    // Positions survive in single precision (OpenMesh's writers store floats).
    HexEx::SurfaceMesh orig = HexEx::boundarySurface(hm), back;
    ASSERT_TRUE(OpenMesh::IO::read_mesh(back, dir.path("boundary.off")));
    ASSERT_EQ(back.n_vertices(), orig.n_vertices());
    for (const auto v : orig.vertices()) {
        EXPECT_LT((back.point(v) - orig.point(v)).norm(), 1e-6);
    }
}

TEST(BoundarySurfaceTest, WriterErrors) {
    const HexEx::HexMesh hm = extractCube(1, 1);
    TempDir dir;
    try {
        HexEx::writeBoundarySurface(dir.path("b.xyz"), hm);
        FAIL() << "no exception for an unknown extension";
    } catch (const HexEx::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("b.xyz: unknown surface mesh format '.xyz'"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(HexEx::writeBoundarySurface(dir.path("noext"), hm), HexEx::InputError);
    try {
        HexEx::writeBoundarySurface(dir.path("missing/b.obj"), hm);
        FAIL() << "no exception for an unwritable path";
    } catch (const HexEx::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("missing/b.obj: cannot open for writing"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(HexEx::writeBoundarySurface(dir.path(""), hm), HexEx::InputError);
    EXPECT_TRUE(HexEx::isSurfaceMeshPath("a/b.Ply"));
    EXPECT_FALSE(HexEx::isSurfaceMeshPath("a.obj/b"));
    EXPECT_FALSE(HexEx::isSurfaceMeshPath(".obj"));
}

namespace {

/// Path of the hexex binary of this build tree (next to this test binary), or empty.
std::string hexexTool() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    const fs::path tool = self.parent_path().parent_path() / "Tools" / "hexex" / "hexex";
    return fs::is_regular_file(tool, ec) && ::access(tool.c_str(), X_OK) == 0 ? tool.string() : std::string();
}

/// Runs the tool with @p args (stdout/stderr discarded); returns the exit status.
int runTool(const std::string& tool, const std::vector<std::string>& args) {
    std::string cmd = "'" + tool + "'";
    for (const auto& a : args) cmd += " '" + a + "'";
    cmd += " </dev/null >/dev/null 2>&1";
    const int raw = std::system(cmd.c_str());
    return raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

} // namespace

TEST(BoundarySurfaceTest, CliExtractSurface) {
    const std::string tool = hexexTool();
    if (tool.empty()) GTEST_SKIP() << "hexex binary not found next to the test binary";
    TempDir dir;
    ASSERT_EQ(runTool(tool, {"generate", "cube", "--n", "2", "--scale", "3", "-o", dir.path("c.hexex")}), 0);
    ASSERT_EQ(runTool(tool, {"extract", dir.path("c.hexex"), "-o", dir.path("c.vtu"), "-q", "--surface",
                             dir.path("c.ply")}),
              0);
    HexEx::SurfaceMesh back;
    ASSERT_TRUE(OpenMesh::IO::read_mesh(back, dir.path("c.ply")));
    EXPECT_EQ(back.n_faces(), 54u);
    EXPECT_EQ(back.n_vertices(), 56u);
    EXPECT_EQ(runTool(tool, {"extract", dir.path("c.hexex"), "-o", dir.path("c.vtu"), "--surface", dir.path("c.xyz")}),
              2);
    EXPECT_EQ(runTool(tool, {"extract", dir.path("c.hexex"), "-o", dir.path("c.vtu"), "--surface",
                             dir.path("nodir/c.obj")}),
              2);
}
