/// @file QuadTraitsTest.cc
/// The templated 2D entry on OpenMesh (TriMesh with halfedge texcoord2D in, PolyMesh out),
/// on plain arrays, and the 2D validator on hand-built maps.

// OpenMesh's PropertyT<VectorT>::push_back() default-constructs an uninitialized vector,
// which GCC reports as -Wmaybe-uninitialized inside the standard library once inlined.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include <HexEx/QuadEx.hh>
#include <HexEx/Quad/QuadGenerators.hh>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <gtest/gtest.h>

using namespace HexEx;

namespace {
using OMTri = OpenMesh::TriMesh_ArrayKernelT<>;   // float points and texcoords, as most users have
using OMPoly = OpenMesh::PolyMesh_ArrayKernelT<>;

/// @p m as an OpenMesh TriMesh with the parameters in halfedge texcoords (to-vertex convention).
OMTri toOpenMesh(const ParametrizedTriMesh& m) {
    OMTri om;
    om.request_halfedge_texcoords2D();
    for (const Vec3d& p : m.points) om.add_vertex(OMTri::Point(float(p[0]), float(p[1]), float(p[2])));
    for (std::size_t f = 0; f < m.triangles.size(); ++f) {
        const auto& t = m.triangles[f];
        const auto fh = om.add_face(OMTri::VertexHandle(t[0]), OMTri::VertexHandle(t[1]), OMTri::VertexHandle(t[2]));
        for (auto h : om.fh_range(fh)) {
            const int v = om.to_vertex_handle(h).idx();
            const int k = v == t[0] ? 0 : v == t[1] ? 1 : 2;
            om.set_texcoord2D(h, OMTri::TexCoord2D(float(m.params[f][k][0]), float(m.params[f][k][1])));
        }
    }
    return om;
}
} // namespace

TEST(QuadTraits, OpenMeshTriMeshToPolyMesh) {
    ParametrizedTriMesh m = generateConeDisk(5, 3, 6);
    applyRandomTriCharts(m, 4);
    const OMTri om = toOpenMesh(m);
    OMPoly out;
    const QuadExtractionReport r = extractQuadMesh(om, out);
    EXPECT_TRUE(r.valid_all_quad);
    EXPECT_EQ(out.n_faces(), 45u);
    EXPECT_EQ(out.n_vertices(), 61u);
    for (auto f : out.faces()) EXPECT_EQ(out.valence(f), 4u);
    // Every interior vertex of a valence-5 cone disk has 4 quads except the cone (5).
    int valence5 = 0;
    for (auto v : out.vertices())
        if (!out.is_boundary(v) && out.valence(v) == 5) ++valence5;
    EXPECT_EQ(valence5, 1);
}

TEST(QuadTraits, PlainArraysToQuadMesh) {
    const ParametrizedTriMesh m = generateTorus(4, 3, 5, 4);
    std::vector<double> pts, par;
    std::vector<int> tris;
    for (const Vec3d& p : m.points) pts.insert(pts.end(), {p[0], p[1], p[2]});
    for (std::size_t f = 0; f < m.triangles.size(); ++f) {
        tris.insert(tris.end(), m.triangles[f].begin(), m.triangles[f].end());
        for (const Vec2d& p : m.params[f]) par.insert(par.end(), {p[0], p[1]});
    }
    TriArraysView view;
    view.points = pts.data();
    view.n_vertices = m.points.size();
    view.triangles = tris.data();
    view.params = par.data();
    view.n_triangles = m.triangles.size();
    QuadMesh qm;
    OMPoly pm;
    const QuadExtractionReport r = extractQuadMesh(view, qm);
    EXPECT_TRUE(r.valid_all_quad);
    EXPECT_EQ(qm.quads.size(), 12u);
    EXPECT_EQ(qm.vertices.size(), 12u);
    extractQuadMesh(view, pm);
    EXPECT_EQ(pm.n_faces(), 12u);
    tris[4] = 1000;
    EXPECT_THROW(extractQuadMesh(view, qm), InputError);
}

TEST(QuadTraits, ValidatorCountsViolations) {
    // One quad: 8 darts d0..d7 around it, alpha_0 pairs (0,1)(2,3)(4,5)(6,7),
    // alpha_1 pairs (1,2)(3,4)(5,6)(7,0), alpha_2 free (boundary).
    GMap<2> g;
    g.add_darts(8);
    for (int k = 0; k < 8; k += 2) g.sew(DartHandle(k), DartHandle(k + 1), 0);
    for (int k = 1; k < 8; k += 2) g.sew(DartHandle(k), DartHandle((k + 1) % 8), 1);
    QuadOrbitLabels labels;
    QuadGMapValidation v = validateQuadGMap(g, &labels);
    EXPECT_TRUE(v.valid()) << v.summary();
    EXPECT_EQ(v.darts, 8);
    EXPECT_EQ(v.boundary_darts, 8);
    EXPECT_EQ(labels.n_faces, 1);
    EXPECT_EQ(labels.n_vertices, 4);
    EXPECT_EQ(labels.n_edges, 4);
    g.unsew(DartHandle(2), 0);  // open face: alpha_0 free, orbit still 8 darts
    v = validateQuadGMap(g);
    EXPECT_EQ(v.open_links, 2);
    EXPECT_FALSE(v.valid());
    g.link(DartHandle(2), DartHandle(5), 0);  // one-sided link
    v = validateQuadGMap(g);
    EXPECT_EQ(v.not_involution, 1);
    EXPECT_EQ(v.eq3_quad, 0);
    g.erase(DartHandle(2));
    v = validateQuadGMap(g);
    EXPECT_EQ(v.darts, 7);
    EXPECT_EQ(v.eq3_quad, 7);
}
