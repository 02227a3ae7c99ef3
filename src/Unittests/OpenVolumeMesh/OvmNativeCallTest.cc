// The OpenVolumeMesh one-call overloads of extractHexMesh() (HexEx/Adapters/OpenVolumeMesh.hh):
// the map passed as a cell property std::map<VertexHandle, Vec3d> (the reference HexEx
// implementation's convention) or as a halfface property (HexHex's), the result written
// into an OpenVolumeMesh mesh in bulk. Both give bit for bit the hexes of the built-in path.

#include "../../TestSupport/OvmTetFixtures.hh"
#include "../TestMeshChecks.hh"

#include <HexEx/Adapters/OpenVolumeMesh.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/Grid/GridTransform.hh>
#include <HexEx/IO/HexExFile.hh>
#include <HexEx/Preprocessing/Transitions.hh>

#include <OpenVolumeMesh/IO/IO.hh>
#include <OpenVolumeMesh/IO/ovmb_read.hh>
#include <OpenVolumeMesh/Mesh/HexahedralMesh.hh>
#include <OpenVolumeMesh/Mesh/PolyhedralMesh.hh>
#include <OpenVolumeMesh/Mesh/TetrahedralMesh.hh>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>

namespace {

using TetMesh = OpenVolumeMesh::GeometricTetrahedralMeshV3d;
using PolyMesh = OpenVolumeMesh::GeometricPolyhedralMeshV3d;
using HexMeshOvm = OpenVolumeMesh::GeometricHexahedralMeshV3d;
using OvmVec = OpenVolumeMesh::Geometry::Vec3d;
using CellMap = std::map<OpenVolumeMesh::VertexHandle, OvmVec>;

/// Output of a shell command ("" if it could not run).
std::string capture(const std::string& cmd) {
    std::unique_ptr<FILE, int (*)(FILE*)> p(popen(cmd.c_str(), "r"), pclose);
    std::string out;
    if (!p) return out;
    char buf[65536];
    std::size_t n = 0;
    while ((n = std::fread(buf, 1, sizeof buf, p.get())) > 0) out.append(buf, n);
    return out;
}

/// The map of @p m's halfface property @p hf as a cell property (per cell, vertex -> parameter).
OpenVolumeMesh::CellPropertyT<CellMap> toCellMap(TetMesh& m, const OpenVolumeMesh::HalfFacePropertyT<OvmVec>& hf) {
    auto prop = m.request_cell_property<CellMap>("Parameters");
    for (std::size_t c = 0; c < m.n_cells(); ++c) {
        const OpenVolumeMesh::CellHandle ch{int(c)};
        const std::vector<OpenVolumeMesh::VertexHandle> cv = m.get_cell_vertices(ch);
        for (const auto& h : m.cell(ch).halffaces()) {
            const auto loop = m.get_halfface_vertices(h);
            for (const auto& v : cv)
                if (std::find(loop.begin(), loop.end(), v) == loop.end()) prop[ch][v] = hf[h];
        }
    }
    return prop;
}

/// Checks that @p a and @p b hold the same vertices (bitwise) and the same cells with the
/// same oriented halfface loops, in the same order.
template <class MeshA, class MeshB>
void expectSameOvmMesh(const MeshA& a, const MeshB& b) {
    ASSERT_EQ(a.n_vertices(), b.n_vertices());
    ASSERT_EQ(a.n_cells(), b.n_cells());
    EXPECT_EQ(a.n_faces(), b.n_faces());
    EXPECT_EQ(a.n_edges(), b.n_edges());
    for (std::size_t v = 0; v < a.n_vertices(); ++v) {
        const OvmVec &p = a.vertex(OpenVolumeMesh::VertexHandle(int(v))), &q = b.vertex(OpenVolumeMesh::VertexHandle(int(v)));
        EXPECT_TRUE(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) << "vertex " << v;
    }
    for (std::size_t c = 0; c < a.n_cells(); ++c) {
        const auto& ha = a.cell(OpenVolumeMesh::CellHandle(int(c))).halffaces();
        const auto& hb = b.cell(OpenVolumeMesh::CellHandle(int(c))).halffaces();
        ASSERT_EQ(ha.size(), hb.size()) << "cell " << c;
        for (std::size_t k = 0; k < ha.size(); ++k) {
            auto la = a.get_halfface_vertices(ha[k]), lb = b.get_halfface_vertices(hb[k]);
            // Equal up to the start vertex.
            std::rotate(la.begin(), std::min_element(la.begin(), la.end()), la.end());
            std::rotate(lb.begin(), std::min_element(lb.begin(), lb.end()), lb.end());
            EXPECT_EQ(la, lb) << "cell " << c << " halfface " << k;
        }
    }
}

/// The hexes of @p m as vertex sets, in cell order.
std::vector<std::set<int>> hexVertexSets(const HexMeshOvm& m) {
    std::vector<std::set<int>> r;
    for (std::size_t c = 0; c < m.n_cells(); ++c) {
        std::set<int> s;
        for (const auto& hf : m.cell(OpenVolumeMesh::CellHandle(int(c))).halffaces())
            for (const auto& v : m.get_halfface_vertices(hf)) s.insert(v.idx());
        r.push_back(s);
    }
    return r;
}

/// Extracts @p tets through both overloads (into the hexahedral kernel) and checks each
/// result against @p ref (the built-in path: positions bitwise, hexes as vertex sets, in
/// order) and against OpenVolumeMesh's own checked construction of the same cells.
void expectBothConventionsGive(TetMesh& tets, const HexEx::HexMesh& ref) {
    auto hf = tets.get_halfface_property<OvmVec>(HexEx::kOvmParametrization);
    ASSERT_TRUE(hf.has_value());
    const auto cellMap = toCellMap(tets, *hf);
    HexMeshOvm viaHalffaces, viaCells, checked;
    const HexEx::ExtractionReport r1 = HexEx::extractHexMesh(tets, *hf, viaHalffaces);
    const HexEx::ExtractionReport r2 = HexEx::extractHexMesh(tets, cellMap, viaCells);
    EXPECT_EQ(r1.output.hexes, std::int64_t(ref.hexes.size()));
    EXPECT_EQ(r2.output.hexes, std::int64_t(ref.hexes.size()));
    HexEx::OvmHexOutput<HexMeshOvm> out(checked, /*topologyCheck=*/true);
    HexEx::fromHexMesh(ref, out);
    for (const HexMeshOvm* m : {&viaHalffaces, &viaCells}) {
        ASSERT_EQ(m->n_cells(), ref.hexes.size());
        const auto sets = hexVertexSets(*m);
        for (std::size_t c = 0; c < ref.hexes.size(); ++c)
            ASSERT_EQ(sets[c], std::set<int>(ref.hexes[c].begin(), ref.hexes[c].end())) << "hex " << c;
        expectSameOvmMesh(*m, checked);
    }
}

} // namespace

TEST(OvmNativeCall, SphereBothConventionsGiveTheBuiltInHexes) {
    TetMesh tets;
    ASSERT_TRUE(OpenVolumeMesh::IO::read_file("src/Unittests/data/ovm/sphere.ovmb", tets));
    const HexEx::HexMesh ref = HexExTest::extracted(HexEx::readHexExFile("Examples/data/sphere.hexex"));
    ASSERT_EQ(ref.hexes.size(), 216u);
    expectBothConventionsGive(tets, ref);
}

TEST(OvmNativeCall, PolycubeS1BothConventionsGiveTheBuiltInHexes) {
    const std::string ovmb = "../shared/data/ovm/S1_polycube_scale1.ovmb.xz",
                      hexex = "../shared/data/S1_polycube_scale1.hexex.xz";
    if (!std::filesystem::exists(ovmb) || !std::filesystem::exists(hexex))
        GTEST_SKIP() << "fixture " << ovmb << " or " << hexex << " absent";
    const std::string bytes = capture("xz -dc '" + ovmb + "'");
    if (bytes.empty()) GTEST_SKIP() << "xz not available";
    std::istringstream in(bytes);
    TetMesh tets;
    ASSERT_EQ(OpenVolumeMesh::IO::ovmb_read(in, tets), OpenVolumeMesh::IO::ReadResult::Ok);
    const HexEx::HexMesh ref =
        HexExTest::extracted(HexEx::readHexExBuffer(capture("xz -dc '" + hexex + "'"), "S1.hexex"));
    ASSERT_EQ(ref.hexes.size(), 10288u);
    expectBothConventionsGive(tets, ref);
}

TEST(OvmNativeCall, PolyhedralKernelAndNonHexCellsMatchTheCheckedConstruction) {
    // A cylinder with a perturbed map gives polyhedra on some seeds; any output must equal
    // OpenVolumeMesh's own construction through find_halfface()/add_face() with its checks.
    const HexEx::HexMesh withPolyhedron{
        {HexEx::Vec3d(0, 0, 0), HexEx::Vec3d(1, 0, 0), HexEx::Vec3d(1, 1, 0), HexEx::Vec3d(0, 1, 0),
         HexEx::Vec3d(0, 0, 1), HexEx::Vec3d(1, 0, 1), HexEx::Vec3d(1, 1, 1), HexEx::Vec3d(0, 1, 1),
         HexEx::Vec3d(0.5, 0.5, 2), HexEx::Vec3d(2, 0.5, 0.5)},
        {{0, 1, 2, 3, 4, 5, 6, 7}},
        {HexEx::Polyhedron{{{4, 7, 6, 5}, {4, 5, 8}, {5, 6, 8}, {6, 7, 8}, {7, 4, 8}}},
         HexEx::Polyhedron{{{1, 5, 6, 2}, {1, 2, 9}, {2, 6, 9}, {6, 5, 9}, {5, 1, 9}}}}};
    PolyMesh bulk, checked;
    HexEx::OvmHexOutput<PolyMesh> a(bulk), b(checked, true);
    HexEx::fromHexMesh(withPolyhedron, a);
    HexEx::fromHexMesh(withPolyhedron, b);
    EXPECT_EQ(bulk.n_cells(), 3u);
    EXPECT_EQ(bulk.n_faces(), 6u + 4u + 4u);
    expectSameOvmMesh(bulk, checked);
    // The sphere into the polyhedral kernel: every quad of the 6x6x6 grid once.
    TetMesh tets;
    ASSERT_TRUE(OpenVolumeMesh::IO::read_file("src/Unittests/data/ovm/sphere.ovmb", tets));
    PolyMesh poly;
    HexEx::extractHexMesh(tets, *tets.get_halfface_property<OvmVec>(HexEx::kOvmParametrization), poly);
    EXPECT_EQ(poly.n_cells(), 216u);
    EXPECT_EQ(poly.n_faces(), 3u * 6 * 6 * 7);
    EXPECT_EQ(poly.n_edges(), 3u * 6 * 7 * 7);
    // The bottom-up incidences, turned off while writing, are back: boundary faces and
    // cells around a vertex are known.
    ASSERT_TRUE(poly.has_full_bottom_up_incidences());
    std::size_t boundary = 0;
    for (std::size_t f = 0; f < poly.n_faces(); ++f) boundary += poly.is_boundary(OpenVolumeMesh::FaceHandle(int(f))) ? 1 : 0;
    EXPECT_EQ(boundary, 6u * 36);
    std::size_t around = 0;
    for (auto it = poly.vc_iter(OpenVolumeMesh::VertexHandle(0)); it.valid(); ++it) ++around;
    EXPECT_GE(around, 1u);
}

TEST(OvmNativeCall, GeneratedCylinderAndErrors) {
    const HexEx::ParametrizedTetMesh pm = HexEx::generateCylinder(5, 2, 2, 2, 1);
    TetMesh tets;
    for (std::size_t v = 0; v < pm.mesh.n_vertices(); ++v) {
        const HexEx::Vec3d p = pm.mesh.position(HexEx::VertexHandle(int(v)));
        tets.add_vertex(OvmVec(p[0], p[1], p[2]));
    }
    auto params = tets.request_cell_property<CellMap>("Parameters");
    for (std::size_t t = 0; t < pm.mesh.n_cells(); ++t) {
        const auto& cv = pm.mesh.cell_vertices(HexEx::CellHandle(int(t)));
        // TetrahedralMeshTopologyKernel::add_cell(vertices): positively oriented a b c d.
        const OpenVolumeMesh::CellHandle ch = tets.add_cell(
            OpenVolumeMesh::VertexHandle(cv[0].idx()), OpenVolumeMesh::VertexHandle(cv[1].idx()),
            OpenVolumeMesh::VertexHandle(cv[2].idx()), OpenVolumeMesh::VertexHandle(cv[3].idx()), true);
        ASSERT_TRUE(ch.is_valid());
        for (int i = 0; i < 4; ++i) {
            const HexEx::Vec3d u = pm.params[t][std::size_t(i)];
            params[ch][OpenVolumeMesh::VertexHandle(cv[std::size_t(i)].idx())] = OvmVec(u[0], u[1], u[2]);
        }
    }
    HexMeshOvm hexes;
    const HexEx::ExtractionReport r = HexEx::extractHexMesh(tets, params, hexes);
    const HexEx::HexMesh ref = HexExTest::extracted(pm);
    EXPECT_TRUE(r.valid_all_hex);
    ASSERT_EQ(hexes.n_cells(), ref.hexes.size());
    ASSERT_EQ(hexes.n_vertices(), ref.vertices.size());
    const auto sets = hexVertexSets(hexes);
    for (std::size_t c = 0; c < ref.hexes.size(); ++c)
        EXPECT_EQ(sets[c], std::set<int>(ref.hexes[c].begin(), ref.hexes[c].end())) << "hex " << c;
    // A missing parameter names the cell, the property and the vertex.
    params[OpenVolumeMesh::CellHandle(3)].erase(OpenVolumeMesh::VertexHandle(pm.mesh.cell_vertex(HexEx::CellHandle(3), 2).idx()));
    try {
        HexEx::extractHexMesh(tets, params, hexes);
        FAIL() << "no exception";
    } catch (const HexEx::InputError& e) {
        EXPECT_EQ(std::string(e.what()), "OpenVolumeMesh cell 3: property 'Parameters' has no parameter for vertex " +
                                             std::to_string(pm.mesh.cell_vertex(HexEx::CellHandle(3), 2).idx()));
    }
    EXPECT_EQ(hexes.n_cells(), ref.hexes.size());  // untouched by the failed call
}

TEST(OvmNativeCall, TransitionsAndSingularEdgesWrittenIntoTheTetMesh) {
    // A cylinder of three wedges (one chart each) around a singular edge chain of valence 3.
    HexEx::ParametrizedTetMesh pm = HexEx::generateCylinder(3, 2, 3, 1, 1);
    pm.mesh.build_adjacency();
    TetMesh tets;
    ASSERT_EQ(HexExTestSupport::buildOvmTets(pm, tets), 0u);
    auto rotation = tets.request_halfface_property<int>("rotation", -1);
    auto translation = tets.request_halfface_property<OpenVolumeMesh::Geometry::Vec3i>("translation");
    auto valence = tets.request_edge_property<int>("valence", -1);
    HexEx::OvmTetProperties results;
    results.rotation = &rotation;
    results.translation = &translation;
    results.singular_valence = &valence;
    HexMeshOvm hexes;
    const HexEx::ExtractionReport report = HexEx::extractHexMesh(
        tets, *tets.get_halfface_property<OvmVec>(HexEx::kOvmParametrization), hexes, HexEx::ExtractionOptions{}, results);
    EXPECT_TRUE(report.valid_all_hex);
    EXPECT_EQ(hexes.n_cells(), std::size_t(3 * 2 * 2 * 3));

    // Halfface by halfface, the library's own transitions (buildOvmTets: the k-th halfface of
    // tet t is opposite its corner kOpposite[k]).
    const HexEx::Transitions tr = HexEx::computeTransitions(pm.mesh, pm.params);
    static const int kOpposite[4] = {3, 1, 2, 0};
    std::size_t rotated = 0, checkedMaps = 0;
    for (std::size_t t = 0; t < pm.mesh.n_cells(); ++t) {
        const OpenVolumeMesh::CellHandle ch{int(t)};
        const auto& hfs = tets.cell(ch).halffaces();
        for (std::size_t k = 0; k < 4; ++k) {
            const HexEx::GridTransform g = tr.halfface[4 * t + std::size_t(kOpposite[k])];
            ASSERT_EQ(rotation[hfs[k]], g.R.index()) << "tet " << t << " halfface " << k;
            EXPECT_EQ(translation[hfs[k]], OpenVolumeMesh::Geometry::Vec3i(g.t[0], g.t[1], g.t[2]));
            rotated += g.R.index() != 0 ? 1 : 0;
            // Independently: the transition maps this cell's parameters of the shared
            // vertices onto the neighbour's.
            const OpenVolumeMesh::CellHandle nb = tets.incident_cell(tets.opposite_halfface_handle(hfs[k]));
            if (!nb.is_valid()) continue;
            const HexEx::GridTransform stored(HexEx::Rotation(rotation[hfs[k]]),
                                              HexEx::Vec3i(translation[hfs[k]][0], translation[hfs[k]][1], translation[hfs[k]][2]));
            for (const auto& v : tets.get_halfface_vertices(hfs[k])) {
                auto paramIn = [&](std::size_t cell) {
                    for (int i = 0; i < 4; ++i)
                        if (pm.mesh.cell_vertex(HexEx::CellHandle(int(cell)), i).idx() == v.idx()) return pm.params[cell][std::size_t(i)];
                    ADD_FAILURE() << "vertex not in cell";
                    return HexEx::Vec3d(0, 0, 0);
                };
                const HexEx::Vec3d a = stored.apply(paramIn(t)), b = paramIn(std::size_t(nb.idx()));
                for (int d = 0; d < 3; ++d) EXPECT_NEAR(a[d], b[d], 1e-9) << "tet " << t << " halfface " << k;
                ++checkedMaps;
            }
        }
    }
    EXPECT_GT(rotated, 0u);
    EXPECT_GT(checkedMaps, 0u);

    // Singular edges: the axis, valence 3; every other edge 0.
    std::size_t singular = 0;
    for (std::size_t e = 0; e < tets.n_edges(); ++e) {
        const OpenVolumeMesh::EdgeHandle eh{int(e)};
        const int val = valence[eh];
        ASSERT_TRUE(val == 0 || val == 3) << "edge " << e << " valence " << val;
        if (val == 0) continue;
        ++singular;
        for (const auto& v : {tets.edge(eh).from_vertex(), tets.edge(eh).to_vertex()}) {
            EXPECT_NEAR(tets.vertex(v)[0], 0.0, 1e-12);
            EXPECT_NEAR(tets.vertex(v)[1], 0.0, 1e-12);
        }
    }
    EXPECT_EQ(long(singular), report.input.singular_edges);
    EXPECT_GT(singular, 0u);
    // The same graph as the library function the CLI writes.
    const HexEx::SingularityGraph graph = HexEx::singularityGraph(pm);
    EXPECT_EQ(graph.segments.size(), singular);
    for (int v : graph.valences) EXPECT_EQ(v, 3);
}

TEST(OvmNativeCall, GivenRotationsAreHonoured) {
    HexEx::ParametrizedTetMesh pm = HexEx::generateCylinder(3, 2, 3, 1, 1);
    TetMesh tets;
    ASSERT_EQ(HexExTestSupport::buildOvmTets(pm, tets), 0u);
    const auto igm = *tets.get_halfface_property<OvmVec>(HexEx::kOvmParametrization);
    // The rotations HexEx infers, written by one call and given to the next: the same hexes.
    auto rotation = tets.request_halfface_property<int>("rotation");
    HexEx::OvmTetProperties write;
    write.rotation = &rotation;
    HexMeshOvm first, second;
    const HexEx::ExtractionReport r1 = HexEx::extractHexMesh(tets, igm, first, HexEx::ExtractionOptions{}, write);
    HexEx::OvmTetProperties read;
    read.given_rotation = &rotation;
    const HexEx::ExtractionReport r2 = HexEx::extractHexMesh(tets, igm, second, HexEx::ExtractionOptions{}, read);
    EXPECT_TRUE(r2.valid_all_hex);
    EXPECT_EQ(r2.input.singular_edges, r1.input.singular_edges);
    EXPECT_GT(r1.input.singular_edges, 0);
    expectSameOvmMesh(second, first);
    // All-identity rotations given: the transitions around the axis compose to the identity,
    // so the extraction sees no singular edge (the given matching is used, not inferred).
    auto identity = tets.request_halfface_property<int>("identity", 0);
    read.given_rotation = &identity;
    HexMeshOvm third;
    const HexEx::ExtractionReport r3 = HexEx::extractHexMesh(tets, igm, third, HexEx::ExtractionOptions{}, read);
    EXPECT_EQ(r3.input.singular_edges, 0);
    // A value that is no rotation index names the halfface.
    auto bad = tets.request_halfface_property<int>("bad", 0);
    OpenVolumeMesh::HalfFaceHandle interior;
    for (std::size_t h = 0; h < tets.n_halffaces() && !interior.is_valid(); ++h) {
        const OpenVolumeMesh::HalfFaceHandle hf{int(h)};
        if (tets.incident_cell(hf).is_valid() && tets.incident_cell(tets.opposite_halfface_handle(hf)).is_valid()) interior = hf;
    }
    ASSERT_TRUE(interior.is_valid());
    bad[interior] = 24;
    read.given_rotation = &bad;
    try {
        HexEx::extractHexMesh(tets, igm, third, HexEx::ExtractionOptions{}, read);
        FAIL() << "no exception";
    } catch (const HexEx::InputError& e) {
        EXPECT_EQ(std::string(e.what()), "OpenVolumeMesh halfface " + std::to_string(interior.idx()) +
                                             ": given rotation 24 is not a rotation index (0..23)");
    }
}

TEST(OvmNativeCall, ProvenanceWrittenIntoTheHexMesh) {
    HexEx::ParametrizedTetMesh pm = HexEx::generateCylinder(3, 2, 3, 1, 1);
    pm.mesh.build_adjacency();
    TetMesh tets;
    ASSERT_EQ(HexExTestSupport::buildOvmTets(pm, tets), 0u);
    const auto igm = *tets.get_halfface_property<OvmVec>(HexEx::kOvmParametrization);
    HexMeshOvm hexes;
    const HexEx::OvmHexProperties names = HexEx::OvmHexProperties::all();
    const HexEx::ExtractionReport r =
        HexEx::extractHexMesh(tets, igm, hexes, HexEx::ExtractionOptions{}, HexEx::OvmTetProperties{}, names);
    EXPECT_TRUE(r.valid_all_hex);
    // The built-in kernel's provenance from the same map: OVM cell i is tet i, vertices and
    // hexes in the same order.
    HexEx::HexProvenance ref;
    HexEx::ExtractionOptions opt;
    opt.provenance = &ref;
    HexEx::HexMesh hm;
    HexEx::extractHexMesh(pm, hm, opt);
    ASSERT_EQ(hexes.n_cells(), hm.hexes.size());
    ASSERT_EQ(hexes.n_vertices(), hm.vertices.size());
    auto sourceTet = hexes.get_cell_property<int>("hexex:source_tet");
    auto gridCell = hexes.get_cell_property<OpenVolumeMesh::Geometry::Vec3i>("hexex:grid_cell");
    auto gridCoords = hexes.get_vertex_property<OpenVolumeMesh::Geometry::Vec3i>("hexex:grid_coords");
    auto vertexTet = hexes.get_vertex_property<int>("hexex:vertex_source_tet");
    ASSERT_TRUE(sourceTet && gridCell && gridCoords && vertexTet);
    for (std::size_t h = 0; h < hm.hexes.size(); ++h) {
        const OpenVolumeMesh::CellHandle ch{int(h)};
        EXPECT_EQ((*sourceTet)[ch], ref.hex_source_tet[h]) << "hex " << h;
        const auto& c = ref.hex_grid_cell[h];
        EXPECT_EQ((*gridCell)[ch], OpenVolumeMesh::Geometry::Vec3i(c[0], c[1], c[2])) << "hex " << h;
    }
    for (std::size_t v = 0; v < hm.vertices.size(); ++v) {
        const OpenVolumeMesh::VertexHandle vh{int(v)};
        ASSERT_GE((*vertexTet)[vh], 0);
        EXPECT_EQ((*vertexTet)[vh], ref.vertex_source_tet[v]);
        const auto& z = ref.vertex_grid_coords[v];
        EXPECT_EQ((*gridCoords)[vh], OpenVolumeMesh::Geometry::Vec3i(z[0], z[1], z[2]));
        // Independently: the grid point is one of the source cell's corner parameters or
        // inside its parameter image (the cylinder's charts are exact).
        const auto& p = pm.params[std::size_t((*vertexTet)[vh])];
        double lo[3], hi[3];
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min({p[0][k], p[1][k], p[2][k], p[3][k]});
            hi[k] = std::max({p[0][k], p[1][k], p[2][k], p[3][k]});
            EXPECT_LE(lo[k] - 1e-9, z[std::size_t(k)]);
            EXPECT_GE(hi[k] + 1e-9, z[std::size_t(k)]);
        }
    }
    // Not asked for: no property.
    HexMeshOvm plain;
    HexEx::extractHexMesh(tets, igm, plain);
    EXPECT_FALSE(plain.get_cell_property<int>("hexex:source_tet"));
}

TEST(OvmNativeCall, UserIncidenceFlagsAreKept) {
    // The bulk writer turns OpenVolumeMesh's bottom-up incidences off while writing and back
    // on afterwards: each kind (vertex, edge, face) the user's mesh had on, and only those.
    // The mesh is the same for every combination, and with all on its incidences are those
    // OpenVolumeMesh computes when they are enabled on the finished mesh.
    TetMesh tets;
    ASSERT_TRUE(OpenVolumeMesh::IO::read_file("src/Unittests/data/ovm/sphere.ovmb", tets));
    // A copy of the property handle: the optional that get_halfface_property() returns is a temporary.
    const auto param = *tets.get_halfface_property<OvmVec>(HexEx::kOvmParametrization);
    HexMeshOvm all;
    HexEx::extractHexMesh(tets, param, all);
    ASSERT_TRUE(all.has_full_bottom_up_incidences());
    ASSERT_EQ(all.n_cells(), 216u);
    for (int flags = 0; flags < 8; ++flags) {
        const bool v = flags & 1, e = flags & 2, f = flags & 4;
        HexMeshOvm m;
        m.enable_vertex_bottom_up_incidences(v);
        m.enable_edge_bottom_up_incidences(e);
        m.enable_face_bottom_up_incidences(f);
        HexEx::extractHexMesh(tets, param, m);
        EXPECT_EQ(m.has_vertex_bottom_up_incidences(), v) << flags;
        EXPECT_EQ(m.has_edge_bottom_up_incidences(), e) << flags;
        EXPECT_EQ(m.has_face_bottom_up_incidences(), f) << flags;
        expectSameOvmMesh(m, all);
        if (flags == 0) {
            m.enable_bottom_up_incidences(true);
            for (std::size_t x = 0; x < m.n_vertices(); ++x) {
                const OpenVolumeMesh::VertexHandle vh{static_cast<int>(x)};
                std::vector<int> a, b;
                for (auto he : m.outgoing_halfedges(vh)) a.push_back(he.idx());
                for (auto he : all.outgoing_halfedges(vh)) b.push_back(he.idx());
                ASSERT_EQ(a, b) << "vertex " << x;
            }
            for (std::size_t x = 0; x < m.n_edges(); ++x) {
                const OpenVolumeMesh::HalfEdgeHandle he = m.halfedge_handle(OpenVolumeMesh::EdgeHandle(int(x)), 0);
                std::vector<int> a, b;
                for (auto hf : m.halfedge_halffaces(he)) a.push_back(hf.idx());
                for (auto hf : all.halfedge_halffaces(he)) b.push_back(hf.idx());
                ASSERT_EQ(a, b) << "edge " << x;
            }
            for (std::size_t x = 0; x < 2 * m.n_faces(); ++x) {
                const OpenVolumeMesh::HalfFaceHandle hf{static_cast<int>(x)};
                ASSERT_EQ(m.incident_cell(hf), all.incident_cell(hf)) << "halfface " << x;
            }
        }
    }
}
