/// @file LccTetFixtures.hh
/// Test and benchmark support (not installed): a parametrized tet mesh built as a CGAL
/// Linear_cell_complex whose darts carry the map, the input the LCC adapter
/// (HexEx/Adapters/CgalLinearCellComplex.hh) reads. Shared by the adapter tests and
/// adapter_benchmark so both build the same structure.
#pragma once

#include <HexEx/Adapters/CgalLinearCellComplex.hh>
#include <HexEx/Mesh/ParametrizedTetMesh.hh>

#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>

#include <array>
#include <cstddef>
#include <tuple>

namespace HexExTestSupport {

/// LCC items whose darts carry the parameter of their vertex in their volume's chart.
struct ParamItems {
    /// CGAL's per-dart configuration: a point per vertex, the parameter as dart info.
    template <class Refs>
    struct Dart_wrapper {
        typedef CGAL::Cell_attribute_with_point<Refs> Vertex_attribute;  ///< vertex with its position
        typedef std::tuple<Vertex_attribute> Attributes;                 ///< only vertex attributes
        typedef std::array<double, 3> Dart_info;                         ///< the dart's (u, v, w)
    };
};

/// A tet LCC with the map in its darts.
using TetLcc = CGAL::Linear_cell_complex_for_combinatorial_map<3, 3, CGAL::Linear_cell_complex_traits<3>, ParamItems>;
/// A plain 3D LCC, the output structure of the hex meshes.
using HexLcc = CGAL::Linear_cell_complex_for_combinatorial_map<3>;

/// Sets the info of every dart of the volume of @p d to the parameter of its vertex
/// (@p corners[i] belongs to the vertex at @p points[i]).
inline void setVolumeParams(TetLcc& lcc, TetLcc::Dart_handle d, const std::array<HexEx::Vec3d, 4>& corners,
                            const std::array<TetLcc::Point, 4>& points) {
    for (auto it = lcc.darts_of_cell<3>(d).begin(); it != lcc.darts_of_cell<3>(d).end(); ++it)
        for (std::size_t i = 0; i < 4; ++i)
            if (lcc.point(it) == points[i]) lcc.info(it) = {corners[i][0], corners[i][1], corners[i][2]};
}

/// The four corner positions of tet @p t of @p pm as LCC points.
inline std::array<TetLcc::Point, 4> tetPoints(const HexEx::ParametrizedTetMesh& pm, std::size_t t) {
    const auto& cv = pm.mesh.cell_vertices(HexEx::CellHandle(int(t)));
    std::array<TetLcc::Point, 4> pts;
    for (std::size_t i = 0; i < 4; ++i) {
        const HexEx::Vec3d p = pm.mesh.position(cv[i]);
        pts[i] = TetLcc::Point(p[0], p[1], p[2]);
    }
    return pts;
}

/// Builds into @p lcc (cleared first) the tets of @p pm: one vertex attribute per vertex
/// (same order) and one volume per tet (same order, first dart at corner 0), 3-sewn, the
/// map in the darts. Returns the number of faces left unsewn (0 for a manifold mesh).
inline std::size_t buildTetLcc(const HexEx::ParametrizedTetMesh& pm, TetLcc& lcc) {
    HexEx::LccHexOutput<TetLcc> b(lcc);
    b.clear();
    for (std::size_t v = 0; v < pm.mesh.n_vertices(); ++v) b.addVertex(pm.mesh.position(HexEx::VertexHandle(int(v))));
    for (std::size_t t = 0; t < pm.mesh.n_cells(); ++t) {
        const auto& cv = pm.mesh.cell_vertices(HexEx::CellHandle(int(t)));
        const std::size_t a = cv[0].uidx(), bb = cv[1].uidx(), c = cv[2].uidx(), d = cv[3].uidx();
        const auto first = b.addVolume({{a, c, bb}, {a, bb, d}, {bb, c, d}, {c, a, d}});  // outward loops
        setVolumeParams(lcc, first, pm.params[t], tetPoints(pm, t));
    }
    return b.unsewnFaces();
}

/// The same tets built with CGAL's own make_tetrahedron() (four new vertex attributes per
/// tet) and joined by sew3_same_facets() (which merges them): vertex order differs.
inline void buildTetLccWithCgalOps(const HexEx::ParametrizedTetMesh& pm, TetLcc& lcc) {
    lcc.clear();
    for (std::size_t t = 0; t < pm.mesh.n_cells(); ++t) {
        const auto pts = tetPoints(pm, t);
        const auto d = lcc.make_tetrahedron(pts[0], pts[1], pts[2], pts[3]);
        setVolumeParams(lcc, d, pm.params[t], pts);
    }
    lcc.sew3_same_facets();
}

} // namespace HexExTestSupport
