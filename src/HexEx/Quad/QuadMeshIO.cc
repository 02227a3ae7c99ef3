/// @file QuadMeshIO.cc
/// Files of the 2D pipeline: OBJ, OFF and PLY through the fast reader and writers of this
/// folder, VTU with a small writer.

#include "QuadMeshIO.hh"

#include "../Core/Error.hh"
#include "TextMeshWriters.hh"
#include "TriObjReader.hh"

#include <fstream>
#include <iomanip>
#include <sstream>

namespace HexEx {

namespace {
/// Lower-case extension of @p path including the dot, or "".
std::string extensionOf(const std::string& path) {
    const std::size_t dot = path.rfind('.');
    const std::size_t slash = path.find_last_of("/\\");
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string e = path.substr(dot);
    for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return e;
}

} // namespace

ParametrizedTriMesh readParametrizedTriMesh(const std::string& path, int threads) {
    if (extensionOf(path) != ".obj") throw InputError(path + ": triangle meshes with parameters are read from .obj files");
    return readTriObjFile(path, threads);
}

void writeParametrizedTriMesh(const std::string& path, const ParametrizedTriMesh& m, int threads) {
    writeTriObjFile(path, m, threads);
}

void writeQuadMesh(const std::string& path, const QuadMesh& qm, int threads) {
    const std::string ext = extensionOf(path);
    if (ext == ".obj" || ext == ".off" || ext == ".ply") {
        writeQuadMeshFile(path, qm, ext == ".obj" ? QuadFileFormat::Obj : ext == ".off" ? QuadFileFormat::Off : QuadFileFormat::Ply,
                          threads);
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
