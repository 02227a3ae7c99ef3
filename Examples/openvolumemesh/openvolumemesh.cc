/// @file openvolumemesh.cc
/// OpenVolumeMesh in, OpenVolumeMesh out. Without arguments: builds the unit cube from six
/// tets in a GeometricTetrahedralMeshV3d with the map "parameter = 2 * position" in the
/// halfface property HexHex::Parametrization (on each halfface the parameter of the
/// opposite vertex), extracts into a GeometricHexahedralMeshV3d with OpenVolumeMesh's
/// topology checks on, and checks the 2x2x2 hexes. With IN (.ovm or .ovmb, read by
/// OpenVolumeMesh) it extracts that mesh instead; with OUT it writes the hex mesh there
/// with OpenVolumeMesh's .ovmb writer. Exits 0 only if the output is valid all-hex.

#include <HexEx/Adapters/OpenVolumeMesh.hh>

#include <OpenVolumeMesh/IO/IO.hh>
#include <OpenVolumeMesh/IO/ovmb_write.hh>
#include <OpenVolumeMesh/Mesh/HexahedralMesh.hh>
#include <OpenVolumeMesh/Mesh/TetrahedralMesh.hh>

#include <iostream>
#include <vector>

namespace {

using OpenVolumeMesh::VertexHandle;
using Vec3 = OpenVolumeMesh::Geometry::Vec3d;

/// Fills @p mesh with the unit cube as six tets; each tet a b c d (positive volume) gets the halffaces a b c,
/// a c d, a d b, b d c (normals into the cell), each holding its opposite corner's parameter.
void makeCube(OpenVolumeMesh::GeometricTetrahedralMeshV3d& mesh) {
    for (int i = 0; i < 8; ++i) mesh.add_vertex(Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
    auto param = mesh.request_halfface_property<Vec3>(HexEx::kOvmParametrization);
    mesh.set_persistent(param, true);
    const int cube[6][4] = {{0, 1, 3, 7}, {0, 5, 1, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 6, 4, 7}};
    const int faces[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};  // loop + opposite corner
    for (const auto& t : cube) {
        std::vector<OpenVolumeMesh::HalfFaceHandle> hfs;
        for (const auto& f : faces) {
            const std::vector<VertexHandle> loop = {VertexHandle(t[f[0]]), VertexHandle(t[f[1]]), VertexHandle(t[f[2]])};
            OpenVolumeMesh::HalfFaceHandle hf = mesh.find_halfface(loop);
            if (!hf.is_valid()) hf = mesh.halfface_handle(mesh.add_face(loop), 0);
            param[hf] = 2.0 * mesh.vertex(VertexHandle(t[f[3]]));  // seamless map: 2 * position
            hfs.push_back(hf);
        }
        mesh.add_cell(hfs, /*topologyCheck=*/true);
    }
}

} // namespace

int main(int argc, char** argv) {
    OpenVolumeMesh::GeometricTetrahedralMeshV3d tets;
    if (argc > 1) {
        if (!OpenVolumeMesh::IO::read_file(argv[1], tets)) {
            std::cerr << "cannot read " << argv[1] << "\n";
            return 1;
        }
    } else {
        makeCube(tets);
    }
    OpenVolumeMesh::GeometricHexahedralMeshV3d hexes;
    HexEx::OvmHexOutput<OpenVolumeMesh::GeometricHexahedralMeshV3d> output(hexes, /*topologyCheck=*/true);
    const HexEx::ExtractionReport report = HexEx::extractHexMesh(HexEx::OvmTetMesh(tets), output);
    HexEx::markOvmNonHexCells(output, static_cast<std::size_t>(report.output.hexes));
    std::cout << "hex mesh: " << hexes.n_cells() << " cells, " << hexes.n_vertices() << " vertices, valid all-hex "
              << report.valid_all_hex << "\n";
    if (argc > 2 && OpenVolumeMesh::IO::ovmb_write(argv[2], hexes) != OpenVolumeMesh::IO::WriteResult::Ok) {
        std::cerr << "cannot write " << argv[2] << "\n";
        return 1;
    }
    if (argc <= 1) return report.valid_all_hex && hexes.n_cells() == 8 && hexes.n_vertices() == 27 ? 0 : 1;
    return report.valid_all_hex ? 0 : 1;
}
