/// @file PerturbHexCommandTest.cc
/// `hexex perturb` on hex meshes and `hexex untangle` of the heavy tangle it makes (issue 32):
/// boundary vertices stay bit for bit, most hexes invert, the same seed gives the same
/// file, and untangling ends with every hex certified valid (exit status 0).

#include "ToolPath.hh"

#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/Mesh/HexMeshQuality.hh>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace fs = std::filesystem;
using namespace HexEx;

namespace {

/// Contents of @p p ("" if unreadable).
std::string slurpFile(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// A temporary directory, removed at the end of the test.
class PerturbHexCommand : public ::testing::Test {
protected:
    void SetUp() override {
        bin_ = HexExTest::hexexBinary();
        if (bin_.empty()) GTEST_SKIP() << "hexex binary not found next to the test binary";
        std::string templ = "/tmp/hexex-perturb-XXXXXX";
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
    /// Runs `hexex ARGS`; returns the exit status, stdout into @p out.
    int run(const std::string& args, std::string* out = nullptr) {
        const std::string cmd = "'" + bin_ + "' " + args + " </dev/null >'" + path("out.txt") + "' 2>'" + path("err.txt") + "'";
        const int raw = std::system(cmd.c_str());
        if (out) *out = slurpFile(path("out.txt"));
        return raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    }
    std::string bin_;
    fs::path dir_;
};

} // namespace

TEST_F(PerturbHexCommand, TanglesTheInteriorAndUntangleCertifiesIt) {
    ASSERT_EQ(run("generate cube --n 3 --scale 6 -q -o '" + path("c.hexex") + "'"), 0);
    ASSERT_EQ(run("extract '" + path("c.hexex") + "' -q -o '" + path("c.vtk") + "'"), 0);
    std::string out;
    ASSERT_EQ(run("perturb '" + path("c.vtk") + "' -a 1.5 --seed 4 -o '" + path("t.vtk") + "'", &out), 0)
        << slurpFile(path("err.txt"));
    EXPECT_NE(out.find("125 of 125 interior vertices moved (218 boundary or fixed vertices kept)"), std::string::npos) << out;
    EXPECT_NE(out.find("inverted hexes:  0 -> "), std::string::npos) << out;
    ASSERT_EQ(run("perturb '" + path("c.vtk") + "' -a 1.5 --seed 4 -q -o '" + path("t2.vtk") + "'"), 0);
    EXPECT_EQ(slurpFile(path("t.vtk")), slurpFile(path("t2.vtk")));  // seeded

    const HexMesh c = readHexMesh(path("c.vtk")), t = readHexMesh(path("t.vtk"));
    ASSERT_EQ(c.hexes, t.hexes);
    Vec3d lo = c.vertices[0], hi = c.vertices[0];
    for (const auto& p : c.vertices) {
        lo.minimize(p);
        hi.maximize(p);
    }
    long boundary = 0, moved = 0;
    for (std::size_t v = 0; v < c.vertices.size(); ++v) {
        const Vec3d& p = c.vertices[v];
        bool on = false;
        for (int a = 0; a < 3; ++a) on = on || std::abs(p[a] - lo[a]) < 1e-12 || std::abs(p[a] - hi[a]) < 1e-12;
        if (on) {
            ++boundary;
            EXPECT_TRUE(t.vertices[v] == p) << "boundary vertex " << v << " moved";
        }
        moved += !(t.vertices[v] == p);
    }
    EXPECT_EQ(boundary, 218);
    EXPECT_EQ(moved, 125);
    const QualityStats q = computeQuality(t, 1);
    EXPECT_GT(q.inverted_hexes, 216 * 8 / 10);

    const std::string n = std::to_string(q.invalid_hexes);
    ASSERT_EQ(run("untangle '" + path("t.vtk") + "' --fixed-boundary -o '" + path("u.vtk") + "'", &out), 0)
        << out << slurpFile(path("err.txt"));
    EXPECT_NE(out.find("untangle: invalid hexes " + n + " -> 0 of 216 (certified: J > 0 on the whole hex); undecided 0 -> 0"),
              std::string::npos)
        << out;
    const QualityStats qu = computeQuality(readHexMesh(path("u.vtk")), 1);
    EXPECT_EQ(qu.invalid_hexes, 0);
    EXPECT_EQ(qu.undecided_hexes, 0);
}

TEST_F(PerturbHexCommand, HexMeshErrorsAreClear) {
    std::ofstream(path("empty.vtk")) << "# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 0 double\n"
                                        "CELLS 0 0\nCELL_TYPES 0\n";
    EXPECT_EQ(run("perturb '" + path("empty.vtk") + "' -a 1 -o '" + path("o.vtk") + "'"), 2);
    EXPECT_NE(slurpFile(path("err.txt")).find("no hexahedra to perturb"), std::string::npos) << slurpFile(path("err.txt"));
    EXPECT_EQ(run("perturb '" + path("missing.vtk") + "' -a 1 -o '" + path("o.vtk") + "'"), 2);
    EXPECT_NE(slurpFile(path("err.txt")).find("hexex perturb: error:"), std::string::npos);
}
