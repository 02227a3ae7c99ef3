/// @file OvmHexFacesTest.cc
/// The all-hex face and edge numbering (OvmHexFaces.hh) against buildOvmFaces() on the same
/// quads: hex grids with shuffled vertices, hexes and corner orders, closed edge rings, and
/// the cases it must refuse (a repeated vertex, a quad of three hexes), where
/// ovmFlatFromHexMesh() falls back to buildOvmFaces().

#include <HexEx/IO/OvmHexFaces.hh>
#include <HexEx/IO/OvmModel.hh>

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

using namespace HexEx;

namespace {

/// An nx x ny x nz block of unit hexes; vertex ids, hex order and each hex's corner order
/// (one of the 24 rotations) shuffled with @p seed (seed 0: no shuffling).
HexMesh hexBlock(int nx, int ny, int nz, unsigned seed) {
    HexMesh m;
    const auto id = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) m.vertices.push_back(Vec3d(i, j, k));
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                m.hexes.push_back({{id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                                    id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)}});
    if (seed == 0) return m;
    std::mt19937 rng(seed);
    std::vector<int> perm(m.vertices.size());
    std::iota(perm.begin(), perm.end(), 0);
    std::shuffle(perm.begin(), perm.end(), rng);
    std::vector<Vec3d> pos(m.vertices.size());
    for (std::size_t v = 0; v < perm.size(); ++v) pos[static_cast<std::size_t>(perm[v])] = m.vertices[v];
    m.vertices = pos;
    std::shuffle(m.hexes.begin(), m.hexes.end(), rng);
    // Rotations of the VTK corner order: turn about the vertical axis, turn upside down.
    constexpr int turn[8] = {1, 2, 3, 0, 5, 6, 7, 4}, flip[8] = {4, 7, 6, 5, 0, 3, 2, 1};
    constexpr int tilt[8] = {1, 5, 6, 2, 0, 4, 7, 3};  // the side 1-2-6-5 becomes the bottom
    for (auto& h : m.hexes) {
        for (auto& v : h) v = perm[static_cast<std::size_t>(v)];
        const int r = static_cast<int>(rng() % 64);
        const int* ops[3] = {turn, flip, tilt};
        for (int o = 0; o < 3; ++o)
            for (int t = 0; t < ((r >> (2 * o)) & 3); ++t) {
                std::array<int, 8> g;
                for (int c = 0; c < 8; ++c) g[static_cast<std::size_t>(c)] = h[static_cast<std::size_t>(ops[o][c])];
                h = g;
            }
    }
    return m;
}

/// buildOvmFaces() of the hexes' quads in loop order (the reference numbering).
OvmFaces reference(const HexMesh& m) {
    IntLists loops;
    for (const auto& h : m.hexes)
        for (const auto& q : detail::kOvmHexFaces) {
            int l[4];
            for (int j = 0; j < 4; ++j) l[j] = h[static_cast<std::size_t>(q[j])];
            loops.add(l, l + 4);
        }
    return buildOvmFaces(loops, static_cast<int>(m.vertices.size()), 1);
}

/// The per-vertex numbering, or a failure.
testing::AssertionResult fast(const HexMesh& m, int threads, OvmFaces& out) {
    if (!ovmHexFaces(m, threads, out)) return testing::AssertionFailure() << "ovmHexFaces refused";
    return testing::AssertionSuccess();
}

void expectSame(const OvmFaces& a, const OvmFaces& b) {
    EXPECT_EQ(a.halffaces, b.halffaces);
    EXPECT_EQ(a.edges, b.edges);
    // ovmHexFaces() stores the faces' halfedges as lists of 4 (stride form), buildOvmFaces()
    // with offsets: the same lists.
    ASSERT_EQ(a.faceHalfedges.size(), b.faceHalfedges.size());
    for (std::size_t f = 0; f < a.faceHalfedges.size(); ++f)
        ASSERT_EQ(std::vector<int>(a.faceHalfedges.begin(f), a.faceHalfedges.end(f)),
                  std::vector<int>(b.faceHalfedges.begin(f), b.faceHalfedges.end(f)))
            << "face " << f;
    EXPECT_EQ(a.faceHalfedges.values, b.faceHalfedges.values);
}

} // namespace

TEST(OvmHexFaces, OrderedBlockMatchesBuildOvmFaces) {
    const HexMesh m = hexBlock(3, 2, 2, 0);
    OvmFaces f;
    ASSERT_TRUE(fast(m, 1, f));
    const OvmFaces r = reference(m);
    EXPECT_EQ(r.faceHalfedges.size(), 52u);  // 4*2*2 + 3*3*2 + 3*2*3 faces across x, y, z
    expectSame(f, r);
}

TEST(OvmHexFaces, ShuffledBlocksMatchOnAnyThreadCount) {
    for (unsigned seed = 1; seed <= 4; ++seed) {
        // 30 x 30 x 25 = 22,500 hexes: above the parallel threshold.
        const HexMesh m = seed == 1 ? hexBlock(30, 30, 25, seed) : hexBlock(4 + seed, 3, 2 + seed, seed);
        const OvmFaces r = reference(m);
        for (const int threads : {1, 2, 3}) {
            SCOPED_TRACE("seed " + std::to_string(seed) + ", threads " + std::to_string(threads));
            OvmFaces f;
            ASSERT_TRUE(fast(m, threads, f));
            expectSame(f, r);
        }
    }
}

TEST(OvmHexFaces, FlatMeshMatchesTheReference) {
    // ovmFlatFromHexMesh() uses ovmHexFaces() from 500,000 hexes on, buildOvmFaces() below.
    HexMesh m = hexBlock(3, 3, 3, 7);
    const OvmFlatMesh fastFlat = ovmFlatFromHexMesh(m, 2);
    const OvmFaces r = reference(m);
    EXPECT_EQ(fastFlat.topology, OvmTopology::Hexahedral);
    EXPECT_EQ(fastFlat.edges, r.edges);
    EXPECT_EQ(fastFlat.faces.values, r.faceHalfedges.values);
    ASSERT_EQ(fastFlat.cells.size(), 27u);
    EXPECT_EQ(fastFlat.cells.values[0], r.halffaces[detail::kOvmHexOrder[0]]);
    EXPECT_EQ(fastFlat.cells.values[2], r.halffaces[detail::kOvmHexOrder[2]]);
}

TEST(OvmHexFaces, RefusesARepeatedVertex) {
    HexMesh m = hexBlock(2, 1, 1, 0);
    m.hexes[1][6] = m.hexes[1][7];
    OvmFaces f;
    EXPECT_FALSE(ovmHexFaces(m, 1, f));
    EXPECT_EQ(ovmFlatFromHexMesh(m, 1).edges, reference(m).edges);
}

TEST(OvmHexFaces, RefusesEveryPairOfRepeatedCorners) {
    // All 28 corner pairs (corner distances 1-7 around the VTK order) of the last hex.
    const HexMesh block = hexBlock(2, 2, 1, 3);
    for (std::size_t i = 0; i < 8; ++i)
        for (std::size_t j = i + 1; j < 8; ++j) {
            HexMesh m = block;
            m.hexes.back()[j] = m.hexes.back()[i];
            OvmFaces f;
            EXPECT_FALSE(ovmHexFaces(m, 1, f)) << "corners " << i << " and " << j;
        }
    OvmFaces f;
    EXPECT_TRUE(ovmHexFaces(block, 1, f));
}

TEST(OvmHexFaces, RefusesQuadsOfOneVertexSetInAnotherCycle) {
    // The upper hex's bottom has the lower hex's top vertices, but two adjacent corners
    // swapped: the same vertex set in another cycle (a side of one is a diagonal of the other).
    HexMesh m = hexBlock(1, 1, 2, 0);
    ASSERT_EQ(m.hexes[1][0], m.hexes[0][4]);  // the upper hex sits on the lower one's top
    std::swap(m.hexes[1][1], m.hexes[1][2]);
    OvmFaces f;
    EXPECT_FALSE(ovmHexFaces(m, 1, f));
    const OvmFlatMesh flat = ovmFlatFromHexMesh(m, 1);  // through buildOvmFaces()
    const OvmFaces r = reference(m);
    EXPECT_EQ(flat.edges, r.edges);
    EXPECT_EQ(flat.faces.values, r.faceHalfedges.values);
}

TEST(OvmHexFaces, FacesAndCellsAreListsOfFourAndSix) {
    // The stride form of IntLists: no offsets, every list of the same length.
    const HexMesh m = hexBlock(3, 2, 2, 5);
    OvmFaces f;
    ASSERT_TRUE(fast(m, 2, f));
    EXPECT_EQ(f.faceHalfedges.stride, 4u);
    EXPECT_EQ(f.faceHalfedges.size(), 52u);
    EXPECT_EQ(f.faceHalfedges.length(51), 4u);
    EXPECT_EQ(f.faceHalfedges.end(51), f.faceHalfedges.values.data() + 4 * 52);
    IntLists cells;
    cells.resizeUniform(3, 6);
    EXPECT_EQ(cells.size(), 3u);
    EXPECT_EQ(cells.begin(2), cells.values.data() + 12);
    EXPECT_EQ(cells.length(0), 6u);
}

TEST(OvmHexFaces, RefusesAQuadOfThreeHexes) {
    HexMesh m = hexBlock(1, 1, 2, 0);
    // A third hex on the quad between the two: its top is their shared quad, its bottom new.
    const int base = static_cast<int>(m.vertices.size());
    for (int c = 0; c < 4; ++c) m.vertices.push_back(Vec3d(c, 9, 9));
    const auto& lower = m.hexes[0];
    m.hexes.push_back({{base, base + 1, base + 2, base + 3, lower[4], lower[5], lower[6], lower[7]}});
    OvmFaces f;
    EXPECT_FALSE(ovmHexFaces(m, 1, f));
    // The writers' model still numbers it, through buildOvmFaces().
    const OvmFlatMesh flat = ovmFlatFromHexMesh(m, 1);
    EXPECT_EQ(flat.faces.size(), reference(m).faceHalfedges.size());
    EXPECT_EQ(flat.faces.size(), 16u);  // 11 of the two stacked hexes, 5 of the third (its top is theirs)
}

TEST(OvmHexFaces, TwoHexesTouchingAlongOneEdgeShareIt) {
    // Two hexes that touch along one edge only (no shared quad): one vertex pair, one edge,
    // as buildOvmFaces() has it.
    HexMesh m = hexBlock(1, 1, 1, 0);
    const int b = static_cast<int>(m.vertices.size());
    for (int c = 0; c < 6; ++c) m.vertices.push_back(Vec3d(c, 5, 5));
    // Edge 1-5 of the first hex is edge 0-4 of the second.
    m.hexes.push_back({{m.hexes[0][1], b, b + 1, b + 2, m.hexes[0][5], b + 3, b + 4, b + 5}});
    OvmFaces f;
    ASSERT_TRUE(fast(m, 1, f));
    const OvmFaces r = reference(m);
    expectSame(f, r);
    EXPECT_EQ(f.edges.size(), 23u);  // 12 + 12 hex edges, one pair shared
    EXPECT_EQ(f.faceHalfedges.size(), 12u);
}
