// End-to-end tests of `hexex validate` through the built tool. The tool's path comes from
// ToolPath.hh (next to the test binary, or $HEXEX_TOOL); the validation
// logic itself is tested through checkHexMesh() in HexMeshQualityTest.cc.

#include <HexEx/Generators/Generators.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/IO/HexMeshWriters.hh>

#include <gtest/gtest.h>

#include "ToolPath.hh"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>

using namespace HexEx;

namespace {

struct RunResult {
    int status = -1;
    std::string out;  // stdout and stderr
};

RunResult runTool(const std::string& args) {
    RunResult r;
    const std::string cmd = "'" + HexExTest::hexexBinary() + "' " + args + " 2>&1";
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return r;
    char buf[512];
    while (fgets(buf, sizeof buf, p)) r.out += buf;
    const int st = pclose(p);
    r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    return r;
}

std::string tempPath(const std::string& file) {
    const auto dir = std::filesystem::temp_directory_path() / "hexex_validate_test";
    std::filesystem::create_directories(dir);
    return (dir / file).string();
}

HexMesh cubeMesh() {
    auto pm = generateCube(2, 3);
    pm.mesh.build_adjacency();
    HexMesh hm;
    extractHexMesh(pm, hm);
    return hm;
}

#define REQUIRE_TOOL()                                                                  \
    if (HexExTest::hexexBinary().empty()) \
    GTEST_SKIP() << "hexex binary not found next to the test binary (set HEXEX_TOOL)"

} // namespace

TEST(ValidateCommand, ValidCubeJson) {
    REQUIRE_TOOL();
    const std::string path = tempPath("cube.vtu");
    writeHexMesh(path, cubeMesh());
    const RunResult r = runTool("validate '" + path + "' --json");
    EXPECT_EQ(r.status, 0) << r.out;
    for (const char* key : {"\"cells\": 27", "\"hexes\": 27", "\"non_hex_cells\": 0", "\"vertices\": 64",
                            "\"quads\": 108", "\"boundary_quads\": 54", "\"quads_shared_by_more_than_two\": 0",
                            "\"nonmanifold_boundary_edges\": 0", "\"euler_characteristic\": 1",
                            "\"min_scaled_jacobian\": 1", "\"mean_scaled_jacobian\": 1", "\"inverted_hexes\": 0",
                            "\"invalid_hexes\": 0", "\"certified_valid\": true", "\"valid_all_hex\": true"})
        EXPECT_NE(r.out.find(key), std::string::npos) << key << " not in\n" << r.out;
}

TEST(ValidateCommand, CertifiedFlagsAHexNegativeInsideWithPositiveCorners) {
    REQUIRE_TOOL();
    // Positive Jacobian at all 8 corners, negative at (u, v, w) = (0.25, 1, 0) (HexValidityTest).
    HexMesh m;
    m.vertices = {{0.34903947519629847, -0.040657101802294204, -0.14580526119256942},
                  {1.3158235993425553, -0.22753776138255985, -0.32283547238959748},
                  {0.66302905271037815, 0.96539898402132385, -0.21103170472141899},
                  {0.38309908700906353, 1.3863647837410384, 0.3657617023242497},
                  {-0.26060920847350455, -0.27169702399717743, 0.61007095309834447},
                  {1.21923850574767, -0.22315681136377602, 0.88364110018111863},
                  {0.63601846817499119, 1.4113433695468787, 0.7938652942780513},
                  {-0.3339704468756034, 1.045714042671493, 1.3534283884624589}};
    m.hexes.push_back({0, 1, 2, 3, 4, 5, 6, 7});
    const std::string path = tempPath("twisted.vtu");
    writeHexMesh(path, m);
    RunResult r = runTool("validate '" + path + "' --json");
    EXPECT_EQ(r.status, 0) << r.out;  // topologically a valid all-hex mesh
    for (const char* key : {"\"inverted_hexes\": 0", "\"invalid_hexes\": 1", "\"undecided_hexes\": 0",
                            "\"first_invalid_hex\": 0", "\"certified_valid\": false"})
        EXPECT_NE(r.out.find(key), std::string::npos) << key << " not in\n" << r.out;
    r = runTool("validate '" + path + "' --certified");
    EXPECT_EQ(r.status, 3) << r.out;
    EXPECT_NE(r.out.find("invalid hexes (certified):"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("1 (first: hex 0)"), std::string::npos) << r.out;
    r = runTool("validate '" + std::string(HEXEX_SOURCE_DIR) + "/Examples/data/sphere.hexex' --certified");
    EXPECT_EQ(r.status, 2) << r.out;  // a tet map is not a hex mesh
}

TEST(ValidateCommand, NonHexExitsThree) {
    REQUIRE_TOOL();
    HexMesh m = cubeMesh();
    m.polyhedra.push_back(Polyhedron{{{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}}});
    const std::string path = tempPath("poly.ovm");
    writeHexMesh(path, m);
    const RunResult r = runTool("validate '" + path + "'");
    EXPECT_EQ(r.status, 3) << r.out;
    const std::size_t at = r.out.find("valid all-hex:");
    ASSERT_NE(at, std::string::npos) << r.out;
    EXPECT_NE(r.out.find(" no\n", at), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("non-hex cells:"), std::string::npos) << r.out;
}

TEST(ValidateCommand, BadInputExitsTwoWithFileAndLine) {
    REQUIRE_TOOL();
    const std::string path = tempPath("bad.mesh");
    std::ofstream(path) << "MeshVersionFormatted 2\nDimension 3\nVertices\n1\n0 0 zero 0\n";
    RunResult r = runTool("validate '" + path + "'");
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_NE(r.out.find(path + ":5:"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("'zero'"), std::string::npos) << r.out;
    r = runTool("validate");
    EXPECT_EQ(r.status, 2) << r.out;
    r = runTool("validate a.vtu --bogus");
    EXPECT_EQ(r.status, 2) << r.out;
    r = runTool("validate '" + tempPath("missing.vtk") + "'");
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_NE(r.out.find("missing.vtk"), std::string::npos) << r.out;
    r = runTool("validate x.stl");
    EXPECT_EQ(r.status, 2) << r.out;
}
