/// @file QuadCliTest.cc
/// End-to-end tests of the 2D commands of the `hexex` tool: `hexex quad` on an OBJ with
/// `vt` written by OpenMesh itself, the 2D shapes of `hexex generate`, `hexex perturb` on
/// 2D maps (the "done when": a perturbed valence-5 cone disk keeps its exact
/// counts), exit statuses and error messages.

// OpenMesh's PropertyT<VectorT>::push_back() default-constructs an uninitialized vector,
// which GCC reports as -Wmaybe-uninitialized inside the standard library once inlined.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include <HexEx/Quad/QuadGenerators.hh>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <gtest/gtest.h>

#include "ToolPath.hh"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

/// Result of one run of the tool.
struct ToolRun {
    int status = -1;  ///< exit status, -1 if it did not exit normally
    std::string out;  ///< standard output
    std::string err;  ///< standard error
};

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// The integer after "key": in @p json, or -1.
long jsonInt(const std::string& json, const std::string& key) {
    std::smatch m;
    if (!std::regex_search(json, m, std::regex("\"" + key + "\": (-?[0-9]+)"))) return -1;
    return std::stol(m[1]);
}

class QuadCli : public ::testing::Test {
protected:
    void SetUp() override {
        bin_ = HexExTest::hexexBinary();
        if (bin_.empty()) GTEST_SKIP() << "hexex binary not found next to the test binary";
        const char* base = std::getenv("TMPDIR");
        std::string templ = std::string(base && *base ? base : "/tmp") + "/hexex-quad-XXXXXX";
        std::vector<char> buf(templ.begin(), templ.end());
        buf.push_back('\0');
        ASSERT_NE(::mkdtemp(buf.data()), nullptr);
        dir_ = buf.data();
    }
    void TearDown() override {
        std::error_code ec;
        if (!dir_.empty()) fs::remove_all(dir_, ec);
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    ToolRun run(const std::vector<std::string>& args) {
        std::string cmd = "'" + bin_ + "'";
        for (const auto& a : args) cmd += " '" + a + "'";
        cmd += " </dev/null >'" + path("stdout.txt") + "' 2>'" + path("stderr.txt") + "'";
        ToolRun r;
        const int raw = std::system(cmd.c_str());
        if (raw != -1 && WIFEXITED(raw)) r.status = WEXITSTATUS(raw);
        r.out = slurp(path("stdout.txt"));
        r.err = slurp(path("stderr.txt"));
        return r;
    }
    std::string bin_;
    fs::path dir_;
};

} // namespace

TEST_F(QuadCli, ObjWrittenByOpenMeshRoundTrips) {
    // A cone disk of valence 3 in random charts, written by OpenMesh's own OBJ writer with
    // per-corner (halfedge) texture coordinates.
    HexEx::ParametrizedTriMesh m = HexEx::generateConeDisk(3, 3, 5);
    HexEx::applyRandomTriCharts(m, 11);
    using Tri = OpenMesh::TriMesh_ArrayKernelT<>;
    Tri om;
    om.request_halfedge_texcoords2D();
    for (const auto& p : m.points) om.add_vertex(Tri::Point(float(p[0]), float(p[1]), float(p[2])));
    for (std::size_t f = 0; f < m.triangles.size(); ++f) {
        const auto& t = m.triangles[f];
        const auto fh = om.add_face(Tri::VertexHandle(t[0]), Tri::VertexHandle(t[1]), Tri::VertexHandle(t[2]));
        for (auto h : om.fh_range(fh)) {
            const int v = om.to_vertex_handle(h).idx();
            const int k = v == t[0] ? 0 : v == t[1] ? 1 : 2;
            om.set_texcoord2D(h, Tri::TexCoord2D(float(m.params[f][k][0]), float(m.params[f][k][1])));
        }
    }
    ASSERT_TRUE(OpenMesh::IO::write_mesh(om, path("in.obj"), OpenMesh::IO::Options::FaceTexCoord));
    ASSERT_NE(slurp(path("in.obj")).find("\nvt "), std::string::npos);

    const ToolRun r = run({"quad", path("in.obj"), "-o", path("out.off"), "--report", path("r.json"), "--threads", "2"});
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string json = slurp(path("r.json"));
    EXPECT_EQ(jsonInt(json, "quads"), 27);
    EXPECT_NE(json.find("\"output\": {\"vertices\": 37, \"quads\": 27"), std::string::npos) << json;
    EXPECT_EQ(jsonInt(json, "cones"), 1);
    EXPECT_NE(json.find("\"valid_all_quad\": true"), std::string::npos);
    for (const char* key : {"\"triangles\"", "\"flipped_triangles\"", "\"degenerate_triangles\"", "\"parametric_area\"",
                            "\"non_quad_faces\"", "\"boundary_edges\"", "\"unconnected_darts\"", "\"extracted\"",
                            "\"anti\"", "\"annihilated_pairs\"", "\"timings_s\"", "\"threads\"", "\"version\"", "\"validation\""})
        EXPECT_NE(json.find(key), std::string::npos) << key;

    OpenMesh::PolyMesh_ArrayKernelT<> out;
    ASSERT_TRUE(OpenMesh::IO::read_mesh(out, path("out.off")));
    EXPECT_EQ(out.n_faces(), 27u);
    EXPECT_EQ(out.n_vertices(), 37u);
    for (auto f : out.faces()) EXPECT_EQ(out.valence(f), 4u);
}

TEST_F(QuadCli, PerturbedValence5DiskKeepsExactCounts) {
    ASSERT_EQ(run({"generate", "cone-disk", "--valence", "5", "--radius", "4", "--n", "8", "-o", path("d.obj")}).status, 0);
    const ToolRun p = run({"perturb", path("d.obj"), "-a", "0.5", "--seed", "7", "-o", path("p.obj")});
    ASSERT_EQ(p.status, 0) << p.err;
    EXPECT_NE(p.out.find("6 fixed"), std::string::npos) << p.out;  // the cone and the 5 outer corners
    const ToolRun r = run({"quad", path("p.obj"), "-o", path("q.vtu"), "--report", "-"});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(jsonInt(r.out, "quads"), 80);
    EXPECT_EQ(jsonInt(r.out, "vertices"), 361);  // the input's
    EXPECT_NE(r.out.find("\"output\": {\"vertices\": 101, \"quads\": 80"), std::string::npos) << r.out;
    EXPECT_GT(jsonInt(r.out, "flipped_triangles"), 20);
    EXPECT_GT(jsonInt(r.out, "annihilated_pairs"), 0);
    const std::string vtu = slurp(path("q.vtu"));
    EXPECT_NE(vtu.find("NumberOfPoints=\"101\" NumberOfCells=\"80\""), std::string::npos);
}

TEST_F(QuadCli, GeneratedShapesExtractWithExactCounts) {
    struct Case { std::vector<std::string> args; std::string quads, vertices; };
    const std::vector<Case> cases = {
        {{"square", "--n", "5", "--scale", "3"}, "9", "16"},
        {{"cone-disk", "--valence", "6", "--radius", "2", "--n", "3"}, "24", "37"},
        {{"torus", "--length", "5", "--width", "3", "--nu", "6", "--nv", "4"}, "15", "15"},
        {{"quarter-seam", "--width", "3", "--n", "4", "--chart-noise", "5", "--fp-noise", "1e-11"}, "9", "16"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> gen = {"generate"};
        gen.insert(gen.end(), c.args.begin(), c.args.end());
        gen.insert(gen.end(), {"-o", path("g.obj")});
        ASSERT_EQ(run(gen).status, 0) << c.args[0];
        const ToolRun r = run({"quad", path("g.obj"), "-o", path("g.ply"), "-q"});
        EXPECT_EQ(r.status, 0) << c.args[0] << ": " << r.err;
        OpenMesh::PolyMesh_ArrayKernelT<> out;
        ASSERT_TRUE(OpenMesh::IO::read_mesh(out, path("g.ply")));
        EXPECT_EQ(std::to_string(out.n_faces()), c.quads) << c.args[0];
        EXPECT_EQ(std::to_string(out.n_vertices()), c.vertices) << c.args[0];
    }
}

TEST_F(QuadCli, ErrorsAndExitStatuses) {
    ToolRun r = run({"quad", path("missing.obj"), "-o", path("x.obj")});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("missing.obj: cannot open file"), std::string::npos) << r.err;

    std::ofstream(path("novt.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    r = run({"quad", path("novt.obj"), "-o", path("x.obj")});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("no per-corner texture coordinates"), std::string::npos) << r.err;

    ASSERT_EQ(run({"generate", "square", "--n", "2", "--scale", "2", "-o", path("s.obj")}).status, 0);
    r = run({"quad", path("s.obj"), "-o", path("x.stl")});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("unknown quad mesh format"), std::string::npos) << r.err;
    r = run({"quad", path("s.obj")});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("no output file given"), std::string::npos) << r.err;
    r = run({"generate", "torus", "--nu", "2", "-o", path("t.obj")});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("nu, nv must be >= 3"), std::string::npos) << r.err;

    // A map whose boundary is not on integer lines: written, but not all-quad (exit 3).
    std::ofstream(path("half.obj")) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                       "vt 0 0\nvt 2.5 0\nvt 2.5 2.5\nvt 0 2.5\n"
                                       "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n";
    r = run({"quad", path("half.obj"), "-o", path("half.vtu"), "--report", path("h.json")});
    EXPECT_EQ(r.status, 3) << r.err;
    EXPECT_EQ(jsonInt(slurp(path("h.json")), "quads"), 4);
    EXPECT_NE(slurp(path("h.json")).find("\"valid_all_quad\": false"), std::string::npos);
    EXPECT_TRUE(fs::exists(path("half.vtu")));
}
