/// @file CliEndToEndTest.cc
/// End-to-end tests of the `hexex` tool: runs the built binary (found next to this test
/// binary: <build>/src/Tools/hexex/hexex for <build>/src/Unittests/unittests) on generated
/// inputs and checks exit statuses, messages, reports and output files.

#include <gtest/gtest.h>

#include "TestMeshChecks.hh"
#include "ToolPath.hh"

#include <HexEx/IO/HexExFile.hh>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using HexExTest::hexexBinary;

/// A shell word for @p s (single-quoted).
std::string quote(const std::string& s) {
    std::string out = "'";
    for (const char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Result of one run of the tool.
struct RunResult {
    int status = -1;  ///< exit status (WEXITSTATUS), -1 if it did not exit normally
    std::string out;  ///< standard output
    std::string err;  ///< standard error
};

class CliEndToEndTest : public ::testing::Test {
protected:
    void SetUp() override {
        bin_ = hexexBinary();
        if (bin_.empty()) GTEST_SKIP() << "hexex binary not found next to the test binary";
        const char* base = std::getenv("TMPDIR");
        std::string templ = std::string(base && *base ? base : "/tmp") + "/hexex-cli-XXXXXX";
        std::vector<char> buf(templ.begin(), templ.end());
        buf.push_back('\0');
        ASSERT_NE(::mkdtemp(buf.data()), nullptr);
        dir_ = buf.data();
    }
    void TearDown() override {
        if (!dir_.empty()) {
            std::error_code ec;
            fs::remove_all(dir_, ec);
        }
    }

    /// Path of @p name in the temp dir.
    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    /// Runs `hexex ARGS` with stdout and stderr captured.
    RunResult run(const std::vector<std::string>& args) {
        std::string cmd = quote(bin_);
        for (const auto& a : args) cmd += " " + quote(a);
        const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
        cmd += " </dev/null >" + quote(out.string()) + " 2>" + quote(err.string());
        RunResult r;
        const int raw = std::system(cmd.c_str());
        if (raw != -1 && WIFEXITED(raw)) r.status = WEXITSTATUS(raw);
        r.out = slurp(out);
        r.err = slurp(err);
        return r;
    }

    /// Generates a cube (n boxes per side, scale s) into @p name.
    void generateCube(const std::string& name, int n, int s) {
        const RunResult r = run({"generate", "cube", "--n", std::to_string(n), "--scale", std::to_string(s), "-o",
                                 path(name)});
        ASSERT_EQ(r.status, 0) << r.err;
    }

    std::string bin_;
    fs::path dir_;
};

/// The keys every report must have.
void expectReportKeys(const std::string& json) {
    for (const char* key :
         {"\"input\"", "\"output\"", "\"darts\"", "\"valid_all_hex\"", "\"quality\"", "\"timings_s\"", "\"threads\"",
          "\"version\"", "\"vertices\"", "\"tets\"", "\"boundary_faces\"", "\"flipped_tets\"", "\"degenerate_tets\"",
          "\"singular_edges\"", "\"parametric_volume\"", "\"hexes\"", "\"non_hex_cells\"", "\"quads\"",
          "\"boundary_quads\"", "\"unconnected_darts\"", "\"extracted\"", "\"anti\"", "\"annihilated_pairs\"",
          "\"min_scaled_jacobian\"", "\"mean_scaled_jacobian\"", "\"inverted_hexes\"", "\"read\"", "\"preprocess\"",
          "\"connect\"", "\"postprocess\"", "\"assemble\"", "\"write\"", "\"total\""})
        EXPECT_NE(json.find(key), std::string::npos) << "report lacks " << key << "\n" << json;
    // Numbers are numbers, not strings.
    EXPECT_TRUE(std::regex_search(json, std::regex("\"threads\": [0-9]+")));
    EXPECT_TRUE(std::regex_search(json, std::regex("\"version\": \"[0-9]+\\.[0-9]+\\.[0-9]+\"")));
}

} // namespace

TEST_F(CliEndToEndTest, CubeGenerateExtractReport) {
    generateCube("cube.hexex", 2, 3);
    const RunResult r = run({"extract", path("cube.hexex"), "-o", path("cube.vtu"), "--report", path("r.json")});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("27 hexes"), std::string::npos) << r.out;
    EXPECT_GT(fs::file_size(path("cube.vtu")), 0u);
    const std::string json = slurp(path("r.json"));
    expectReportKeys(json);
    EXPECT_NE(json.find("\"hexes\": 27"), std::string::npos) << json;
    EXPECT_NE(json.find("\"valid_all_hex\": true"), std::string::npos) << json;
    EXPECT_NE(json.find("\"tets\": 48"), std::string::npos) << json;
}

TEST_F(CliEndToEndTest, QuietPrintsNothing) {
    generateCube("cube.hexex", 2, 2);
    const RunResult r = run({"extract", path("cube.hexex"), "-o", path("cube.vtk"), "--quiet"});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "");
}

TEST_F(CliEndToEndTest, CylinderValence3) {
    RunResult r = run({"generate", "cylinder", "--valence", "3", "--radius", "2", "--height", "2", "-o",
                       path("cyl.hexex")});
    ASSERT_EQ(r.status, 0) << r.err;
    r = run({"extract", path("cyl.hexex"), "-o", path("cyl.ovm"), "--report", path("r.json"), "--singularities",
             path("sing.vtk")});
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string json = slurp(path("r.json"));
    expectReportKeys(json);
    EXPECT_NE(json.find("\"hexes\": 24"), std::string::npos) << json;  // 3 * 2 * 2 * 2
    EXPECT_FALSE(std::regex_search(json, std::regex("\"singular_edges\": 0[,\\n]"))) << json;
    EXPECT_NE(slurp(path("sing.vtk")).find("valence"), std::string::npos);
}

TEST_F(CliEndToEndTest, ChartNoiseAndOutputFormats) {
    RunResult r = run({"generate", "twisted-ring", "--chart-noise", "7", "-o", path("t.hexex")});
    ASSERT_EQ(r.status, 0) << r.err;
    for (const char* ext : {".vtu", ".vtk", ".ovm", ".mesh"}) {
        r = run({"extract", path("t.hexex"), "-o", path(std::string("t") + ext), "-q"});
        EXPECT_EQ(r.status, 0) << ext << ": " << r.err;
        EXPECT_GT(fs::file_size(path(std::string("t") + ext)), 0u) << ext;
    }
}

TEST_F(CliEndToEndTest, ThreadCountDoesNotChangeOutput) {
    RunResult r = run({"generate", "cube", "--n", "3", "--scale", "4", "--chart-noise", "3", "-o", path("c.hexex")});
    ASSERT_EQ(r.status, 0) << r.err;
    ASSERT_EQ(run({"extract", path("c.hexex"), "-o", path("a.vtu"), "--threads", "1", "-q"}).status, 0);
    ASSERT_EQ(run({"extract", path("c.hexex"), "-o", path("b.vtu"), "--threads", "4", "-q"}).status, 0);
    EXPECT_EQ(slurp(path("a.vtu")), slurp(path("b.vtu")));
}

TEST_F(CliEndToEndTest, ParamMeshOutput) {
    generateCube("cube.hexex", 1, 2);
    const RunResult r = run({"extract", path("cube.hexex"), "-o", path("c.vtu"), "--param-mesh", path("p.vtk"), "-q"});
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string vtk = slurp(path("p.vtk"));
    EXPECT_NE(vtk.find("POINTS 24 double"), std::string::npos);  // 6 tets x 4 corners
    EXPECT_NE(vtk.find("SCALARS flipped int 1"), std::string::npos);
    EXPECT_NE(vtk.find("SCALARS degenerate int 1"), std::string::npos);
}

TEST_F(CliEndToEndTest, MissingInputFile) {
    const RunResult r = run({"extract", path("does-not-exist.hexex"), "-o", path("x.vtu")});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("does-not-exist.hexex"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("x.vtu")));
}

TEST_F(CliEndToEndTest, TruncatedInputNamesLine) {
    generateCube("cube.hexex", 2, 3);
    const std::string text = slurp(path("cube.hexex"));
    {
        std::ofstream out(path("bad.hexex"), std::ios::binary);
        out << text.substr(0, text.size() / 2);
    }
    const std::regex located("bad\\.hexex:[0-9]+: ");
    RunResult r = run({"extract", path("bad.hexex"), "-o", path("x.vtu")});
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(std::regex_search(r.err, located)) << r.err;
    r = run({"info", path("bad.hexex")});
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(std::regex_search(r.err, located)) << r.err;
    r = run({"perturb", path("bad.hexex"), "-a", "0.1", "-o", path("y.hexex")});
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(std::regex_search(r.err, located)) << r.err;
}

TEST_F(CliEndToEndTest, MalformedNumberNamesLine) {
    {
        std::ofstream out(path("bad.hexex"));
        out << "4\n0 0 0\n1 0 0\n0 1 0\n0 0 x\n1\n0 1 2 3  0 0 0 1 0 0 0 1 0 0 0 1\n";
    }
    const RunResult r = run({"extract", path("bad.hexex"), "-o", path("x.vtu")});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("bad.hexex:5:"), std::string::npos) << r.err;
}

TEST_F(CliEndToEndTest, UsageErrors) {
    generateCube("cube.hexex", 1, 1);
    RunResult r = run({"extract", path("cube.hexex"), "-o", path("x.vtu"), "--bogus"});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--bogus"), std::string::npos) << r.err;

    r = run({"extract", path("cube.hexex")});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("no output file"), std::string::npos) << r.err;

    r = run({"extract", path("cube.hexex"), "-o"});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("needs a value"), std::string::npos) << r.err;

    r = run({"extract", path("cube.hexex"), "-o", path("x.vtu"), "--threads", "many"});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--threads"), std::string::npos) << r.err;

    r = run({"extract", path("cube.hexex"), "-o", path("x.txt")});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("x.txt"), std::string::npos) << r.err;

    r = run({"extract", path("cube.hexex"), "-o", path("x.vtu"), "--surface", path("b.xyz")});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("unknown surface format"), std::string::npos) << r.err;

    r = run({"extract"});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("no input file"), std::string::npos) << r.err;

    r = run({"generate", "sphere", "-o", path("s.hexex")});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("sphere"), std::string::npos) << r.err;

    r = run({"generate", "cylinder", "--valence", "2", "-o", path("s.hexex")});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--valence"), std::string::npos) << r.err;  // the shape's usage

    r = run({"generate", "cube", "--radius", "2", "-o", path("s.hexex")});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--radius"), std::string::npos) << r.err;

    r = run({"perturb", path("cube.hexex"), "-o", path("p.hexex")});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("amplitude"), std::string::npos) << r.err;

    r = run({"perturb", path("cube.hexex"), "-a", "-1", "-o", path("p.hexex")});
    EXPECT_EQ(r.status, 2);

    r = run({"frobnicate"});
    EXPECT_EQ(r.status, 2);
}

TEST_F(CliEndToEndTest, PerturbThenExtract) {
    generateCube("cube.hexex", 3, 3);
    RunResult r = run({"perturb", path("cube.hexex"), "-a", "0.3", "--seed", "5", "-o", path("p.hexex")});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("flipped tets"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("degenerate tets"), std::string::npos) << r.out;
    // Same seed, same file.
    r = run({"perturb", path("cube.hexex"), "-a", "0.3", "--seed", "5", "-o", path("q.hexex"), "-q"});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(path("p.hexex")), slurp(path("q.hexex")));

    r = run({"extract", path("p.hexex"), "-o", path("p.vtu"), "--report", path("r.json")});
    EXPECT_TRUE(r.status == 0 || r.status == 3) << r.status << "\n" << r.err;
    ASSERT_TRUE(fs::exists(path("r.json")));
    const std::string json = slurp(path("r.json"));
    expectReportKeys(json);
    if (r.status == 0) {
        EXPECT_NE(json.find("\"valid_all_hex\": true"), std::string::npos);
    } else {
        EXPECT_NE(json.find("\"valid_all_hex\": false"), std::string::npos);
        EXPECT_NE(r.err.find("not a valid all-hex"), std::string::npos) << r.err;
    }
}

TEST_F(CliEndToEndTest, ReportToStdout) {
    generateCube("cube.hexex", 1, 2);
    const RunResult r = run({"extract", path("cube.hexex"), "-o", path("c.vtu"), "--report", "-"});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out.rfind("{", 0), 0u) << r.out;
    EXPECT_NE(r.out.find("\"hexes\": 8"), std::string::npos) << r.out;
}

TEST_F(CliEndToEndTest, DestroyedMapStillWritesBestMesh) {
    // Independent noise of 0.4 per tet corner destroys the map; the tool must still write
    // a mesh and a report and exit with 3 (or 0), never crash or claim bad input.
    RunResult r = run({"generate", "ring", "--fp-noise", "0.4", "-o", path("r.hexex"), "-q"});
    ASSERT_EQ(r.status, 0) << r.err;
    r = run({"extract", path("r.hexex"), "-o", path("r.vtu"), "--report", path("r.json")});
    EXPECT_TRUE(r.status == 0 || r.status == 3) << r.status << "\n" << r.err;
    EXPECT_TRUE(fs::exists(path("r.vtu")));
    expectReportKeys(slurp(path("r.json")));
}

TEST_F(CliEndToEndTest, EdgeArcsAndFacePatches) {
    generateCube("cube.hexex", 2, 3);  // 27 hexes: 3*3*16 = 144 edges, 3*9*4 = 108 faces
    const RunResult r = run({"extract", path("cube.hexex"), "-o", path("cube.vtu"), "--edge-arcs", path("a.vtu"),
                             "--face-patches", path("p.vtu"), "--report", path("r.json")});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("wrote 144 edge arcs to"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("wrote 108 face patches to"), std::string::npos) << r.err;
    const std::string arcs = slurp(path("a.vtu")), patches = slurp(path("p.vtu"));
    EXPECT_NE(arcs.find("NumberOfCells=\"144\""), std::string::npos);
    EXPECT_NE(arcs.find("Name=\"edge_id\""), std::string::npos);
    EXPECT_NE(patches.find("Name=\"face_id\""), std::string::npos);
    const std::string json = slurp(path("r.json"));
    EXPECT_TRUE(std::regex_search(json, std::regex("\"arcs\": \\{\\s*\"edges\": 144,\\s*\"faces\": 108,\\s*\"failed_edges\": 0,"
                                                   "\\s*\"failed_faces\": 0,")))
        << json;
    // Without the options the report has no arcs object.
    const RunResult plain = run({"extract", path("cube.hexex"), "-o", path("cube.vtu"), "--report", path("r2.json")});
    ASSERT_EQ(plain.status, 0) << plain.err;
    EXPECT_EQ(slurp(path("r2.json")).find("\"arcs\""), std::string::npos);
}

TEST_F(CliEndToEndTest, EdgeArcsNeedVtu) {
    generateCube("cube.hexex", 1, 1);
    const RunResult r = run({"extract", path("cube.hexex"), "-o", path("cube.vtu"), "--edge-arcs", path("a.vtk")});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--edge-arcs: '" + path("a.vtk") + "' must end in .vtu"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("cube.vtu")));
}

TEST_F(CliEndToEndTest, MaxMemoryRefusesANeedleWithExitTwo) {
    const std::string sphere = "Examples/data/sphere.hexex";
    if (!std::ifstream(sphere)) GTEST_SKIP() << sphere << " not present";
    HexEx::ParametrizedTetMesh pm = HexEx::readHexExFile(sphere);
    // The interior vertex 40 moved by 1e6 along v in all its tets: a genuine fold (every
    // tet agrees, so the majority vote cannot repair it) that would cost gigabytes.
    for (std::size_t c = 0; c < pm.params.size(); ++c)
        for (int k = 0; k < 4; ++k)
            if (pm.mesh.cell_vertex(HexEx::CellHandle(static_cast<int>(c)), k).idx() == 40) pm.params[c][k][1] += 1e6;
    HexEx::writeHexExFile(path("needle.hexex"), pm);
    const RunResult r = run({"extract", path("needle.hexex"), "-o", path("out.vtu"), "--max-memory", "300M", "-q"});
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("more than the budget of 300.0 MB"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("largest parametric images in the input: tet "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--max-memory"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("out.vtu")));
}

TEST_F(CliEndToEndTest, ACorruptedNumberIsRepairedWithAWarning) {
    const std::string sphere = "Examples/data/sphere.hexex";
    if (!std::ifstream(sphere)) GTEST_SKIP() << sphere << " not present";
    HexEx::ParametrizedTetMesh pm = HexEx::readHexExFile(sphere);
    pm.params[10][2][1] = 1e6;  // one typo
    HexEx::writeHexExFile(path("typo.hexex"), pm);
    const RunResult r = run({"extract", path("typo.hexex"), "-o", path("out.vtu"), "--report", path("r.json")});
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("216 hexes, 343 vertices, valid all-hex"), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("warning: 1 corner parameter disagreed with the majority of the tets at its vertex and was "
                         "replaced by the majority value (a corrupted number in the input?): tet 10 corner 2 (vertex 27) "
                         "(6 1000000 0) -> (6 6 0)"),
              std::string::npos)
        << r.err;
    const std::string json = slurp(path("r.json"));
    EXPECT_NE(json.find("\"repaired_corners\": 1"), std::string::npos) << json;
    EXPECT_NE(json.find("\"repairs\": ["), std::string::npos) << json;
}

TEST_F(CliEndToEndTest, ANeedleFoldIsSkippedUnlessFullAnnihilationIsAsked) {
    const std::string sphere = "Examples/data/sphere.hexex";
    if (!std::ifstream(sphere)) GTEST_SKIP() << sphere << " not present";
    HexEx::ParametrizedTetMesh pm;
    ASSERT_TRUE(HexExTest::sphereWithNeedle(500, pm));
    HexEx::writeHexExFile(path("needle.hexex"), pm);
    const RunResult cheap = run({"extract", path("needle.hexex"), "-o", path("cheap.ovm"), "--report", path("cheap.json")});
    ASSERT_EQ(cheap.status, 0) << cheap.err;
    EXPECT_NE(cheap.out.find("216 hexes, 343 vertices, valid all-hex"), std::string::npos) << cheap.out;
    const RunResult full = run({"extract", path("needle.hexex"), "-o", path("full.ovm"), "--report", path("full.json"),
                                "--full-annihilation"});
    ASSERT_EQ(full.status, 0) << full.err;
    EXPECT_EQ(slurp(path("cheap.ovm")), slurp(path("full.ovm")));  // the same mesh, byte for byte
    const std::string cj = slurp(path("cheap.json")), fj = slurp(path("full.json"));
    EXPECT_NE(fj.find("\"cancelled_fold_points\": 0"), std::string::npos) << fj;
    EXPECT_EQ(cj.find("\"cancelled_fold_points\": 0"), std::string::npos) << cj;
    EXPECT_NE(cj.find("\"cancelled_fold_points\": "), std::string::npos) << cj;
}

TEST_F(CliEndToEndTest, MaxMemoryRejectsABadSize) {
    generateCube("cube.hexex", 1, 1);
    const RunResult r = run({"extract", path("cube.hexex"), "-o", path("out.vtu"), "--max-memory", "12X"});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--max-memory: memory size '12X': unknown unit"), std::string::npos) << r.err;
    const RunResult ok = run({"extract", path("cube.hexex"), "-o", path("out.vtu"), "--max-memory", "64M", "-q"});
    EXPECT_EQ(ok.status, 0) << ok.err;
}

// `generate from-hex`: an extracted mesh becomes a folded map whose extraction is that mesh
// again; a file with non-hex cells or a bad option is refused with a clear message.
TEST_F(CliEndToEndTest, GenerateFromHexMesh) {
    generateCube("cube.hexex", 2, 3);
    RunResult r = run({"extract", path("cube.hexex"), "-o", path("cube.vtk"), "--quiet"});
    ASSERT_EQ(r.status, 0) << r.err;
    r = run({"generate", "from-hex", path("cube.vtk"), "--perturb", "0.6", "--seed", "4", "-o", path("map.hexex")});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("from-hex, 199 vertices, 648 tets, parametric volume 27"), std::string::npos) << r.out;
    r = run({"extract", path("map.hexex"), "-o", path("again.vtk"), "--report", path("r.json")});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("27 hexes, 64 vertices, valid all-hex"), std::string::npos) << r.out;
    r = run({"generate", "from-hex", path("cube.vtk"), "--scale", "2", "-o", path("map2.hexex"), "--quiet"});
    ASSERT_EQ(r.status, 0) << r.err;
    r = run({"extract", path("map2.hexex"), "-o", path("again2.vtk")});
    EXPECT_NE(r.out.find("216 hexes, 343 vertices, valid all-hex"), std::string::npos) << r.out;
    r = run({"generate", "from-hex", path("cube.vtk"), "--perturb", "2.5", "-o", path("bad.hexex")});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--perturb"), std::string::npos) << r.err;
    r = run({"generate", "from-hex", "-o", path("bad.hexex")});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("no hex mesh file given"), std::string::npos) << r.err;
    {
        std::ofstream tet(path("tet.vtk"));
        tet << "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
               "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n";
    }
    r = run({"generate", "from-hex", path("tet.vtk"), "-o", path("bad.hexex")});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("1 non-hex cells"), std::string::npos) << r.err;
}

TEST_F(CliEndToEndTest, UntangleAFoldedCylinderInExtractAndAlone) {
    // The README's before/after case: a valence-5 cylinder whose map is perturbed by 0.8
    // extracts to 240 hexes of which 24 are inverted; untangling leaves none.
    RunResult r = run({"generate", "cylinder", "--valence", "5", "--radius", "4", "--height", "3", "--n", "4",
                       "--m", "3", "-o", path("c.hexex"), "-q"});
    ASSERT_EQ(r.status, 0) << r.err;
    r = run({"perturb", path("c.hexex"), "-a", "0.8", "--seed", "3", "-o", path("p.hexex"), "-q"});
    ASSERT_EQ(r.status, 0) << r.err;

    r = run({"extract", path("p.hexex"), "-o", path("before.vtu"), "--report", path("plain.json"), "-q"});
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string plain = slurp(path("plain.json"));
    EXPECT_NE(plain.find("\"inverted_hexes\": 24"), std::string::npos) << plain;
    EXPECT_EQ(plain.find("\"untangle\""), std::string::npos) << plain;

    r = run({"extract", path("p.hexex"), "-o", path("after.vtu"), "--untangle", "--report", path("u.json")});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("untangle: inverted hexes 24 -> 0 of 240"), std::string::npos) << r.out;
    const std::string json = slurp(path("u.json"));
    expectReportKeys(json);
    EXPECT_NE(json.find("\"inverted_before\": 24"), std::string::npos) << json;
    EXPECT_NE(json.find("\"inverted_after\": 0"), std::string::npos) << json;
    EXPECT_NE(json.find("\"success\": true"), std::string::npos) << json;
    EXPECT_NE(json.find("\"inverted_hexes\": 0"), std::string::npos) << json;  // quality after untangling
    EXPECT_EQ(json.find("\"optimize\""), std::string::npos) << json;  // untangling sufficed: no pillowing repair
    r = run({"extract", path("p.hexex"), "-o", path("x.vtu"), "--pillow", "--no-pillow"});
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--pillow and --no-pillow exclude each other"), std::string::npos) << r.err;

    // The same from the written mesh with the map's boundary as the surface.
    r = run({"untangle", path("before.vtu"), "--surface-from", path("p.hexex"), "-o", path("alone.vtu")});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("untangle: inverted hexes 24 -> 0 of 240"), std::string::npos) << r.out;
    r = run({"validate", path("alone.vtu"), "--json"});
    EXPECT_EQ(r.status, 0) << r.out << r.err;
}

TEST_F(CliEndToEndTest, UntangleReleasesFeatureVerticesUnlessKept) {
    // The bundled cut-out of S1 x2: 3 inverted hexes on a feature curve of the boundary.
    const std::string fold = std::string(HEXEX_SOURCE_DIR) + "/src/Unittests/data/untangle/s1x2_feature_fold.vtk";
    RunResult r = run({"untangle", fold, "-o", path("fold.vtk"), "--quality-iterations", "0"});
    ASSERT_EQ(r.status, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("untangle: inverted hexes 3 -> 0 of 276"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("vertices on feature curves/corners released onto the surface"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("(+0 for quality)"), std::string::npos) << r.out;
    r = run({"untangle", fold, "-o", path("kept.vtk"), "--keep-features"});
    EXPECT_EQ(r.status, 3) << r.out << r.err;
    EXPECT_NE(r.err.find("3 hexes remain invalid (3 inverted at a corner, 0 undecided); 3 of them have vertices held on feature curves or corners"),
              std::string::npos)
        << r.err;
    r = run({"untangle", fold, "-o", path("x.vtk"), "--quality-iterations", "-1"});
    EXPECT_EQ(r.status, 2) << r.out << r.err;
}

TEST_F(CliEndToEndTest, ProvenanceCsvNamesEveryHexsTetAndCell) {
    generateCube("cube.hexex", 2, 3);  // 48 tets, parameters in [0, 3]^3: 27 hexes
    const RunResult r = run({"extract", path("cube.hexex"), "-o", path("cube.vtu"), "--provenance", path("p.csv")});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("wrote the provenance of 27 hexes to"), std::string::npos) << r.err;
    std::istringstream in(slurp(path("p.csv")));
    std::string line;
    ASSERT_TRUE(std::getline(in, line));
    EXPECT_EQ(line, "hex,tet,i,j,k");
    std::set<std::array<int, 3>> cells;
    int expectedHex = 0;
    while (std::getline(in, line)) {
        int h = -1, t = -1;
        std::array<int, 3> c{};
        char sep[4];
        std::istringstream ls(line);
        ls >> h >> sep[0] >> t >> sep[1] >> c[0] >> sep[2] >> c[1] >> sep[3] >> c[2];
        ASSERT_TRUE(ls && sep[0] == ',' && sep[3] == ',') << line;
        EXPECT_EQ(h, expectedHex++);
        EXPECT_GE(t, 0);
        EXPECT_LT(t, 48);
        for (const int x : c) {
            EXPECT_GE(x, 0) << line;
            EXPECT_LE(x, 2) << line;
        }
        cells.insert(c);
    }
    EXPECT_EQ(expectedHex, 27);
    EXPECT_EQ(cells.size(), 27u);  // every grid cell of the cube once
    const RunResult pillow =
        run({"extract", path("cube.hexex"), "-o", path("c2.vtu"), "--provenance", path("q.csv"), "--pillow"});
    EXPECT_EQ(pillow.status, 2);
    EXPECT_NE(pillow.err.find("--provenance and --pillow exclude each other"), std::string::npos) << pillow.err;
}
