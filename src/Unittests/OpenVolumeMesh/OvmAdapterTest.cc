// OpenVolumeMesh adapter (HexEx/Adapters/OpenVolumeMesh.hh) against the real library:
// meshes read with OpenVolumeMesh's own readers from the files it wrote, and tet meshes
// built in memory, extract the same mesh as the .hexex path bit for bit; the output
// passes OpenVolumeMesh's topology checks and writes and reads back with its writers.

#include "../../TestSupport/OvmTetFixtures.hh"
#include "../TestMeshChecks.hh"

#include <HexEx/Adapters/OpenVolumeMesh.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/IO/HexExFile.hh>
#include <HexEx/IO/OvmTetReader.hh>

#include <OpenVolumeMesh/FileManager/FileManager.hh>
#include <OpenVolumeMesh/IO/IO.hh>
#include <OpenVolumeMesh/IO/ovmb_read.hh>
#include <OpenVolumeMesh/IO/ovmb_write.hh>
#include <OpenVolumeMesh/Mesh/HexahedralMesh.hh>
#include <OpenVolumeMesh/Mesh/PolyhedralMesh.hh>
#include <OpenVolumeMesh/Mesh/TetrahedralGeometryKernel.hh>
#include <OpenVolumeMesh/Mesh/TetrahedralMesh.hh>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <unistd.h>

namespace {

using TetMesh = OpenVolumeMesh::GeometricTetrahedralMeshV3d;
using PolyMesh = OpenVolumeMesh::GeometricPolyhedralMeshV3d;
using HexMeshOvm = OpenVolumeMesh::GeometricHexahedralMeshV3d;
using OvmVec = OpenVolumeMesh::Geometry::Vec3d;

/// Fixtures written by OpenVolumeMesh 3.4.1 (bundled copies of ../shared/data/ovm).
const std::string kOvmDir = "src/Unittests/data/ovm/";

std::string tempPath(const std::string& file) {
    return ::testing::TempDir() + "ovmadapter_" + std::to_string(::getpid()) + "_" + file;
}

/// Output of a shell command ("" if it could not run).
std::string capture(const std::string& cmd) {
    std::unique_ptr<FILE, int (*)(FILE*)> p(popen(cmd.c_str(), "r"), pclose);
    std::string out;
    if (!p) return out;
    char buf[65536];
    std::size_t n = 0;
    while ((n = std::fread(buf, 1, sizeof buf, p.get())) > 0) out.append(buf, n);
    return out;
}

/// The tets of @p pm in OpenVolumeMesh with the halfface map (OvmTetFixtures.hh).
template <class Mesh>
Mesh toOvm(const HexEx::ParametrizedTetMesh& pm) {
    Mesh m;
    EXPECT_EQ(HexExTestSupport::buildOvmTets(pm, m), 0u);
    return m;
}

/// True if loop @p a equals @p b up to a cyclic shift.
bool cyclicEqual(const std::vector<OpenVolumeMesh::VertexHandle>& a, const std::vector<OpenVolumeMesh::VertexHandle>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t s = 0; s < a.size(); ++s) {
        bool eq = true;
        for (std::size_t i = 0; i < a.size() && eq; ++i) eq = a[(s + i) % a.size()] == b[i];
        if (eq) return true;
    }
    return a.empty();
}

/// The hexes of an OpenVolumeMesh hex mesh as sets of vertex indices, per cell.
std::vector<std::set<int>> cellVertexSets(const HexMeshOvm& m) {
    std::vector<std::set<int>> r;
    for (std::size_t c = 0; c < m.n_cells(); ++c) {
        std::set<int> s;
        for (const auto& hf : m.cell(OpenVolumeMesh::CellHandle(int(c))).halffaces())
            for (const auto& v : m.get_halfface_vertices(hf)) s.insert(v.idx());
        r.push_back(s);
    }
    return r;
}

/// Checks @p out against @p ref: same vertex positions (bitwise), same hexes as vertex
/// sets. @p tolerance > 0 allows rounded positions (OpenVolumeMesh's .ovm writer prints 6 digits).
void expectOvmHexMeshEquals(const HexMeshOvm& out, const HexEx::HexMesh& ref, double tolerance = 0) {
    ASSERT_EQ(out.n_vertices(), ref.vertices.size());
    ASSERT_EQ(out.n_cells(), ref.hexes.size());
    for (std::size_t v = 0; v < ref.vertices.size(); ++v) {
        const OvmVec& p = out.vertex(OpenVolumeMesh::VertexHandle(int(v)));
        if (tolerance == 0)
            EXPECT_TRUE(p[0] == ref.vertices[v][0] && p[1] == ref.vertices[v][1] && p[2] == ref.vertices[v][2]) << v;
        else
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[k], ref.vertices[v][k], tolerance) << v;
    }
    const auto sets = cellVertexSets(out);
    for (std::size_t c = 0; c < ref.hexes.size(); ++c)
        EXPECT_EQ(sets[c], std::set<int>(ref.hexes[c].begin(), ref.hexes[c].end())) << "hex " << c;
}

} // namespace

TEST(OvmAdapter, SphereOvmbReadByOpenVolumeMeshMatchesHexExFile) {
    for (const bool polyhedralKernel : {false, true}) {
        const HexEx::HexMesh ref = HexExTest::extracted(HexEx::readHexExFile("Examples/data/sphere.hexex"));
        HexEx::HexMesh out;
        if (polyhedralKernel) {
            PolyMesh m;
            ASSERT_TRUE(OpenVolumeMesh::IO::read_file(kOvmDir + "sphere.ovmb", m));
            HexEx::extractHexMesh(HexEx::OvmTetMesh(m), out);
        } else {
            TetMesh m;
            ASSERT_TRUE(OpenVolumeMesh::IO::read_file(kOvmDir + "sphere.ovmb", m));
            EXPECT_EQ(m.n_cells(), 76u);
            HexEx::extractHexMesh(HexEx::OvmTetMesh(m), out);
        }
        ASSERT_EQ(out.hexes.size(), 216u);
        HexExTest::expectSameMesh(out, ref);
    }
}

TEST(OvmAdapter, TetrahedralGeometryKernelReads) {
    // TetrahedralGeometryKernel: the geometry kernel with the tet-specific helpers.
    OpenVolumeMesh::TetrahedralGeometryKernel<OvmVec, OpenVolumeMesh::TetrahedralMeshTopologyKernel> m;
    ASSERT_TRUE(OpenVolumeMesh::IO::read_file(kOvmDir + "sphere.ovmb", m));
    HexEx::HexMesh out;
    HexEx::extractHexMesh(HexEx::OvmTetMesh(m), out);
    HexExTest::expectSameMesh(out, HexExTest::extracted(HexEx::readHexExFile("Examples/data/sphere.hexex")));
}

TEST(OvmAdapter, SphereAsciiReadByOpenVolumeMeshMatchesOurReader) {
    // sphere.ovm holds 6-digit numbers: compare with our own reader of the same file.
    TetMesh m;
    OpenVolumeMesh::IO::FileManager fm;
    ASSERT_TRUE(fm.readFile(kOvmDir + "sphere.ovm", m));
    HexEx::HexMesh out;
    const HexEx::ExtractionReport r = HexEx::extractHexMesh(HexEx::OvmTetMesh(m), out);
    EXPECT_TRUE(r.valid_all_hex);
    EXPECT_EQ(out.hexes.size(), 216u);
    HexExTest::expectSameMesh(out, HexExTest::extracted(HexEx::readOvmTetMesh(kOvmDir + "sphere.ovm")));
}

TEST(OvmAdapter, PolycubeOvmbMatchesHexExFile) {
    const std::string ovmb = "../shared/data/ovm/S1_polycube_scale1.ovmb.xz",
                      hexex = "../shared/data/S1_polycube_scale1.hexex.xz";
    if (!std::filesystem::exists(ovmb) || !std::filesystem::exists(hexex))
        GTEST_SKIP() << "fixture " << ovmb << " absent";
    const std::string bytes = capture("xz -dc '" + ovmb + "'");
    if (bytes.empty()) GTEST_SKIP() << "xz not available";
    std::istringstream in(bytes);
    TetMesh m;
    ASSERT_EQ(OpenVolumeMesh::IO::ovmb_read(in, m), OpenVolumeMesh::IO::ReadResult::Ok);
    EXPECT_EQ(m.n_cells(), 113683u);
    HexEx::HexMesh out;
    HexEx::extractHexMesh(HexEx::OvmTetMesh(m), out);
    const std::string text = capture("xz -dc '" + hexex + "'");
    const HexEx::HexMesh ref = HexExTest::extracted(HexEx::readHexExBuffer(text, "S1.hexex"));
    EXPECT_EQ(out.hexes.size(), 10288u);
    HexExTest::expectSameMesh(out, ref);
}

TEST(OvmAdapter, InMemoryCubeAndCylinderIntoTheHexahedralKernel) {
    for (const auto& pm : {HexEx::generateCube(3, 5), HexEx::generateCylinder(3, 3, 2, 2, 1)}) {
        const TetMesh tets = toOvm<TetMesh>(pm);
        const HexEx::HexMesh ref = HexExTest::extracted(pm);
        HexMeshOvm hexes;
        HexEx::OvmHexOutput<HexMeshOvm> output(hexes, /*topologyCheck=*/true);
        const HexEx::ExtractionReport r = HexEx::extractHexMesh(HexEx::OvmTetMesh(tets), output);
        EXPECT_TRUE(r.valid_all_hex);
        expectOvmHexMeshEquals(hexes, ref);
        EXPECT_EQ(output.cells().size(), ref.hexes.size());
        // Through the built-in output kernel too: bit for bit.
        HexEx::HexMesh viaTraits;
        HexEx::extractHexMesh(HexEx::OvmTetMesh(tets), viaTraits);
        HexExTest::expectSameMesh(viaTraits, ref);
    }
}

TEST(OvmAdapter, HexKernelOutputHasTheFixtureLayoutAndWritesWithOpenVolumeMesh) {
    const HexEx::HexMesh ref = HexExTest::extracted(HexEx::readHexExFile("Examples/data/sphere.hexex"));
    TetMesh tets;
    ASSERT_TRUE(OpenVolumeMesh::IO::read_file(kOvmDir + "sphere.ovmb", tets));
    HexMeshOvm hexes;
    HexEx::OvmHexOutput<HexMeshOvm> output(hexes, true);
    const HexEx::ExtractionReport r = HexEx::extractHexMesh(HexEx::OvmTetMesh(tets), output);
    expectOvmHexMeshEquals(hexes, ref);
    // The fixture was written by OpenVolumeMesh's hexahedral kernel from the same mesh:
    // the same oriented halfface loops (up to their start vertex), cell by cell.
    HexMeshOvm fixture;
    ASSERT_TRUE(OpenVolumeMesh::IO::read_file(kOvmDir + "sphere_hex.ovmb", fixture));
    ASSERT_EQ(fixture.n_cells(), hexes.n_cells());
    for (std::size_t c = 0; c < hexes.n_cells(); ++c) {
        const auto& a = hexes.cell(OpenVolumeMesh::CellHandle(int(c))).halffaces();
        const auto& b = fixture.cell(OpenVolumeMesh::CellHandle(int(c))).halffaces();
        for (std::size_t k = 0; k < 6; ++k) {
            bool found = false;
            for (std::size_t j = 0; j < 6 && !found; ++j)
                found = cyclicEqual(hexes.get_halfface_vertices(a[k]), fixture.get_halfface_vertices(b[j]));
            EXPECT_TRUE(found) << "hex " << c << " halfface " << k;
        }
        // The bottom and top come first, as in the fixture.
        for (std::size_t k = 0; k < 2; ++k)
            EXPECT_TRUE(cyclicEqual(hexes.get_halfface_vertices(a[k]), fixture.get_halfface_vertices(b[k])))
                << "hex " << c << " halfface " << k;
    }
    // Per-cell data back as a persistent property; OpenVolumeMesh writes and reads it.
    HexEx::markOvmNonHexCells(output, std::size_t(r.output.hexes));
    std::vector<int> ids(output.cells().size());
    for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = int(i) * 7;
    HexEx::writeOvmCellProperty(output, "HexEx::CellIndex", ids);
    const std::string ovmb = tempPath("sphere_hex.ovmb"), ovm = tempPath("sphere_hex.ovm");
    ASSERT_EQ(OpenVolumeMesh::IO::ovmb_write(ovmb, hexes), OpenVolumeMesh::IO::WriteResult::Ok);
    OpenVolumeMesh::IO::FileManager fm;
    ASSERT_TRUE(fm.writeFile(ovm, hexes));
    for (const std::string& path : {ovmb, ovm}) {
        HexMeshOvm back;
        ASSERT_TRUE(OpenVolumeMesh::IO::read_file(path, back, /*topology check*/ true)) << path;
        expectOvmHexMeshEquals(back, ref, path == ovm ? 1e-5 : 0.0);
        auto prop = back.get_cell_property<int>("HexEx::CellIndex");
        ASSERT_TRUE(prop.has_value()) << path;
        EXPECT_EQ((*prop)[OpenVolumeMesh::CellHandle(5)], 35) << path;
        std::remove(path.c_str());
    }
    EXPECT_THROW(HexEx::writeOvmCellProperty(output, "x", std::vector<int>(3)), HexEx::InputError);
}

TEST(OvmAdapter, PolyhedralKernelKeepsNonHexCells) {
    // A hexahedron and a square pyramid on its top face: one shared halfface pair.
    PolyMesh m;
    HexEx::OvmHexOutput<PolyMesh> out(m, true);
    HexEx::fromHexMesh(
        HexEx::HexMesh{{HexEx::Vec3d(0, 0, 0), HexEx::Vec3d(1, 0, 0), HexEx::Vec3d(1, 1, 0), HexEx::Vec3d(0, 1, 0),
                        HexEx::Vec3d(0, 0, 1), HexEx::Vec3d(1, 0, 1), HexEx::Vec3d(1, 1, 1), HexEx::Vec3d(0, 1, 1),
                        HexEx::Vec3d(0.5, 0.5, 2)},
                       {{0, 1, 2, 3, 4, 5, 6, 7}},
                       {HexEx::Polyhedron{{{4, 7, 6, 5}, {4, 5, 8}, {5, 6, 8}, {6, 7, 8}, {7, 4, 8}}}}},
        out);
    EXPECT_EQ(m.n_cells(), 2u);
    EXPECT_EQ(m.n_faces(), 6u + 4u);
    EXPECT_EQ(m.n_vertices(), 9u);
    ASSERT_EQ(out.cells().size(), 2u);
    HexEx::markOvmNonHexCells(out, 1);
    auto flag = m.get_cell_property<bool>("HexEx::NonHex");
    ASSERT_TRUE(flag.has_value());
    EXPECT_FALSE((*flag)[out.cells()[0]]);
    EXPECT_TRUE((*flag)[out.cells()[1]]);
    // The hexahedral kernel cannot hold the pyramid: skipped and counted.
    HexMeshOvm h;
    HexEx::OvmHexOutput<HexMeshOvm> hout(h, true);
    HexEx::fromHexMesh(HexEx::HexMesh{{HexEx::Vec3d(0, 0, 0), HexEx::Vec3d(1, 0, 0), HexEx::Vec3d(0, 1, 0), HexEx::Vec3d(0, 0, 1)},
                                      {},
                                      {HexEx::Polyhedron{{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}}}},
                       hout);
    EXPECT_EQ(h.n_cells(), 0u);
    EXPECT_EQ(hout.skippedPolyhedra(), 1u);
    EXPECT_FALSE(hout.cells()[0].is_valid());
}

TEST(OvmAdapter, MapPerCellAndVertex) {
    // The map as a cell property std::map<VertexHandle, Vec3d> (AlgoHex style), name given by the caller.
    const HexEx::ParametrizedTetMesh pm = HexEx::generateCylinder(5, 2, 2, 2, 1);
    TetMesh tets = toOvm<TetMesh>(pm);
    auto prop = tets.request_cell_property<std::map<OpenVolumeMesh::VertexHandle, OvmVec>>("igm");
    for (std::size_t t = 0; t < pm.mesh.n_cells(); ++t)
        for (int i = 0; i < 4; ++i) {
            const HexEx::Vec3d u = pm.params[t][std::size_t(i)];
            prop[OpenVolumeMesh::CellHandle(int(t))][OpenVolumeMesh::VertexHandle(
                pm.mesh.cell_vertex(HexEx::CellHandle(int(t)), i).idx())] = OvmVec(u[0], u[1], u[2]);
        }
    HexEx::HexMesh out;
    HexEx::extractHexMesh(HexEx::OvmTetMesh(tets, "igm", HexEx::OvmMapStorage::CellVertexMap), out);
    HexExTest::expectSameMesh(out, HexExTest::extracted(pm));
    prop[OpenVolumeMesh::CellHandle(3)].erase(OpenVolumeMesh::VertexHandle(
        pm.mesh.cell_vertex(HexEx::CellHandle(3), 2).idx()));
    try {
        HexEx::OvmTetMesh view(tets, "igm", HexEx::OvmMapStorage::CellVertexMap);
        FAIL() << "no exception";
    } catch (const HexEx::InputError& e) {
        EXPECT_EQ(std::string(e.what()), "OpenVolumeMesh cell 3: property 'igm' has no parameter for vertex " +
                                             std::to_string(pm.mesh.cell_vertex(HexEx::CellHandle(3), 2).idx()));
    }
}

TEST(OvmAdapter, MissingPropertyAndNonTetCellsAreInputErrors) {
    TetMesh m;
    ASSERT_TRUE(OpenVolumeMesh::IO::read_file(kOvmDir + "sphere.ovmb", m));
    try {
        HexEx::OvmTetMesh view(m, "uvw");
        FAIL() << "no exception";
    } catch (const HexEx::InputError& e) {
        EXPECT_STREQ(e.what(), "OpenVolumeMesh mesh has no halfface property 'uvw' of type Vec3d");
    }
    HexMeshOvm hexes;
    ASSERT_TRUE(OpenVolumeMesh::IO::read_file(kOvmDir + "sphere_hex.ovmb", hexes));
    auto p = hexes.request_halfface_property<OvmVec>(HexEx::kOvmParametrization);
    try {
        HexEx::OvmTetMesh view(hexes);
        FAIL() << "no exception";
    } catch (const HexEx::InputError& e) {
        EXPECT_STREQ(e.what(), "OpenVolumeMesh cell 0 has 6 halffaces, not a tetrahedron");
    }
}

TEST(OvmAdapter, SphereIntoThePolyhedralKernelSharesFaces) {
    TetMesh tets;
    ASSERT_TRUE(OpenVolumeMesh::IO::read_file(kOvmDir + "sphere.ovmb", tets));
    PolyMesh out;
    HexEx::OvmHexOutput<PolyMesh> output(out, /*topologyCheck=*/true);
    HexEx::extractHexMesh(HexEx::OvmTetMesh(tets), output);
    EXPECT_EQ(out.n_cells(), 216u);
    EXPECT_EQ(out.n_vertices(), 343u);
    EXPECT_EQ(out.n_faces(), 3u * 6 * 6 * 7);  // every quad of the 6x6x6 grid once
    std::size_t boundary = 0;
    for (std::size_t f = 0; f < out.n_faces(); ++f) boundary += out.is_boundary(OpenVolumeMesh::FaceHandle(int(f))) ? 1 : 0;
    EXPECT_EQ(boundary, 6u * 36);
}
