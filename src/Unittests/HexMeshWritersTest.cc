// Tests of the hex mesh writers and readers: round trips through all four formats,
// polyhedra, malformed input, and an independent Python reader of .vtu files.

#include <HexEx/Core/Error.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/IO/HexMeshWriters.hh>
#include <HexEx/Mesh/HexMeshCheck.hh>
#include <HexEx/Mesh/HexMeshQuality.hh>

#include <gtest/gtest.h>

#include "TestMeshChecks.hh"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace HexEx;

namespace {

using HexExTest::extracted;

std::string tempPath(const std::string& file) {
    const auto dir = std::filesystem::temp_directory_path() / "hexex_writers_test";
    std::filesystem::create_directories(dir);
    return (dir / file).string();
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// Cyclic canonical form of an oriented loop (rotated to start at its smallest vertex).
std::vector<int> canonicalLoop(std::vector<int> f) {
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    return f;
}

/// The oriented faces of a hex as canonical loops (identifies the hex up to its VTK start).
std::set<std::vector<int>> hexFaceSet(const std::array<int, 8>& h) {
    std::set<std::vector<int>> out;
    for (const auto& f : kHexFaces) out.insert(canonicalLoop({h[f[0]], h[f[1]], h[f[2]], h[f[3]]}));
    return out;
}

std::set<std::vector<int>> polyFaceSet(const Polyhedron& p) {
    std::set<std::vector<int>> out;
    for (const auto& f : p.faces) out.insert(canonicalLoop(f));
    return out;
}

/// One hex (unit cube) with a pyramid polyhedron on top (apex vertex 8).
HexMesh hexWithPyramid() {
    HexMesh m;
    m.vertices = {Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(1, 1, 0), Vec3d(0, 1, 0),  Vec3d(0, 0, 1),
                  Vec3d(1, 0, 1), Vec3d(1, 1, 1), Vec3d(0, 1, 1), Vec3d(0.5, 0.5, 1.75)};
    m.hexes.push_back({{0, 1, 2, 3, 4, 5, 6, 7}});
    Polyhedron p;
    p.faces = {{4, 7, 6, 5}, {4, 5, 8}, {5, 6, 8}, {6, 7, 8}, {7, 4, 8}};
    m.polyhedra.push_back(p);
    return m;
}

void expectSameMesh(const HexMesh& a, const HexMesh& b, bool exactHexOrder, const std::string& what) {
    ASSERT_EQ(a.vertices.size(), b.vertices.size()) << what;
    ASSERT_EQ(a.hexes.size(), b.hexes.size()) << what;
    ASSERT_EQ(a.polyhedra.size(), b.polyhedra.size()) << what;
    for (std::size_t i = 0; i < a.vertices.size(); ++i)
        for (int d = 0; d < 3; ++d) EXPECT_NEAR(a.vertices[i][d], b.vertices[i][d], 1e-12) << what << " vertex " << i;
    for (std::size_t i = 0; i < a.hexes.size(); ++i) {
        if (exactHexOrder)
            EXPECT_EQ(a.hexes[i], b.hexes[i]) << what << " hex " << i;
        else
            EXPECT_EQ(hexFaceSet(a.hexes[i]), hexFaceSet(b.hexes[i])) << what << " hex " << i;
    }
    for (std::size_t i = 0; i < a.polyhedra.size(); ++i)
        EXPECT_EQ(polyFaceSet(a.polyhedra[i]), polyFaceSet(b.polyhedra[i])) << what << " polyhedron " << i;
}

const char* const kExtensions[] = {"vtu", "vtk", "ovm", "mesh"};

} // namespace

TEST(HexMeshWriters, FormatFromExtension) {
    EXPECT_EQ(hexMeshFormatFromPath("a/b.vtu"), HexMeshFormat::Vtu);
    EXPECT_EQ(hexMeshFormatFromPath("x.VTK"), HexMeshFormat::Vtk);
    EXPECT_EQ(hexMeshFormatFromPath("x.ovm"), HexMeshFormat::Ovm);
    EXPECT_EQ(hexMeshFormatFromPath("x.mesh"), HexMeshFormat::Medit);
    try {
        hexMeshFormatFromPath("dir.v/out.stl");
        FAIL() << "no exception";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("dir.v/out.stl"), std::string::npos) << e.what();
    }
    EXPECT_THROW(hexMeshFormatFromPath("noext"), InputError);
}

TEST(HexMeshWriters, UnwritablePathNamesPath) {
    HexMesh m = hexWithPyramid();
    const std::string bad = "/nonexistent-dir-hexex/out.vtu";
    try {
        writeHexMesh(bad, m);
        FAIL() << "no exception";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
    EXPECT_THROW(writeHexMesh(tempPath("x.obj"), m), InputError);
}

TEST(HexMeshWriters, InvalidIndexRejected) {
    HexMesh m = hexWithPyramid();
    m.hexes[0][3] = 99;
    std::ostringstream out;
    EXPECT_THROW(writeHexMeshStream(out, m, HexMeshFormat::Vtu), std::invalid_argument);
}

TEST(HexMeshWriters, RoundTripCubeAllFormats) {
    const HexMesh cube = extracted(generateCube(2, 3));
    ASSERT_EQ(cube.hexes.size(), 27u);
    ASSERT_EQ(cube.vertices.size(), 64u);
    for (const char* ext : kExtensions) {
        const std::string path = tempPath(std::string("cube.") + ext);
        const auto warnings = writeHexMesh(path, cube);
        EXPECT_TRUE(warnings.empty()) << ext;
        const HexMesh back = readHexMesh(path);
        expectSameMesh(cube, back, std::string(ext) != "ovm", ext);
        const auto r = checkHexMesh(back);
        EXPECT_TRUE(r.valid_all_hex) << ext;
        EXPECT_EQ(r.boundary_quads, 54) << ext;
        EXPECT_EQ(r.quality.inverted_hexes, 0) << ext;
    }
}

TEST(HexMeshWriters, RoundTripCylinderAllFormats) {
    const HexMesh cyl = extracted(generateCylinder(3, 2, 2, 1, 1));
    ASSERT_EQ(cyl.hexes.size(), 24u);
    for (const char* ext : kExtensions) {
        const std::string path = tempPath(std::string("cylinder.") + ext);
        writeHexMesh(path, cyl);
        const HexMesh back = readHexMesh(path);
        expectSameMesh(cyl, back, std::string(ext) != "ovm", ext);
        EXPECT_TRUE(checkHexMesh(back).valid_all_hex) << ext;
        // Orientation is preserved: the same scaled Jacobians.
        const auto a = scaledJacobians(cyl), b = scaledJacobians(back);
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-12) << ext;
    }
}

TEST(HexMeshWriters, PositionsBitExact) {
    HexMesh m = hexWithPyramid();
    m.vertices[0] = Vec3d(0.1, 1.0 / 3.0, -2.5e-300);
    m.vertices[1] = Vec3d(1e17 + 1, 0.7, 3.14159265358979);
    for (const char* ext : kExtensions) {
        const std::string path = tempPath(std::string("exact.") + ext);
        writeHexMesh(path, m);
        const HexMesh back = readHexMesh(path);
        ASSERT_EQ(back.vertices.size(), m.vertices.size());
        for (std::size_t i = 0; i < m.vertices.size(); ++i)
            for (int d = 0; d < 3; ++d) EXPECT_EQ(back.vertices[i][d], m.vertices[i][d]) << ext;
    }
}

TEST(HexMeshWriters, OvmStoresSharedFacesOnce) {
    const HexMesh cube = extracted(generateCube(1, 2));  // 8 hexes
    std::ostringstream out;
    writeHexMeshStream(out, cube, HexMeshFormat::Ovm);
    std::istringstream in(out.str());
    std::string tok;
    long faces = -1, cells = -1, edges = -1;
    while (in >> tok) {
        if (tok == "Edges") in >> edges;
        if (tok == "Faces") in >> faces;
        if (tok == "Polyhedra") in >> cells;
    }
    EXPECT_EQ(cells, 8);
    EXPECT_EQ(faces, 36);  // 3 directions x 3 planes x 4
    EXPECT_EQ(edges, 54);  // 3 directions x 9 lines x 2
    const HexMesh back = readHexMeshBuffer(out.str(), HexMeshFormat::Ovm, "mem.ovm");
    expectSameMesh(cube, back, false, "ovm");
}

TEST(HexMeshWriters, OvmInwardConventionIsDetected) {
    // The same hex written with inward halffaces (all orientation bits flipped) reads back
    // as the same, positively oriented hex.
    HexMesh m;
    m.vertices = hexWithPyramid().vertices;
    m.vertices.pop_back();
    m.hexes.push_back({{0, 1, 2, 3, 4, 5, 6, 7}});
    std::ostringstream out;
    writeHexMeshStream(out, m, HexMeshFormat::Ovm);
    std::string text = out.str();
    const std::size_t p = text.find("Polyhedra\n1\n6 ");
    ASSERT_NE(p, std::string::npos);
    std::istringstream cell(text.substr(p + 14));
    std::string flipped = "Polyhedra\n1\n6";
    for (int i = 0; i < 6; ++i) {
        int hf;
        cell >> hf;
        flipped += " " + std::to_string(hf ^ 1);
    }
    text = text.substr(0, p) + flipped + "\n";
    const HexMesh back = readHexMeshBuffer(text, HexMeshFormat::Ovm, "inward.ovm");
    ASSERT_EQ(back.hexes.size(), 1u);
    EXPECT_EQ(hexFaceSet(back.hexes[0]), hexFaceSet(m.hexes[0]));
    EXPECT_DOUBLE_EQ(computeQuality(back).min_scaled_jacobian, 1.0);
}

TEST(HexMeshWriters, PolyhedronRoundTrip) {
    const HexMesh m = hexWithPyramid();
    for (const char* ext : {"vtu", "vtk", "ovm"}) {
        const std::string path = tempPath(std::string("poly.") + ext);
        EXPECT_TRUE(writeHexMesh(path, m).empty()) << ext;
        const HexMesh back = readHexMesh(path);
        expectSameMesh(m, back, std::string(ext) != "ovm", ext);
        ASSERT_EQ(back.polyhedra.size(), 1u) << ext;
        EXPECT_EQ(back.polyhedra[0].faces.size(), 5u) << ext;
        const auto r = checkHexMesh(back);
        EXPECT_EQ(r.non_hex_cells, 1) << ext;
        EXPECT_FALSE(r.valid_all_hex) << ext;
        EXPECT_EQ(r.nonmanifold_boundary_edges, 0) << ext;
    }
}

TEST(HexMeshWriters, MeditWarnsAboutPolyhedra) {
    const HexMesh m = hexWithPyramid();
    const std::string path = tempPath("poly.mesh");
    const auto warnings = writeHexMesh(path, m);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("1 non-hex cell"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find(path), std::string::npos) << warnings[0];
    const HexMesh back = readHexMesh(path);
    EXPECT_EQ(back.hexes.size(), 1u);
    EXPECT_EQ(back.polyhedra.size(), 0u);
}

TEST(HexMeshWriters, SingularEdgesVtk) {
    const std::string path = tempPath("sing.vtk");
    writeSingularEdgesVtk(path, {Vec3d(0, 0, 0), Vec3d(0, 0, 1), Vec3d(0, 0, 2)}, {{{0, 1}}, {{1, 2}}}, {3, 5});
    const std::string text = slurp(path);
    EXPECT_NE(text.find("DATASET POLYDATA"), std::string::npos);
    EXPECT_NE(text.find("LINES 2 6\n2 0 1\n2 1 2\n"), std::string::npos);
    EXPECT_NE(text.find("SCALARS valence int 1\nLOOKUP_TABLE default\n3\n5\n"), std::string::npos);
    EXPECT_THROW(writeSingularEdgesVtk(path, {Vec3d(0, 0, 0)}, {{{0, 1}}}, {3}), std::invalid_argument);
    EXPECT_THROW(writeSingularEdgesVtk(path, {Vec3d(0, 0, 0), Vec3d(1, 0, 0)}, {{{0, 1}}}, {}), std::invalid_argument);
}

TEST(HexMeshReaders, ForeignVtkCellTypes) {
    // Version 5.1 legacy layout with a voxel, a tetra and a hexahedron.
    const std::string text =
        "# vtk DataFile Version 5.1\nforeign\nASCII\nDATASET UNSTRUCTURED_GRID\n"
        "POINTS 9 float\n0 0 0 1 0 0 0 1 0 1 1 0 0 0 1 1 0 1 0 1 1 1 1 1 5 5 5\n"
        "CELLS 4 16\nOFFSETS vtktypeint64\n0 8 12 16\nCONNECTIVITY vtktypeint64\n"
        "0 1 2 3 4 5 6 7\n0 1 2 8\n0 1 3 2\n"
        "CELL_TYPES 3\n11\n10\n9\n"
        "CELL_DATA 3\nFIELD FieldData 1\nq 1 3 double\n1 2 3\n";
    const HexMesh m = readHexMeshBuffer(text, HexMeshFormat::Vtk, "foreign.vtk");
    ASSERT_EQ(m.hexes.size(), 1u);
    EXPECT_EQ(m.hexes[0], (std::array<int, 8>{{0, 1, 3, 2, 4, 5, 7, 6}}));
    EXPECT_DOUBLE_EQ(computeQuality(m).min_scaled_jacobian, 1.0);
    EXPECT_EQ(m.polyhedra.size(), 2u);
}

namespace {

/// Expects readHexMeshBuffer to throw InputError whose message contains every part.
void expectReadError(const std::string& text, HexMeshFormat f, const std::vector<std::string>& parts) {
    try {
        readHexMeshBuffer(text, f, "bad.file");
        ADD_FAILURE() << "no exception for:\n" << text;
    } catch (const InputError& e) {
        const std::string msg = e.what();
        for (const auto& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
    }
}

const char* kVtkHead = "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n";

} // namespace

TEST(HexMeshReaders, MalformedInputsNameLineAndReason) {
    const std::string pts8 = "POINTS 8 double\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n";
    // Legacy VTK.
    expectReadError(std::string(kVtkHead) + pts8 + "CELLS 1 9\n8 0 1 2 3 4 5 6 99\nCELL_TYPES 1\n12\n",
                    HexMeshFormat::Vtk, {"bad.file:14:", "cell 0: point index 99 out of range"});
    expectReadError(std::string(kVtkHead) + pts8 + "CELLS 1 9\n8 0 1 2 3 4 5 6\n", HexMeshFormat::Vtk,
                    {"bad.file:", "end of file"});
    expectReadError(std::string(kVtkHead) + pts8 + "CELLS 1 9\n8 0 1 2 3 4 5 6 7\nCELL_TYPES 1\n3\n",
                    HexMeshFormat::Vtk, {"unsupported VTK cell type 3"});
    expectReadError(std::string(kVtkHead) + "POINTS 2 double\n0 0 0\n1 x 0\n", HexMeshFormat::Vtk,
                    {"bad.file:7:", "'x'"});
    expectReadError("hello\n", HexMeshFormat::Vtk, {"bad.file:1:", "not a legacy VTK file"});
    expectReadError(std::string(kVtkHead) + "POINTS 99999999999 double\n", HexMeshFormat::Vtk,
                    {"bad.file:5:", "larger than the file"});
    // VTU.
    expectReadError("<VTKFile type=\"UnstructuredGrid\">\n<UnstructuredGrid>\n</VTKFile>\n", HexMeshFormat::Vtu,
                    {"bad.file:3:", "malformed XML", "mismatch"});
    expectReadError("<VTKFile type=\"PolyData\"></VTKFile>", HexMeshFormat::Vtu, {"bad.file:1:", "PolyData"});
    expectReadError("<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid><Piece NumberOfPoints=\"1\" "
                    "NumberOfCells=\"1\">\n<Points><DataArray NumberOfComponents=\"3\" format=\"ascii\">0 0 0"
                    "</DataArray></Points>\n<Cells><DataArray Name=\"connectivity\">0 0 0 0 0 0 0 5</DataArray>\n"
                    "<DataArray Name=\"offsets\">8</DataArray><DataArray Name=\"types\">12</DataArray></Cells>"
                    "</Piece></UnstructuredGrid></VTKFile>",
                    HexMeshFormat::Vtu, {"bad.file:4:", "point index 5 out of range"});
    expectReadError("<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid><Piece NumberOfPoints=\"1\" "
                    "NumberOfCells=\"0\">\n<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"binary\">AAAA"
                    "</DataArray></Points></Piece></UnstructuredGrid></VTKFile>",
                    HexMeshFormat::Vtu, {"bad.file:2:", "(binary): needs 4 bytes, at most 3 left"});
    // Medit.
    expectReadError("MeshVersionFormatted 2\nDimension 3\nVertices\n1\n0 0 0 0\nHexahedra\n1\n1 1 1 1 1 1 1 9 0\nEnd\n",
                    HexMeshFormat::Medit, {"bad.file:8:", "vertex index 9 out of range"});
    expectReadError("MeshVersionFormatted 2\nDimension 3\nBogus 1\n", HexMeshFormat::Medit,
                    {"bad.file:3:", "'Bogus'"});
    // OVM.
    expectReadError("OVM ASCII\nVertices\n2\n0 0 0\n1 0 0\nEdges\n1\n0 2\n", HexMeshFormat::Ovm,
                    {"bad.file:8:", "out of range"});
    expectReadError("OVM ASCII\nVertices\n3\n0 0 0\n1 0 0\n0 1 0\nEdges\n3\n0 1\n1 2\n2 0\nFaces\n1\n3 0 4 2\n"
                    "Polyhedra\n1\n1 0\n",
                    HexMeshFormat::Ovm, {"bad.file:14:", "not closed"});
    expectReadError("OVM ASCII\nVertices\n3\n0 0 0\n1 0 0\n0 1 0\nEdges\n3\n0 1\n1 2\n2 0\nFaces\n1\n3 0 2 4\n"
                    "Polyhedra\n1\n1 7\n",
                    HexMeshFormat::Ovm, {"bad.file:17:", "halfface 0 of polyhedron 0 7 out of range [0, 2)"});
}

TEST(HexMeshReaders, MissingFileNamesPath) {
    try {
        readHexMesh("/nonexistent-hexex/x.vtk");
        FAIL() << "no exception";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent-hexex/x.vtk"), std::string::npos);
    }
}

TEST(HexMeshReaders, TruncatedAndMutatedInputsNeverCrash) {
    HexMesh m = extracted(generateCube(1, 2));
    m.polyhedra.push_back(hexWithPyramid().polyhedra[0]);  // references vertices 4..8
    const HexMeshFormat formats[] = {HexMeshFormat::Vtu, HexMeshFormat::Vtk, HexMeshFormat::Ovm, HexMeshFormat::Medit};
    std::mt19937 rng(12345);
    for (const HexMeshFormat f : formats) {
        std::ostringstream out;
        writeHexMeshStream(out, m, f);
        const std::string text = out.str();
        ASSERT_NO_THROW(readHexMeshBuffer(text, f, "ok"));
        for (std::size_t cut = 0; cut < text.size(); cut += 7) {
            try {
                readHexMeshBuffer(text.substr(0, cut), f, "cut");
            } catch (const InputError&) {
            }
        }
        const char junk[] = {'9', '-', 'x', ' ', '\n', '<', '>', '"', '0', '7'};
        for (int trial = 0; trial < 400; ++trial) {
            std::string t = text;
            const int edits = 1 + static_cast<int>(rng() % 3);
            for (int e = 0; e < edits; ++e) t[rng() % t.size()] = junk[rng() % sizeof junk];
            try {
                const HexMesh r = readHexMeshBuffer(t, f, "mutated");
                checkHexMesh(r);  // whatever was read must be checkable
            } catch (const InputError&) {
            }
        }
    }
}

TEST(HexMeshWriters, IndependentPythonVtuReader) {
    if (std::system("python3 -c \"import xml.etree.ElementTree\" > /dev/null 2>&1") != 0)
        GTEST_SKIP() << "python3 not available";
    const std::string script = std::string(HEXEX_SOURCE_DIR) + "/scripts/read_vtu_counts.py";
    auto run = [&](const std::string& vtu) {
        const std::string cmd = "python3 '" + script + "' '" + vtu + "'";
        std::string out;
        FILE* p = popen(cmd.c_str(), "r");
        if (!p) return out;
        char buf[256];
        while (fgets(buf, sizeof buf, p)) out += buf;
        EXPECT_EQ(pclose(p), 0) << cmd;
        return out;
    };
    const std::string cubePath = tempPath("py_cube.vtu");
    writeHexMesh(cubePath, extracted(generateCube(2, 3)), VtuEncoding::Ascii);  // the script reads ASCII
    EXPECT_EQ(run(cubePath), "64 27 27 0\n");
    const std::string polyPath = tempPath("py_poly.vtu");
    writeHexMesh(polyPath, hexWithPyramid(), VtuEncoding::Ascii);
    EXPECT_EQ(run(polyPath), "9 2 1 1\n");
}
