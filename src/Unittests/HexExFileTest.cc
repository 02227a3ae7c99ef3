/// @file HexExFileTest.cc
/// Tests of the .hexex reader and writer: every error case, round trip, mirrored meshes.

#include <HexEx/Core/Error.hh>
#include <HexEx/IO/HexExFile.hh>

#include <gtest/gtest.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

using namespace HexEx;

namespace {

// Two positive tets sharing the face (1 2 3); parameters equal to the positions.
// Line 1: vertex count, lines 2-6: vertices, line 7: tet count, lines 8-9: tets.
const char* kVertices[5] = {"0 0 0", "1 0 0", "0 1 0", "0 0 1", "1 1 1"};

std::string tetLine(const std::vector<int>& corners, const std::vector<std::string>& pos) {
    std::string s;
    for (int c : corners) s += std::to_string(c) + " ";
    for (std::size_t i = 0; i < corners.size(); ++i)
        s += pos[static_cast<std::size_t>(corners[i])] + (i + 1 < corners.size() ? " " : "");
    return s;
}

/// Lines of the valid two-tet file (without newlines), to be edited by the tests.
std::vector<std::string> validLines() {
    std::vector<std::string> pos(kVertices, kVertices + 5);
    return {"5",  kVertices[0], kVertices[1], kVertices[2], kVertices[3], kVertices[4], "2",
            tetLine({0, 1, 2, 3}, pos), tetLine({1, 2, 3, 4}, pos)};
}

std::string join(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return s;
}

/// The message of the InputError thrown when reading @p text, or "" (test failure) if none.
std::string errorOf(const std::string& text) {
    try {
        readHexExBuffer(text, "test.hexex");
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no InputError for input:\n" << text;
    return "";
}

/// Expects the error to start with "test.hexex:<line>: " and to contain @p reason.
void expectError(const std::string& text, int line, const std::string& reason) {
    const std::string msg = errorOf(text);
    const std::string prefix = "test.hexex:" + std::to_string(line) + ": ";
    EXPECT_EQ(msg.rfind(prefix, 0), 0u) << "message: " << msg << "\nexpected prefix: " << prefix;
    EXPECT_NE(msg.find(reason), std::string::npos) << "message: " << msg << "\nexpected reason: " << reason;
}

} // namespace

TEST(HexExFileTest, ReadsValidFile) {
    ReadReport report;
    const auto pm = readHexExBuffer(join(validLines()), "test.hexex", &report);
    EXPECT_EQ(pm.mesh.n_vertices(), 5u);
    EXPECT_EQ(pm.mesh.n_cells(), 2u);
    EXPECT_TRUE(pm.mesh.has_adjacency());
    EXPECT_EQ(pm.mesh.n_boundary_faces(), 6u);
    EXPECT_FALSE(report.reoriented);
    EXPECT_TRUE(report.warnings.empty());
    EXPECT_EQ(pm.params[1][3], Vec3d(1, 1, 1));
}

TEST(HexExFileTest, AcceptsCrLfTabsPlusSignsAndAnyLayout) {
    std::string text = "5\r\n0 0 0\r\n+1 0 0\r\n0\t1 0\r\n0 0 1e0\r\n1 1 1\r\n2\r\n";
    auto lines = validLines();
    text += lines[7] + "\r\n";
    // The second tet spread over several lines.
    std::string t = lines[8];
    for (auto& ch : t)
        if (ch == ' ') ch = '\n';
    text += t + "\r\n\r\n";
    const auto pm = readHexExBuffer(text, "test.hexex");
    EXPECT_EQ(pm.mesh.n_cells(), 2u);
}

TEST(HexExFileTest, UnderflowReadsAsZero) {
    auto lines = validLines();
    lines[1] = "1e-400 0 0";
    const auto pm = readHexExBuffer(join(lines), "test.hexex");
    EXPECT_EQ(pm.mesh.position(VertexHandle(0))[0], 0.0);
}

TEST(HexExFileTest, MissingFile) {
    try {
        readHexExFile("/nonexistent/dir/missing.hexex");
        FAIL() << "no exception";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "/nonexistent/dir/missing.hexex: cannot open file: No such file or directory");
    }
}

TEST(HexExFileTest, DirectoryIsNotAFile) {
    const std::string dir = std::filesystem::temp_directory_path().string();
    try {
        readHexExFile(dir);
        FAIL() << "no exception";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), dir + ": cannot open file: is a directory");
    }
}

// Files are memory-mapped; an empty file (which cannot be mapped) and a named pipe (not a
// regular file) are read into memory instead, with the same results and errors.
TEST(HexExFileTest, EmptyFileAndNamedPipeAreReadWithoutMapping) {
    const auto dir = std::filesystem::temp_directory_path();
    const std::string empty = (dir / ("hexex_empty_" + std::to_string(::getpid()) + ".hexex")).string();
    { std::ofstream(empty, std::ios::binary); }
    try {
        readHexExFile(empty);
        ADD_FAILURE() << "no exception";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), empty + ":1: unexpected end of file: expected vertex count");
    }
    std::filesystem::remove(empty);

    const std::string fifo = (dir / ("hexex_fifo_" + std::to_string(::getpid()) + ".hexex")).string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
    const std::string text = join(validLines());
    std::thread writer([&] { std::ofstream(fifo, std::ios::binary) << text; });
    const ParametrizedTetMesh fromPipe = readHexExFile(fifo);
    writer.join();
    std::filesystem::remove(fifo);
    const ParametrizedTetMesh fromText = readHexExBuffer(text, "test.hexex");
    EXPECT_EQ(fromPipe.mesh.n_cells(), 2u);
    EXPECT_EQ(fromPipe.params, fromText.params);
}

TEST(HexExFileTest, EmptyFile) { expectError("", 1, "unexpected end of file: expected vertex count"); }

TEST(HexExFileTest, TruncatedInVertices) {
    auto lines = validLines();
    lines.resize(4);
    lines[3] = "0 1";  // vertex 2 lacks z
    expectError(join(lines), 4, "unexpected end of file: expected z coordinate of vertex 2 (file declares 5 vertices)");
}

TEST(HexExFileTest, TruncatedWithoutFinalNewline) {
    std::string text = join(validLines());
    text.resize(text.size() - 3);  // drop " 1\n": last parameter of tet 1
    expectError(text, 9, "unexpected end of file: expected parameter w of corner 3 of tet 1 (file declares 2 tets)");
}

TEST(HexExFileTest, TruncatedBeforeTetCount) {
    auto lines = validLines();
    lines.resize(6);
    expectError(join(lines), 6, "unexpected end of file: expected tet count");
}

TEST(HexExFileTest, TruncatedInTets) {
    auto lines = validLines();
    lines.pop_back();
    expectError(join(lines), 8, "unexpected end of file: expected vertex index 0 of tet 1 (file declares 2 tets)");
    lines = validLines();
    lines[8].resize(lines[8].rfind(' '));  // last parameter missing
    expectError(join(lines), 9, "unexpected end of file: expected parameter w of corner 3 of tet 1");
}

TEST(HexExFileTest, TrailingData) {
    auto lines = validLines();
    lines.push_back(lines[8]);
    expectError(join(lines), 10, "unexpected data after last tet");
}

TEST(HexExFileTest, VertexCountTooSmall) {
    // One vertex fewer declared: "1 1 1" of the fifth vertex is read as tet count 1 and a tet "1 1 ...".
    auto lines = validLines();
    lines[0] = "4";
    expectError(join(lines), 6, "tet 0 repeats vertex 1");
}

TEST(HexExFileTest, NotANumber) {
    auto lines = validLines();
    lines[2] = "1 abc 0";
    expectError(join(lines), 3, "expected a number for y coordinate of vertex 1, got 'abc'");
    lines = validLines();
    lines[0] = "five";
    expectError(join(lines), 1, "expected an integer for vertex count, got 'five'");
    lines = validLines();
    lines[7].replace(0, 1, "0.5");
    expectError(join(lines), 8, "expected an integer for vertex index 0 of tet 0");
    lines = validLines();
    lines[8] += "x";
    expectError(join(lines), 9, "expected a number for parameter w of corner 3 of tet 1, got '1x'");
}

TEST(HexExFileTest, NegativeCounts) {
    auto lines = validLines();
    lines[0] = "-5";
    expectError(join(lines), 1, "negative vertex count -5");
    lines = validLines();
    lines[6] = "-2";
    expectError(join(lines), 7, "negative tet count -2");
}

TEST(HexExFileTest, HugeCounts) {
    auto lines = validLines();
    lines[0] = "999999999999";
    expectError(join(lines), 1, "vertex count 999999999999 too large");
    lines[0] = "99999999999999999999999999";
    expectError(join(lines), 1, "out of range for vertex count");
    // Within range but far more than the file holds: must fail on truncation, not on allocation.
    lines = validLines();
    lines[0] = "2000000000";
    expectError(join(lines), 9, "unexpected end of file");
    lines = validLines();
    lines[6] = "200000000";
    expectError(join(lines), 9, "unexpected end of file: expected vertex index 0 of tet 2 (file declares 200000000 tets)");
}

TEST(HexExFileTest, NaNAndInf) {
    for (const char* bad : {"nan", "NaN", "inf", "-inf", "infinity"}) {
        auto lines = validLines();
        lines[4] = std::string("0 ") + bad + " 1";
        expectError(join(lines), 5, "NaN or infinite value");
        lines = validLines();
        lines[7] = lines[7].substr(0, lines[7].rfind(' ')) + " " + bad;  // last parameter of tet 0
        expectError(join(lines), 8, "NaN or infinite value");
    }
    auto lines = validLines();
    lines[1] = "1e400 0 0";
    expectError(join(lines), 2, "out of double range for x coordinate of vertex 0");
}

TEST(HexExFileTest, VertexIndexOutOfRange) {
    auto lines = validLines();
    lines[8].replace(lines[8].find("4 "), 1, "5");
    expectError(join(lines), 9, "vertex index 5 of tet 1 out of range [0, 5)");
    lines = validLines();
    lines[7].replace(0, 1, "-1");
    expectError(join(lines), 8, "vertex index -1 of tet 0 out of range [0, 5)");
}

TEST(HexExFileTest, RepeatedVertex) {
    auto lines = validLines();
    lines[8].replace(lines[8].find("4 "), 1, "2");
    expectError(join(lines), 9, "tet 1 repeats vertex 2");
}

TEST(HexExFileTest, EmptyMesh) {
    expectError("0\n0\n", 1, "mesh has no vertices");
    expectError("1\n0 0 0\n0\n", 3, "mesh has no tets");
}

TEST(HexExFileTest, DegenerateIn3D) {
    auto lines = validLines();
    lines[5] = "1 1 -1";  // vertex 4 in the plane x+y+z=1 of vertices 1, 2, 3
    expectError(join(lines), 9, "tet 1 is degenerate in 3D (zero volume)");
}

TEST(HexExFileTest, MixedOrientationNamesMinority) {
    auto lines = validLines();
    // Tet 1 inverted.
    std::vector<std::string> pos(kVertices, kVertices + 5);
    lines[8] = tetLine({1, 3, 2, 4}, pos);
    expectError(join(lines), 9, "inconsistent tet orientation: 1 of 2 tets are inverted in 3D");
    EXPECT_NE(errorOf(join(lines)).find("tet 1 (line 9)"), std::string::npos);

    // Majority inverted, one positive tet: the positive one is named.
    lines = validLines();
    lines[0] = "6";
    lines.insert(lines.begin() + 6, "1 0 -1");  // vertex 5; tets now start on line 9
    pos.push_back("1 0 -1");
    lines[7] = "3";
    lines[8] = tetLine({0, 2, 1, 3}, pos);   // inverted
    lines[9] = tetLine({1, 2, 3, 4}, pos);   // positive
    lines.push_back(tetLine({0, 1, 2, 5}, pos));  // inverted (5 below the plane z=0)
    const std::string msg = errorOf(join(lines));
    EXPECT_EQ(msg.rfind("test.hexex:10: ", 0), 0u) << msg;
    EXPECT_NE(msg.find("1 of 3 tets are positively oriented"), std::string::npos) << msg;
    EXPECT_NE(msg.find("tet 1 (line 10)"), std::string::npos) << msg;
}

TEST(HexExFileTest, MixedOrientationListsAtMostFive) {
    // A fan of 14 tets around the z axis; 7 of them inverted.
    std::ostringstream os;
    const int n = 14;
    os << (n + 2) << "\n0 0 0\n0 0 1\n";
    for (int i = 0; i < n; ++i) {
        const double a = 2 * std::acos(-1.0) * i / n;
        char buf[100];
        std::snprintf(buf, sizeof buf, "%.17g %.17g 0\n", std::cos(a), std::sin(a));
        os << buf;
    }
    os << n << "\n";
    for (int i = 0; i < n; ++i) {
        const int a = 2 + i, b = 2 + (i + 1) % n;
        // Positive: 0 a b 1 (a, b counter-clockwise seen from above, apex up).
        if (i % 2) os << "0 " << b << " " << a << " 1";
        else os << "0 " << a << " " << b << " 1";
        os << " 0 0 0 0 0 0 0 0 0 0 0 0\n";
    }
    const std::string msg = errorOf(os.str());
    EXPECT_NE(msg.find("7 of 14 tets are inverted"), std::string::npos) << msg;
    EXPECT_NE(msg.find("tet 1 (line 20)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("tet 9 (line 28)"), std::string::npos) << msg;
    EXPECT_EQ(msg.find("tet 11 (line"), std::string::npos) << msg;
    EXPECT_NE(msg.find("and 2 more"), std::string::npos) << msg;
}

TEST(HexExFileTest, MirroredMeshIsReoriented) {
    auto lines = validLines();
    for (int v = 1; v <= 5; ++v) lines[static_cast<std::size_t>(v)] = "-" + lines[static_cast<std::size_t>(v)];
    // Parameters stay as they were (unmirrored), so we can check they were swapped along.
    ReadReport report;
    const auto pm = readHexExBuffer(join(lines), "test.hexex", &report);
    EXPECT_TRUE(report.reoriented);
    ASSERT_EQ(report.warnings.size(), 1u);
    EXPECT_NE(report.warnings[0].find("mesh is mirrored: all 2 tets were negatively oriented and have been reoriented"),
              std::string::npos)
        << report.warnings[0];
    const auto& c0 = pm.mesh.cell_vertices(CellHandle(0));
    EXPECT_EQ(c0[0].idx(), 0);
    EXPECT_EQ(c0[1].idx(), 1);
    EXPECT_EQ(c0[2].idx(), 3);
    EXPECT_EQ(c0[3].idx(), 2);
    EXPECT_EQ(pm.params[0][2], Vec3d(0, 0, 1));
    EXPECT_EQ(pm.params[0][3], Vec3d(0, 1, 0));
    EXPECT_EQ(pm.mesh.n_boundary_faces(), 6u);
}

TEST(HexExFileTest, NonManifoldFace) {
    // Three tets on the face (0 1 2).
    std::string text = "6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0.2 0.2 2\n0.3 0.1 3\n3\n";
    const std::string zeros = " 0 0 0 0 0 0 0 0 0 0 0 0\n";
    text += "0 1 2 3" + zeros + "0 1 2 4" + zeros + "0 1 2 5" + zeros;
    const std::string msg = errorOf(text);
    EXPECT_EQ(msg.rfind("test.hexex: non-manifold mesh", 0), 0u) << msg;
}

TEST(HexExFileTest, NonManifoldVertex) {
    // Two tets touching only at vertex 3.
    std::string text = "8\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n0 0 2\n1 0 2\n0 1 2\n3\n";
    const std::string zeros = " 0 0 0 0 0 0 0 0 0 0 0 0\n";
    text += "0 1 2 3" + zeros + "1 2 3 4" + zeros + "5 7 6 3" + zeros;
    const std::string msg = errorOf(text);
    EXPECT_EQ(msg.rfind("test.hexex: non-manifold vertex 3", 0), 0u) << msg;
}

TEST(HexExFileTest, UnusedVertexWarns) {
    auto lines = validLines();
    lines[0] = "6";
    lines.insert(lines.begin() + 6, "5 5 5");
    ReadReport report;
    const auto pm = readHexExBuffer(join(lines), "test.hexex", &report);
    EXPECT_EQ(pm.mesh.n_vertices(), 6u);
    ASSERT_EQ(report.warnings.size(), 1u);
    EXPECT_NE(report.warnings[0].find("1 of 6 vertices are not used"), std::string::npos);
}

TEST(HexExFileTest, RoundTripIsBitExact) {
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1);
    auto pm = readHexExBuffer(join(validLines()), "test.hexex");
    for (std::size_t v = 0; v < pm.mesh.n_vertices(); ++v) {
        VertexHandle vh(static_cast<int>(v));
        Vec3d p = pm.mesh.position(vh);
        for (int k = 0; k < 3; ++k) p[k] += jitter(rng);
        pm.mesh.set_position(vh, p);
    }
    // Parameters: random bit patterns (finite only) plus awkward values.
    const double special[] = {0.0, -0.0, 5e-324, 2.2250738585072014e-308, 1.7976931348623157e308, 0.1, 1.0 / 3.0,
                              -123456789.123456789};
    std::size_t s = 0;
    for (auto& tet : pm.params)
        for (auto& p : tet)
            for (int k = 0; k < 3; ++k) {
                if (s < sizeof special / sizeof special[0]) {
                    p[k] = special[s++];
                    continue;
                }
                double x;
                do {
                    const std::uint64_t bits = rng();
                    std::memcpy(&x, &bits, sizeof x);
                } while (!std::isfinite(x));
                p[k] = x;
            }
    std::stringstream ss;
    writeHexExStream(ss, pm);
    const auto back = readHexExBuffer(ss.str(), "roundtrip");
    ASSERT_EQ(back.mesh.n_vertices(), pm.mesh.n_vertices());
    ASSERT_EQ(back.mesh.n_cells(), pm.mesh.n_cells());
    for (std::size_t v = 0; v < pm.mesh.n_vertices(); ++v) {
        const Vec3d a = pm.mesh.position(VertexHandle(static_cast<int>(v)));
        const Vec3d b = back.mesh.position(VertexHandle(static_cast<int>(v)));
        EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << "vertex " << v;
    }
    for (std::size_t c = 0; c < pm.mesh.n_cells(); ++c) {
        EXPECT_EQ(pm.mesh.cell_vertices(CellHandle(static_cast<int>(c))),
                  back.mesh.cell_vertices(CellHandle(static_cast<int>(c))));
        EXPECT_EQ(std::memcmp(pm.params[c].data(), back.params[c].data(), sizeof pm.params[c]), 0) << "tet " << c;
    }
    EXPECT_TRUE(std::signbit(back.params[0][0][1]));  // -0.0 kept
}

TEST(HexExFileTest, FileRoundTrip) {
    const auto pm = readHexExBuffer(join(validLines()), "test.hexex");
    const std::string path =
        (std::filesystem::temp_directory_path() / ("hexex_io_test_" + std::to_string(::getpid()) + ".hexex")).string();
    writeHexExFile(path, pm);
    const auto back = readHexExFile(path);
    std::filesystem::remove(path);
    EXPECT_EQ(back.mesh.n_cells(), 2u);
    EXPECT_EQ(back.params, pm.params);
    std::istringstream in(join(validLines()));
    EXPECT_EQ(readHexExStream(in, "stream").mesh.n_vertices(), 5u);
    EXPECT_THROW(writeHexExFile("/nonexistent/dir/out.hexex", pm), std::runtime_error);
}

TEST(HexExFileTest, ReadsSphere) {
    const std::string path = std::string(HEXEX_SOURCE_DIR) + "/Examples/data/sphere.hexex";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "test data not found: " << path;
    ReadReport report;
    const auto pm = readHexExFile(path, &report);
    EXPECT_EQ(pm.mesh.n_vertices(), 41u);
    EXPECT_EQ(pm.mesh.n_cells(), 76u);
    EXPECT_EQ(pm.params.size(), 76u);
    EXPECT_FALSE(report.reoriented);
}
