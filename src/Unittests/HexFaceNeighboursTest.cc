/// @file HexFaceNeighboursTest.cc
/// The face-neighbour table the extraction hands to the OpenVolumeMesh writers
/// (HexFaceNeighbours.hh): on extracted meshes (cylinders with implicit cells, explicit
/// cells only, a folded map) it equals the table of the quads matched by their vertices, and
/// the numbering from it equals ovmHexFaces() and buildOvmFaces() at 1-3 threads; a table
/// that does not fit the mesh (changed hexes, broken pairs, pairs of other quads) is not used.

#include <HexEx/Generators/Generators.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/IO/HexMeshWriters.hh>
#include <HexEx/IO/OvmHexFaces.hh>
#include <HexEx/IO/OvmModel.hh>
#include <HexEx/Mesh/HexFaceNeighbours.hh>
#include <HexEx/Postprocessing/AssembledMeshCheck.hh>

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <utility>

using namespace HexEx;

namespace {

/// Extraction of @p pm on @p threads threads with the face-neighbour table.
struct Extracted {
    HexMesh mesh;               ///< the hex mesh
    ExtractionReport report;    ///< its report
    HexFaceNeighbours table;    ///< the assembly's table
};

Extracted extractWithTable(ParametrizedTetMesh pm, int threads, bool implicitCells = true) {
    pm.mesh.build_adjacency();
    ExtractionOptions o;
    o.threads = threads;
    o.implicit_cells = implicitCells;
    Extracted e;
    e.report = extractHexMesh(std::move(pm), e.mesh, o, &e.table);
    return e;
}

/// The table of the quads matched by their vertex sets (no twin faces), as the reference.
HexFaceNeighbours matchedTable(const HexMesh& mesh) {
    HexFaceNeighbours t;
    checkAssembledHexes(mesh, 1, nullptr, 0, &t);
    return t;
}

/// Expects the faces, edges and cells of the two flat models to be equal.
void expectSameFlat(const OvmFlatMesh& a, const OvmFlatMesh& b) {
    EXPECT_EQ(a.edges, b.edges);
    EXPECT_EQ(a.faces.values, b.faces.values);
    EXPECT_EQ(a.faces.size(), b.faces.size());
    EXPECT_EQ(a.cells.values, b.cells.values);
}

/// The table of @p e equals the matched one, and the numbering from it at 1-3 threads equals
/// ovmHexFaces() without it and buildOvmFaces() (ovmFromHexMesh() of a small mesh).
void expectTableNumbering(const Extracted& e) {
    ASSERT_FALSE(e.table.items.empty());
    const HexFaceNeighbours ref = matchedTable(e.mesh);
    ASSERT_EQ(ref.items.size(), 6 * e.mesh.hexes.size());
    EXPECT_EQ(e.table.items, ref.items);
    EXPECT_EQ(e.table.digest, hexMeshDigest(e.mesh, 1));
    EXPECT_TRUE(hexFaceNeighboursFit(e.mesh, e.table, hexMeshDigest(e.mesh, 2), 2));
    OvmFaces matched;
    ASSERT_TRUE(ovmHexFaces(e.mesh, 1, matched));
    const OvmFlatMesh plain = ovmFlatFromHexMesh(e.mesh, 1);  // buildOvmFaces() below 500,000 hexes
    for (int threads : {1, 2, 3}) {
        SCOPED_TRACE(std::to_string(threads) + " threads");
        HexFaceNeighbours t = e.table;
        OvmFaces fromTable;
        ASSERT_TRUE(ovmHexFaces(e.mesh, threads, fromTable, &t));
        EXPECT_TRUE(t.items.empty());  // taken over
        EXPECT_EQ(fromTable.halffaces, matched.halffaces);
        EXPECT_EQ(fromTable.edges, matched.edges);
        EXPECT_EQ(fromTable.faceHalfedges.values, matched.faceHalfedges.values);
        t = e.table;
        expectSameFlat(ovmFlatFromHexMesh(e.mesh, threads, &t), plain);
        EXPECT_TRUE(t.items.empty());  // used up
    }
}

} // namespace

TEST(HexFaceNeighbours, CylindersWithImplicitCellsAtAnyThreadCount) {
    for (int k : {3, 4, 5, 6}) {
        for (int threads : {1, 2, 3}) {
            SCOPED_TRACE("valence " + std::to_string(k) + ", " + std::to_string(threads) + " threads");
            const Extracted e = extractWithTable(generateCylinder(k, 8, 8, 1, 1), threads);
            ASSERT_TRUE(e.report.valid_all_hex);
            EXPECT_GT(e.report.darts.implicit_cells, 0);
            expectTableNumbering(e);
        }
    }
}

TEST(HexFaceNeighbours, TheSameTableOnAnyThreadCount) {
    // Large enough for the mesh check's parallel chunks (and two parts of records).
    const Extracted one = extractWithTable(generateCylinder(6, 12, 12, 1, 1), 1);
    ASSERT_FALSE(one.table.items.empty());
    for (int threads : {2, 3}) {
        const Extracted e = extractWithTable(generateCylinder(6, 12, 12, 1, 1), threads);
        EXPECT_EQ(e.table.items, one.table.items) << threads << " threads";
        EXPECT_EQ(e.table.digest, one.table.digest) << threads << " threads";
    }
    expectTableNumbering(one);
}

TEST(HexFaceNeighbours, ExplicitCellsOnlyAndCharts) {
    {
        SCOPED_TRACE("cube without implicit cells");
        const Extracted e = extractWithTable(generateCube(2, 6), 2, false);
        ASSERT_TRUE(e.report.valid_all_hex);
        EXPECT_EQ(e.report.darts.implicit_cells, 0);
        expectTableNumbering(e);
    }
    {
        SCOPED_TRACE("random chart per tet");
        ParametrizedTetMesh pm = generateCube(2, 8);
        applyRandomChartTransforms(pm, 3);
        const Extracted e = extractWithTable(std::move(pm), 2);
        ASSERT_TRUE(e.report.valid_all_hex);
        expectTableNumbering(e);
    }
}

TEST(HexFaceNeighbours, FoldedMap) {
    // The centre of a cube of scale 9 pushed through the top: large flipped tets over proper
    // ones (no implicit cells, the annihilation removes the fold).
    ParametrizedTetMesh pm = generateCube(2, 9);
    for (auto& corners : pm.params)
        for (auto& p : corners)
            if (p[0] == 4.5 && p[1] == 4.5 && p[2] == 4.5) p[2] = 13.25;
    for (int threads : {1, 2, 3}) {
        SCOPED_TRACE(std::to_string(threads) + " threads");
        const Extracted e = extractWithTable(pm, threads);
        EXPECT_GT(e.report.input.flipped_tets, 0);
        ASSERT_TRUE(e.report.valid_all_hex);
        expectTableNumbering(e);
    }
}

TEST(HexFaceNeighbours, AStaleTableIsNotUsed) {
    const Extracted e = extractWithTable(generateCylinder(4, 6, 4, 1, 1), 2);
    ASSERT_FALSE(e.table.items.empty());
    const std::uint64_t digest = hexMeshDigest(e.mesh, 1);
    EXPECT_EQ(hexMeshDigest(e.mesh, 3), digest);

    // Changed hexes: two hexes swapped (the same quads, other items), one hex's corners turned.
    HexMesh swapped = e.mesh;
    std::swap(swapped.hexes[0], swapped.hexes[swapped.hexes.size() - 1]);
    HexMesh turned = e.mesh;
    auto& h = turned.hexes[5];
    turned.hexes[5] = {{h[1], h[2], h[3], h[0], h[5], h[6], h[7], h[4]}};
    for (const HexMesh* m : {&swapped, &turned}) {
        EXPECT_NE(hexMeshDigest(*m, 1), digest);
        EXPECT_FALSE(hexFaceNeighboursFit(*m, e.table, hexMeshDigest(*m, 1), 1));
        HexFaceNeighbours t = e.table;
        expectSameFlat(ovmFlatFromHexMesh(*m, 2, &t), ovmFlatFromHexMesh(*m, 2));
        EXPECT_TRUE(t.items.empty());
    }
    // A vertex more: another digest.
    HexMesh more = e.mesh;
    more.vertices.push_back(Vec3d(0, 0, 0));
    EXPECT_NE(hexMeshDigest(more, 1), digest);

    // The same mesh, a broken table: a pair made one-sided, an entry out of range, too short.
    std::size_t paired = 0;
    while (e.table.items[paired] < 0) ++paired;
    HexFaceNeighbours oneSided = e.table;
    oneSided.items[paired] = -1;
    HexFaceNeighbours outOfRange = e.table;
    outOfRange.items[paired] = static_cast<int>(outOfRange.items.size());
    HexFaceNeighbours shorter = e.table;
    shorter.items.resize(shorter.items.size() - 6);
    for (const HexFaceNeighbours* t : {&oneSided, &outOfRange, &shorter})
        EXPECT_FALSE(hexFaceNeighboursFit(e.mesh, *t, digest, 2));

    // Mutual pairs, right digest, but two pairs crossed: quads of other vertices. The fit
    // without the vertex comparison passes; the numbering refuses it, the writers fall back.
    std::size_t a = 0;
    while (e.table.items[a] < 0 || static_cast<std::size_t>(e.table.items[a]) < a) ++a;
    std::size_t b = a + 1;
    while (e.table.items[b] < 0 || static_cast<std::size_t>(e.table.items[b]) < b || b / 6 == a / 6) ++b;
    HexFaceNeighbours crossed = e.table;
    const int na = crossed.items[a], nbr = crossed.items[b];
    crossed.items[a] = nbr;
    crossed.items[static_cast<std::size_t>(nbr)] = static_cast<int>(a);
    crossed.items[b] = na;
    crossed.items[static_cast<std::size_t>(na)] = static_cast<int>(b);
    EXPECT_TRUE(hexFaceNeighboursFit(e.mesh, crossed, digest, 2, false));
    EXPECT_FALSE(hexFaceNeighboursFit(e.mesh, crossed, digest, 2, true));
    {
        HexFaceNeighbours t = crossed;
        OvmFaces faces;
        EXPECT_FALSE(ovmHexFaces(e.mesh, 2, faces, &t));
    }
    const OvmFlatMesh plain = ovmFlatFromHexMesh(e.mesh, 2);
    for (HexFaceNeighbours t : {oneSided, outOfRange, shorter, crossed}) expectSameFlat(ovmFlatFromHexMesh(e.mesh, 2, &t), plain);

    // The writers: the same bytes with the stale table as without.
    for (HexMeshFormat format : {HexMeshFormat::Ovmb, HexMeshFormat::Ovm}) {
        std::ostringstream withTable, without;
        HexFaceNeighbours t = e.table;
        writeHexMeshStream(withTable, turned, format, VtuEncoding::Binary, 2, &t);
        writeHexMeshStream(without, turned, format, VtuEncoding::Binary, 2);
        EXPECT_EQ(withTable.str(), without.str());
    }
}

TEST(HexFaceNeighbours, NoTableWhereTheMeshCheckFails) {
    // A quad in three hexes: the check does not agree, and no table is made.
    HexMesh m;
    for (int k = 0; k < 12; ++k) m.vertices.push_back(Vec3d(k, 0, 0));
    m.hexes.push_back({{0, 1, 2, 3, 4, 5, 6, 7}});
    m.hexes.push_back({{4, 5, 6, 7, 8, 9, 10, 11}});
    m.hexes.push_back({{7, 6, 5, 4, 11, 10, 9, 8}});
    HexFaceNeighbours t;
    const AssembledMeshCheck c = checkAssembledHexes(m, 1, nullptr, 0, &t);
    EXPECT_EQ(c.quads_shared_by_more_than_two, 1);
    EXPECT_TRUE(t.items.empty());
    // Twin faces without the cells' corners: no table either.
    const std::vector<unsigned char> twins(1, 0);
    HexMesh one;
    one.vertices = m.vertices;
    one.hexes.push_back(m.hexes[0]);
    checkAssembledHexes(one, 1, &twins, 0, &t);
    EXPECT_TRUE(t.items.empty());
    checkAssembledHexes(one, 1, nullptr, 0, &t);
    EXPECT_EQ(t.items, (DefaultInitVector<int>{-1, -1, -1, -1, -1, -1}));
}
