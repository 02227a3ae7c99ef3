/// @file QuadObjIOTest.cc
/// The OBJ files of the 2D pipeline: every map `hexex generate` and `hexex perturb` can
/// write (shapes x chart noise x amplitudes x seeds) is read back exactly by our reader and
/// by OpenMesh's OBJ reader; errors of the reader name file, line and reason; reader and
/// writers give the same result for any thread count; the same quad mesh comes out
/// through our reader and through OpenMesh's.

// OpenMesh's PropertyT<VectorT>::push_back() default-constructs an uninitialized vector,
// which GCC reports as -Wmaybe-uninitialized inside the standard library once inlined.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include <HexEx/Core/Error.hh>
#include <HexEx/Quad/TextMeshWriters.hh>
#include <HexEx/Quad/QuadExtraction.hh>
#include <HexEx/Quad/QuadGenerators.hh>
#include <HexEx/Quad/QuadMeshIO.hh>
#include <HexEx/Quad/QuadTraits.hh>
#include <HexEx/Quad/TriObjReader.hh>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using namespace HexEx;
namespace fs = std::filesystem;

namespace {

/// OpenMesh triangle mesh with double positions and texture coordinates.
struct DoubleTraits : public OpenMesh::DefaultTraits {
    typedef OpenMesh::Vec3d Point;       ///< positions
    typedef OpenMesh::Vec3d Normal;      ///< normals
    typedef OpenMesh::Vec2d TexCoord2D;  ///< texture coordinates
};
using OmTri = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

/// A temporary directory, removed at the end.
class TempDir {
public:
    TempDir() {
        const char* base = std::getenv("TMPDIR");
        std::string templ = std::string(base && *base ? base : "/tmp") + "/hexex-quadobj-XXXXXX";
        std::vector<char> buf(templ.begin(), templ.end());
        buf.push_back('\0');
        if (::mkdtemp(buf.data())) dir_ = buf.data();
    }
    ~TempDir() {
        std::error_code ec;
        if (!dir_.empty()) fs::remove_all(dir_, ec);
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }

private:
    fs::path dir_;
};

/// Reads @p path through OpenMesh's OBJ reader (per-corner texture coordinates); fails the
/// test if OpenMesh refuses it.
ParametrizedTriMesh readThroughOpenMesh(const std::string& path) {
    OmTri om;
    om.request_halfedge_texcoords2D();
    OpenMesh::IO::Options opt = OpenMesh::IO::Options::FaceTexCoord;
    const bool ok = OpenMesh::IO::read_mesh(om, path, opt);
    EXPECT_TRUE(ok) << path;
    EXPECT_TRUE(opt.face_has_texcoord()) << path;
    return toParametrizedTriMesh(om);
}

/// Corner k of triangle f of @p b that has the vertex of corner k of triangle f of @p a
/// (OpenMesh may start a face at another corner), or -1.
int matchingCorner(const ParametrizedTriMesh& a, const ParametrizedTriMesh& b, std::size_t f, std::size_t k) {
    for (std::size_t j = 0; j < 3; ++j)
        if (b.triangles[f][j] == a.triangles[f][k]) return static_cast<int>(j);
    return -1;
}

/// @p b equals @p a: the same triangles (up to a rotation of the corners) with the same
/// corner parameters and points, within @p tol (0: exactly).
void expectSameMap(const ParametrizedTriMesh& a, const ParametrizedTriMesh& b, double tol, const std::string& what) {
    ASSERT_EQ(a.points.size(), b.points.size()) << what;
    ASSERT_EQ(a.triangles.size(), b.triangles.size()) << what;
    ASSERT_EQ(b.params.size(), b.triangles.size()) << what;
    for (std::size_t v = 0; v < a.points.size(); ++v)
        for (int d = 0; d < 3; ++d) ASSERT_LE(std::fabs(a.points[v][d] - b.points[v][d]), tol) << what << " vertex " << v;
    for (std::size_t f = 0; f < a.triangles.size(); ++f)
        for (std::size_t k = 0; k < 3; ++k) {
            const int j = matchingCorner(a, b, f, k);
            ASSERT_GE(j, 0) << what << " triangle " << f;
            ASSERT_EQ((j + 3 - static_cast<int>(k)) % 3, (matchingCorner(a, b, f, 0) + 3) % 3) << what << " orientation, triangle " << f;
            for (int d = 0; d < 2; ++d) {
                const double x = a.params[f][k][d], y = b.params[f][static_cast<std::size_t>(j)][d];
                ASSERT_TRUE(std::isfinite(y)) << what;
                ASSERT_LE(std::fabs(x - y), tol * std::max(1.0, std::fabs(x))) << what << " triangle " << f << " corner " << k;
            }
        }
}

/// The faces of @p qm as vertex loops starting at their smallest vertex.
std::vector<std::vector<int>> canonicalLoops(const QuadMesh& qm) {
    std::vector<std::vector<int>> loops;
    for (const auto& q : qm.quads) loops.emplace_back(q.begin(), q.end());
    for (const auto& p : qm.polygons) loops.push_back(p);
    for (auto& l : loops) std::rotate(l.begin(), std::min_element(l.begin(), l.end()), l.end());
    return loops;
}

/// Error text of parseTriObj(@p text) named "m.obj", or "no error".
std::string parseError(const std::string& text) {
    try {
        parseTriObj(text, "m.obj");
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

/// A named generated map.
struct Shape {
    std::string name;
    ParametrizedTriMesh m;
};

/// Every 2D generator at a small size.
std::vector<Shape> smallShapes() {
    return {{"square", generateSquare(6, 5)},          {"cone-disk3", generateConeDisk(3, 3, 4)},
            {"cone-disk5", generateConeDisk(5, 4, 5)}, {"cone-disk6", generateConeDisk(6, 2, 3)},
            {"torus", generateTorus(6, 4, 7, 5)},      {"quarter-seam", generateQuarterTurnSeam(4, 5)}};
}

} // namespace

TEST(QuadObjIO, EveryGeneratedAndPerturbedMapReadsBackThroughBothReaders) {
    TempDir tmp;
    const std::string file = tmp.path("m.obj");
    int maps = 0;
    for (const Shape& s : smallShapes())
        for (const bool charts : {false, true})
            for (const double a : {0.0, 0.2, 0.3, 0.5, 0.9})
                for (unsigned seed = 1; seed <= (a == 0 ? 1u : 3u); ++seed) {
                    ParametrizedTriMesh m = s.m;
                    if (charts) applyRandomTriCharts(m, seed + 100);
                    if (a > 0) perturbTriParameters(m, a, seed);
                    const std::string what = s.name + (charts ? " charts" : "") + " a=" + std::to_string(a) + " seed " + std::to_string(seed);
                    writeParametrizedTriMesh(file, m);
                    expectSameMap(m, readParametrizedTriMesh(file), 0, what + " (ours)");
                    expectSameMap(m, readThroughOpenMesh(file), 1e-6, what + " (OpenMesh)");
                    ++maps;
                }
    EXPECT_EQ(maps, 6 * 2 * (1 + 4 * 3));
}

TEST(QuadObjIO, IssueReproducersReadBack) {
    // The issue's files, smaller: a perturbed valence-5 cone disk (a = 0.3, seed 1) and a
    // square with scale 17 perturbed with a = 0.2, seeds 1..5 (OpenMesh refused them when
    // its writer put "vt -nan 0" on boundary halfedges).
    TempDir tmp;
    const std::string file = tmp.path("p.obj");
    ParametrizedTriMesh disk = generateConeDisk(5, 31, 31);
    perturbTriParameters(disk, 0.3, 1);
    std::vector<ParametrizedTriMesh> maps = {disk};
    for (unsigned seed = 1; seed <= 5; ++seed) {
        maps.push_back(generateSquare(60, 17));
        perturbTriParameters(maps.back(), 0.2, seed);
    }
    for (const ParametrizedTriMesh& m : maps) {
        writeParametrizedTriMesh(file, m);
        const std::string text = formatTriObj(m);
        EXPECT_EQ(text.find("nan"), std::string::npos);
        EXPECT_EQ(text.find("inf"), std::string::npos);
        expectSameMap(m, readParametrizedTriMesh(file), 0, "ours");
        expectSameMap(m, readThroughOpenMesh(file), 1e-6, "OpenMesh");
    }
}

TEST(QuadObjIO, ReaderAndWritersDoNotDependOnThreads) {
    // 49,000 triangles: the writers' threshold is 20,000 elements; the reader uses one
    // thread per MB, so 3 threads really run on this 9 MB text.
    ParametrizedTriMesh m = generateConeDisk(5, 70, 70);
    perturbTriParameters(m, 0.3, 2);
    const std::string one = formatTriObj(m, 1);
    ASSERT_GT(one.size(), std::size_t(3) << 20);
    EXPECT_EQ(formatTriObj(m, 2), one);
    EXPECT_EQ(formatTriObj(m, 5), one);
    for (const int t : {1, 2, 3, 8}) expectSameMap(m, parseTriObj(one, "m.obj", t), 0, std::to_string(t) + " threads");
    QuadMesh qm;
    ASSERT_TRUE(extractQuadMesh(m, qm).valid_all_quad);
    for (const QuadFileFormat f : {QuadFileFormat::Obj, QuadFileFormat::Off, QuadFileFormat::Ply})
        EXPECT_EQ(formatQuadMesh(qm, f, 3), formatQuadMesh(qm, f, 1));
    // Errors are the first in file order for any thread count.
    std::string bad = one;
    const std::size_t late = bad.find("\nf ", bad.size() / 2);
    bad.insert(late + 1, "f 1/1 2/2\n");
    const std::size_t early = bad.find("\nvt ", bad.size() / 4);
    bad.insert(early + 1, "vt nan 0\n");
    std::string first;
    for (const int t : {1, 2, 4}) {
        try {
            parseTriObj(bad, "m.obj", t);
            FAIL() << "no error";
        } catch (const InputError& e) {
            if (first.empty()) first = e.what();
            EXPECT_EQ(std::string(e.what()), first);
        }
    }
    EXPECT_NE(first.find("u coordinate 'nan' is not finite"), std::string::npos) << first;
}

TEST(QuadObjIO, ReaderAcceptsObjVariants) {
    // Comments, blank lines, CRLF, tabs, normals, 3D texture coordinates, relative indices,
    // objects and groups; corners in the order written.
    const std::string text = "# a comment\r\nmtllib x.mtl\r\no thing\r\nv 0 0 0\r\nv\t1 0 0 1\r\nv 0 1 0\r\n\r\n"
                             "vt 0 0 0\r\nvt 1 0\r\nvt 0 1\r\nvn 0 0 1\r\ng part\r\ns off\r\nusemtl m\r\n"
                             "f 1/1/1 2/2/1 3/3/1\r\nf -3/-3 -2/-2 -1/-1\r\n";
    const ParametrizedTriMesh m = parseTriObj(text, "m.obj");
    ASSERT_EQ(m.points.size(), 3u);
    ASSERT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.triangles[1], (std::array<int, 3>{{0, 1, 2}}));
    EXPECT_EQ(m.params[0][1], Vec2d(1, 0));
    EXPECT_EQ(m.params[1][2], Vec2d(0, 1));
    EXPECT_EQ(m.points[1], Vec3d(1, 0, 0));
}

TEST(QuadObjIO, ReaderErrorsNameFileLineAndReason) {
    const std::string head = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n";
    EXPECT_EQ(parseError(head + "f 1/1 2/2 4/3\n"), "m.obj:7: vertex index 4 out of range (3 vertices in the file)");
    EXPECT_EQ(parseError(head + "f 1/1 2/2 3/0\n"), "m.obj:7: texture coordinate index 0 (OBJ indices start at 1)");
    EXPECT_EQ(parseError(head + "f 1/1 2/2 -4/3\n"), "m.obj:7: vertex index -4 out of range (3 vertices defined before this line)");
    EXPECT_EQ(parseError(head + "f 1/1 2/2 3/x\n"), "m.obj:7: expected texture coordinate index, got 'x'");
    EXPECT_EQ(parseError(head + "f 1 2 3\n"),
              "m.obj:7: no per-corner texture coordinates: face corner '1' has no vt index (faces need 'f v/vt v/vt v/vt')");
    EXPECT_EQ(parseError(head + "f 1//1 2//1 3//1\n"),
              "m.obj:7: no per-corner texture coordinates: face corner '1//1' has no vt index (faces need 'f v/vt v/vt v/vt')");
    EXPECT_EQ(parseError(head + "f 1/1 2/2 3/3 1/1\n"), "m.obj:7: face with more than 3 corners (only triangles are supported)");
    EXPECT_EQ(parseError("v 0 0 0\nvt NaN 0\nf 1/1 1/1 1/1\n"), "m.obj:2: u coordinate 'NaN' is not finite");
    EXPECT_EQ(parseError("v 0 0 inf\n"), "m.obj:1: z coordinate 'inf' is not finite");
    EXPECT_EQ(parseError("v 0 0 1e999\n"), "m.obj:1: z coordinate '1e999' is out of range");
    EXPECT_EQ(parseError("vt 0 0 0 0\n"), "m.obj:1: unexpected '0' after the texture coordinate");
    // Truncated files.
    EXPECT_EQ(parseError(head + "f 1/1 2/2"), "m.obj:7: face with 2 corners (only triangles are supported)");
    EXPECT_EQ(parseError(head + "f 1/1 2/2 3/"),
              "m.obj:7: no per-corner texture coordinates: face corner '3/' has no vt index (faces need 'f v/vt v/vt v/vt')");
    EXPECT_EQ(parseError("v 0 0 0\nv 1 0"), "m.obj:2: expected z coordinate, the line ends");
    EXPECT_EQ(parseError(head), "m.obj: no faces");
    EXPECT_EQ(parseError(""), "m.obj: no faces");
    // Through the file reader: the path names the file.
    TempDir tmp;
    const std::string file = tmp.path("bad.obj");
    {
        std::FILE* f = std::fopen(file.c_str(), "wb");
        ASSERT_NE(f, nullptr);
        const std::string t = head + "f 1/1 2/2 3/4\n";
        std::fwrite(t.data(), 1, t.size(), f);
        std::fclose(f);
    }
    try {
        readParametrizedTriMesh(file);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), file + ":7: texture coordinate index 4 out of range (3 texture coordinates in the file)");
    }
    EXPECT_THROW(readParametrizedTriMesh(tmp.path("missing.obj")), InputError);
}

TEST(QuadObjIO, SameQuadMeshThroughBothReaders) {
    TempDir tmp;
    const std::string file = tmp.path("m.obj");
    for (const Shape& s : smallShapes())
        for (const double a : {0.0, 0.3}) {
            ParametrizedTriMesh m = s.m;
            if (a > 0) perturbTriParameters(m, a, 4);
            writeParametrizedTriMesh(file, m);
            QuadMesh ours, theirs;
            const ParametrizedTriMesh in1 = readParametrizedTriMesh(file), in2 = readThroughOpenMesh(file);
            EXPECT_EQ(in1.triangles, in2.triangles) << s.name;  // the same corners in the same order
            const QuadExtractionReport r1 = extractQuadMesh(in1, ours);
            const QuadExtractionReport r2 = extractQuadMesh(in2, theirs);
            EXPECT_TRUE(r1.valid_all_quad) << s.name;
            EXPECT_EQ(r1.output.quads, r2.output.quads) << s.name;
            ASSERT_EQ(ours.vertices.size(), theirs.vertices.size()) << s.name;
            // OpenMesh reads parameters as floats: where a dart lands on a triangle edge, the
            // rounding can make another triangle own it, and a face then starts at another
            // corner. The faces are the same loops.
            EXPECT_EQ(canonicalLoops(ours), canonicalLoops(theirs)) << s.name << " a=" << a;
            for (std::size_t v = 0; v < ours.vertices.size(); ++v)
                for (int d = 0; d < 3; ++d) EXPECT_NEAR(ours.vertices[v][d], theirs.vertices[v][d], 1e-5) << s.name << " vertex " << v;
        }
}

TEST(QuadObjIO, QuadMeshFilesReadBackThroughOpenMesh) {
    // OBJ, OFF and PLY of a quad mesh with a polygon (a pentagon over the quads' vertices
    // is not manifold, so it gets its own vertices) read back by OpenMesh's readers.
    QuadMesh qm;
    ASSERT_TRUE(extractQuadMesh(generateConeDisk(5, 2, 3), qm).valid_all_quad);
    const int v0 = static_cast<int>(qm.vertices.size());
    for (int i = 0; i < 5; ++i) qm.vertices.push_back(Vec3d(10 + std::cos(1.25 * i), std::sin(1.25 * i), 0.1 * i));
    qm.polygons.push_back({v0, v0 + 1, v0 + 2, v0 + 3, v0 + 4});
    TempDir tmp;
    for (const std::string ext : {".obj", ".off", ".ply"}) {
        const std::string file = tmp.path("q" + ext);
        writeQuadMesh(file, qm);
        OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits> om;
        ASSERT_TRUE(OpenMesh::IO::read_mesh(om, file)) << ext;
        ASSERT_EQ(om.n_vertices(), qm.vertices.size()) << ext;
        ASSERT_EQ(om.n_faces(), qm.quads.size() + 1) << ext;
        for (std::size_t v = 0; v < qm.vertices.size(); ++v)
            for (int d = 0; d < 3; ++d)
                EXPECT_NEAR(om.point(OpenMesh::VertexHandle(static_cast<int>(v)))[d], qm.vertices[v][d], 1e-6) << ext;
        for (std::size_t f = 0; f < om.n_faces(); ++f) {
            std::vector<int> loop;
            for (auto vh : om.fv_range(OpenMesh::FaceHandle(static_cast<int>(f)))) loop.push_back(vh.idx());
            const std::vector<int> want = f < qm.quads.size() ? std::vector<int>(qm.quads[f].begin(), qm.quads[f].end()) : qm.polygons[0];
            ASSERT_EQ(loop.size(), want.size()) << ext << " face " << f;
            // The same loop, possibly starting at another corner.
            const auto start = std::find(loop.begin(), loop.end(), want[0]);
            ASSERT_NE(start, loop.end()) << ext;
            std::rotate(loop.begin(), start, loop.end());
            EXPECT_EQ(loop, want) << ext << " face " << f;
        }
    }
}
