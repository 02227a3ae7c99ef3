// The paper's Figure 13 as a map (issue 35): a valence-5 edge whose tets are flipped so that
// the signed angle sum around it is 2 pi short. Built from the generated valence-5 cylinder
// (5 wedges of 2 x 2 x 1 hexes, one chart per wedge) by swapping the first two parameters
// of every tet of some wedges, which reflects those wedges (their tets flip) and makes the
// transitions to their neighbours identities: the signed angle sum is 90 degrees per proper
// wedge minus 90 per flipped one.

#include <HexEx/Generators/Generators.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/IO/ReportJson.hh>

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <utility>

using namespace HexEx;

namespace {

/// The valence-5 cylinder (radius 2, height 1, one grid cell per unit) with the wedges in
/// @p flipped reflected (a and b swapped in their parameters).
ParametrizedTetMesh cylinderWithFlippedWedges(const std::set<int>& flipped) {
    ParametrizedTetMesh pm = generateCylinder(5, 2, 1, 2, 1);
    const double pi = std::acos(-1.0);
    for (std::size_t t = 0; t < pm.mesh.n_cells(); ++t) {
        Vec3d c(0, 0, 0);
        for (VertexHandle v : pm.mesh.cell_vertices(CellHandle(static_cast<int>(t)))) c += 0.25 * pm.mesh.position(v);
        const double phi = std::fmod(std::atan2(c[1], c[0]) + 2 * pi, 2 * pi);
        if (!flipped.count(static_cast<int>(phi / (2 * pi / 5)))) continue;
        for (Vec3d& p : pm.params[t]) std::swap(p[0], p[1]);
    }
    pm.mesh.build_adjacency();
    return pm;
}

} // namespace

// One wedge flipped: 270 degrees around the axis, like a valence-3 edge. The flipped wedge
// cancels one proper wedge: 3 wedges of 4 hexes, valid all-hex.
TEST(PaperFigureMaps, OneFlippedWedgeOfAValenceFiveEdgeLeavesAValenceThreeCylinder) {
    HexMesh out;
    const ExtractionReport rep = extractHexMesh(cylinderWithFlippedWedges({1}), out, ExtractionOptions());
    EXPECT_EQ(rep.darts.annihilated_pairs, 192);
    EXPECT_EQ(rep.darts.remaining_anti, 0);
    EXPECT_EQ(out.hexes.size(), 12u);
    EXPECT_EQ(out.polyhedra.size(), 0u);
    EXPECT_EQ(out.vertices.size(), 38u);
    EXPECT_TRUE(rep.valid_all_hex) << rep.validation.summary();
}

// Figure 13: two wedges flipped, 3 x 90 - 2 x 90 = 90 degrees around the axis, 2 pi short of
// the valence-5 edge's 450. The annihilation leaves the darts of one wedge (4 cells of 48),
// and the cell at the axis wraps around an edge of valence 1: its faces a = 0 and b = 0 are
// one face (the 90-degree holonomy maps one onto the other), so it is glued to itself. No
// all-hex mesh has an interior edge of valence 1, so nothing can reconnect it: the output is
// 3 hexes and the axis cell as a polyhedron, reported as not valid, with the two self-glued
// quads named in a warning. The same for non-adjacent flipped wedges.
TEST(PaperFigureMaps, TwoFlippedWedgesOfAValenceFiveEdgeLeaveAValenceOneEdge) {
    for (const std::set<int>& flipped : {std::set<int>{1, 2}, std::set<int>{1, 3}}) {
        const std::string what = "flipped wedges " + std::to_string(*flipped.begin()) + "," + std::to_string(*flipped.rbegin());
        HexMesh out;
        const ExtractionReport rep = extractHexMesh(cylinderWithFlippedWedges(flipped), out, ExtractionOptions());
        EXPECT_EQ(rep.darts.extracted, 960) << what;
        EXPECT_EQ(rep.darts.annihilated_pairs, 384) << what;
        EXPECT_EQ(rep.darts.remaining_anti, 0) << what;
        EXPECT_EQ(rep.darts.broken_cells_after_annihilation, 1) << what;
        EXPECT_EQ(rep.darts.reconnected_cells, 0) << what;
        EXPECT_EQ(out.hexes.size(), 3u) << what;
        EXPECT_EQ(out.polyhedra.size(), 1u) << what;
        EXPECT_EQ(out.vertices.size(), 14u) << what;
        EXPECT_FALSE(rep.valid_all_hex) << what;
        bool named = false;
        for (const std::string& w : rep.warnings) named = named || w.find("2 quads had inconsistent alpha_3 links") != std::string::npos;
        EXPECT_TRUE(named) << what;
    }
}

// Figure 15's kind (darts missing, partially connected quads), constructed: only the 10 tets
// of one wedge next to the axis are reflected (centroid within 0.7 of it), so the fold
// cancels some of the darts of the cells there, not whole cells. 80 pairs annihilate and
// leave one group of 128 darts, no multiple of 48: no set of whole hexes can be made of them,
// and nothing is created or split. The report names the group (its smallest dart, its tet,
// its darts, why) in the warnings and in the JSON; the mesh is returned as the best it can
// be: the 14 hexes away from the fold and the 2 broken cells as polyhedra, not valid.
TEST(PaperFigureMaps, PartlyReflectedWedgeLeavesCellsWithMissingDartsNamedInTheReport) {
    ParametrizedTetMesh pm = generateCylinder(5, 2, 1, 2, 1);
    const double pi = std::acos(-1.0);
    int reflected = 0;
    for (std::size_t t = 0; t < pm.mesh.n_cells(); ++t) {
        Vec3d c(0, 0, 0);
        for (VertexHandle v : pm.mesh.cell_vertices(CellHandle(static_cast<int>(t)))) c += 0.25 * pm.mesh.position(v);
        const double phi = std::fmod(std::atan2(c[1], c[0]) + 2 * pi, 2 * pi);
        if (static_cast<int>(phi / (2 * pi / 5)) != 1 || std::hypot(c[0], c[1]) >= 0.7) continue;
        for (Vec3d& p : pm.params[t]) std::swap(p[0], p[1]);
        ++reflected;
    }
    pm.mesh.build_adjacency();
    ASSERT_EQ(reflected, 10);
    for (int threads : {1, 2}) {
        const std::string what = "threads " + std::to_string(threads);
        HexMesh out;
        ExtractionOptions o;
        o.threads = threads;
        const ExtractionReport rep = extractHexMesh(pm, out, o);
        EXPECT_EQ(rep.darts.extracted, 960) << what;
        EXPECT_EQ(rep.darts.annihilated_pairs, 80) << what;
        EXPECT_EQ(rep.darts.reconnected_cells, 0) << what;
        EXPECT_EQ(rep.darts.unreconnected_cells, 1) << what;
        ASSERT_EQ(rep.darts.unreconnected.size(), 1u) << what;
        const auto& u = rep.darts.unreconnected[0];
        EXPECT_EQ(u.dart, 48) << what;
        EXPECT_EQ(u.tet, 6) << what;
        EXPECT_EQ(u.darts, 128) << what;
        EXPECT_EQ(u.broken_cells, 1) << what;
        EXPECT_EQ(u.reason, "128 darts, not a multiple of 48") << what;
        bool warned = false;
        for (const std::string& w : rep.warnings)
            warned = warned || w == "broken hex cells at dart 48 (tet 6) could not be reconnected: 128 darts, not a multiple of 48";
        EXPECT_TRUE(warned) << what;
        const std::string json = reportToJson(rep, ReportExtras());
        EXPECT_NE(json.find("{\"dart\": 48, \"tet\": 6, \"darts\": 128, \"broken_cells\": 1, \"reason\": \"128 darts, not a multiple of 48\"}"),
                  std::string::npos) << json;
        EXPECT_EQ(out.hexes.size(), 14u) << what;
        EXPECT_EQ(out.polyhedra.size(), 2u) << what;
        EXPECT_EQ(out.vertices.size(), 60u) << what;
        EXPECT_FALSE(rep.valid_all_hex) << what;
        EXPECT_EQ(rep.validation.summary(), "INVALID: 800 darts, eq4 44, eq5 64, eq6 80") << what;
    }
}
