// OpenVolumeMesh files: the fixtures written by OpenVolumeMesh 3.4.1 itself
// (bundled copies in src/Unittests/data/ovm; S1 from ../shared/data/ovm), the .ovmb writer (byte-identical to OpenVolumeMesh's own output),
// the hexahedral-kernel layout, and `hexex convert`.

#include "TestMeshChecks.hh"
#include "ToolPath.hh"

#include <HexEx/Core/Error.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/IO/HexExFile.hh>
#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/IO/HexMeshWriters.hh>
#include <HexEx/IO/OvmTetReader.hh>
#include <HexEx/IO/ReaderSupport.hh>
#include <HexEx/Mesh/HexMeshCheck.hh>

#include <gtest/gtest.h>

#include <cstdio>
#include <algorithm>
#include <filesystem>
#include <sstream>
#include <fstream>
#include <memory>
#include <unistd.h>

using namespace HexEx;
using HexExTest::extracted;

namespace {

/// Bundled copies of the small OpenVolumeMesh-written fixtures (see data/ovm/README.md).
const std::string kOvmDir = "src/Unittests/data/ovm/";

std::string fileBytes(const std::string& path) {
    std::ifstream in = detail::openInputFile(path);
    return detail::readWholeStream(in, path);
}

/// Output of a shell command ("" if it could not run).
std::string capture(const std::string& cmd) {
    std::unique_ptr<FILE, int (*)(FILE*)> p(popen(cmd.c_str(), "r"), pclose);
    std::string out;
    if (!p) return out;
    char buf[4096];
    std::size_t n = 0;
    while ((n = std::fread(buf, 1, sizeof buf, p.get())) > 0) out.append(buf, n);
    return out;
}

std::string tempPath(const std::string& file) {
    return ::testing::TempDir() + "ovmfiles_" + std::to_string(::getpid()) + "_" + file;
}

bool sameMesh(const HexMesh& a, const HexMesh& b) {
    if (a.vertices.size() != b.vertices.size() || a.hexes != b.hexes || a.polyhedra.size() != b.polyhedra.size())
        return false;
    for (std::size_t i = 0; i < a.vertices.size(); ++i)
        if (a.vertices[i] != b.vertices[i]) return false;
    for (std::size_t i = 0; i < a.polyhedra.size(); ++i)
        if (a.polyhedra[i].faces != b.polyhedra[i].faces) return false;
    return true;
}

/// Same vertices and cells; hexes compared as vertex sets (an OpenVolumeMesh file does not
/// keep which corner of a hex was first).
bool sameCellsAndVertices(const HexMesh& a, const HexMesh& b) {
    if (checkHexMesh(a).valid_all_hex != checkHexMesh(b).valid_all_hex) return false;
    HexMesh s = a, t = b;
    for (HexMesh* m : {&s, &t})
        for (auto& h : m->hexes) std::sort(h.begin(), h.end());
    return sameMesh(s, t);
}

/// True if @p f is @p g rotated.
bool cyclicEqual(const std::vector<int>& f, const std::vector<int>& g) {
    if (f.size() != g.size()) return false;
    for (std::size_t s = 0; s < f.size(); ++s) {
        bool eq = true;
        for (std::size_t i = 0; i < f.size() && eq; ++i) eq = f[(s + i) % f.size()] == g[i];
        if (eq) return true;
    }
    return false;
}

} // namespace

TEST(OvmFiles, SphereAsciiWithSixDigitsExtractsAllHex) {
    if (!std::filesystem::exists(kOvmDir + "sphere.ovm")) GTEST_SKIP() << "fixture " << kOvmDir << "sphere.ovm absent";
    ReadReport rr;
    const ParametrizedTetMesh pm = readOvmTetMesh(kOvmDir + "sphere.ovm", &rr);
    EXPECT_EQ(pm.mesh.n_vertices(), 41u);
    EXPECT_EQ(pm.mesh.n_cells(), 76u);
    EXPECT_TRUE(rr.warnings.empty()) << rr.warnings[0];
    const HexMesh hm = extracted(pm);
    EXPECT_EQ(hm.hexes.size(), 216u);
    EXPECT_EQ(hm.vertices.size(), 343u);
    EXPECT_TRUE(hm.polyhedra.empty());
    EXPECT_TRUE(checkHexMesh(hm).valid_all_hex);
}

TEST(OvmFiles, SphereBinaryReadsExactlyTheHexexMap) {
    if (!std::filesystem::exists(kOvmDir + "sphere.ovmb")) GTEST_SKIP() << "fixture " << kOvmDir << "sphere.ovmb absent";
    const ParametrizedTetMesh fromOvmb = readOvmTetMesh(kOvmDir + "sphere.ovmb");
    const ParametrizedTetMesh fromHexex = readHexExFile("Examples/data/sphere.hexex");
    ASSERT_EQ(fromOvmb.mesh.n_cells(), 76u);
    for (std::size_t c = 0; c < 76; ++c) {
        const CellHandle ch(static_cast<int>(c));
        EXPECT_EQ(fromOvmb.mesh.cell_vertices(ch), fromHexex.mesh.cell_vertices(ch)) << "tet " << c;
        EXPECT_EQ(fromOvmb.params[c], fromHexex.params[c]) << "tet " << c;
    }
    const HexMesh hm = extracted(fromOvmb);
    EXPECT_EQ(hm.hexes.size(), 216u);
    EXPECT_EQ(hm.vertices.size(), 343u);
    EXPECT_TRUE(checkHexMesh(hm).valid_all_hex);
    EXPECT_TRUE(sameMesh(hm, extracted(fromHexex)));
}

TEST(OvmFiles, TetWriterIsByteIdenticalToOpenVolumeMesh) {
    if (!std::filesystem::exists(kOvmDir + "sphere.ovmb")) GTEST_SKIP() << "fixture " << kOvmDir << "sphere.ovmb absent";
    const OvmModel m = ovmFromTetMesh(readHexExFile("Examples/data/sphere.hexex"));
    EXPECT_EQ(writeOvmBinary(m), fileBytes(kOvmDir + "sphere.ovmb"));
    // The ASCII writer keeps all digits; its map reads back exactly.
    const ParametrizedTetMesh back = readOvmTetBuffer(writeOvmAscii(m), "sphere17.ovm");
    EXPECT_EQ(back.params, readHexExFile("Examples/data/sphere.hexex").params);
}

TEST(OvmFiles, HexKernelFileValidatesAndItsLayoutIsOurs) {
    if (!std::filesystem::exists(kOvmDir + "sphere_hex.ovmb"))
        GTEST_SKIP() << "fixture " << kOvmDir << "sphere_hex.ovmb absent";
    const std::string bytes = fileBytes(kOvmDir + "sphere_hex.ovmb");
    const OvmModel fixture = parseOvm(bytes, "sphere_hex.ovmb");
    EXPECT_EQ(fixture.topology, OvmTopology::Hexahedral);
    const HexMesh hm = readHexMesh(kOvmDir + "sphere_hex.ovmb");
    ASSERT_EQ(hm.hexes.size(), 216u);
    EXPECT_EQ(hm.vertices.size(), 343u);
    EXPECT_TRUE(hm.polyhedra.empty());
    EXPECT_TRUE(checkHexMesh(hm).valid_all_hex);
    // Every hex, written alone by our writer, has the fixture's halfface loops in the
    // fixture's order (up to the start vertex of each loop): the kernel's layout.
    for (std::size_t c = 0; c < hm.hexes.size(); ++c) {
        HexMesh one;
        one.vertices = hm.vertices;
        one.hexes = {hm.hexes[c]};
        const OvmModel ours = ovmFromHexMesh(one);
        EXPECT_EQ(ours.topology, OvmTopology::Hexahedral);
        for (int k = 0; k < 6; ++k)
            EXPECT_TRUE(cyclicEqual(ours.halffaceLoop(ours.cells[0][k]), fixture.halffaceLoop(fixture.cells[c][k])))
                << "hex " << c << " halfface " << k;
    }
    // Our .ovmb of the mesh reads back to the same mesh; same for .ovm.
    for (const std::string ext : {".ovmb", ".ovm"}) {
        const std::string path = tempPath("sphere_hex" + ext);
        writeHexMesh(path, hm);
        EXPECT_TRUE(sameCellsAndVertices(readHexMesh(path), hm)) << ext;
        std::remove(path.c_str());
    }
}

TEST(OvmFiles, PolycubeFromOvmbExtractsBitIdenticallyToHexex) {
    const std::string ovmb = std::string("../shared/data/ovm/S1_polycube_scale1.ovmb.xz"), hexex = "../shared/data/S1_polycube_scale1.hexex.xz";
    if (!std::filesystem::exists(ovmb) || !std::filesystem::exists(hexex)) GTEST_SKIP() << "fixture " << ovmb << " absent";
    const std::string a = capture("xz -dc '" + ovmb + "'"), b = capture("xz -dc '" + hexex + "'");
    if (a.empty() || b.empty()) GTEST_SKIP() << "xz not available";
    ASSERT_EQ(a.size(), 17257368u);
    const ParametrizedTetMesh fromOvmb = readOvmTetBuffer(a, "S1.ovmb"), fromHexex = readHexExBuffer(b, "S1.hexex");
    EXPECT_EQ(fromOvmb.mesh.n_vertices(), 23999u);
    EXPECT_EQ(fromOvmb.mesh.n_cells(), 113683u);
    EXPECT_EQ(fromOvmb.params, fromHexex.params);
    const HexMesh ha = extracted(fromOvmb), hb = extracted(fromHexex);
    EXPECT_GT(ha.hexes.size(), 0u);
    EXPECT_TRUE(sameMesh(ha, hb));
    std::ostringstream va, vb;
    writeHexMeshStream(va, ha, HexMeshFormat::Vtu);
    writeHexMeshStream(vb, hb, HexMeshFormat::Vtu);
    EXPECT_EQ(va.str(), vb.str());
    EXPECT_EQ(writeOvmBinary(ovmFromTetMesh(fromHexex)), a);  // and our writer gives OpenVolumeMesh's bytes
}

TEST(OvmFiles, ConvertBetweenMapFormatsAndHexFormats) {
    const std::string tool = HexExTest::hexexBinary();
    if (tool.empty()) GTEST_SKIP() << "hexex binary not found";
    const std::string hexex = tempPath("cube.hexex");
    const ParametrizedTetMesh cube = generateCube(2, 3);
    writeHexExFile(hexex, cube);
    const auto run = [&](const std::string& args) { return std::system((tool + " " + args + " 2>/dev/null").c_str()); };
    // Map: .hexex -> .ovmb -> .ovm -> .hexex keeps the mesh and its map exactly.
    const std::string ovmb = tempPath("cube.ovmb"), ovm = tempPath("cube.ovm"), back = tempPath("back.hexex");
    ASSERT_EQ(run("convert " + hexex + " " + ovmb), 0);
    ASSERT_EQ(run("convert " + ovmb + " " + ovm), 0);
    ASSERT_EQ(run("convert " + ovm + " " + back), 0);
    EXPECT_EQ(fileBytes(back), fileBytes(hexex));
    // Hex mesh: .vtu -> .ovmb -> .vtk -> .mesh keeps the mesh.
    const HexMesh hm = extracted(cube);
    const std::string vtu = tempPath("hex.vtu"), hovmb = tempPath("hex.ovmb"), vtk = tempPath("hex.vtk"), medit = tempPath("hex.mesh");
    writeHexMesh(vtu, hm);
    ASSERT_EQ(run("convert " + vtu + " " + hovmb), 0);
    ASSERT_EQ(run("convert " + hovmb + " " + vtk), 0);
    ASSERT_EQ(run("convert " + vtk + " " + medit + " --encoding ascii"), 0);
    EXPECT_TRUE(sameCellsAndVertices(readHexMesh(medit), hm));
    EXPECT_TRUE(checkHexMesh(readHexMesh(medit)).valid_all_hex);
    // Wrong directions are usage errors.
    EXPECT_EQ(WEXITSTATUS(run("convert " + hexex + " " + tempPath("x.vtu"))), 2);
    EXPECT_EQ(WEXITSTATUS(run("convert " + vtu + " " + tempPath("x.hexex"))), 2);
    EXPECT_EQ(WEXITSTATUS(run("convert " + vtu + " " + tempPath("x.vtu") + " --encoding zip")), 2);
    for (const auto& p : {hexex, ovmb, ovm, back, vtu, hovmb, vtk, medit}) std::remove(p.c_str());
}
