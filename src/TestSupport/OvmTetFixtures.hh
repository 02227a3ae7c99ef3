/// @file OvmTetFixtures.hh
/// Test and benchmark support (not installed): a parametrized tet mesh built in
/// OpenVolumeMesh with the map in the halfface property of the files' convention, the input
/// the OpenVolumeMesh adapter (HexEx/Adapters/OpenVolumeMesh.hh) reads. Shared by the
/// adapter tests and adapter_benchmark. Needs OpenVolumeMesh 3.x headers.
#pragma once

#include <HexEx/Adapters/OpenVolumeMesh.hh>
#include <HexEx/Mesh/ParametrizedTetMesh.hh>

#include <cstddef>
#include <vector>

namespace HexExTestSupport {

/// Builds into the empty @p m the tets of @p pm in the files' convention: tet a b c d
/// becomes the cell of halffaces a b c, a c d, a d b, b d c, each carrying the parameter of
/// the opposite corner (d, b, c, a) in the persistent halfface property
/// HexEx::kOvmParametrization. Cells are added with OVM's topology check; returns the
/// number of tets it refused (0 for a manifold mesh).
template <class Mesh>
std::size_t buildOvmTets(const HexEx::ParametrizedTetMesh& pm, Mesh& m) {
    using Vec = OpenVolumeMesh::Geometry::Vec3d;
    for (std::size_t v = 0; v < pm.mesh.n_vertices(); ++v) {
        const HexEx::Vec3d p = pm.mesh.position(HexEx::VertexHandle(int(v)));
        m.add_vertex(Vec(p[0], p[1], p[2]));
    }
    auto prop = m.template request_halfface_property<Vec>(HexEx::kOvmParametrization);
    m.set_persistent(prop, true);  // outlives this handle, as after reading a file
    static const int kFaces[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
    std::size_t refused = 0;
    for (std::size_t t = 0; t < pm.mesh.n_cells(); ++t) {
        const auto& cv = pm.mesh.cell_vertices(HexEx::CellHandle(int(t)));
        std::vector<OpenVolumeMesh::HalfFaceHandle> hfs;
        for (const auto& f : kFaces) {
            std::vector<OpenVolumeMesh::VertexHandle> vs = {OpenVolumeMesh::VertexHandle(cv[f[0]].idx()),
                                                            OpenVolumeMesh::VertexHandle(cv[f[1]].idx()),
                                                            OpenVolumeMesh::VertexHandle(cv[f[2]].idx())};
            OpenVolumeMesh::HalfFaceHandle hf = m.find_halfface(vs);
            if (!hf.is_valid()) hf = m.halfface_handle(m.add_face(vs), 0);
            hfs.push_back(hf);
        }
        if (!m.add_cell(hfs, true).is_valid()) ++refused;
        for (std::size_t k = 0; k < 4; ++k) {
            const HexEx::Vec3d u = pm.params[t][std::size_t(kFaces[k][3])];
            prop[hfs[k]] = Vec(u[0], u[1], u[2]);
        }
    }
    return refused;
}

} // namespace HexExTestSupport
