/// @file openvolumemesh.cc
/// OpenVolumeMesh in, OpenVolumeMesh out, in the call of the reference HexEx implementation:
/// `HexEx::extractHexMesh(tetMesh, parameters, hexMesh)` with the map as a cell property
/// holding, per cell, the parameter of each of its vertices.
///
/// Without arguments: the unit cube split into five tets (four corner tets and the central
/// one), parameter = 2 * position, gives 2 x 2 x 2 hexes on 27 vertices; the program exits 0
/// only if it does. With IN (.ovm or .ovmb, read by OpenVolumeMesh, the map in the halfface
/// property "HexHex::Parametrization" as HexHex writes it) it extracts that mesh through the
/// HexHex-style overload instead; with OUT it writes the hex mesh there (.ovmb).

#include <HexEx/Adapters/OpenVolumeMesh.hh>

#include <OpenVolumeMesh/IO/IO.hh>
#include <OpenVolumeMesh/IO/ovmb_write.hh>
#include <OpenVolumeMesh/Mesh/HexahedralMesh.hh>
#include <OpenVolumeMesh/Mesh/TetrahedralGeometryKernel.hh>

#include <iostream>
#include <map>
#include <vector>

// The type aliases a user of the reference implementation has in its place.
using Vec3d = OpenVolumeMesh::Geometry::Vec3d;
using TetrahedralMesh = OpenVolumeMesh::TetrahedralGeometryKernel<Vec3d, OpenVolumeMesh::TetrahedralMeshTopologyKernel>;
using HexahedralMesh = OpenVolumeMesh::GeometryKernel<Vec3d, OpenVolumeMesh::HexahedralMeshTopologyKernel>;

namespace {

/// Adds the tet a b c d to @p mesh, turned to positive volume.
void addTet(TetrahedralMesh& mesh, std::vector<OpenVolumeMesh::VertexHandle> t) {
    const Vec3d e1 = mesh.vertex(t[1]) - mesh.vertex(t[0]), e2 = mesh.vertex(t[2]) - mesh.vertex(t[0]),
                e3 = mesh.vertex(t[3]) - mesh.vertex(t[0]);
    if (((e1 % e2) | e3) < 0) std::swap(t[1], t[2]);  // (e1 x e2) . e3
    mesh.add_cell(t, /*topologyCheck=*/true);
}

/// The unit cube as five tets.
void makeCube(TetrahedralMesh& mesh) {
    std::vector<OpenVolumeMesh::VertexHandle> v;
    for (int i = 0; i < 8; ++i) v.push_back(mesh.add_vertex(Vec3d(i & 1, (i >> 1) & 1, (i >> 2) & 1)));
    addTet(mesh, {v[1], v[2], v[4], v[7]});  // the central tet
    addTet(mesh, {v[0], v[1], v[2], v[4]});  // one tet per cube corner of even parity
    addTet(mesh, {v[3], v[2], v[1], v[7]});
    addTet(mesh, {v[5], v[1], v[4], v[7]});
    addTet(mesh, {v[6], v[4], v[2], v[7]});
}

} // namespace

int main(int argc, char** argv) {
    TetrahedralMesh tetMesh;
    HexahedralMesh hexMesh;
    HexEx::ExtractionReport report;
    if (argc > 1) {
        if (!OpenVolumeMesh::IO::read_file(argv[1], tetMesh)) {
            std::cerr << "cannot read " << argv[1] << "\n";
            return 1;
        }
        auto igm = tetMesh.get_halfface_property<Vec3d>(HexEx::kOvmParametrization);
        if (!igm) {
            std::cerr << argv[1] << " has no halfface property " << HexEx::kOvmParametrization << "\n";
            return 1;
        }
        report = HexEx::extractHexMesh(tetMesh, *igm, hexMesh);
    } else {
        makeCube(tetMesh);
        auto parameters = tetMesh.request_cell_property<std::map<OpenVolumeMesh::VertexHandle, Vec3d>>("Parameters");
        for (const auto c : tetMesh.cells())
            for (const auto v : tetMesh.cell_vertices(c)) parameters[c][v] = 2.0 * tetMesh.vertex(v);
        report = HexEx::extractHexMesh(tetMesh, parameters, hexMesh);
    }
    std::cout << "hex mesh: " << hexMesh.n_cells() << " cells, " << hexMesh.n_vertices() << " vertices, valid all-hex "
              << report.valid_all_hex << "\n";
    if (argc > 2 && OpenVolumeMesh::IO::ovmb_write(argv[2], hexMesh) != OpenVolumeMesh::IO::WriteResult::Ok) {
        std::cerr << "cannot write " << argv[2] << "\n";
        return 1;
    }
    if (argc <= 1) return report.valid_all_hex && hexMesh.n_cells() == 8 && hexMesh.n_vertices() == 27 ? 0 : 1;
    return report.valid_all_hex ? 0 : 1;
}
