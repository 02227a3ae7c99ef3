// Face relinking after the annihilation (FaceRelinking.hh): quads whose alpha_3 links cross
// are cut and sewn again by their vertices, with the vertex labels searched around the cut
// quads (every link returns) or taken from the whole map (some link is one-way).

#include <HexEx/GMap/GMap.hh>
#include <HexEx/GMap/GMapValidator.hh>
#include <HexEx/Postprocessing/FaceRelinking.hh>

#include <gtest/gtest.h>

using namespace HexEx;

namespace {

/// Darts per hex.
constexpr int kHex = 48;

/// @p hexes separate hexahedra (48 darts each, no alpha_3 links). Dart 8f + 2k + s of a hex:
/// face f, edge k of the face's loop, s = 0 at the edge's first corner, 1 at its second.
GMap<3> makeHexes(int hexes) {
    static const int F[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    GMap<3> g;
    g.add_darts(static_cast<std::size_t>(hexes * kHex));
    for (int h = 0; h < hexes; ++h) {
        auto id = [&](int f, int k, int s) { return DartHandle(h * kHex + 8 * f + 2 * k + s); };
        for (int f = 0; f < 6; ++f)
            for (int k = 0; k < 4; ++k) {
                g.sew(id(f, k, 0), id(f, k, 1), 0);
                g.sew(id(f, k, 1), id(f, (k + 1) % 4, 0), 1);
            }
        // alpha_2: the darts of two faces at the same corner of the same edge.
        for (int f = 0; f < 6; ++f)
            for (int k = 0; k < 4; ++k)
                for (int s = 0; s < 2; ++s) {
                    const int v = F[f][(k + s) % 4], w = F[f][(k + 1 - s) % 4];
                    for (int f2 = 0; f2 < 6; ++f2)
                        for (int k2 = 0; k2 < 4 && f2 != f; ++k2)
                            for (int s2 = 0; s2 < 2; ++s2)
                                if (F[f2][(k2 + s2) % 4] == v && F[f2][(k2 + 1 - s2) % 4] == w) g.link(id(f, k, s), id(f2, k2, s2), 2);
                }
    }
    return g;
}

/// Hexes 0 and 1 glued by their face 1 (darts 8..15 of each, dart to dart), as the source
/// would be, and the same map with the links of two darts at one corner crossed: dart 8
/// (edge 0) and dart 15 (edge 3) of hex 0 both sit at corner 4 and take each other's partner,
/// so alpha_0 and alpha_1 no longer commute with alpha_3 there (equation 2).
void gluedAndCrossed(GMap<3>& glued, GMap<3>& crossed, int hexes) {
    glued = makeHexes(hexes);
    for (int d = 8; d < 16; ++d) glued.sew(DartHandle(d), DartHandle(kHex + d), 3);
    crossed = glued;
    crossed.sew(DartHandle(8), DartHandle(kHex + 15), 3);
    crossed.sew(DartHandle(15), DartHandle(kHex + 8), 3);
}

} // namespace

TEST(FaceRelinking, CrossedLinksAtOneCornerAreSewnBackByTheVertices) {
    GMap<3> glued, crossed;
    gluedAndCrossed(glued, crossed, 2);
    ASSERT_TRUE(validateHexGMap(glued).valid());
    ASSERT_FALSE(validateHexGMap(crossed).valid());
    const FaceRelinkStats st = relinkInconsistentFaces(crossed);
    EXPECT_EQ(st.inconsistent_faces, 2);
    EXPECT_EQ(st.relinked_faces, 2);
    EXPECT_EQ(crossed.links(), glued.links());
    EXPECT_TRUE(validateHexGMap(crossed).valid());
}

// A one-way alpha_3 link elsewhere (hex 2: dart 0 to dart 8, which stays free) makes the
// relinking label the vertices of the whole map: the crossed quads are sewn back the same
// way, and hex 2's two quads, cut as well, find no partner.
TEST(FaceRelinking, AOneWayLinkElsewhereGivesTheSamePairs) {
    GMap<3> glued, crossed;
    gluedAndCrossed(glued, crossed, 3);
    crossed.link(DartHandle(2 * kHex + 0), DartHandle(2 * kHex + 8), 3);
    const FaceRelinkStats st = relinkInconsistentFaces(crossed);
    EXPECT_EQ(st.inconsistent_faces, 4);
    EXPECT_EQ(st.relinked_faces, 2);
    for (int d = 0; d < 2 * kHex; ++d) EXPECT_EQ(crossed.links()[static_cast<std::size_t>(d)], glued.links()[static_cast<std::size_t>(d)]) << "dart " << d;
    for (int d = 2 * kHex; d < 3 * kHex; ++d) EXPECT_TRUE(crossed.is_free(DartHandle(d), 3)) << "dart " << d;
}
