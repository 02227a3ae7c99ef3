// The OpenVolumeMesh one-call overloads' read (detail::ovmToParametrizedTetMesh()) on several
// threads: the same built-in mesh and parameters for any thread count, equal to the
// sequential OvmTetMesh view's, also for meshes stored with outward halffaces, and the error
// of the first bad cell whichever thread meets it; both through a plain accessor (read on the
// threads) and through the halfface overload's OvmHalffaceParams (read in a pass of its own).

#include "../../TestSupport/OvmTetFixtures.hh"

#include <HexEx/Adapters/OpenVolumeMesh.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/HexExTraits.hh>

#include <OpenVolumeMesh/Mesh/PolyhedralMesh.hh>
#include <OpenVolumeMesh/Mesh/TetrahedralMesh.hh>

#include <gtest/gtest.h>

#include <string>
#include <utility>

namespace {

using TetMesh = OpenVolumeMesh::GeometricTetrahedralMeshV3d;
using PolyMesh = OpenVolumeMesh::GeometricPolyhedralMeshV3d;
using OvmVec = OpenVolumeMesh::Geometry::Vec3d;

/// 48,000 tets: three read blocks (HexEx::detail::kOvmReadBlock cells each), so two or more
/// threads share the cells.
HexEx::ParametrizedTetMesh cube10() { return HexEx::generateCube(20, 10); }

/// The read of @p m (halfface map of the fixtures) on @p threads threads.
template <class Mesh>
HexEx::ParametrizedTetMesh readOn(const Mesh& m, int threads) {
    const auto prop = *m.template get_halfface_property<OvmVec>(HexEx::kOvmParametrization);
    return HexEx::detail::ovmToParametrizedTetMesh(
        m,
        [&](const OpenVolumeMesh::HalfFaceHandle& hf, const OpenVolumeMesh::CellHandle&,
            const OpenVolumeMesh::VertexHandle&) -> const OvmVec& { return prop[hf]; },
        threads);
}

/// The read of @p m through the halfface overload's accessor (parameters in a pass of their own).
template <class Mesh>
HexEx::ParametrizedTetMesh readWithAccessorOn(const Mesh& m, int threads) {
    const auto prop = *m.template get_halfface_property<OvmVec>(HexEx::kOvmParametrization);
    return HexEx::detail::ovmToParametrizedTetMesh(m, HexEx::detail::OvmHalffaceParams<OvmVec>{prop.data_vector().data()},
                                                   threads);
}

/// Positions, corners and parameters of @p a and @p b equal bitwise.
void expectSameCopy(const HexEx::ParametrizedTetMesh& a, const HexEx::ParametrizedTetMesh& b, const std::string& what) {
    ASSERT_EQ(a.mesh.n_vertices(), b.mesh.n_vertices()) << what;
    ASSERT_EQ(a.mesh.n_cells(), b.mesh.n_cells()) << what;
    for (std::size_t v = 0; v < a.mesh.n_vertices(); ++v)
        ASSERT_EQ(a.mesh.position(HexEx::VertexHandle(int(v))), b.mesh.position(HexEx::VertexHandle(int(v))))
            << what << ", vertex " << v;
    for (std::size_t c = 0; c < a.mesh.n_cells(); ++c) {
        ASSERT_EQ(a.mesh.cell_vertices(HexEx::CellHandle(int(c))), b.mesh.cell_vertices(HexEx::CellHandle(int(c))))
            << what << ", cell " << c;
        ASSERT_EQ(a.params[c], b.params[c]) << what << ", cell " << c;
    }
}

} // namespace

TEST(OvmParallelRead, SameCopyForAnyThreadCountAndAsTheSequentialView) {
    HexEx::ParametrizedTetMesh pm = cube10();
    ASSERT_GT(pm.mesh.n_cells(), 2 * HexEx::detail::kOvmReadBlock);
    for (const bool outward : {false, true}) {
        if (outward)  // every tet turned the other way: the read turns them back
            for (std::size_t c = 0; c < pm.mesh.n_cells(); ++c) {
                pm.mesh.swap_corners(HexEx::CellHandle(int(c)), 1, 2);
                std::swap(pm.params[c][1], pm.params[c][2]);
            }
        TetMesh m;
        ASSERT_EQ(HexExTestSupport::buildOvmTets(pm, m), 0u);
        const HexEx::ParametrizedTetMesh view = HexEx::toParametrizedTetMesh(HexEx::OvmTetMesh<TetMesh>(m));
        const std::string kind = outward ? "outward" : "inward";
        for (const int threads : {1, 2, 3, 5}) {
            const HexEx::ParametrizedTetMesh r = readOn(m, threads);
            expectSameCopy(r, view, kind + ", " + std::to_string(threads) + " threads");
            EXPECT_TRUE(r.mesh.has_adjacency());
            const HexEx::ParametrizedTetMesh a = readWithAccessorOn(m, threads);
            expectSameCopy(a, view, kind + ", accessor, " + std::to_string(threads) + " threads");
        }
    }
}

TEST(OvmParallelRead, FirstBadCellReportedForAnyThreadCount) {
    // Cells 5,000 and 40,000 (first and third block) get a fourth halfface of a triangle
    // outside the mesh: both span more than four vertices; the first is reported.
    const HexEx::ParametrizedTetMesh pm = cube10();
    PolyMesh m;
    for (std::size_t v = 0; v < pm.mesh.n_vertices(); ++v) {
        const HexEx::Vec3d p = pm.mesh.position(HexEx::VertexHandle(int(v)));
        m.add_vertex(OvmVec(p[0], p[1], p[2]));
    }
    const OpenVolumeMesh::VertexHandle x = m.add_vertex(OvmVec(-1, 0, 0)), y = m.add_vertex(OvmVec(-1, 1, 0)),
                                       z = m.add_vertex(OvmVec(-1, 0, 1));
    const OpenVolumeMesh::HalfFaceHandle outside = m.halfface_handle(m.add_face({x, y, z}), 0);
    auto prop = m.request_halfface_property<OvmVec>(HexEx::kOvmParametrization);
    m.set_persistent(prop, true);
    static const int kFaces[4][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
    for (std::size_t t = 0; t < pm.mesh.n_cells(); ++t) {
        const auto& cv = pm.mesh.cell_vertices(HexEx::CellHandle(int(t)));
        std::vector<OpenVolumeMesh::HalfFaceHandle> hfs;
        for (const auto& f : kFaces) {
            std::vector<OpenVolumeMesh::VertexHandle> vs;
            for (const int i : f) vs.emplace_back(cv[std::size_t(i)].idx());
            OpenVolumeMesh::HalfFaceHandle hf = m.find_halfface(vs);
            if (!hf.is_valid()) hf = m.halfface_handle(m.add_face(vs), 0);
            hfs.push_back(hf);
        }
        if (t == 5000 || t == 40000) hfs[3] = outside;
        ASSERT_TRUE(m.add_cell(hfs, false).is_valid());
    }
    for (const int threads : {1, 2, 3})
        for (const bool accessor : {false, true}) {
            try {
                if (accessor) readWithAccessorOn(m, threads);
                else readOn(m, threads);
                ADD_FAILURE() << "no exception at " << threads << " threads";
            } catch (const HexEx::InputError& e) {
                EXPECT_EQ(std::string(e.what()), "OpenVolumeMesh cell 5000 spans more than four vertices")
                    << threads << " threads, accessor " << accessor;
            }
        }
}
