// CGAL Linear_cell_complex adapter (HexEx/Adapters/CgalLinearCellComplex.hh): tet LCCs with
// the map per dart, built with shared vertex attributes or with CGAL's own make_tetrahedron +
// sew3_same_facets, extract the same mesh as the .hexex path; the output LCC is valid, its
// volumes are combinatorial hexahedra, 3-sewn along every interior face.

#include "../TestSupport/LccTetFixtures.hh"
#include "TestMeshChecks.hh"

#include <HexEx/Adapters/CgalLinearCellComplex.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/IO/HexExFile.hh>

#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

using HexExTestSupport::HexLcc;
using HexExTestSupport::TetLcc;

/// The tets of @p pm as a 3-sewn LCC with the map in the darts (LccTetFixtures.hh).
TetLcc toLcc(const HexEx::ParametrizedTetMesh& pm) {
    TetLcc lcc;
    EXPECT_EQ(HexExTestSupport::buildTetLcc(pm, lcc), 0u);
    return lcc;
}

/// The same tets built with CGAL's make_tetrahedron() and sew3_same_facets().
TetLcc toLccWithCgalOps(const HexEx::ParametrizedTetMesh& pm) {
    TetLcc lcc;
    HexExTestSupport::buildTetLccWithCgalOps(pm, lcc);
    return lcc;
}

/// The hex mesh held by an output LCC, read back through its darts: vertices in attribute
/// order, hex i from cellDarts()[i] (bottom loop from the first dart, top above it).
HexEx::HexMesh readBack(const HexLcc& lcc, const std::vector<HexLcc::Dart_handle>& cells) {
    HexEx::HexMesh hm;
    std::map<const void*, int> id;
    for (auto it = lcc.vertex_attributes().begin(); it != lcc.vertex_attributes().end(); ++it) {
        id[&*it] = int(hm.vertices.size());
        hm.vertices.push_back(HexEx::detail::lccToVec3d(it->point()));
    }
    auto vid = [&](HexLcc::Dart_const_handle d) { return id.at(&*lcc.vertex_attribute(d)); };
    for (HexLcc::Dart_const_handle d : cells) {
        if (!lcc.is_volume_combinatorial_hexahedron(d)) continue;
        std::array<int, 8> h;
        HexLcc::Dart_const_handle b = d;
        for (int k = 0; k < 4; ++k, b = lcc.beta(b, 1)) {
            h[k] = vid(b);
            h[k + 4] = vid(lcc.beta(b, 2, 1, 1));
        }
        hm.hexes.push_back(h);
    }
    return hm;
}

/// Hexes as sorted tuples of corner positions (independent of vertex numbering).
std::vector<std::array<std::array<double, 3>, 8>> hexesByPosition(const HexEx::HexMesh& hm) {
    std::vector<std::array<std::array<double, 3>, 8>> r;
    for (const auto& h : hm.hexes) {
        std::array<std::array<double, 3>, 8> c;
        for (int k = 0; k < 8; ++k) c[k] = {hm.vertices[h[k]][0], hm.vertices[h[k]][1], hm.vertices[h[k]][2]};
        r.push_back(c);
    }
    std::sort(r.begin(), r.end());
    return r;
}

/// Number of 3-free darts of an LCC.
std::size_t freeDarts3(const HexLcc& lcc) {
    std::size_t n = 0;
    for (auto it = lcc.darts().begin(); it != lcc.darts().end(); ++it) n += lcc.is_free<3>(it) ? 1 : 0;
    return n;
}

/// Number of boundary quads of a hex mesh (faces used by one hex).
std::size_t boundaryQuads(const HexEx::HexMesh& hm) {
    static const int kFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    std::map<std::array<int, 4>, int> count;
    for (const auto& h : hm.hexes)
        for (const auto& f : kFaces) {
            std::array<int, 4> k = {h[f[0]], h[f[1]], h[f[2]], h[f[3]]};
            std::sort(k.begin(), k.end());
            ++count[k];
        }
    std::size_t n = 0;
    for (const auto& [k, c] : count) n += c == 1 ? 1 : 0;
    return n;
}

/// Extracts @p pm through the LCC adapter (both directions) and checks the result against
/// the .hexex path bit for bit and against CGAL's own validity checks.
void checkLccRoundTrip(const HexEx::ParametrizedTetMesh& pm, std::size_t expectedHexes) {
    const HexEx::HexMesh ref = HexExTest::extracted(pm);
    ASSERT_EQ(ref.hexes.size(), expectedHexes);
    ASSERT_TRUE(ref.polyhedra.empty());

    const TetLcc tets = toLcc(pm);
    ASSERT_TRUE(tets.is_valid());
    const HexEx::LccTetMesh input(tets);
    ASSERT_EQ(input.n_tets(), pm.mesh.n_cells());

    // Input side alone: LCC -> built-in output.
    HexEx::HexMesh viaTraits;
    HexEx::extractHexMesh(input, viaTraits);
    HexExTest::expectSameMesh(viaTraits, ref);

    // Both sides: LCC -> LCC.
    HexLcc hexes;
    HexEx::LccHexOutput<HexLcc> output(hexes);
    const HexEx::ExtractionReport report = HexEx::extractHexMesh(input, output);
    EXPECT_TRUE(report.valid_all_hex);
    EXPECT_TRUE(hexes.is_valid());
    EXPECT_EQ(output.unsewnFaces(), 0u);
    ASSERT_EQ(output.cellDarts().size(), expectedHexes);
    EXPECT_EQ(hexes.number_of_vertex_attributes(), ref.vertices.size());
    EXPECT_EQ(hexes.number_of_darts(), 24 * expectedHexes);
    for (auto d : output.cellDarts()) EXPECT_TRUE(hexes.is_volume_combinatorial_hexahedron(d));
    EXPECT_EQ(hexes.one_dart_per_cell<3>().size(), expectedHexes);
    EXPECT_EQ(freeDarts3(hexes), 4 * boundaryQuads(ref));
    HexExTest::expectSameMesh(readBack(hexes, output.cellDarts()), ref);
}

} // namespace

TEST(CgalLccAdapter, SphereMatchesHexExFileBitForBit) {
    const HexEx::ParametrizedTetMesh pm = HexEx::readHexExFile(std::string(HEXEX_SOURCE_DIR) + "/Examples/data/sphere.hexex");
    checkLccRoundTrip(pm, 216);
}

TEST(CgalLccAdapter, CubeMatchesBuiltInKernel) { checkLccRoundTrip(HexEx::generateCube(3, 5), 125); }

TEST(CgalLccAdapter, SingularCylinderMatchesBuiltInKernel) {
    checkLccRoundTrip(HexEx::generateCylinder(3, 3, 2, 2, 1), 3 * 3 * 3 * 2);
}

TEST(CgalLccAdapter, CgalBuiltTetsGiveTheSameHexes) {
    // make_tetrahedron + sew3_same_facets: the vertices are numbered differently, so the
    // hexes are compared by their corner positions.
    const HexEx::ParametrizedTetMesh pm = HexEx::readHexExFile(std::string(HEXEX_SOURCE_DIR) + "/Examples/data/sphere.hexex");
    const TetLcc tets = toLccWithCgalOps(pm);
    ASSERT_TRUE(tets.is_valid());
    ASSERT_EQ(tets.number_of_vertex_attributes(), pm.mesh.n_vertices());
    HexLcc hexes;
    HexEx::LccHexOutput<HexLcc> output(hexes);
    EXPECT_TRUE(HexEx::extractHexMesh(HexEx::LccTetMesh(tets), output).valid_all_hex);
    EXPECT_TRUE(hexes.is_valid());
    EXPECT_EQ(hexesByPosition(readBack(hexes, output.cellDarts())), hexesByPosition(HexExTest::extracted(pm)));
}

TEST(CgalLccAdapter, MapPerCellAndVertexThroughAnAccessor) {
    // The map kept outside the darts: a table keyed by (volume index, vertex attribute).
    const HexEx::ParametrizedTetMesh pm = HexEx::generateCube(2, 3);
    const TetLcc tets = toLcc(pm);
    std::map<std::pair<const void*, const void*>, HexEx::Vec3d> table;
    const HexEx::LccTetMesh byDart(tets);
    for (std::size_t t = 0; t < byDart.n_tets(); ++t)
        for (int i = 0; i < 4; ++i) {
            // Key by the volume's first dart and the corner's vertex attribute.
            const void* cell = &*byDart.cornerDart(t, 0);
            table[{cell, &*tets.vertex_attribute(byDart.cornerDart(t, i))}] = pm.params[t][std::size_t(i)];
        }
    std::map<const void*, const void*> firstDart;  // any dart of a volume -> its first dart
    for (std::size_t t = 0; t < byDart.n_tets(); ++t)
        for (auto it = tets.darts_of_cell<3>(byDart.cornerDart(t, 0)).begin();
             it != tets.darts_of_cell<3>(byDart.cornerDart(t, 0)).end(); ++it)
            firstDart[&*it] = &*byDart.cornerDart(t, 0);
    auto accessor = [&](const TetLcc& lcc, TetLcc::Dart_const_handle d) {
        return table.at({firstDart.at(&*d), &*lcc.vertex_attribute(d)});
    };
    HexEx::HexMesh out;
    HexEx::extractHexMesh(HexEx::LccTetMesh(tets, accessor), out);
    HexExTest::expectSameMesh(out, HexExTest::extracted(pm));
}

TEST(CgalLccAdapter, NonTetVolumeIsAnInputError) {
    TetLcc lcc;
    using P = TetLcc::Point;
    lcc.make_hexahedron(P(0, 0, 0), P(1, 0, 0), P(1, 1, 0), P(0, 1, 0), P(0, 1, 1), P(0, 0, 1), P(1, 0, 1), P(1, 1, 1));
    try {
        HexEx::LccTetMesh view(lcc);
        FAIL() << "no exception";
    } catch (const HexEx::InputError& e) {
        EXPECT_STREQ(e.what(), "LCC volume 0 is not a closed combinatorial tetrahedron");
    }
}

TEST(CgalLccAdapter, OpenAndTwoFacedVolumesAreInputErrors) {
    // The adapter's own closed-tetrahedron check rejects what CGAL's
    // is_volume_combinatorial_tetrahedron() rejects: a lone triangle (2-free darts) and a
    // closed volume of two triangles 2-sewn along all three edges.
    using P = TetLcc::Point;
    const auto expectRejected = [](const TetLcc& lcc) {
        EXPECT_FALSE(lcc.is_volume_combinatorial_tetrahedron(lcc.darts().begin()));
        try {
            HexEx::LccTetMesh view(lcc);
            ADD_FAILURE() << "no exception";
        } catch (const HexEx::InputError& e) {
            EXPECT_STREQ(e.what(), "LCC volume 0 is not a closed combinatorial tetrahedron");
        }
    };
    TetLcc triangle;
    triangle.make_triangle(P(0, 0, 0), P(1, 0, 0), P(0, 1, 0));
    expectRejected(triangle);

    TetLcc pillow;
    const TetLcc::Dart_handle a = pillow.make_triangle(P(0, 0, 0), P(1, 0, 0), P(0, 1, 0));
    const TetLcc::Dart_handle b = pillow.make_triangle(P(0, 0, 0), P(0, 1, 0), P(1, 0, 0));
    int sewn = 0;
    TetLcc::Dart_handle x = a;
    for (int i = 0; i < 3; ++i, x = pillow.beta(x, 1)) {
        TetLcc::Dart_handle y = b;
        for (int j = 0; j < 3; ++j, y = pillow.beta(y, 1))
            if (pillow.point(x) == pillow.point(pillow.beta(y, 1)) && pillow.point(y) == pillow.point(pillow.beta(x, 1)) &&
                pillow.is_sewable<2>(x, y)) {
                pillow.sew<2>(x, y);
                ++sewn;
                break;
            }
    }
    ASSERT_EQ(sewn, 3);
    EXPECT_EQ(pillow.number_of_darts(), 6u);
    expectRejected(pillow);

    // A tetrahedron made by CGAL passes both checks.
    TetLcc tet;
    tet.make_tetrahedron(P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(0, 0, 1));
    EXPECT_TRUE(tet.is_volume_combinatorial_tetrahedron(tet.darts().begin()));
    EXPECT_TRUE(HexEx::detail::lccIsClosedTet(tet, tet.darts().begin()));
}

TEST(CgalLccAdapter, PolyhedraBecomeClosedVolumes) {
    // A square pyramid and a hexahedron sharing the pyramid's base: one 3-sewn quad.
    HexLcc lcc;
    HexEx::LccHexOutput<HexLcc> out(lcc);
    HexEx::fromHexMesh(
        HexEx::HexMesh{{HexEx::Vec3d(0, 0, 0), HexEx::Vec3d(1, 0, 0), HexEx::Vec3d(1, 1, 0), HexEx::Vec3d(0, 1, 0),
                        HexEx::Vec3d(0, 0, 1), HexEx::Vec3d(1, 0, 1), HexEx::Vec3d(1, 1, 1), HexEx::Vec3d(0, 1, 1),
                        HexEx::Vec3d(0.5, 0.5, 2)},
                       {{0, 1, 2, 3, 4, 5, 6, 7}},
                       {HexEx::Polyhedron{{{4, 7, 6, 5}, {4, 5, 8}, {5, 6, 8}, {6, 7, 8}, {7, 4, 8}}}}},
        out);
    EXPECT_TRUE(lcc.is_valid());
    EXPECT_EQ(out.unsewnFaces(), 0u);
    EXPECT_EQ(lcc.number_of_darts(), 24u + 16u);
    EXPECT_EQ(lcc.one_dart_per_cell<3>().size(), 2u);
    EXPECT_EQ(freeDarts3(lcc), 40u - 8u);
    EXPECT_EQ(lcc.number_of_vertex_attributes(), 9u);
}

TEST(CgalLccAdapter, FacesOrientedLikeMakeHexahedron) {
    // CGAL's make_hexahedron() orients every face so that its normal points into the
    // volume; the adapter's hexes do the same.
    auto inwardFaces = [](const HexLcc& lcc, HexLcc::Dart_const_handle d) {
        HexLcc::Vector c(0, 0, 0);
        int n = 0;
        for (auto it = lcc.darts_of_cell<3>(d).begin(); it != lcc.darts_of_cell<3>(d).end(); ++it, ++n)
            c = c + (lcc.point(it) - CGAL::ORIGIN);
        const HexLcc::Point centre = CGAL::ORIGIN + c / n;
        int inward = 0;
        for (auto it = lcc.darts_of_cell<3>(d).begin(); it != lcc.darts_of_cell<3>(d).end(); ++it) {
            const HexLcc::Point& a = lcc.point(it);
            const HexLcc::Point& b = lcc.point(lcc.beta(it, 1));
            const HexLcc::Point& e = lcc.point(lcc.beta(it, 1, 1));
            inward += CGAL::orientation(a, b, e, centre) == CGAL::POSITIVE ? 1 : 0;
        }
        return inward;
    };
    using P = HexLcc::Point;
    HexLcc cgal;
    const auto d = cgal.make_hexahedron(P(0, 0, 0), P(1, 0, 0), P(1, 1, 0), P(0, 1, 0), P(0, 1, 1), P(0, 0, 1),
                                        P(1, 0, 1), P(1, 1, 1));
    ASSERT_TRUE(cgal.is_volume_combinatorial_hexahedron(d));
    EXPECT_EQ(inwardFaces(cgal, d), 24);
    HexLcc ours;
    HexEx::LccHexOutput<HexLcc> out(ours);
    HexEx::fromHexMesh(HexEx::HexMesh{{HexEx::Vec3d(0, 0, 0), HexEx::Vec3d(1, 0, 0), HexEx::Vec3d(1, 1, 0),
                                       HexEx::Vec3d(0, 1, 0), HexEx::Vec3d(0, 0, 1), HexEx::Vec3d(1, 0, 1),
                                       HexEx::Vec3d(1, 1, 1), HexEx::Vec3d(0, 1, 1)},
                                      {{0, 1, 2, 3, 4, 5, 6, 7}},
                                      {}},
                       out);
    EXPECT_EQ(inwardFaces(ours, out.cellDarts()[0]), 24);
}

namespace {

/// One dart per volume of @p lcc in creation order (the order of the extractor's cells
/// when the one-call overload wrote them into a cleared LCC).
std::vector<HexLcc::Dart_handle> volumeDarts(HexLcc& lcc) {
    std::vector<HexLcc::Dart_handle> r;
    for (auto it = lcc.one_dart_per_cell<3>().begin(); it != lcc.one_dart_per_cell<3>().end(); ++it) r.push_back(it);
    return r;
}

} // namespace

TEST(CgalLccAdapter, OneCallOverloadsWithDartInfoAndPointAccessor) {
    for (const auto& pm : {HexEx::readHexExFile(std::string(HEXEX_SOURCE_DIR) + "/Examples/data/sphere.hexex"), HexEx::generateCylinder(3, 3, 2, 2, 1)}) {
        const HexEx::HexMesh ref = HexExTest::extracted(pm);
        const TetLcc tets = toLcc(pm);
        // The map in the darts' info.
        HexLcc viaInfo;
        const HexEx::ExtractionReport r = HexEx::extractHexMesh(tets, viaInfo);
        EXPECT_TRUE(r.valid_all_hex);
        EXPECT_EQ(r.output.hexes, std::int64_t(ref.hexes.size()));
        EXPECT_TRUE(viaInfo.is_valid());
        HexExTest::expectSameMesh(readBack(viaInfo, volumeDarts(viaInfo)), ref);
        // An accessor returning CGAL's Point_3.
        const auto asPoint = [](const TetLcc& lcc, TetLcc::Dart_const_handle d) {
            const std::array<double, 3>& u = lcc.info(d);
            return TetLcc::Point(u[0], u[1], u[2]);
        };
        HexLcc viaAccessor;
        HexEx::extractHexMesh(tets, asPoint, viaAccessor, HexEx::ExtractionOptions{});
        HexExTest::expectSameMesh(readBack(viaAccessor, volumeDarts(viaAccessor)), ref);
        // The same accessor through the view (a Point_3 used not to convert).
        HexEx::HexMesh viaView;
        HexEx::extractHexMesh(HexEx::LccTetMesh(tets, asPoint), viaView);
        HexExTest::expectSameMesh(viaView, ref);
    }
    // Bad input: the output LCC stays untouched.
    TetLcc bad;
    using P = TetLcc::Point;
    bad.make_hexahedron(P(0, 0, 0), P(1, 0, 0), P(1, 1, 0), P(0, 1, 0), P(0, 1, 1), P(0, 0, 1), P(1, 0, 1), P(1, 1, 1));
    HexLcc out;
    out.make_tetrahedron(HexLcc::Point(0, 0, 0), HexLcc::Point(1, 0, 0), HexLcc::Point(0, 1, 0), HexLcc::Point(0, 0, 1));
    try {
        HexEx::extractHexMesh(bad, out);
        FAIL() << "no exception";
    } catch (const HexEx::InputError& e) {
        EXPECT_STREQ(e.what(), "LCC volume 0 is not a closed combinatorial tetrahedron");
    }
    EXPECT_EQ(out.number_of_darts(), 12u);
}

TEST(CgalLccAdapter, TransitionsSingularEdgesAndGivenMatching) {
    // A cylinder of three wedges around a singular edge chain of valence 3.
    const HexEx::ParametrizedTetMesh pm = HexEx::generateCylinder(3, 2, 3, 1, 1);
    const TetLcc tets = toLcc(pm);
    using Dart = TetLcc::Dart_const_handle;
    using Results = HexEx::LccResults<TetLcc, HexLcc>;
    std::map<const void*, std::pair<int, std::array<int, 3>>> transition;  // face dart -> (R, t)
    std::vector<std::pair<Dart, int>> singular;
    Results results;
    results.transition = [&](Dart f, int r, const std::array<int, 3>& t) {
        EXPECT_TRUE(transition.emplace(&*f, std::make_pair(r, t)).second) << "face reported twice";
    };
    results.singular_edge = [&](Dart e, int valence) { singular.emplace_back(e, valence); };
    HexLcc first;
    const HexEx::ExtractionReport r1 = HexEx::extractHexMesh(tets, first, HexEx::ExtractionOptions{}, results);
    EXPECT_TRUE(r1.valid_all_hex);
    EXPECT_EQ(transition.size(), 4 * pm.mesh.n_cells());
    // Each transition maps this volume's parameters of the face's vertices onto the
    // neighbour's (read from the darts' info, independently of the adapter).
    std::size_t rotated = 0, checked = 0;
    for (auto it = tets.darts().begin(); it != tets.darts().end(); ++it) {
        const auto found = transition.find(&*it);
        if (found == transition.end()) continue;
        const auto& [rot, t] = found->second;
        rotated += rot != 0 ? 1 : 0;
        if (tets.is_free<3>(it)) {
            EXPECT_EQ(rot, 0);
            continue;
        }
        const HexEx::GridTransform g(HexEx::Rotation(rot), HexEx::Vec3i(t[0], t[1], t[2]));
        Dart x = it;
        for (int k = 0; k < 3; ++k, x = tets.beta(x, 1)) {
            Dart y = tets.beta(Dart(it), 3);
            for (int j = 0; j < 3 && tets.vertex_attribute(y) != tets.vertex_attribute(x); ++j) y = tets.beta(y, 1);
            ASSERT_EQ(tets.vertex_attribute(y), tets.vertex_attribute(x));
            const auto& a = tets.info(x);
            const auto& b = tets.info(y);
            const HexEx::Vec3d mapped = g.apply(HexEx::Vec3d(a[0], a[1], a[2]));
            for (int d = 0; d < 3; ++d) EXPECT_NEAR(mapped[d], b[std::size_t(d)], 1e-9);
            ++checked;
        }
    }
    EXPECT_GT(rotated, 0u);
    EXPECT_GT(checked, 0u);
    // Singular edges: on the axis, valence 3, as many as the report counts.
    EXPECT_EQ(long(singular.size()), r1.input.singular_edges);
    EXPECT_GT(singular.size(), 0u);
    for (const auto& [e, valence] : singular) {
        EXPECT_EQ(valence, 3);
        for (Dart d : {e, tets.beta(e, 1)}) {
            EXPECT_NEAR(tets.point(d).x(), 0.0, 1e-12);
            EXPECT_NEAR(tets.point(d).y(), 0.0, 1e-12);
        }
    }
    // The reported rotations given back: the same hexes; all-identity: no singular edge.
    Results given;
    given.given_rotation = [&](const TetLcc&, Dart f) { return transition.at(&*f).first; };
    HexLcc second;
    const HexEx::ExtractionReport r2 = HexEx::extractHexMesh(tets, second, HexEx::ExtractionOptions{}, given);
    EXPECT_EQ(r2.input.singular_edges, r1.input.singular_edges);
    HexExTest::expectSameMesh(readBack(second, volumeDarts(second)), readBack(first, volumeDarts(first)));
    given.given_rotation = [](const TetLcc&, Dart) { return 0; };
    HexLcc third;
    EXPECT_EQ(HexEx::extractHexMesh(tets, third, HexEx::ExtractionOptions{}, given).input.singular_edges, 0);
    given.given_rotation = [](const TetLcc&, Dart) { return 24; };
    try {
        HexEx::extractHexMesh(tets, third, HexEx::ExtractionOptions{}, given);
        FAIL() << "no exception";
    } catch (const HexEx::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("given rotation 24 of the face opposite corner"), std::string::npos) << e.what();
    }
}

TEST(CgalLccAdapter, ProvenanceThroughCallables) {
    HexEx::ParametrizedTetMesh pm = HexEx::generateCylinder(3, 2, 3, 1, 1);
    const TetLcc tets = toLcc(pm);
    pm.mesh.build_adjacency();
    HexEx::HexProvenance ref;
    HexEx::ExtractionOptions opt;
    opt.provenance = &ref;
    HexEx::HexMesh hm;
    HexEx::extractHexMesh(pm, hm, opt);
    using Dart = TetLcc::Dart_const_handle;
    std::vector<std::size_t> hexTet, vertexTet;
    std::vector<std::array<int, 3>> cells, coords;
    std::vector<HexEx::Vec3d> points;
    std::vector<const void*> hexDarts;
    HexEx::LccResults<TetLcc, HexLcc> results;
    results.hex_provenance = [&](HexLcc::Dart_handle d, std::size_t t, Dart td, const std::array<int, 3>& c) {
        hexDarts.push_back(&*d);
        hexTet.push_back(t);
        cells.push_back(c);
        EXPECT_TRUE(tets.is_volume_combinatorial_tetrahedron(td));
    };
    results.vertex_provenance = [&](HexLcc::Vertex_attribute_handle v, std::size_t t, Dart, const std::array<int, 3>& z) {
        points.push_back(HexEx::detail::lccToVec3d(v->point()));
        vertexTet.push_back(t);
        coords.push_back(z);
    };
    HexLcc hexes;
    HexEx::extractHexMesh(tets, hexes, HexEx::ExtractionOptions{}, results);
    ASSERT_EQ(hexTet.size(), hm.hexes.size());
    ASSERT_EQ(vertexTet.size(), hm.vertices.size());
    for (std::size_t h = 0; h < hm.hexes.size(); ++h) {
        EXPECT_EQ(int(hexTet[h]), ref.hex_source_tet[h]);
        EXPECT_EQ(cells[h], ref.hex_grid_cell[h]);
    }
    for (std::size_t v = 0; v < hm.vertices.size(); ++v) {
        EXPECT_EQ(int(vertexTet[v]), ref.vertex_source_tet[v]);
        EXPECT_EQ(coords[v], ref.vertex_grid_coords[v]);
        EXPECT_EQ(points[v], hm.vertices[v]);
    }
}

TEST(CgalLccAdapter, VertexNumberingFollowsTheContainerWithHoles) {
    // 1,000 attributes fill several of CGAL's blocks; erasing every seventh leaves holes,
    // and 20 new ones go into some of them.
    TetLcc lcc;
    std::vector<TetLcc::Vertex_attribute_handle> made;
    for (int i = 0; i < 1000; ++i) made.push_back(lcc.create_vertex_attribute(TetLcc::Point(i, 0, 0)));
    for (std::size_t i = 0; i < made.size(); i += 7) lcc.erase_vertex_attribute(made[i]);
    for (int i = 0; i < 20; ++i) lcc.create_vertex_attribute(TetLcc::Point(-i, 1, 0));
    const HexEx::detail::LccVertexNumbering numbering(lcc);
    ASSERT_EQ(numbering.size(), 1000u - 143u + 20u);
    std::size_t k = 0;
    for (auto it = lcc.vertex_attributes().begin(); it != lcc.vertex_attributes().end(); ++it, ++k) {
        ASSERT_EQ(numbering.find(&*it), k);
        // An address inside an attribute is none of them.
        EXPECT_EQ(numbering.find(reinterpret_cast<const char*>(&*it) + 1), HexEx::detail::LccVertexNumbering::npos);
    }
    EXPECT_EQ(k, numbering.size());
    const TetLcc::Point elsewhere(0, 0, 0);
    EXPECT_EQ(numbering.find(&elsewhere), HexEx::detail::LccVertexNumbering::npos);
    // With a run hint kept between calls (as the reader does), backwards through the
    // container and with a stale hint: the same numbers; every address strictly inside an
    // attribute (each byte offset, so that both the power-of-two and the odd part of the
    // attribute size are exercised) is none of them.
    const std::size_t stride = sizeof(*lcc.vertex_attributes().begin());
    std::vector<const char*> addresses;
    for (auto it = lcc.vertex_attributes().begin(); it != lcc.vertex_attributes().end(); ++it)
        addresses.push_back(reinterpret_cast<const char*>(&*it));
    std::size_t hint = 12345;
    for (std::size_t i = addresses.size(); i-- > 0;) {
        ASSERT_EQ(numbering.find(addresses[i], hint), i);
        for (std::size_t b = 1; b < stride; ++b)
            ASSERT_EQ(numbering.find(addresses[i] + b, hint), HexEx::detail::LccVertexNumbering::npos) << i << " + " << b;
    }
    EXPECT_EQ(numbering.find(&elsewhere, hint), HexEx::detail::LccVertexNumbering::npos);
    EXPECT_EQ(numbering.find(addresses[0], hint), 0u);
}
