/// @file HexMeshWriters.cc
/// Implementation of the hex mesh writers (.vtu, .vtk, .ovm, .ovmb, .mesh) and of the singular
/// edge writer. Output is appended to a BlockOutput that hands 1 MiB blocks to the stream.

#include "HexMeshWriters.hh"

#include "OvmModel.hh"
#include "ReaderSupport.hh"
#include "VtkCells.hh"
#include "VtkDataBlocks.hh"

#include "../Core/Error.hh"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <type_traits>

namespace HexEx {

namespace {

using detail::BlockOutput;

using detail::hostIsLittleEndian;

/// The data arrays of a `.vtu` file: text inside the XML (ascii), or appended blocks that
/// point into the caller's arrays (binary) or hold their compressed bytes.
class VtuWriter {
public:
    VtuWriter(BlockOutput& o, VtuEncoding enc) : o_(o), enc_(enc) {}

    /// Adds a DataArray element for the @p count values at @p values (@p type is the VTK
    /// name of T); binary data is not copied, so @p values must live until finish().
    template <class T>
    void array(const char* name, const char* type, int comps, const T* values, std::size_t count) {
        o_ << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\"";
        if (comps > 1) o_ << " NumberOfComponents=\"" << comps << "\"";
        if (enc_ != VtuEncoding::Ascii) {
            const std::string_view bytes(reinterpret_cast<const char*>(values), count * sizeof(T));
            o_ << " format=\"appended\" offset=\"" << offset_ << "\"/>\n";
            if (enc_ == VtuEncoding::Compressed) blocks_.push_back({detail::makeVtkBlock(bytes, true), {}});
            else blocks_.push_back({sizeOf(bytes.size()), bytes});
            offset_ += blocks_.back().first.size() + blocks_.back().second.size();
            return;
        }
        o_ << " format=\"ascii\">\n";
        for (std::size_t i = 0; i < count; ++i) {
            if constexpr (std::is_floating_point_v<T>) o_.real17(values[i]);
            else o_ << static_cast<long long>(values[i]);
            o_ << ((i + 1) % static_cast<std::size_t>(comps) == 0 ? '\n' : ' ');
        }
        o_ << "        </DataArray>\n";
    }
    /// Appends the closing tags of the XML, the appended blocks and the last closing tags.
    void finish() {
        o_ << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n";
        if (enc_ != VtuEncoding::Ascii) o_ << "  <AppendedData encoding=\"raw\">\n_";
        for (const auto& [owned, borrowed] : blocks_) o_ << std::string_view(owned) << borrowed;
        o_ << (enc_ != VtuEncoding::Ascii ? "\n  </AppendedData>\n</VTKFile>\n" : "</VTKFile>\n");
    }

private:
    /// The UInt64 little-endian header of a block of @p n bytes.
    static std::string sizeOf(std::size_t n) {
        std::string h(8, '\0');
        for (int k = 0; k < 8; ++k) h[static_cast<std::size_t>(k)] = static_cast<char>((static_cast<std::uint64_t>(n) >> (8 * k)) & 0xff);
        return h;
    }

    BlockOutput& o_;
    VtuEncoding enc_;
    std::size_t offset_ = 0;
    std::vector<std::pair<std::string, std::string_view>> blocks_;  // owned bytes, then borrowed bytes
};

/// The cell arrays of a `.vtu` file (T = int32 or int64) and writing them.
template <class T>
struct VtuCells {
    std::vector<T> conn, offsets, faces, faceoffsets;  ///< built arrays (hex connectivity may be borrowed)
    std::vector<std::uint8_t> types;                   ///< cell types

    /// Builds and adds the arrays of @p m to @p w.
    void add(VtuWriter& w, const HexMesh& m) {
        const char* type = sizeof(T) == 4 ? "Int32" : "Int64";
        const std::size_t nh = m.hexes.size(), np = m.polyhedra.size();
        const bool borrowHexes = sizeof(T) == sizeof(int) && np == 0;
        if (!borrowHexes)
            for (const auto& h : m.hexes) conn.insert(conn.end(), h.begin(), h.end());
        offsets.reserve(nh + np);
        for (std::size_t c = 1; c <= nh; ++c) offsets.push_back(static_cast<T>(8 * c));
        for (const auto& p : m.polyhedra) {
            for (const int v : detail::polyVertices(p)) conn.push_back(v);
            offsets.push_back(static_cast<T>(conn.size()));
            faces.push_back(static_cast<T>(p.faces.size()));
            for (const auto& f : p.faces) {
                faces.push_back(static_cast<T>(f.size()));
                faces.insert(faces.end(), f.begin(), f.end());
            }
            faceoffsets.push_back(static_cast<T>(faces.size()));
        }
        types.assign(nh, 12);
        types.resize(nh + np, 42);
        if (borrowHexes) w.array("connectivity", type, 1, reinterpret_cast<const T*>(m.hexes.data()), 8 * nh);
        else w.array("connectivity", type, 1, conn.data(), conn.size());
        w.array("offsets", type, 1, offsets.data(), offsets.size());
        w.array("types", "UInt8", 1, types.data(), types.size());
        if (np > 0) {
            faceoffsets.insert(faceoffsets.begin(), nh, T(-1));
            w.array("faces", type, 1, faces.data(), faces.size());
            w.array("faceoffsets", type, 1, faceoffsets.data(), faceoffsets.size());
        }
    }
};

void writeVtu(BlockOutput& o, const HexMesh& m, VtuEncoding enc) {
    static_assert(sizeof(Vec3d) == 3 * sizeof(double) && sizeof(std::array<int, 8>) == 8 * sizeof(int),
                  "points and hexes are written from the mesh's own arrays");
    o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\""
      << (hostIsLittleEndian() ? "LittleEndian" : "BigEndian") << "\" header_type=\"UInt64\""
      << (enc == VtuEncoding::Compressed ? " compressor=\"vtkZLibDataCompressor\"" : "") << ">\n"
      << "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"" << m.vertices.size() << "\" NumberOfCells=\""
      << (m.hexes.size() + m.polyhedra.size()) << "\">\n      <Points>\n";
    VtuWriter w(o, enc);
    w.array("Points", "Float64", 3, m.vertices.empty() ? nullptr : m.vertices[0].data(), 3 * m.vertices.size());
    o << "      </Points>\n      <Cells>\n";
    std::size_t total = 8 * m.hexes.size();
    for (const auto& p : m.polyhedra)
        for (const auto& f : p.faces) total += 2 * f.size() + 2;
    VtuCells<std::int32_t> small;
    VtuCells<std::int64_t> large;
    if (total < static_cast<std::size_t>(INT32_MAX)) small.add(w, m);
    else large.add(w, m);
    w.finish();
}

/// The header of an ASCII legacy VTK file titled @p title and its POINTS section.
void vtkHeader(BlockOutput& o, const char* title, const char* dataset, const std::vector<Vec3d>& points,
               int threads) {
    o << "# vtk DataFile Version 3.0\n" << title << "\nASCII\nDATASET " << dataset << "\nPOINTS " << points.size()
      << " double\n";
    detail::formatItems(o, points.size(), threads,
                        [&](BlockOutput& t, std::size_t i) { t.vec17(points[i].data()) << '\n'; });
}

void writeVtk(BlockOutput& o, const HexMesh& m, int threads) {
    const std::size_t nh = m.hexes.size();
    std::size_t ncells = nh, size = 9 * nh;
    for (const auto& p : m.polyhedra) {
        ncells += p.faces.size();
        for (const auto& f : p.faces) size += 1 + f.size();
    }
    vtkHeader(o, "HexEx hex mesh", "UNSTRUCTURED_GRID", m.vertices, threads);
    o << "CELLS " << ncells << ' ' << size << '\n';
    detail::formatItems(o, nh, threads, [&](BlockOutput& t, std::size_t c) {
        t << '8';
        for (const int v : m.hexes[c]) t << ' ' << v;
        t << '\n';
    });
    for (const auto& p : m.polyhedra)
        for (const auto& f : p.faces) {
            o << f.size();
            for (const int v : f) o << ' ' << v;
            o << '\n';
        }
    o << "CELL_TYPES " << ncells << '\n';
    for (std::size_t c = 0; c < nh; ++c) o << "12\n";
    for (std::size_t c = nh; c < ncells; ++c) o << "7\n";
    if (!m.polyhedra.empty()) {
        o << "CELL_DATA " << ncells << '\n' << "SCALARS hexex_cell_id int 1\n" << "LOOKUP_TABLE default\n";
        for (std::size_t c = 0; c < nh; ++c) o << c << '\n';
        for (std::size_t c = 0; c < m.polyhedra.size(); ++c)
            for (std::size_t f = 0; f < m.polyhedra[c].faces.size(); ++f) o << (nh + c) << '\n';
    }
}

std::vector<std::string> writeMedit(BlockOutput& o, const HexMesh& m, int threads) {
    o << "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n" << m.vertices.size() << '\n';
    detail::formatItems(o, m.vertices.size(), threads,
                        [&](BlockOutput& t, std::size_t i) { t.vec17(m.vertices[i].data()) << " 0\n"; });
    if (!m.hexes.empty()) {
        o << "\nHexahedra\n" << m.hexes.size() << '\n';
        detail::formatItems(o, m.hexes.size(), threads, [&](BlockOutput& t, std::size_t c) {
            for (const int v : m.hexes[c]) t << (v + 1) << ' ';
            t << "0\n";
        });
    }
    o << "\nEnd\n";
    std::vector<std::string> warnings;
    if (!m.polyhedra.empty())
        warnings.push_back(std::to_string(m.polyhedra.size()) +
                           " non-hex cell(s) could not be stored in .mesh (Medit has no polyhedra) and were left out");
    return warnings;
}

std::vector<std::string> writeTo(std::ostream& out, const HexMesh& mesh, HexMeshFormat format, VtuEncoding enc,
                                 int threads, HexFaceNeighbours* neighbours) {
    detail::checkCellIndices(mesh);
    threads = resolveThreadCount(threads);
    BlockOutput o(&out);
    std::vector<std::string> warnings;
    switch (format) {
    case HexMeshFormat::Vtu: writeVtu(o, mesh, enc); break;
    case HexMeshFormat::Vtk: writeVtk(o, mesh, threads); break;
    case HexMeshFormat::Ovm: writeOvmAscii(o, mesh, threads, neighbours); break;
    case HexMeshFormat::Ovmb: writeOvmBinary(o, ovmFlatFromHexMesh(mesh, threads, neighbours), threads); break;
    default: warnings = writeMedit(o, mesh, threads);
    }
    o.flush();
    return warnings;
}

} // namespace

VtuEncoding vtuEncodingFromName(const std::string& name) {
    if (name == "binary") return VtuEncoding::Binary;
    if (name == "compressed") return VtuEncoding::Compressed;
    if (name == "ascii") return VtuEncoding::Ascii;
    throw std::invalid_argument("unknown encoding '" + name + "' (expected binary, compressed or ascii)");
}

HexMeshFormat hexMeshFormatFromPath(const std::string& path) {
    const std::size_t dot = path.find_last_of('.');
    const std::size_t slash = path.find_last_of("/\\");
    std::string ext;
    if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) ext = path.substr(dot + 1);
    for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (ext == "vtu") return HexMeshFormat::Vtu;
    if (ext == "vtk") return HexMeshFormat::Vtk;
    if (ext == "ovm") return HexMeshFormat::Ovm;
    if (ext == "ovmb") return HexMeshFormat::Ovmb;
    if (ext == "mesh") return HexMeshFormat::Medit;
    throw InputError(path + ": unknown hex mesh file extension '" + (ext.empty() ? std::string() : "." + ext) +
                     "' (expected .vtu, .vtk, .ovm, .ovmb or .mesh)");
}

std::vector<std::string> writeHexMeshStream(std::ostream& out, const HexMesh& mesh, HexMeshFormat format,
                                            VtuEncoding encoding, int threads, HexFaceNeighbours* neighbours) {
    return writeTo(out, mesh, format, encoding, threads, neighbours);
}

std::vector<std::string> writeHexMesh(const std::string& path, const HexMesh& mesh, VtuEncoding encoding,
                                      int threads, HexFaceNeighbours* neighbours) {
    const HexMeshFormat format = hexMeshFormatFromPath(path);
    detail::checkCellIndices(mesh);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path + ": cannot open file for writing");
    auto warnings = writeTo(out, mesh, format, encoding, threads, neighbours);
    out.flush();
    if (!out) throw InputError(path + ": error while writing the file");
    for (auto& w : warnings) w = path + ": " + w;
    return warnings;
}

void writeSingularEdgesVtk(const std::string& path, const std::vector<Vec3d>& points,
                           const std::vector<std::array<int, 2>>& segments, const std::vector<int>& valences) {
    if (segments.size() != valences.size())
        throw std::invalid_argument("writeSingularEdgesVtk: " + std::to_string(segments.size()) + " segments but " +
                                    std::to_string(valences.size()) + " valences");
    const long np = static_cast<long>(points.size());
    for (std::size_t s = 0; s < segments.size(); ++s)
        for (const int v : segments[s])
            if (v < 0 || v >= np)
                throw std::invalid_argument("writeSingularEdgesVtk: segment " + std::to_string(s) +
                                            " references point " + std::to_string(v) + " (" + std::to_string(np) +
                                            " points)");
    BlockOutput o;
    vtkHeader(o, "HexEx singular edges", "POLYDATA", points, 1);
    o << "LINES " << segments.size() << ' ' << 3 * segments.size() << '\n';
    for (const auto& s : segments) o << "2 " << s[0] << ' ' << s[1] << '\n';
    o << "CELL_DATA " << segments.size() << '\n' << "SCALARS valence int 1\n" << "LOOKUP_TABLE default\n";
    for (const int v : valences) o << v << '\n';
    detail::writeWholeFile(path, o.take());
}

} // namespace HexEx
