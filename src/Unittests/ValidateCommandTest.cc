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
                            "\"valid_all_hex\": true"})
        EXPECT_NE(r.out.find(key), std::string::npos) << key << " not in\n" << r.out;
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
