// Generalized map kernel (2D and 3D), the validator, and dart annihilation step by step.

#include "../TestSupport/HexGMapFixtures.hh"

#include <HexEx/Core/UnionFind.hh>
#include <HexEx/GMap/GMap.hh>
#include <HexEx/GMap/GMapValidator.hh>
#include <HexEx/Postprocessing/DartAnnihilation.hh>
#include <HexEx/Postprocessing/FaceConnectionRepair.hh>
#include <HexEx/Postprocessing/LocalHexCheck.hh>
#include <HexEx/Postprocessing/LocalVertexCheck.hh>

#include <gtest/gtest.h>

#include <random>

#include <numeric>

#include <map>

#include <algorithm>
#include <string>

using namespace HexEx;

namespace {
/// A quad as a 2D generalized map: 8 darts, alpha_0 pairs along edges, alpha_1 at corners.
GMap<2> makeQuad() {
    GMap<2> g;
    g.add_darts(8);
    for (int k = 0; k < 4; ++k) {
        g.sew(DartHandle(2 * k), DartHandle(2 * k + 1), 0);            // edge k
        g.sew(DartHandle(2 * k + 1), DartHandle((2 * k + 2) % 8), 1);  // corner after edge k
    }
    return g;
}

/// A single hexahedron as a 3D generalized map (48 darts; numbering in HexGMapFixtures.hh).
GMap<3> makeHex() { return HexExTestSupport::makeHexGMaps(1); }
} // namespace

TEST(GMap, QuadOrbits2D) {
    GMap<2> g = makeQuad();
    EXPECT_EQ(g.orbit(DartHandle(0), 0b011).size(), 8u);  // the face
    EXPECT_EQ(g.orbit(DartHandle(0), 0b001).size(), 2u);  // an edge
    EXPECT_EQ(g.orbit(DartHandle(1), 0b010).size(), 2u);  // a corner
    EXPECT_TRUE(g.is_free(DartHandle(0), 2));               // boundary edge of a lone quad
    g.unsew(DartHandle(0), 0);
    EXPECT_TRUE(g.is_free(DartHandle(1), 0));
    EXPECT_EQ(g.orbit(DartHandle(0), 0b011).size(), 8u);  // still connected through alpha_1
    g.erase(DartHandle(3));
    EXPECT_FALSE(g.is_alive(DartHandle(3)));
    EXPECT_TRUE(g.is_free(DartHandle(2), 0));  // 3 was 2's alpha_0 partner ...
    EXPECT_TRUE(g.is_free(DartHandle(4), 1));  // ... and 4's alpha_1 partner
}

TEST(GMap, ValidatorAcceptsAHexAndCatchesBrokenLinks) {
    GMap<3> g = makeHex();
    auto v = validateHexGMap(g);
    EXPECT_TRUE(v.valid()) << v.summary();
    EXPECT_EQ(v.darts, 48);
    EXPECT_EQ(v.boundary_darts, 48);
    // Break one alpha_2 link in one direction only: not an involution any more.
    GMap<3> h = g;
    h.link(DartHandle(0), DartHandle(0), 2);
    v = validateHexGMap(h);
    EXPECT_FALSE(v.valid());
    EXPECT_GT(v.not_involution, 0);
    // Unsew a whole alpha_2 pair: the cell opens.
    h = g;
    h.unsew(DartHandle(0), 2);
    v = validateHexGMap(h);
    EXPECT_FALSE(v.valid());
    EXPECT_EQ(v.open_links, 2);  // dart 0 and its former partner
}

TEST(GMap, CellByCellLabelsAgreeWithGenericOrbits) {
    GMap<3> g = makeHex();
    HexOrbitLabels labels;
    EXPECT_TRUE(validateHexGMap(g, &labels).valid());
    ASSERT_EQ(labels.cell_offset.size(), 2u);  // involutive map: per-cell dart lists filled
    EXPECT_EQ(labels.cell_darts.size(), 48u);
    std::vector<int> cellDarts = labels.cell_darts;
    EXPECT_EQ(cellDarts.front(), 0);  // breadth-first from the smallest dart
    std::sort(cellDarts.begin(), cellDarts.end());
    for (int d = 0; d < 48; ++d) EXPECT_EQ(cellDarts[static_cast<std::size_t>(d)], d);
    EXPECT_EQ(labels.face_size, std::vector<int>(6, 8));
    EXPECT_EQ(labels.corner_size, std::vector<int>(8, 6));
    int nv = 0, nGeneric = 0;
    EXPECT_EQ(labelVertexOrbits(g, labels, &nv), labelOrbits(g, 0b1110, &nGeneric));
    EXPECT_EQ(nv, nGeneric);
    long boundary = 0;
    EXPECT_EQ(countQuadOrbits(g, labels, &boundary), 6);
    EXPECT_EQ(boundary, 6);
    // Not an involution: the general path, without per-cell lists, same answers.
    GMap<3> h = g;
    h.link(DartHandle(0), DartHandle(0), 2);
    HexOrbitLabels broken;
    validateHexGMap(h, &broken);
    EXPECT_TRUE(broken.cell_offset.empty());
    EXPECT_EQ(labelVertexOrbits(h, broken, &nv), labelOrbits(h, 0b1110, &nGeneric));
    int nq = 0;
    labelOrbits(h, 0b1011, &nq);
    EXPECT_EQ(countQuadOrbits(h, broken, &boundary), nq);
}

// Many pairs of hexes glued over one quad, every third pair only partly (3 of 8 alpha_3
// links cut): enough darts that the candidate search runs in several chunks; the repair
// must sew exactly the missing links, with any thread count.
TEST(GMap, PartialFaceConnectionsRepairedWithAnyThreadCount) {
    const GMap<3> hex = makeHex();
    const int pairs = 1800;  // 172800 darts
    GMap<3> g;
    g.add_darts(static_cast<std::size_t>(pairs) * 96);
    for (int p = 0; p < pairs; ++p)
        for (int h = 0; h < 2; ++h) {
            const int base = 96 * p + 48 * h;
            for (int d = 0; d < 48; ++d)
                for (int i = 0; i < 3; ++i) g.link(DartHandle(base + d), DartHandle(base + hex.alpha(DartHandle(d), i).idx()), i);
        }
    for (int p = 0; p < pairs; ++p)
        for (int d = 8; d < 16; ++d) {  // quad 1 of the first hex to quad 1 of the second
            if (p % 3 == 0 && (d == 9 || d == 12 || d == 14)) continue;
            g.sew(DartHandle(96 * p + d), DartHandle(96 * p + 48 + d), 3);
        }
    GMap<3> full = g;
    for (int p = 0; p < pairs; p += 3)
        for (int d : {9, 12, 14}) full.sew(DartHandle(96 * p + d), DartHandle(96 * p + 48 + d), 3);
    EXPECT_TRUE(validateHexGMap(full).valid());
    for (int threads : {1, 2, 3}) {
        SCOPED_TRACE("threads = " + std::to_string(threads));
        GMap<3> h = g;
        EXPECT_EQ(completePartialFaceConnections(h, threads), (pairs + 2) / 3);
        EXPECT_EQ(h.links(), full.links());
    }
}

// Many cells with their darts shuffled over the whole index range (as in real maps, where a
// cell's darts come from several tets), some glued, some with broken corners: the
// cell-by-cell labels must not depend on the thread count and must be the generic orbits.
TEST(GMap, CellByCellLabelsIndependentOfThreads) {
    const GMap<3> hex = makeHex();
    const int cells = 9000;  // more than 2 * 4096: the per-cell pass runs in several chunks
    const int n = 48 * cells;
    std::vector<int> perm(static_cast<std::size_t>(n));
    std::iota(perm.begin(), perm.end(), 0);
    std::shuffle(perm.begin(), perm.end(), std::mt19937(5));
    auto D = [&](int c, int d) { return DartHandle(perm[static_cast<std::size_t>(48 * c + d)]); };
    GMap<3> g;
    g.add_darts(static_cast<std::size_t>(n));
    for (int c = 0; c < cells; ++c)
        for (int d = 0; d < 48; ++d)
            for (int i = 0; i < 3; ++i) g.link(D(c, d), D(c, hex.alpha(DartHandle(d), i).idx()), i);
    for (int c = 0; c + 1 < cells; c += 2)
        for (int d = 8; d < 16; ++d) g.sew(D(c, d), D(c + 1, d), 3);
    int broken = 0;
    for (int c = 0; c < cells; c += 7) {  // swap alpha_1 between two corners: still involutive
        const DartHandle x = D(c, 0), y = D(c, 20);
        const DartHandle ax = g.alpha(x, 1), ay = g.alpha(y, 1);
        if (ax == y || ay == x) continue;
        g.sew(x, ay, 1);
        g.sew(y, ax, 1);
        ++broken;
    }
    ASSERT_GT(broken, 1000);
    // Runs of three cells joined into one of 144 darts (alpha_1 swapped between a corner of
    // one and of the next): most of its darts lie outside the chunk of its smallest dart.
    int joined = 0;
    for (int c = 3; c + 2 < cells; c += 50) {
        for (int k = 0; k < 2; ++k) {
            const DartHandle x = D(c + k, 5), y = D(c + k + 1, 29);
            const DartHandle ax = g.alpha(x, 1), ay = g.alpha(y, 1);
            g.sew(x, ay, 1);
            g.sew(y, ax, 1);
        }
        ++joined;
    }
    ASSERT_GT(joined, 100);
    HexOrbitLabels ref;
    const GMapValidation v1 = validateHexGMap(g, &ref, 1);
    ASSERT_FALSE(ref.cell_offset.empty());
    EXPECT_FALSE(v1.valid()) << v1.summary();
    // Same partitions as the generic labelling (numbering aside).
    auto samePartition = [&](const std::vector<int>& a, const std::vector<int>& b) {
        std::map<int, int> ab, ba;
        for (std::size_t d = 0; d < a.size(); ++d) {
            if (ab.emplace(a[d], b[d]).first->second != b[d]) return false;
            if (ba.emplace(b[d], a[d]).first->second != a[d]) return false;
        }
        return true;
    };
    EXPECT_TRUE(samePartition(ref.face, labelOrbits(g, 0b0011)));
    EXPECT_TRUE(samePartition(ref.corner, labelOrbits(g, 0b0110)));
    EXPECT_EQ(ref.cell, labelOrbits(g, 0b0111));
    EXPECT_EQ(std::count(ref.cell_size.begin(), ref.cell_size.end(), 144), joined);
    for (int threads : {2, 3}) {
        SCOPED_TRACE("threads = " + std::to_string(threads));
        HexOrbitLabels l;
        const GMapValidation v = validateHexGMap(g, &l, threads);
        EXPECT_EQ(v.summary(), v1.summary());
        EXPECT_EQ(l.face, ref.face);
        EXPECT_EQ(l.corner, ref.corner);
        EXPECT_EQ(l.cell, ref.cell);
        EXPECT_EQ(l.face_size, ref.face_size);
        EXPECT_EQ(l.corner_size, ref.corner_size);
        EXPECT_EQ(l.cell_darts, ref.cell_darts);
        EXPECT_EQ(l.cell_offset, ref.cell_offset);
        EXPECT_EQ(l.cell_size, ref.cell_size);
    }
}

TEST(GMap, LabelOrbitsCountsCells) {
    GMap<3> g = makeHex();
    int n = 0;
    labelOrbits(g, 0b0111, &n);
    EXPECT_EQ(n, 1);
    labelOrbits(g, 0b0011, &n);
    EXPECT_EQ(n, 6);
    labelOrbits(g, 0b1110, &n);
    EXPECT_EQ(n, 8);
}

// Paper 4.4.1, step by step on a hand-built configuration (in the spirit of figures 5 and 6):
// regular darts 0, 2, 3, 5 and anti darts 1, 4.
TEST(DartAnnihilation, ReconnectionRuleStepByStep) {
    std::vector<std::array<int, 4>> a(6);
    for (int d = 0; d < 6; ++d) a[d] = {d, d, d, d};
    auto sew = [&](int x, int y, int i) { a[x][i] = y; a[y][i] = x; };
    sew(0, 1, 0);  // regular 0 and anti 1 share an edge
    sew(0, 2, 1);  // 0's other edge goes to 2
    sew(1, 3, 1);  // 1's other edge goes to 3
    sew(3, 4, 0);  // 3 meets anti dart 4 along alpha_0
    sew(4, 5, 1);  // and 4 continues to 5
    const std::vector<signed char> sign = {1, -1, 1, 1, -1, 1};
    std::vector<char> alive(6, 1);
    const auto st = annihilateDarts(a, sign, alive);
    // First pair (0, 1): alpha_1(2) = alpha_1(1) = 3 and back. Then 3 (regular) and 4 (anti)
    // are linked by alpha_0: they cancel and 2 is reconnected to alpha_1(4) = 5.
    EXPECT_EQ(st.pairs, 2);
    EXPECT_EQ(st.remaining_anti, 0);
    EXPECT_EQ(alive, (std::vector<char>{0, 0, 1, 0, 0, 1}));
    EXPECT_EQ(a[2][1], 5);
    EXPECT_EQ(a[5][1], 2);
    EXPECT_EQ(a[2][0], 2);  // free links stay free
}

TEST(DartAnnihilation, AntiDartWithoutRegularNeighbourRemains) {
    std::vector<std::array<int, 4>> a = {{1, 0, 0, 0}, {0, 1, 1, 1}};
    const std::vector<signed char> sign = {-1, -1};
    std::vector<char> alive(2, 1);
    const auto st = annihilateDarts(a, sign, alive);
    EXPECT_EQ(st.pairs, 0);
    EXPECT_EQ(st.remaining_anti, 2);
}

// The per-cell check the annihilation retries use (LocalHexCheck.hh): two separate hexes are
// fine; crossing an alpha_1 link between them makes one broken cell of 96 darts; an alpha_3
// link inside one cell (a cell glued to itself) and a link to a removed dart are broken too.
TEST(LocalHexCheck, FindsMergedAndSelfGluedCells) {
    const auto hex = makeHex().links();
    std::vector<std::array<int, 4>> a(hex.begin(), hex.end());
    for (const auto& l : hex) a.push_back({l[0] + 48, l[1] + 48, l[2] + 48, l[3] + 48});
    for (int d = 0; d < 96; ++d) a[d][3] = d;  // boundary
    std::vector<char> alive(96, 1);
    std::vector<std::uint8_t> mark(96, 0);
    std::vector<int> all(96);
    std::iota(all.begin(), all.end(), 0);
    std::vector<int> bad;
    EXPECT_EQ(countDefectiveHexCells(a, alive, all, mark, 1, 2, &bad), 0);
    EXPECT_TRUE(bad.empty());
    EXPECT_EQ(std::count(mark.begin(), mark.end(), 0), 96);  // scratch bits cleared
    {
        auto b = a;
        const int d = 0, d1 = b[0][1], e = 48, e1 = b[48][1];
        b[d][1] = e1, b[e1][1] = d, b[e][1] = d1, b[d1][1] = e;  // crossed alpha_1
        EXPECT_EQ(countDefectiveHexCells(b, alive, {0, 50, 90}, mark, 1, 2, &bad), 1);
        EXPECT_EQ(bad.size(), 96u);
        EXPECT_EQ(std::count(mark.begin(), mark.end(), 0), 96);
    }
    {
        auto b = a;
        b[0][3] = 20, b[20][3] = 0;  // glued to itself
        EXPECT_EQ(countDefectiveHexCells(b, alive, {5, 60}, mark, 1, 2), 1);
        b[0][3] = 60, b[60][3] = 0;  // a link to the other cell, but not over a whole face (eq2)
        b[20][3] = 20;
        EXPECT_EQ(countDefectiveHexCells(b, alive, {5, 60}, mark, 1, 2), 2);
    }
    {
        auto dead = alive;
        dead[7] = 0;  // its partners now point at a removed dart
        EXPECT_EQ(countDefectiveHexCells(a, dead, {0, 48}, mark, 1, 2), 1);
    }
}

// Merged vertices that the per-cell check cannot see (LocalVertexCheck.hh): two hexes glued
// along one face are two cells with 12 vertices and no repeated quad; glued along the opposite
// face too (every cell still passes countDefectiveHexCells(), eq2 holds), their 8 vertices
// are shared and each of A's four side quads has the same four vertices as one of B's.
TEST(LocalVertexCheck, FindsQuadsWithTheSameVertices) {
    const auto hex = makeHex().links();
    std::vector<std::array<int, 4>> a(hex.begin(), hex.end());
    for (const auto& l : hex) a.push_back({l[0] + 48, l[1] + 48, l[2] + 48, l[3] + 48});
    for (int d = 0; d < 96; ++d) a[d][3] = d;  // boundary
    for (int d = 8; d < 16; ++d) a[d][3] = 48 + d, a[48 + d][3] = d;  // face {4, 5, 6, 7} of A onto that of B
    const std::vector<char> alive(96, 1);
    std::vector<int> all(96);
    std::iota(all.begin(), all.end(), 0);
    EXPECT_EQ(countMergedVertexQuads(a, alive, all), 0);
    EXPECT_EQ(countMergedVertexQuads(a, alive, {9}), 0);
    for (int d = 0; d < 8; ++d) a[d][3] = 48 + d, a[48 + d][3] = d;  // and face {0, 3, 2, 1}
    std::vector<std::uint8_t> mark(96, 0);
    EXPECT_EQ(countDefectiveHexCells(a, alive, all, mark, 1, 2), 0);
    EXPECT_EQ(countMergedVertexQuads(a, alive, all), 4);
    EXPECT_EQ(countMergedVertexQuads(a, alive, {0}), 2);  // corner 0: the side quads {0, 1, 5, 4} and {3, 0, 4, 7} of A and B
    std::vector<char> dead(96, 1);
    for (int d = 48; d < 96; ++d) dead[d] = 0;  // B removed: A alone, glued to nothing alive
    EXPECT_EQ(countMergedVertexQuads(a, dead, all), 0);
}

TEST(UnionFind, ClassesAndSmallestRoot) {
    UnionFind uf(10);
    uf.unite(7, 3);
    uf.unite(9, 7);
    uf.unite(2, 5);
    uf.unite(5, 8);
    uf.unite(3, 9);  // already joined
    for (int x : {3, 7, 9}) EXPECT_EQ(uf.find(x), 3);
    for (int x : {2, 5, 8}) EXPECT_EQ(uf.find(x), 2);
    for (int x : {0, 1, 4, 6}) EXPECT_EQ(uf.find(x), x);
    uf.unite(8, 1);
    for (int x : {1, 2, 5, 8}) EXPECT_EQ(uf.find(x), 1);
    EXPECT_NE(uf.find(3), uf.find(1));
}

// An invalid map names its offending darts: the first ones per failing check, in dart
// order, at most kExamplesPerCheck each, the same for any thread count; a valid one none.
TEST(GMap, ValidatorNamesOffendingDarts) {
    const GMap<3> hex = makeHex();
    GMap<3> g;
    g.add_darts(96);
    for (int h = 0; h < 2; ++h)
        for (int d = 0; d < 48; ++d)
            for (int i = 0; i < 3; ++i) g.link(DartHandle(48 * h + d), DartHandle(48 * h + hex.alpha(DartHandle(d), i).idx()), i);
    for (int d = 8; d < 16; ++d) g.sew(DartHandle(d), DartHandle(48 + d), 3);
    EXPECT_TRUE(validateHexGMap(g).valid());
    EXPECT_TRUE(validateHexGMap(g).examples.empty());
    // Cross two alpha_3 links of the shared quad: darts 8, 9 go to 57, 56 (eq2 breaks).
    g.unsew(DartHandle(8), 3);
    g.unsew(DartHandle(9), 3);
    g.sew(DartHandle(8), DartHandle(57), 3);
    g.sew(DartHandle(9), DartHandle(56), 3);
    for (int threads : {1, 2}) {
        const GMapValidation v = validateHexGMap(g, nullptr, threads);
        EXPECT_FALSE(v.valid());
        EXPECT_EQ(v.eq2_face_connection, 8);  // 8, 9, 10, 15 and 56, 57, 58, 63 on the other side
        ASSERT_EQ(v.examples.size(), 4u);
        std::vector<int> darts;
        for (const auto& e : v.examples) {
            EXPECT_EQ(e.check, "eq2");
            darts.push_back(e.dart);
        }
        EXPECT_EQ(darts, (std::vector<int>{8, 9, 10, 15}));
        // Face vertices from a vertex labelling: corner k of the loop of quad 1 gets id 100+k.
        GMapValidation w = v;
        std::vector<int> vertex(96, -1);
        for (int d = 0; d < 96; ++d) vertex[static_cast<std::size_t>(d)] = 100 + ((d % 48) / 2 + (d % 2)) % 4;
        describeViolations(g, vertex, w);
        EXPECT_EQ(w.examples[0].face_vertices, (std::vector<int>{100, 101, 102, 103}));
    }
}
