// The position rules of mergedVertexPositions() that issue 22 added: a vertex whose own
// darts are interior stays interior although a removed dart inherited by it lies on the
// boundary, and a position held by most of a vertex's surviving darts is its only
// preferred candidate (for interior vertices, the position with most of its placed points
// first), and a boundary vertex of the tet mesh among the candidates of a boundary vertex
// (any vertex of the tet mesh among those of an interior vertex) is its only preferred
// candidate.

#include <HexEx/Mesh/TetMesh.hh>
#include <HexEx/Postprocessing/VertexMerging.hh>

#include <gtest/gtest.h>

using namespace HexEx;

namespace {

/// One tet spanning the unit cube's corner (only its size matters: the tolerance).
TetMesh unitTet() {
    TetMesh m;
    const VertexHandle a = m.add_vertex(Vec3d(0, 0, 0)), b = m.add_vertex(Vec3d(1, 0, 0)),
                       c = m.add_vertex(Vec3d(0, 1, 0)), d = m.add_vertex(Vec3d(0, 0, 1));
    m.add_cell({a, b, c, d});
    m.build_adjacency();
    return m;
}

/// The same tet split into four at an interior vertex (0.25, 0.25, 0.25).
TetMesh splitTet() {
    TetMesh m;
    const VertexHandle a = m.add_vertex(Vec3d(0, 0, 0)), b = m.add_vertex(Vec3d(1, 0, 0)),
                       c = m.add_vertex(Vec3d(0, 1, 0)), d = m.add_vertex(Vec3d(0, 0, 1)),
                       e = m.add_vertex(Vec3d(0.25, 0.25, 0.25));
    m.add_cell({e, b, c, d});
    m.add_cell({a, e, c, d});
    m.add_cell({a, b, e, d});
    m.add_cell({a, b, c, e});
    m.build_adjacency();
    return m;
}

/// Placement of one class: @p counts[k] surviving darts at @p points[k] (interior h-vertices).
DartPlacement interiorDarts(const std::vector<Vec3d>& points, const std::vector<int>& counts) {
    DartPlacement p;
    for (std::size_t k = 0; k < points.size(); ++k) {
        p.position.push_back(points[k]);
        p.boundary_hf.push_back({-1, -1, -1});
        for (int i = 0; i < counts[k]; ++i) p.point.push_back(static_cast<int>(k));
    }
    return p;
}

/// Adds @p count placed points at @p at, each seen through a removed regular dart the
/// vertex inherited (as from that many more tets).
void addInheritedPlacedPoints(DartPlacement& p, const Vec3d& at, int count) {
    for (int k = 0; k < count; ++k) {
        p.position.push_back(at);
        p.boundary_hf.push_back({-1, -1, -1});
        p.extra_dart.push_back(0);
        p.extra_point.push_back(static_cast<int>(p.position.size()) - 1);
        p.extra_flipped.push_back(0);
    }
}

/// The one ambiguous vertex has two candidates: @p first, its only preferred one, then @p second.
void expectOnlyPreferredOfTwo(const VertexCandidates& cand, const Vec3d& first, const Vec3d& second) {
    ASSERT_EQ(cand.vertex.size(), 1u);
    EXPECT_EQ(cand.preferred[0], 1);
    ASSERT_EQ(cand.offset[1] - cand.offset[0], 2);
    EXPECT_EQ(cand.position[0], first);
    EXPECT_EQ(cand.position[1], second);
}

} // namespace

// 20 darts at one preimage, 4 at a fold copy: the majority is the only preferred candidate,
// whatever the order of the positions.
TEST(VertexMajority, MostDartsMakeTheOnlyPreferredCandidate) {
    const TetMesh mesh = unitTet();
    const Vec3d proper(0.2, 0.2, 0.2), copy(0.1, 0.1, 0.1);
    for (bool swapped : {false, true}) {
        const DartPlacement p = swapped ? interiorDarts({copy, proper}, {4, 20}) : interiorDarts({proper, copy}, {20, 4});
        const std::vector<int> label(p.point.size(), 0);
        VertexCandidates cand;
        const std::vector<Vec3d> pos = mergedVertexPositions(mesh, label, 1, p, 1, &cand);
        ASSERT_EQ(pos.size(), 1u);
        EXPECT_EQ(pos[0], proper);
        ASSERT_EQ(cand.vertex.size(), 1u);
        EXPECT_EQ(cand.preferred[0], 1);
        ASSERT_EQ(cand.offset.size(), 2u);
        EXPECT_EQ(cand.offset[1] - cand.offset[0], 2);
        EXPECT_EQ(cand.position[0], proper);
        EXPECT_EQ(cand.position[1], copy);
    }
    // No majority (12 against 12): both are preferred, as before.
    const DartPlacement even = interiorDarts({proper, copy}, {12, 12});
    VertexCandidates cand;
    mergedVertexPositions(mesh, std::vector<int>(even.point.size(), 0), 1, even, 1, &cand);
    ASSERT_EQ(cand.vertex.size(), 1u);
    EXPECT_EQ(cand.preferred[0], 2);
}

// A removed dart on the boundary (its heir is this vertex) does not make an interior vertex
// a boundary vertex: its position is one more candidate, rated like the surviving darts'
// one (both preferred; the hexes decide). As a boundary vertex, only the boundary position
// would have been preferred.
TEST(VertexMajority, InheritedBoundaryDartDoesNotPullAnInteriorVertex) {
    const TetMesh mesh = unitTet();
    const Vec3d own(0.2, 0.2, 0.2), onBoundary(0, 0.3, 0.3);
    DartPlacement p = interiorDarts({own}, {10});
    p.position.push_back(onBoundary);
    p.boundary_hf.push_back({0, -1, -1});  // a boundary halfface of the tet
    p.extra_dart.push_back(0);
    p.extra_point.push_back(1);
    p.extra_flipped.push_back(0);
    VertexCandidates cand;
    const std::vector<Vec3d> pos = mergedVertexPositions(mesh, std::vector<int>(10, 0), 1, p, 1, &cand);
    ASSERT_EQ(pos.size(), 1u);
    ASSERT_EQ(cand.vertex.size(), 1u);
    EXPECT_EQ(cand.preferred[0], 2);
    ASSERT_EQ(cand.offset[1] - cand.offset[0], 2);
    EXPECT_TRUE((cand.position[0] == own && cand.position[1] == onBoundary) ||
                (cand.position[0] == onBoundary && cand.position[1] == own));
}

// No majority of darts (10, 8 and 6 at three positions), but one position is seen from 5
// tets (placed points, here of removed regular darts inherited by the vertex) and the others
// from one each: that position is the only preferred candidate.
TEST(VertexMajority, MostPlacedPointsDecideWithoutAMajorityOfDarts) {
    const TetMesh mesh = unitTet();
    const Vec3d proper(0.2, 0.2, 0.2), copyA(0.1, 0.1, 0.1), copyB(0.3, 0.1, 0.1);
    DartPlacement p = interiorDarts({copyA, proper, copyB}, {10, 8, 6});
    addInheritedPlacedPoints(p, proper, 4);  // four more tets see the proper preimage
    VertexCandidates cand;
    const std::vector<Vec3d> pos = mergedVertexPositions(mesh, std::vector<int>(24, 0), 1, p, 1, &cand);
    EXPECT_EQ(pos[0], proper);
    ASSERT_EQ(cand.vertex.size(), 1u);
    EXPECT_EQ(cand.preferred[0], 1);
    EXPECT_EQ(cand.offset[1] - cand.offset[0], 3);
    EXPECT_EQ(cand.position[0], proper);
}

// The darts favour a fold copy (15 against 9), but the proper preimage is seen from 6 tets
// (5 of them through removed darts) and the copy from one: the placed points decide.
TEST(VertexMajority, PlacedPointsComeBeforeTheDartsForInteriorVertices) {
    const TetMesh mesh = unitTet();
    const Vec3d proper(0.2, 0.2, 0.2), copy(0.1, 0.1, 0.1);
    DartPlacement p = interiorDarts({copy, proper}, {15, 9});
    addInheritedPlacedPoints(p, proper, 5);
    VertexCandidates cand;
    const std::vector<Vec3d> pos = mergedVertexPositions(mesh, std::vector<int>(24, 0), 1, p, 1, &cand);
    EXPECT_EQ(pos[0], proper);
    expectOnlyPreferredOfTwo(cand, proper, copy);
}

// A boundary vertex whose only boundary h-vertex is a fold copy inside a boundary face
// (8 darts on the face z = 0), with 8 darts at a corner of the tet mesh off that plane and
// 8 at a copy inside the tet (cfpc16_hollow8 at a = 0.7, seed 8): the plane rule alone
// keeps the copy on the face and lists no other candidate. The corner maps exactly onto
// the grid point, so it is the only preferred candidate, the face copy the next.
TEST(VertexMajority, TetMeshBoundaryVertexBeatsAFoldCopyOnABoundaryFace) {
    const TetMesh mesh = unitTet();
    int bottom = -1;  // the boundary halfface in the plane z = 0
    for (std::size_t hf = 0; hf < mesh.n_halffaces(); ++hf) {
        const auto v = mesh.halfface_vertices(HalfFaceHandle(static_cast<int>(hf)));
        if (mesh.position(v[0])[2] == 0 && mesh.position(v[1])[2] == 0 && mesh.position(v[2])[2] == 0) bottom = static_cast<int>(hf);
    }
    ASSERT_GE(bottom, 0);
    const Vec3d onFace(0.3, 0.3, 0), corner(0, 0, 1), inside(0.2, 0.2, 0.2);
    for (bool withCorner : {true, false}) {
        DartPlacement p = interiorDarts({onFace, withCorner ? corner : Vec3d(0.1, 0.1, 0.6), inside}, {8, 8, 8});
        p.boundary_hf[0] = {bottom, -1, -1};
        addInheritedPlacedPoints(p, inside, 1);
        VertexCandidates cand;
        const std::vector<Vec3d> pos = mergedVertexPositions(mesh, std::vector<int>(24, 0), 1, p, 1, &cand);
        ASSERT_EQ(pos.size(), 1u);
        if (!withCorner) {
            // No candidate at a vertex of the tet mesh: the plane rule's only boundary candidate.
            EXPECT_EQ(pos[0], onFace);
            EXPECT_TRUE(cand.vertex.empty());
            continue;
        }
        EXPECT_EQ(pos[0], corner);
        expectOnlyPreferredOfTwo(cand, corner, onFace);
    }
}

// An interior vertex with both majorities at a fold copy inside a tet (18 of 24 darts, 7 of
// 9 placed points) and the rest at an interior vertex of the tet mesh (pig at a = 0.8,
// seed 18): the tet-mesh vertex maps exactly onto the grid point, so it is the only
// preferred candidate. With two candidates at vertices of the tet mesh the rule says
// nothing and the majority stays first; without annihilated darts (no inherited placed
// point) it is not applied either.
TEST(VertexMajority, TetMeshVertexBeatsTheMajoritiesOfAnInteriorVertex) {
    const TetMesh mesh = splitTet();
    const Vec3d vertex(0.25, 0.25, 0.25), copy(0.3, 0.2, 0.1), corner(0, 0, 0);
    {
        DartPlacement p = interiorDarts({copy, vertex}, {18, 6});
        addInheritedPlacedPoints(p, copy, 6);
        addInheritedPlacedPoints(p, vertex, 1);
        VertexCandidates cand;
        const std::vector<Vec3d> pos = mergedVertexPositions(mesh, std::vector<int>(24, 0), 1, p, 1, &cand);
        ASSERT_EQ(pos.size(), 1u);
        EXPECT_EQ(pos[0], vertex);
        expectOnlyPreferredOfTwo(cand, vertex, copy);
    }
    {
        DartPlacement p = interiorDarts({copy, vertex, corner}, {18, 3, 3});
        addInheritedPlacedPoints(p, copy, 6);
        VertexCandidates cand;
        const std::vector<Vec3d> pos = mergedVertexPositions(mesh, std::vector<int>(24, 0), 1, p, 1, &cand);
        EXPECT_EQ(pos[0], copy);
        ASSERT_EQ(cand.vertex.size(), 1u);
        EXPECT_EQ(cand.preferred[0], 1);
    }
    {
        const DartPlacement p = interiorDarts({copy, vertex}, {18, 6});
        VertexCandidates cand;
        const std::vector<Vec3d> pos = mergedVertexPositions(mesh, std::vector<int>(24, 0), 1, p, 1, &cand);
        EXPECT_EQ(pos[0], copy);
    }
}
