/// @file WriterBytesTest.cc
/// The bytes of the hex mesh writers: equal to those of the writers before they were made
/// fast (hashes of files written by the earlier code), independent of the thread count and
/// of the output block size; number formatting equal to printf's "%.17g"; and the face and
/// edge numbering of buildOvmFaces() on small cases.

#include <HexEx/Generators/Generators.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/IO/BlockOutput.hh>
#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/IO/HexMeshWriters.hh>
#include <HexEx/IO/OvmFaces.hh>
#include <gtest/gtest.h>

#include "TestMeshChecks.hh"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace HexEx;

namespace {

using HexExTest::extracted;

/// 64-bit FNV-1a of @p s.
std::uint64_t fnv1a(const std::string& s) {
    std::uint64_t h = 1469598103934665603ull;
    for (const char c : s) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    return h;
}

std::string written(const HexMesh& m, HexMeshFormat f, int threads = 1) {
    std::ostringstream out;
    writeHexMeshStream(out, m, f, VtuEncoding::Binary, threads);
    return out.str();
}

/// A grid of n^3 unit hexes (vertex (i, j, k) at index i + (n+1) (j + (n+1) k)), positions
/// scaled by 1/3 so they need all 17 digits.
HexMesh hexGrid(int n) {
    HexMesh m;
    const int p = n + 1;
    for (int k = 0; k < p; ++k)
        for (int j = 0; j < p; ++j)
            for (int i = 0; i < p; ++i) m.vertices.emplace_back(i / 3.0, j / 3.0 - 1e-300, k * 1e10 / 3.0);
    const auto v = [p](int i, int j, int k) { return i + p * (j + p * k); };
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                m.hexes.push_back({{v(i, j, k), v(i + 1, j, k), v(i + 1, j + 1, k), v(i, j + 1, k), v(i, j, k + 1),
                                    v(i + 1, j, k + 1), v(i + 1, j + 1, k + 1), v(i, j + 1, k + 1)}});
    return m;
}

} // namespace

// Hashes and sizes of the files `hexex extract` wrote for `hexex generate cube --n 2 --scale 3`
// (27 hexes) with the writers before they were rewritten (commit 8491d80).
TEST(WriterBytes, SameAsEarlierWritersOnCube) {
    const HexMesh cube = extracted(generateCube(2, 3));
    ASSERT_EQ(cube.hexes.size(), 27u);
    const struct {
        HexMeshFormat format;
        std::size_t size;
        std::uint64_t hash;
    } expected[] = {{HexMeshFormat::Ovm, 5363, 0x651de33b13788339ull},
                    {HexMeshFormat::Ovmb, 3072, 0xcc388be3823ff6e3ull},
                    {HexMeshFormat::Vtk, 2983, 0x30744097d2b10209ull},
                    {HexMeshFormat::Medit, 2981, 0xd685719b27eeec54ull},
                    {HexMeshFormat::Vtu, 3262, 0x887d0b8645e460f5ull}};
    for (const auto& e : expected) {
        const std::string bytes = written(cube, e.format);
        EXPECT_EQ(bytes.size(), e.size) << static_cast<int>(e.format);
        EXPECT_EQ(fnv1a(bytes), e.hash) << static_cast<int>(e.format);
    }
}

// Large enough (68,921 vertices, 64,000 hexes) that the text is formatted in pieces on two threads.
TEST(WriterBytes, ThreadCountDoesNotChangeBytes) {
    const HexMesh m = hexGrid(40);
    for (const HexMeshFormat f : {HexMeshFormat::Ovm, HexMeshFormat::Ovmb, HexMeshFormat::Vtk, HexMeshFormat::Medit,
                                  HexMeshFormat::Vtu}) {
        const std::string one = written(m, f, 1);
        EXPECT_EQ(written(m, f, 2), one) << static_cast<int>(f);
        EXPECT_EQ(written(m, f, 3), one) << static_cast<int>(f);
    }
    // The .ovm file holds every face once: 3 n^2 (n + 1) faces and 3 n (n + 1)^2 edges.
    const std::string ovm = written(m, HexMeshFormat::Ovm, 2);
    EXPECT_NE(ovm.find("\nEdges\n" + std::to_string(3 * 40 * 41 * 41) + "\n"), std::string::npos);
    EXPECT_NE(ovm.find("\nFaces\n" + std::to_string(3 * 40 * 40 * 41) + "\n"), std::string::npos);
    const HexMesh back = readHexMeshBuffer(ovm, HexMeshFormat::Ovm, "grid.ovm");
    EXPECT_EQ(back.vertices, m.vertices);
    EXPECT_EQ(back.hexes, m.hexes);
}

TEST(WriterBytes, Real17IsPrintfFormat) {
    std::vector<double> xs = {0.0,
                              -0.0,
                              1.0,
                              -1.5,
                              0.1,
                              1.0 / 3.0,
                              1e-300,
                              5e-324,
                              1e21,
                              1e16,
                              123456789012345678.0,
                              std::numeric_limits<double>::max(),
                              std::numeric_limits<double>::min(),
                              std::numeric_limits<double>::epsilon(),
                              0.30000000000000004};
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::uniform_int_distribution<int> exponent(-320, 308);
    for (int i = 0; i < 20000; ++i) xs.push_back(std::ldexp(unit(rng), exponent(rng) / 3) * std::pow(10.0, exponent(rng) / 4));
    for (const double x : xs) {
        detail::BlockOutput o(nullptr, 64);
        o.real17(x);
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.17g", x);
        ASSERT_EQ(o.take(), std::string(buf)) << x;
    }
}

TEST(WriterBytes, SmallBlocksGiveTheSameBytes) {
    const HexMesh m = hexGrid(3);
    for (const HexMeshFormat f : {HexMeshFormat::Ovm, HexMeshFormat::Ovmb, HexMeshFormat::Vtk, HexMeshFormat::Vtu}) {
        const std::string whole = written(m, f);
        std::ostringstream out;
        {
            detail::BlockOutput o(&out, 7);
            for (std::size_t i = 0; i < whole.size(); i += 300) o << std::string_view(whole).substr(i, 300) << 'x';
            o.flush();
        }
        std::string expected;
        for (std::size_t i = 0; i < whole.size(); i += 300) expected += whole.substr(i, 300) + "x";
        EXPECT_EQ(out.str(), expected);
    }
}

TEST(OvmFaces, SharedFacesOrientationAndEdges) {
    IntLists loops;
    const std::vector<std::vector<int>> in = {{0, 1, 2, 3}, {3, 2, 1, 0}, {1, 2, 3, 0}, {2, 1, 0, 3}, {1, 4, 2}, {2, 4, 1}};
    for (const auto& l : in) loops.add(l.begin(), l.end());
    const OvmFaces f = buildOvmFaces(loops, 5, 1);
    // 0 1 2 3 is face 0; its reversal is halfface 1; a rotation keeps the direction; 2 1 0 3 reverses it.
    EXPECT_EQ(std::vector<int>(f.halffaces.begin(), f.halffaces.end()), (std::vector<int>{0, 1, 0, 1, 2, 3}));
    // Edges in order of first use: 0-1, 1-2, 2-3, 3-0 (face 0), then 1-4, 4-2 (face 1).
    ASSERT_EQ(f.edges.size(), 6u);
    EXPECT_EQ(f.edges[0], (std::array<int, 2>{{0, 1}}));
    EXPECT_EQ(f.edges[3], (std::array<int, 2>{{3, 0}}));
    EXPECT_EQ(f.edges[4], (std::array<int, 2>{{1, 4}}));
    EXPECT_EQ(f.edges[5], (std::array<int, 2>{{4, 2}}));
    ASSERT_EQ(f.faceHalfedges.size(), 2u);
    EXPECT_EQ(std::vector<int>(f.faceHalfedges.begin(0), f.faceHalfedges.end(0)), (std::vector<int>{0, 2, 4, 6}));
    // Face 1 = 1 4 2: 1->4 (edge 4), 4->2 (edge 5), 2->1 (edge 1 reversed).
    EXPECT_EQ(std::vector<int>(f.faceHalfedges.begin(1), f.faceHalfedges.end(1)), (std::vector<int>{8, 10, 3}));
    // The same on more threads, and one big bucket (vertex 0 in 100 triangles) sorted instead of compared pairwise.
    IntLists fan;
    for (int k = 0; k < 100; ++k) {
        const int t[3] = {0, 1 + k, 1 + (k + 1) % 100};
        fan.add(t, t + 3);
        const int r[3] = {1 + (k + 1) % 100, 1 + k, 0};
        fan.add(r, r + 3);
    }
    const OvmFaces g = buildOvmFaces(fan, 101, 2);
    for (int k = 0; k < 100; ++k) {
        EXPECT_EQ(g.halffaces[static_cast<std::size_t>(2 * k)], 2 * k);
        EXPECT_EQ(g.halffaces[static_cast<std::size_t>(2 * k + 1)], 2 * k + 1);
    }
    EXPECT_EQ(g.edges.size(), 200u);
}

TEST(OvmFaces, BadLoopsRejected) {
    IntLists loops;
    const int a[3] = {0, 1, 5};
    loops.add(a, a + 3);
    try {
        buildOvmFaces(loops, 5, 1);
        FAIL() << "expected an error";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "buildOvmFaces: vertex 5 out of range [0, 5)");
    }
    IntLists empty;
    empty.offsets.push_back(0);  // one list without entries
    EXPECT_THROW(buildOvmFaces(empty, 5, 1), std::invalid_argument);
}
