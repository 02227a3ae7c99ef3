// Face relinking after the annihilation (FaceRelinking.hh): quads whose alpha_3 links cross
// are cut and sewn again by their vertices, with the vertex labels searched around the cut
// quads (every link returns) or taken from the whole map (some link is one-way).

#include "../TestSupport/HexGMapFixtures.hh"

#include <HexEx/GMap/GMap.hh>
#include <HexEx/GMap/GMapValidator.hh>
#include <HexEx/Postprocessing/FaceRelinking.hh>

#include <gtest/gtest.h>

using namespace HexEx;

namespace {

/// Darts per hex.
constexpr int kHex = HexExTestSupport::kHexDarts;

/// @p hexes separate hexahedra (HexGMapFixtures.hh).
GMap<3> makeHexes(int hexes) { return HexExTestSupport::makeHexGMaps(hexes); }

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
