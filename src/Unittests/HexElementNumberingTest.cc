// Numbering of hex edges and faces by first appearance (Pipeline/HexElementNumbering.hh),
// checked against a plain map-based reference on extracted meshes, for 1 and 2 threads.

#include <HexEx/Generators/Generators.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/Pipeline/HexElementNumbering.hh>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <vector>

using namespace HexEx;

namespace {

/// Reference: ids in order of first occurrence via a std::map of sorted vertex sets.
void expectSameAsReference(const HexMesh& hm) {
    std::map<std::vector<int>, int> edgeIds, faceIds;
    std::vector<std::array<int, 12>> hexEdges(hm.hexes.size());
    std::vector<std::array<int, 6>> hexFaces(hm.hexes.size());
    std::vector<std::array<signed char, 6>> signs(hm.hexes.size());
    for (std::size_t h = 0; h < hm.hexes.size(); ++h) {
        for (std::size_t k = 0; k < 12; ++k) {
            std::vector<int> key = {hm.hexes[h][static_cast<std::size_t>(HexArcs::kHexEdges[k][0])],
                                    hm.hexes[h][static_cast<std::size_t>(HexArcs::kHexEdges[k][1])]};
            std::sort(key.begin(), key.end());
            hexEdges[h][k] = edgeIds.emplace(key, static_cast<int>(edgeIds.size())).first->second;
        }
        for (std::size_t k = 0; k < 6; ++k) {
            std::vector<int> key;
            for (int q = 0; q < 4; ++q) key.push_back(hm.hexes[h][static_cast<std::size_t>(HexArcs::kHexFaces[k][q])]);
            std::sort(key.begin(), key.end());
            const auto [it, fresh] = faceIds.emplace(key, static_cast<int>(faceIds.size()));
            hexFaces[h][k] = it->second;
            signs[h][k] = fresh ? 1 : -1;
        }
    }
    for (int threads : {1, 2}) {
        SCOPED_TRACE("threads " + std::to_string(threads));
        HexArcs out;
        HexElementOwners edgeOwner, faceOwner;
        numberHexEdgesAndFaces(hm, threads, out, edgeOwner, faceOwner);
        EXPECT_EQ(out.hex_edges, hexEdges);
        EXPECT_EQ(out.hex_faces, hexFaces);
        EXPECT_EQ(out.hex_face_sign, signs);
        ASSERT_EQ(out.edges.size(), edgeIds.size());
        ASSERT_EQ(out.faces.size(), faceIds.size());
        ASSERT_EQ(edgeOwner.size(), edgeIds.size());
        ASSERT_EQ(faceOwner.size(), faceIds.size());
        // Owners: the first (hex, local index) holding the id, and the stored vertices are theirs.
        for (std::size_t e = 0; e < edgeOwner.size(); ++e) {
            const auto [h, k] = edgeOwner[e];
            EXPECT_EQ(hexEdges[static_cast<std::size_t>(h)][static_cast<std::size_t>(k)], static_cast<int>(e));
            EXPECT_EQ(out.edges[e][0], hm.hexes[static_cast<std::size_t>(h)][static_cast<std::size_t>(HexArcs::kHexEdges[k][0])]);
        }
        for (std::size_t f = 0; f < faceOwner.size(); ++f) {
            const auto [h, k] = faceOwner[f];
            EXPECT_EQ(signs[static_cast<std::size_t>(h)][static_cast<std::size_t>(k)], 1);
            EXPECT_EQ(out.faces[f][0], hm.hexes[static_cast<std::size_t>(h)][static_cast<std::size_t>(HexArcs::kHexFaces[k][0])]);
        }
    }
}

} // namespace

TEST(HexElementNumbering, TwoHexesShareOneFace) {
    HexMesh hm;
    hm.hexes.push_back({0, 1, 2, 3, 4, 5, 6, 7});
    hm.hexes.push_back({1, 8, 9, 2, 5, 10, 11, 6});  // shares face 1-2-6-5
    HexArcs out;
    HexElementOwners edgeOwner, faceOwner;
    numberHexEdgesAndFaces(hm, 2, out, edgeOwner, faceOwner);
    EXPECT_EQ(out.edges.size(), 20u);
    EXPECT_EQ(out.faces.size(), 11u);
    EXPECT_EQ(out.hex_faces[0][3], out.hex_faces[1][5]);
    EXPECT_EQ(out.hex_face_sign[0][3], 1);
    EXPECT_EQ(out.hex_face_sign[1][5], -1);
    for (int k = 0; k < 12; ++k) EXPECT_EQ(out.hex_edges[0][static_cast<std::size_t>(k)], k);
    expectSameAsReference(hm);
}

TEST(HexElementNumbering, MatchesReferenceOnExtractedMeshes) {
    for (ParametrizedTetMesh pm : {generateCube(3, 5), generateCylinder(5, 3, 2, 2, 1), generateTwistedRing(6, 2, 4, 2)}) {
        pm.mesh.build_adjacency();
        HexMesh hm;
        extractHexMesh(pm, hm);
        ASSERT_GT(hm.hexes.size(), 20u);
        expectSameAsReference(hm);
    }
}
