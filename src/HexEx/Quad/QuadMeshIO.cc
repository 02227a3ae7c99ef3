/// @file QuadMeshIO.cc
/// OBJ with vt in and out, quad meshes out, through OpenMesh's IO (plus a VTU writer).

// OpenMesh's PropertyT<VectorT>::push_back() default-constructs an uninitialized vector,
// which GCC reports as -Wmaybe-uninitialized inside the standard library once inlined.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "QuadMeshIO.hh"

#include "../Core/Error.hh"
#include "QuadTraits.hh"

#include <OpenMesh/Core/IO/MeshIO.hh>

#include <fstream>
#include <iomanip>
#include <sstream>

namespace HexEx {

namespace {
/// OpenMesh traits with double positions and texture coordinates.
struct DoubleTraits : public OpenMesh::DefaultTraits {
    typedef OpenMesh::Vec3d Point;       ///< positions
    typedef OpenMesh::Vec3d Normal;      ///< normals
    typedef OpenMesh::Vec2d TexCoord2D;  ///< texture coordinates
};
using DTriMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;
using DPolyMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

/// Lower-case extension of @p path including the dot, or "".
std::string extensionOf(const std::string& path) {
    const std::size_t dot = path.rfind('.');
    const std::size_t slash = path.find_last_of("/\\");
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string e = path.substr(dot);
    for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return e;
}

/// Counts the faces an OBJ file declares (lines starting with "f ").
std::size_t countObjFaces(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::size_t n = 0;
    while (std::getline(in, line))
        if (line.size() > 1 && line[0] == 'f' && (line[1] == ' ' || line[1] == '\t')) ++n;
    return n;
}
} // namespace

ParametrizedTriMesh readParametrizedTriMesh(const std::string& path) {
    if (extensionOf(path) != ".obj") throw InputError(path + ": triangle meshes with parameters are read from .obj files");
    {
        std::ifstream probe(path);
        if (!probe) throw InputError(path + ": cannot open file");
    }
    DTriMesh mesh;
    mesh.request_halfedge_texcoords2D();
    OpenMesh::IO::Options opt = OpenMesh::IO::Options::FaceTexCoord;
    if (!OpenMesh::IO::read_mesh(mesh, path, opt))
        throw InputError(path + ": OpenMesh's OBJ reader could not read the file");
    if (mesh.n_faces() == 0) throw InputError(path + ": no faces");
    if (!opt.face_has_texcoord())
        throw InputError(path + ": no per-corner texture coordinates (faces need 'f v/vt' with 'vt u v' lines)");
    const std::size_t declared = countObjFaces(path);
    if (declared != mesh.n_faces())
        throw InputError(path + ": " + std::to_string(declared) + " faces declared but OpenMesh added " +
                         std::to_string(mesh.n_faces()) +
                         " (polygons, non-manifold or inconsistently oriented faces are not supported)");
    return toParametrizedTriMesh(mesh);
}

void writeParametrizedTriMesh(const std::string& path, const ParametrizedTriMesh& m) {
    DTriMesh mesh;
    mesh.request_halfedge_texcoords2D();
    for (const Vec3d& p : m.points) mesh.add_vertex(DTriMesh::Point(p[0], p[1], p[2]));
    for (std::size_t f = 0; f < m.triangles.size(); ++f) {
        const auto& t = m.triangles[f];
        const auto fh = mesh.add_face(DTriMesh::VertexHandle(t[0]), DTriMesh::VertexHandle(t[1]), DTriMesh::VertexHandle(t[2]));
        if (!fh.is_valid()) throw InputError(path + ": triangle " + std::to_string(f) + " cannot be added (non-manifold)");
        // Corner k's parameter goes to the halfedge pointing to corner k's vertex.
        for (auto h : mesh.fh_range(fh)) {
            const int v = mesh.to_vertex_handle(h).idx();
            const int k = v == t[0] ? 0 : v == t[1] ? 1 : 2;
            mesh.set_texcoord2D(h, DTriMesh::TexCoord2D(m.params[f][static_cast<std::size_t>(k)][0], m.params[f][static_cast<std::size_t>(k)][1]));
        }
    }
    if (!OpenMesh::IO::write_mesh(mesh, path, OpenMesh::IO::Options::FaceTexCoord, 17))
        throw InputError(path + ": OpenMesh could not write the file");
}

void writeQuadMesh(const std::string& path, const QuadMesh& qm) {
    const std::string ext = extensionOf(path);
    if (ext == ".obj" || ext == ".off" || ext == ".ply") {
        DPolyMesh mesh;
        fromQuadMesh(qm, mesh);
        if (!OpenMesh::IO::write_mesh(mesh, path, OpenMesh::IO::Options::Default, 17))
            throw InputError(path + ": OpenMesh could not write the file");
        return;
    }
    if (ext != ".vtu") throw InputError(path + ": unknown quad mesh format (use .obj, .off, .ply or .vtu)");
    std::ofstream out(path);
    if (!out) throw InputError(path + ": cannot open for writing");
    out << std::setprecision(17);
    const std::size_t nc = qm.quads.size() + qm.polygons.size();
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << qm.vertices.size() << "\" NumberOfCells=\"" << nc << "\">\n"
        << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const Vec3d& p : qm.vertices) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto& q : qm.quads) out << q[0] << ' ' << q[1] << ' ' << q[2] << ' ' << q[3] << '\n';
    for (const auto& p : qm.polygons) {
        for (int v : p) out << v << ' ';
        out << '\n';
    }
    out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    long off = 0;
    for (std::size_t i = 0; i < qm.quads.size(); ++i) out << (off += 4) << '\n';
    for (const auto& p : qm.polygons) out << (off += static_cast<long>(p.size())) << '\n';
    out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < qm.quads.size(); ++i) out << "9\n";
    for (std::size_t i = 0; i < qm.polygons.size(); ++i) out << "7\n";
    out << "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    if (!out) throw InputError(path + ": write error");
}

} // namespace HexEx
