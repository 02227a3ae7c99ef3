/// @file OvmTetReaderTest.cc
/// Tests of the OpenVolumeMesh ASCII tet mesh reader: a hand-written single tet, the
/// generated cube written as .ovm by a small writer in this test (halfface and cell
/// parametrization properties, outward and inward halfface conventions) and extracted,
/// and malformed files with their line numbers.

#include <HexEx/Core/Error.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/IO/OvmTetReader.hh>
#include <HexEx/Predicates/ExactPredicates.hh>

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

/// How the test writer stores the map.
enum class MapStorage { HalfFace, Cell };

/// Writes @p pm as OpenVolumeMesh ASCII. Faces are stored with the loop of their first
/// occurrence (outward for that cell); cells list their halffaces in the order
/// @p hfOrder (TetMesh local halfface indices) pointing outward, or inward if @p inward.
/// The map goes into `HFProp vec3d "<propName>"` or `CProp vec12d "<propName>"`.
std::string toOvm(const HexEx::ParametrizedTetMesh& pm, MapStorage storage, bool inward = false,
                  const std::string& propName = "Parametrization", std::array<int, 4> hfOrder = {0, 1, 2, 3}) {
    const HexEx::TetMesh& m = pm.mesh;
    std::ostringstream o;
    o.precision(17);
    o << "OVM ASCII\nVertices\n" << m.n_vertices() << "\n";
    for (std::size_t v = 0; v < m.n_vertices(); ++v) {
        const auto& p = m.position(HexEx::VertexHandle(static_cast<int>(v)));
        o << p[0] << " " << p[1] << " " << p[2] << "\n";
    }
    std::vector<std::array<int, 2>> edges;
    std::map<std::pair<int, int>, int> edgeId;
    std::vector<std::array<int, 3>> faces;
    std::map<std::array<int, 3>, int> faceId;
    auto halfedge = [&](int a, int b) {
        const auto key = std::make_pair(std::min(a, b), std::max(a, b));
        auto it = edgeId.find(key);
        if (it == edgeId.end()) {
            it = edgeId.emplace(key, static_cast<int>(edges.size())).first;
            edges.push_back({a, b});
        }
        return 2 * it->second + (edges[it->second][0] == a ? 0 : 1);
    };
    // Halfface (2f+o) of every TetMesh halfface, and the loop the reader will see.
    std::vector<std::array<int, 4>> cellHf(m.n_cells());
    for (std::size_t c = 0; c < m.n_cells(); ++c)
        for (int i = 0; i < 4; ++i) {
            const auto hv = m.halfface_vertices(HexEx::TetMesh::halfface(HexEx::CellHandle(static_cast<int>(c)), i));
            std::array<int, 3> loop{hv[0].idx(), hv[1].idx(), hv[2].idx()};
            std::array<int, 3> key = loop;
            std::sort(key.begin(), key.end());
            auto it = faceId.find(key);
            int hf = 0;
            if (it == faceId.end()) {
                faceId.emplace(key, static_cast<int>(faces.size()));
                hf = 2 * static_cast<int>(faces.size());
                faces.push_back(loop);
            } else {
                const auto& s = faces[static_cast<std::size_t>(it->second)];
                const int k = static_cast<int>(std::find(s.begin(), s.end(), loop[0]) - s.begin());
                hf = 2 * it->second + (s[static_cast<std::size_t>((k + 1) % 3)] == loop[1] ? 0 : 1);
            }
            cellHf[c][static_cast<std::size_t>(i)] = inward ? (hf ^ 1) : hf;
        }
    std::vector<std::array<int, 3>> faceHe;
    for (const auto& f : faces) faceHe.push_back({halfedge(f[0], f[1]), halfedge(f[1], f[2]), halfedge(f[2], f[0])});
    o << "Edges\n" << edges.size() << "\n";
    for (const auto& e : edges) o << e[0] << " " << e[1] << "\n";
    o << "Faces\n" << faces.size() << "\n";
    for (const auto& he : faceHe) o << "3 " << he[0] << " " << he[1] << " " << he[2] << "\n";
    o << "Polyhedra\n" << m.n_cells() << "\n";
    for (const auto& hfs : cellHf) {
        o << "4";
        for (const int i : hfOrder) o << " " << hfs[static_cast<std::size_t>(i)];
        o << "\n";
    }
    o << "VProp double \"unrelated\"\n";
    for (std::size_t v = 0; v < m.n_vertices(); ++v) o << 0.5 << "\n";
    if (storage == MapStorage::HalfFace) {
        std::vector<HexEx::Vec3d> value(2 * faces.size(), HexEx::Vec3d(0, 0, 0));
        for (std::size_t c = 0; c < m.n_cells(); ++c)
            for (int i = 0; i < 4; ++i) value[static_cast<std::size_t>(cellHf[c][static_cast<std::size_t>(i)])] = pm.params[c][static_cast<std::size_t>(i)];
        o << "HFProp vec3d \"" << propName << "\"\n";
        for (const auto& u : value) o << u[0] << " " << u[1] << " " << u[2] << "\n";
    } else {
        // File corner order: first listed halfface's loop (as the reader sees it) + the fourth vertex.
        o << "CProp vec12d \"" << propName << "\"\n";
        for (std::size_t c = 0; c < m.n_cells(); ++c) {
            const int hf0 = cellHf[c][static_cast<std::size_t>(hfOrder[0])];
            const auto& l = faces[static_cast<std::size_t>(hf0 / 2)];
            const std::array<int, 3> loop = hf0 % 2 == 0 ? l : std::array<int, 3>{l[0], l[2], l[1]};
            std::array<int, 4> order{loop[0], loop[1], loop[2], -1};
            const auto& cv = m.cell_vertices(HexEx::CellHandle(static_cast<int>(c)));
            for (const auto v : cv)
                if (std::find(loop.begin(), loop.end(), v.idx()) == loop.end()) order[3] = v.idx();
            for (int j = 0; j < 4; ++j) {
                const int corner = static_cast<int>(std::find_if(cv.begin(), cv.end(), [&](HexEx::VertexHandle v) {
                                                        return v.idx() == order[static_cast<std::size_t>(j)];
                                                    }) - cv.begin());
                const auto& u = pm.params[c][static_cast<std::size_t>(corner)];
                o << (j ? " " : "") << u[0] << " " << u[1] << " " << u[2];
            }
            o << "\n";
        }
    }
    return o.str();
}

/// For every cell: vertex index -> parameter (independent of the corner order).
std::vector<std::map<int, HexEx::Vec3d>> paramsByVertex(const HexEx::ParametrizedTetMesh& pm) {
    std::vector<std::map<int, HexEx::Vec3d>> out(pm.mesh.n_cells());
    for (std::size_t c = 0; c < pm.mesh.n_cells(); ++c)
        for (int i = 0; i < 4; ++i)
            out[c][pm.mesh.cell_vertex(HexEx::CellHandle(static_cast<int>(c)), i).idx()] = pm.params[c][static_cast<std::size_t>(i)];
    return out;
}

/// Reads @p text, checks it against @p ref (same vertices, same cells as vertex sets with
/// the same per-vertex parameters, positive orientation), and extracts it.
void checkRoundTrip(const HexEx::ParametrizedTetMesh& ref, const std::string& text, long expectedHexes) {
    HexEx::ReadReport rr;
    HexEx::ParametrizedTetMesh pm;
    ASSERT_NO_THROW(pm = HexEx::readOvmTetBuffer(text, "cube.ovm", &rr));
    ASSERT_EQ(rr.warnings.size(), 1u);  // properties not needed are named
    EXPECT_NE(rr.warnings[0].find("cube.ovm: skipped 1 unused property: VProp double \"unrelated\" (line "),
              std::string::npos) << rr.warnings[0];
    ASSERT_EQ(pm.mesh.n_vertices(), ref.mesh.n_vertices());
    ASSERT_EQ(pm.mesh.n_cells(), ref.mesh.n_cells());
    ASSERT_TRUE(pm.mesh.has_adjacency());
    for (std::size_t v = 0; v < ref.mesh.n_vertices(); ++v)
        EXPECT_EQ(pm.mesh.position(HexEx::VertexHandle(static_cast<int>(v))),
                  ref.mesh.position(HexEx::VertexHandle(static_cast<int>(v))));
    EXPECT_EQ(paramsByVertex(pm), paramsByVertex(ref));
    for (std::size_t c = 0; c < pm.mesh.n_cells(); ++c) {
        const auto& cv = pm.mesh.cell_vertices(HexEx::CellHandle(static_cast<int>(c)));
        EXPECT_GT(HexEx::orient3d(pm.mesh.position(cv[0]), pm.mesh.position(cv[1]), pm.mesh.position(cv[2]),
                                  pm.mesh.position(cv[3])),
                  0)
            << "cell " << c;
    }
    HexEx::HexMesh hm;
    const auto r = HexEx::extractHexMesh(pm, hm);
    EXPECT_EQ(r.output.hexes, expectedHexes);
    EXPECT_TRUE(r.valid_all_hex);
}

/// A unit tet with the identity map; line numbers are given on the right.
const char* const kTet =
    "OVM ASCII\n"         // 1
    "Vertices\n"          // 2
    "4\n"                 // 3
    "0 0 0\n"             // 4
    "1 0 0\n"             // 5
    "0 1 0\n"             // 6
    "0 0 1\n"             // 7
    "Edges\n"             // 8
    "6\n"                 // 9
    "0 1\n"               // 10  e0
    "0 2\n"               // 11  e1
    "0 3\n"               // 12  e2
    "1 2\n"               // 13  e3
    "1 3\n"               // 14  e4
    "2 3\n"               // 15  e5
    "Faces\n"             // 16
    "4\n"                 // 17
    "3 6 10 9\n"          // 18  f0: 1 2 3
    "3 4 11 3\n"          // 19  f1: 0 3 2
    "3 0 8 5\n"           // 20  f2: 0 1 3
    "3 2 7 1\n"           // 21  f3: 0 2 1
    "Polyhedra\n"         // 22
    "1\n"                 // 23
    "4 0 2 4 6\n"         // 24  outward halffaces
    "HFProp vec3d \"Parametrization\"\n"  // 25
    "0 0 0\n"             // 26  hf0 (opposite vertex 0)
    "7 7 7\n"             // 27  hf1 (no cell)
    "1 0 0\n"             // 28  hf2 (opposite vertex 1)
    "7 7 7\n"             // 29
    "0 1 0\n"             // 30  hf4 (opposite vertex 2)
    "7 7 7\n"             // 31
    "0 0 1\n"             // 32  hf6 (opposite vertex 3)
    "7 7 7\n";            // 33

/// @p text with the whole line @p line (1-based) replaced by @p replacement.
std::string withLine(const std::string& text, int line, const std::string& replacement) {
    std::istringstream in(text);
    std::string out, l;
    for (int n = 1; std::getline(in, l); ++n) out += (n == line ? replacement : l) + "\n";
    return out;
}

/// @p text cut after line @p line.
std::string firstLines(const std::string& text, int line) {
    std::istringstream in(text);
    std::string out, l;
    for (int n = 1; n <= line && std::getline(in, l); ++n) out += l + "\n";
    return out;
}

/// The message of the InputError thrown when reading @p text (empty if none).
std::string errorOf(const std::string& text) {
    try {
        HexEx::readOvmTetBuffer(text, "t.ovm");
    } catch (const HexEx::InputError& e) {
        return e.what();
    }
    return "";
}

#define EXPECT_OVM_ERROR(text, prefix, reason)                                                   \
    do {                                                                                          \
        const std::string msg_ = errorOf(text);                                                   \
        EXPECT_EQ(msg_.rfind(prefix, 0), 0u) << "message: '" << msg_ << "'";                      \
        EXPECT_NE(msg_.find(reason), std::string::npos) << "message: '" << msg_ << "'";           \
    } while (0)

} // namespace

TEST(OvmTetReaderTest, SingleTetHalfFaceProperty) {
    HexEx::ParametrizedTetMesh pm;
    ASSERT_NO_THROW(pm = HexEx::readOvmTetBuffer(kTet, "tet.ovm"));
    ASSERT_EQ(pm.mesh.n_vertices(), 4u);
    ASSERT_EQ(pm.mesh.n_cells(), 1u);
    const auto& cv = pm.mesh.cell_vertices(HexEx::CellHandle(0));
    // File corner order (1 2 3 0), started at the corner opposite the last halfface (3 1 2 0),
    // is negative (outward halffaces): corners 1 and 2 swapped.
    EXPECT_EQ(cv[0].idx(), 3);
    EXPECT_EQ(cv[1].idx(), 2);
    EXPECT_EQ(cv[2].idx(), 1);
    EXPECT_EQ(cv[3].idx(), 0);
    for (int i = 0; i < 4; ++i) EXPECT_EQ(pm.params[0][static_cast<std::size_t>(i)], pm.mesh.position(cv[static_cast<std::size_t>(i)]));
    // TetMesh halfface 3 is the file's first halfface (loop 1 2 3), with its orientation.
    const auto hv = pm.mesh.halfface_vertices(HexEx::TetMesh::halfface(HexEx::CellHandle(0), 3));
    EXPECT_EQ(hv[0].idx(), 3);
    EXPECT_EQ(hv[1].idx(), 1);
    EXPECT_EQ(hv[2].idx(), 2);
    EXPECT_TRUE(pm.mesh.has_adjacency());
    EXPECT_EQ(pm.mesh.n_boundary_faces(), 4u);
}

TEST(OvmTetReaderTest, SingleTetCellPropertyCommentsAndCase) {
    std::string text = firstLines(kTet, 24);
    text = withLine(text, 1, "  ovm ascii   # header");
    text = withLine(text, 2, "# a comment line\n\nVERTICES");
    text += "CProp vec12d \"uvw\"   # per-cell corner parameters in file corner order\n"
            "1 0 0  0 1 0  0 0 1  0 0 0\n";
    HexEx::ParametrizedTetMesh pm;
    ASSERT_NO_THROW(pm = HexEx::readOvmTetBuffer(text, "tet.ovm"));
    const auto& cv = pm.mesh.cell_vertices(HexEx::CellHandle(0));
    for (int i = 0; i < 4; ++i) EXPECT_EQ(pm.params[0][static_cast<std::size_t>(i)], pm.mesh.position(cv[static_cast<std::size_t>(i)]));
}

TEST(OvmTetReaderTest, CubeHalfFacePropertyExtracts) {
    const HexEx::ParametrizedTetMesh ref = HexEx::generateCube(1, 2);
    checkRoundTrip(ref, toOvm(ref, MapStorage::HalfFace), 8);
    checkRoundTrip(ref, toOvm(ref, MapStorage::HalfFace, /*inward=*/true, "param"), 8);
    checkRoundTrip(ref, toOvm(ref, MapStorage::HalfFace, false, "Parametrization", {2, 0, 3, 1}), 8);
}

TEST(OvmTetReaderTest, CubeCellPropertyExtracts) {
    const HexEx::ParametrizedTetMesh ref = HexEx::generateCube(1, 2);
    checkRoundTrip(ref, toOvm(ref, MapStorage::Cell, false, "uvw"), 8);
    checkRoundTrip(ref, toOvm(ref, MapStorage::Cell, true, "IGM", {3, 1, 2, 0}), 8);
    const HexEx::ParametrizedTetMesh big = HexEx::generateCube(2, 3);
    checkRoundTrip(big, toOvm(big, MapStorage::Cell, false, "parameters", {1, 2, 3, 0}), 27);
}

TEST(OvmTetReaderTest, FileApiAndSecondPropertyWarning) {
    const HexEx::ParametrizedTetMesh ref = HexEx::generateCube(1, 2);
    const char* base = std::getenv("TMPDIR");
    const std::string path = std::string(base && *base ? base : "/tmp") + "/hexex-ovm-test-" +
                             std::to_string(static_cast<long>(::getpid())) + ".ovm";
    {
        std::ofstream out(path);
        out << toOvm(ref, MapStorage::HalfFace) << "CProp vec12d \"params\"\n";
        for (std::size_t c = 0; c < ref.mesh.n_cells(); ++c) out << "0 0 0 0 0 0 0 0 0 0 0 0\n";
    }
    HexEx::ReadReport rr;
    HexEx::ParametrizedTetMesh pm;
    ASSERT_NO_THROW(pm = HexEx::readOvmTetMesh(path, &rr));
    std::remove(path.c_str());
    EXPECT_EQ(paramsByVertex(pm), paramsByVertex(ref));  // the first block wins
    ASSERT_EQ(rr.warnings.size(), 2u);
    EXPECT_NE(rr.warnings[0].find("ignoring parametrization property CProp vec12d \"params\""), std::string::npos)
        << rr.warnings[0];
    EXPECT_NE(rr.warnings[1].find("skipped 1 unused property: VProp double \"unrelated\""), std::string::npos)
        << rr.warnings[1];
    EXPECT_FALSE(rr.reoriented);

    try {
        HexEx::readOvmTetMesh(path);
        FAIL() << "no error for a missing file";
    } catch (const HexEx::InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path + ": cannot open file", 0), 0u) << e.what();
    }
}

TEST(OvmTetReaderTest, UnusedVertexWarning) {
    std::string text = withLine(kTet, 3, "5");
    text = withLine(text, 7, "0 0 1\n5 5 5");
    HexEx::ReadReport rr;
    ASSERT_NO_THROW(HexEx::readOvmTetBuffer(text, "t.ovm", &rr));
    ASSERT_EQ(rr.warnings.size(), 1u);
    EXPECT_NE(rr.warnings[0].find("1 of 5 vertices are not used"), std::string::npos) << rr.warnings[0];
}

TEST(OvmTetReaderTest, ErrorsNameFileLineAndReason) {
    const std::string t = kTet;
    EXPECT_OVM_ERROR(withLine(t, 1, "OVM BINARY"), "t.ovm:1: ", "binary");
    EXPECT_OVM_ERROR(withLine(t, 1, "PLY"), "t.ovm:1: ", "expected header 'OVM ASCII'");
    EXPECT_OVM_ERROR(std::string(), "t.ovm:1: ", "unexpected end of file");
    EXPECT_OVM_ERROR(withLine(t, 2, "Edges"), "t.ovm:2: ", "expected section 'Vertices'");
    EXPECT_OVM_ERROR(withLine(t, 3, "-1"), "t.ovm:3: ", "negative vertices count");
    EXPECT_OVM_ERROR(withLine(t, 3, "four"), "t.ovm:3: ", "expected an integer");
    EXPECT_OVM_ERROR(withLine(t, 3, "0"), "t.ovm:3: ", "no vertices");
    EXPECT_OVM_ERROR(withLine(t, 5, "1 0 nan"), "t.ovm:5: ", "NaN or infinite value 'nan' for z coordinate of vertex 1");
    EXPECT_OVM_ERROR(withLine(t, 5, "1 0"), "t.ovm:5: ", "expected 3 values for vertex 1");
    EXPECT_OVM_ERROR(withLine(t, 12, "0 4"), "t.ovm:12: ", "vertex index 1 of edge 2 4 out of range [0, 4)");
    EXPECT_OVM_ERROR(withLine(t, 12, "3 3"), "t.ovm:12: ", "edge 2 connects vertex 3 to itself");
    EXPECT_OVM_ERROR(withLine(t, 19, "4 4 11 3 0"), "t.ovm:19: ", "face 1 has valence 4: only triangles");
    EXPECT_OVM_ERROR(withLine(t, 19, "3 4 11 12"), "t.ovm:19: ", "halfedge 2 of face 1 12 out of range [0, 12)");
    EXPECT_OVM_ERROR(withLine(t, 19, "3 4 11 2"), "t.ovm:19: ", "not closed");
    EXPECT_OVM_ERROR(withLine(t, 23, "0"), "t.ovm:23: ", "no tets");
    EXPECT_OVM_ERROR(withLine(t, 24, "5 0 2 4 6 1"), "t.ovm:24: ", "polyhedron 0 has 5 halffaces: only tetrahedra");
    EXPECT_OVM_ERROR(withLine(t, 24, "4 0 2 4 8"), "t.ovm:24: ", "halfface 3 of polyhedron 0 8 out of range [0, 8)");
    EXPECT_OVM_ERROR(withLine(t, 24, "4 0 2 4 4"), "t.ovm:24: ", "lists halfface 4 twice");
    EXPECT_OVM_ERROR(withLine(t, 24, "4 0 2 4 7"), "t.ovm:24: ", "not consistently oriented");
    EXPECT_OVM_ERROR(withLine(t, 24, "4 0 2"), "t.ovm:24: ", "expected 5 values");
    EXPECT_OVM_ERROR(withLine(t, 7, "1 1 0"), "t.ovm:24: ", "polyhedron 0 is degenerate in 3D");
    EXPECT_OVM_ERROR(withLine(t, 28, "1 inf 0"), "t.ovm:28: ", "NaN or infinite value 'inf' for v of halfface 2");
    EXPECT_OVM_ERROR(withLine(t, 28, "1 0"), "t.ovm:28: ", "expected 3 values for value 2 of property");
    EXPECT_OVM_ERROR(firstLines(t, 30), "t.ovm:30: ", "unexpected end of file: expected value 5 of property");
    EXPECT_OVM_ERROR(withLine(t, 25, "XProp vec3d \"Parametrization\""), "t.ovm:25: ", "unknown property entity 'XProp'");
    EXPECT_OVM_ERROR(withLine(t, 25, "HFProp vec3d Parametrization"), "t.ovm:25: ", "expected a property block header");
    EXPECT_OVM_ERROR(firstLines(t, 24), "t.ovm:24: ", "no parametrization property");
    EXPECT_OVM_ERROR(withLine(t, 25, "HFProp vec3d \"colour\""), "t.ovm:33: ",
                     "found HFProp vec3d \"colour\" (line 25)");
    EXPECT_OVM_ERROR(withLine(t, 25, "HFProp double \"param\""), "t.ovm:33: ", "no parametrization property");
    EXPECT_OVM_ERROR(t + "trailing garbage\n", "t.ovm:34: ", "expected a property block header");
    // Two cells on the same halfface.
    std::string two = withLine(t, 23, "2");
    two = withLine(two, 24, "4 0 2 4 6\n4 0 3 5 7");
    EXPECT_OVM_ERROR(two, "t.ovm:25: ", "halfface 0 is used by polyhedron 0 and polyhedron 1");
}

TEST(OvmTetReaderTest, FoldedMeshIsRejected) {
    // Two tets on the face (1 2 3); the second apex lies on the same side as the first.
    HexEx::ParametrizedTetMesh pm;
    pm.mesh.add_vertex(HexEx::Vec3d(0, 0, 0));
    pm.mesh.add_vertex(HexEx::Vec3d(1, 0, 0));
    pm.mesh.add_vertex(HexEx::Vec3d(0, 1, 0));
    pm.mesh.add_vertex(HexEx::Vec3d(0, 0, 1));
    pm.mesh.add_vertex(HexEx::Vec3d(0.1, 0.1, 0.1));
    pm.mesh.add_cell({HexEx::VertexHandle(0), HexEx::VertexHandle(1), HexEx::VertexHandle(2), HexEx::VertexHandle(3)});
    pm.mesh.add_cell({HexEx::VertexHandle(4), HexEx::VertexHandle(1), HexEx::VertexHandle(3), HexEx::VertexHandle(2)});
    pm.params.assign(2, {HexEx::Vec3d(0, 0, 0), HexEx::Vec3d(1, 0, 0), HexEx::Vec3d(0, 1, 0), HexEx::Vec3d(0, 0, 1)});
    const std::string text = toOvm(pm, MapStorage::HalfFace);
    EXPECT_OVM_ERROR(text, "t.ovm:", "inconsistent orientation");
    EXPECT_NE(errorOf(text).find("inverted in 3D relative to its neighbours"), std::string::npos) << errorOf(text);
}

TEST(OvmTetReaderTest, CliExtractReadsOvmByExtension) {
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    const std::filesystem::path tool = self.parent_path().parent_path() / "Tools" / "hexex" / "hexex";
    if (ec || !std::filesystem::is_regular_file(tool, ec) || ::access(tool.c_str(), X_OK) != 0)
        GTEST_SKIP() << "hexex binary not found next to the test binary";
    const char* base = std::getenv("TMPDIR");
    const std::string stem = std::string(base && *base ? base : "/tmp") + "/hexex-ovm-cli-" +
                             std::to_string(static_cast<long>(::getpid()));
    const HexEx::ParametrizedTetMesh ref = HexEx::generateCube(1, 2);
    {
        std::ofstream out(stem + ".OVM");
        out << toOvm(ref, MapStorage::HalfFace);
    }
    {
        std::ofstream out(stem + "-bad.ovm");
        out << firstLines(kTet, 24);
    }
    auto run = [&](const std::string& in, const std::string& err) {
        const std::string cmd = "'" + tool.string() + "' extract '" + in + "' -o '" + stem + ".vtu' -q 2>'" + err + "'";
        const int raw = std::system(cmd.c_str());
        return raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    };
    EXPECT_EQ(run(stem + ".OVM", stem + ".err"), 0);
    EXPECT_EQ(run(stem + "-bad.ovm", stem + ".err"), 2);
    std::ifstream errIn(stem + ".err");
    std::stringstream err;
    err << errIn.rdbuf();
    EXPECT_NE(err.str().find("-bad.ovm:24: no parametrization property"), std::string::npos) << err.str();
    for (const char* suffix : {".OVM", "-bad.ovm", ".vtu", ".err"}) std::remove((stem + suffix).c_str());
}
