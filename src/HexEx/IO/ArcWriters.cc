#include "ArcWriters.hh"

#include "../Core/Error.hh"

#include <fstream>
#include <vector>

namespace HexEx {

namespace {

/// Cells of a .vtu piece: point list, per cell its point indices, a VTK type and an id.
struct Piece {
    const std::vector<Vec3d>* points = nullptr;
    std::vector<std::size_t> connectivity, offsets;
    std::vector<int> type;
    std::vector<std::pair<const char*, std::vector<int>>> cell_data;
};

void writePiece(const std::string& path, const Piece& p) {
    std::ofstream out(path);
    if (!out) throw InputError(path + ": cannot open for writing");
    out.precision(17);
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << p.points->size() << "\" NumberOfCells=\"" << p.type.size()
        << "\">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const Vec3d& x : *p.points) out << x[0] << " " << x[1] << " " << x[2] << "\n";
    out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (std::size_t k = 0; k < p.connectivity.size(); ++k) out << p.connectivity[k] << ((k + 1) % 16 == 0 ? "\n" : " ");
    out << "\n</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t k = 0; k < p.offsets.size(); ++k) out << p.offsets[k] << ((k + 1) % 16 == 0 ? "\n" : " ");
    out << "\n</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (std::size_t k = 0; k < p.type.size(); ++k) out << p.type[k] << ((k + 1) % 32 == 0 ? "\n" : " ");
    out << "\n</DataArray>\n</Cells>\n<CellData>\n";
    for (const auto& d : p.cell_data) {
        out << "<DataArray type=\"Int32\" Name=\"" << d.first << "\" format=\"ascii\">\n";
        for (std::size_t k = 0; k < d.second.size(); ++k) out << d.second[k] << ((k + 1) % 16 == 0 ? "\n" : " ");
        out << "\n</DataArray>\n";
    }
    out << "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    out.flush();
    if (!out) throw InputError(path + ": write failed");
}

constexpr int kVtkTriangle = 5;
constexpr int kVtkPolyLine = 4;

} // namespace

void writeEdgeArcsVtu(const std::string& path, const HexArcs& arcs) {
    Piece p;
    p.points = &arcs.arc_points;
    std::vector<int> id, v0, v1;
    for (std::size_t e = 0; e + 1 < arcs.arc_offset.size(); ++e) {
        const std::size_t b = arcs.arc_offset[e], n = arcs.arc_offset[e + 1];
        if (n == b) continue;
        for (std::size_t k = b; k < n; ++k) p.connectivity.push_back(k);
        p.offsets.push_back(p.connectivity.size());
        p.type.push_back(kVtkPolyLine);
        id.push_back(static_cast<int>(e));
        v0.push_back(arcs.edges[e][0]);
        v1.push_back(arcs.edges[e][1]);
    }
    p.cell_data = {{"edge_id", id}, {"vertex0", v0}, {"vertex1", v1}};
    writePiece(path, p);
}

void writeFacePatchesVtu(const std::string& path, const HexArcs& arcs) {
    Piece p;
    p.points = &arcs.patch_points;
    std::vector<int> id;
    for (std::size_t f = 0; f + 1 < arcs.patch_offset.size(); ++f)
        for (std::size_t k = arcs.patch_offset[f]; k < arcs.patch_offset[f + 1]; ++k) {
            for (int c : arcs.patch_triangles[k]) p.connectivity.push_back(static_cast<std::size_t>(c));
            p.offsets.push_back(p.connectivity.size());
            p.type.push_back(kVtkTriangle);
            id.push_back(static_cast<int>(f));
        }
    p.cell_data = {{"face_id", id}};
    writePiece(path, p);
}

} // namespace HexEx
