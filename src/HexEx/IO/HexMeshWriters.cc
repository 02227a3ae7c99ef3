/// @file HexMeshWriters.cc
/// Implementation of the hex mesh writers (.vtu, .vtk, .ovm, .mesh) and of the singular
/// edge writer. Text is assembled in a string buffer and written in one go.

#include "HexMeshWriters.hh"

#include "../Core/Error.hh"
#include "../Mesh/HexMeshCheck.hh"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <map>

namespace HexEx {

namespace {

/// Appends text with fast number formatting.
class Out {
public:
    /// Appends a string.
    Out& operator<<(const char* s) {
        buf_ += s;
        return *this;
    }
    /// Appends a string.
    Out& operator<<(const std::string& s) {
        buf_ += s;
        return *this;
    }
    /// Appends a character.
    Out& operator<<(char c) {
        buf_ += c;
        return *this;
    }
    /// Appends an integer.
    Out& operator<<(long long v) {
        char tmp[32];
        const auto res = std::to_chars(tmp, tmp + sizeof tmp, v);
        buf_.append(tmp, res.ptr);
        return *this;
    }
    /// Appends an integer.
    Out& operator<<(int v) { return *this << static_cast<long long>(v); }
    /// Appends an integer.
    Out& operator<<(long v) { return *this << static_cast<long long>(v); }
    /// Appends an integer.
    Out& operator<<(std::size_t v) { return *this << static_cast<long long>(v); }
    /// Appends a double with 17 significant digits.
    Out& num(double x) {
        char tmp[40];
        const int n = std::snprintf(tmp, sizeof tmp, "%.17g", x);
        buf_.append(tmp, static_cast<std::size_t>(n > 0 ? n : 0));
        return *this;
    }
    /// Appends "x y z".
    Out& vec(const Vec3d& p) {
        num(p[0]);
        buf_ += ' ';
        num(p[1]);
        buf_ += ' ';
        num(p[2]);
        return *this;
    }
    /// The text.
    const std::string& str() const { return buf_; }

private:
    std::string buf_;
};

/// Throws std::invalid_argument if a cell references a vertex out of range.
void checkIndices(const HexMesh& mesh) {
    const long nv = static_cast<long>(mesh.vertices.size());
    for (std::size_t c = 0; c < mesh.hexes.size(); ++c)
        for (const int v : mesh.hexes[c])
            if (v < 0 || v >= nv)
                throw std::invalid_argument("hex " + std::to_string(c) + " references vertex " + std::to_string(v) +
                                            " (mesh has " + std::to_string(nv) + " vertices)");
    for (std::size_t c = 0; c < mesh.polyhedra.size(); ++c) {
        if (mesh.polyhedra[c].faces.empty())
            throw std::invalid_argument("polyhedron " + std::to_string(c) + " has no faces");
        for (const auto& f : mesh.polyhedra[c].faces) {
            if (f.size() < 3)
                throw std::invalid_argument("polyhedron " + std::to_string(c) + " has a face with " +
                                            std::to_string(f.size()) + " vertices");
            for (const int v : f)
                if (v < 0 || v >= nv)
                    throw std::invalid_argument("polyhedron " + std::to_string(c) + " references vertex " +
                                                std::to_string(v) + " (mesh has " + std::to_string(nv) +
                                                " vertices)");
        }
    }
}

/// Distinct vertices of a polyhedron in order of first appearance.
std::vector<int> polyVertices(const Polyhedron& p) {
    std::vector<int> out;
    for (const auto& f : p.faces)
        for (const int v : f)
            if (std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
    return out;
}

void writeVtu(Out& o, const HexMesh& m) {
    const std::size_t nh = m.hexes.size(), np = m.polyhedra.size();
    o << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << m.vertices.size() << "\" NumberOfCells=\"" << (nh + np) << "\">\n"
      << "      <Points>\n"
      << "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto& p : m.vertices) o.vec(p) << '\n';
    o << "        </DataArray>\n"
      << "      </Points>\n"
      << "      <Cells>\n"
      << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    std::vector<std::vector<int>> pverts(np);
    for (const auto& h : m.hexes) {
        for (int i = 0; i < 8; ++i) o << (i ? " " : "") << h[i];
        o << '\n';
    }
    for (std::size_t c = 0; c < np; ++c) {
        pverts[c] = polyVertices(m.polyhedra[c]);
        for (std::size_t i = 0; i < pverts[c].size(); ++i) o << (i ? " " : "") << pverts[c][i];
        o << '\n';
    }
    o << "        </DataArray>\n"
      << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    long long off = 0;
    for (std::size_t c = 0; c < nh; ++c) {
        off += 8;
        o << off << '\n';
    }
    for (std::size_t c = 0; c < np; ++c) {
        off += static_cast<long long>(pverts[c].size());
        o << off << '\n';
    }
    o << "        </DataArray>\n"
      << "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (std::size_t c = 0; c < nh; ++c) o << "12\n";
    for (std::size_t c = 0; c < np; ++c) o << "42\n";
    o << "        </DataArray>\n";
    if (np > 0) {
        o << "        <DataArray type=\"Int64\" Name=\"faces\" format=\"ascii\">\n";
        std::vector<long long> ends;
        long long fo = 0;
        for (const auto& p : m.polyhedra) {
            o << p.faces.size() << '\n';
            fo += 1;
            for (const auto& f : p.faces) {
                o << f.size();
                for (const int v : f) o << ' ' << v;
                o << '\n';
                fo += 1 + static_cast<long long>(f.size());
            }
            ends.push_back(fo);
        }
        o << "        </DataArray>\n"
          << "        <DataArray type=\"Int64\" Name=\"faceoffsets\" format=\"ascii\">\n";
        for (std::size_t c = 0; c < nh; ++c) o << "-1\n";
        for (const long long e : ends) o << e << '\n';
        o << "        </DataArray>\n";
    }
    o << "      </Cells>\n"
      << "    </Piece>\n"
      << "  </UnstructuredGrid>\n"
      << "</VTKFile>\n";
}

void writeVtk(Out& o, const HexMesh& m) {
    const std::size_t nh = m.hexes.size();
    std::size_t ncells = nh, size = 9 * nh;
    for (const auto& p : m.polyhedra) {
        ncells += p.faces.size();
        for (const auto& f : p.faces) size += 1 + f.size();
    }
    o << "# vtk DataFile Version 3.0\n"
      << "HexEx hex mesh\n"
      << "ASCII\n"
      << "DATASET UNSTRUCTURED_GRID\n"
      << "POINTS " << m.vertices.size() << " double\n";
    for (const auto& p : m.vertices) o.vec(p) << '\n';
    o << "CELLS " << ncells << ' ' << size << '\n';
    for (const auto& h : m.hexes) {
        o << "8";
        for (const int v : h) o << ' ' << v;
        o << '\n';
    }
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

/// Hash of a sorted, -1-padded small face key.
struct SmallKeyHash {
    std::size_t operator()(const std::array<int, 4>& k) const {
        std::uint64_t h = 1469598103934665603ull;
        for (const int v : k) h = (h ^ static_cast<std::uint32_t>(v)) * 1099511628211ull;
        return static_cast<std::size_t>(h);
    }
};

void writeOvm(Out& o, const HexMesh& m) {
    std::vector<std::array<int, 2>> edges;
    std::unordered_map<std::uint64_t, int> edgeId;
    std::vector<std::vector<int>> faces;  // stored loops
    std::unordered_map<std::array<int, 4>, int, SmallKeyHash> smallFace;
    std::map<std::vector<int>, int> largeFace;
    std::vector<std::vector<int>> cells;  // halfface lists

    auto halfedge = [&](int a, int b) {
        const std::uint64_t key = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(std::min(a, b))) << 32) |
                                  static_cast<std::uint32_t>(std::max(a, b));
        auto it = edgeId.find(key);
        if (it == edgeId.end()) {
            it = edgeId.emplace(key, static_cast<int>(edges.size())).first;
            edges.push_back({{a, b}});
        }
        const int e = it->second;
        return 2 * e + (edges[e][0] == a ? 0 : 1);
    };
    auto halfface = [&](const std::vector<int>& loop) {
        int* slot = nullptr;
        int fresh = static_cast<int>(faces.size());
        if (loop.size() <= 4) {
            std::array<int, 4> key{{-1, -1, -1, -1}};
            std::copy(loop.begin(), loop.end(), key.begin());
            std::sort(key.begin(), key.end());
            slot = &smallFace.emplace(key, fresh).first->second;
        } else {
            std::vector<int> key = loop;
            std::sort(key.begin(), key.end());
            slot = &largeFace.emplace(std::move(key), fresh).first->second;
        }
        const int f = *slot;
        if (f == fresh) {
            faces.push_back(loop);
            return 2 * f;
        }
        const auto& s = faces[f];
        const std::size_t n = s.size();
        const std::size_t k = static_cast<std::size_t>(std::find(s.begin(), s.end(), loop[0]) - s.begin());
        const bool same = k < n && s[(k + 1) % n] == loop[1 % loop.size()];
        return 2 * f + (same ? 0 : 1);
    };

    for (const auto& h : m.hexes) {
        std::vector<int> hfs;
        for (const auto& lf : kHexFaces) hfs.push_back(halfface({h[lf[0]], h[lf[1]], h[lf[2]], h[lf[3]]}));
        cells.push_back(std::move(hfs));
    }
    for (const auto& p : m.polyhedra) {
        std::vector<int> hfs;
        for (const auto& f : p.faces) hfs.push_back(halfface(f));
        cells.push_back(std::move(hfs));
    }
    // Edges in face order (so that edge ids follow the faces).
    std::vector<std::vector<int>> faceHalfedges;
    faceHalfedges.reserve(faces.size());
    for (const auto& f : faces) {
        std::vector<int> hes;
        for (std::size_t i = 0; i < f.size(); ++i) hes.push_back(halfedge(f[i], f[(i + 1) % f.size()]));
        faceHalfedges.push_back(std::move(hes));
    }

    o << "OVM ASCII\nVertices\n" << m.vertices.size() << '\n';
    for (const auto& p : m.vertices) o.vec(p) << '\n';
    o << "Edges\n" << edges.size() << '\n';
    for (const auto& e : edges) o << e[0] << ' ' << e[1] << '\n';
    o << "Faces\n" << faces.size() << '\n';
    for (const auto& hes : faceHalfedges) {
        o << hes.size();
        for (const int he : hes) o << ' ' << he;
        o << '\n';
    }
    o << "Polyhedra\n" << cells.size() << '\n';
    for (const auto& c : cells) {
        o << c.size();
        for (const int hf : c) o << ' ' << hf;
        o << '\n';
    }
}

std::vector<std::string> writeMedit(Out& o, const HexMesh& m) {
    o << "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n" << m.vertices.size() << '\n';
    for (const auto& p : m.vertices) o.vec(p) << " 0\n";
    if (!m.hexes.empty()) {
        o << "\nHexahedra\n" << m.hexes.size() << '\n';
        for (const auto& h : m.hexes) {
            for (const int v : h) o << (v + 1) << ' ';
            o << "0\n";
        }
    }
    o << "\nEnd\n";
    std::vector<std::string> warnings;
    if (!m.polyhedra.empty())
        warnings.push_back(std::to_string(m.polyhedra.size()) +
                           " non-hex cell(s) could not be stored in .mesh (Medit has no polyhedra) and were left out");
    return warnings;
}

std::vector<std::string> writeTo(Out& o, const HexMesh& mesh, HexMeshFormat format) {
    checkIndices(mesh);
    switch (format) {
    case HexMeshFormat::Vtu: writeVtu(o, mesh); return {};
    case HexMeshFormat::Vtk: writeVtk(o, mesh); return {};
    case HexMeshFormat::Ovm: writeOvm(o, mesh); return {};
    case HexMeshFormat::Medit: return writeMedit(o, mesh);
    }
    return {};
}

/// Writes @p text to @p path or throws InputError naming the path.
void writeFile(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path + ": cannot open file for writing");
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.flush();
    if (!out) throw InputError(path + ": error while writing the file");
}

} // namespace

HexMeshFormat hexMeshFormatFromPath(const std::string& path) {
    const std::size_t dot = path.find_last_of('.');
    const std::size_t slash = path.find_last_of("/\\");
    std::string ext;
    if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) ext = path.substr(dot + 1);
    for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (ext == "vtu") return HexMeshFormat::Vtu;
    if (ext == "vtk") return HexMeshFormat::Vtk;
    if (ext == "ovm") return HexMeshFormat::Ovm;
    if (ext == "mesh") return HexMeshFormat::Medit;
    throw InputError(path + ": unknown hex mesh file extension '" + (ext.empty() ? std::string() : "." + ext) +
                     "' (expected .vtu, .vtk, .ovm or .mesh)");
}

std::vector<std::string> writeHexMeshStream(std::ostream& out, const HexMesh& mesh, HexMeshFormat format) {
    Out o;
    auto warnings = writeTo(o, mesh, format);
    out.write(o.str().data(), static_cast<std::streamsize>(o.str().size()));
    return warnings;
}

std::vector<std::string> writeHexMesh(const std::string& path, const HexMesh& mesh) {
    const HexMeshFormat format = hexMeshFormatFromPath(path);
    Out o;
    auto warnings = writeTo(o, mesh, format);
    writeFile(path, o.str());
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
    Out o;
    o << "# vtk DataFile Version 3.0\n"
      << "HexEx singular edges\n"
      << "ASCII\n"
      << "DATASET POLYDATA\n"
      << "POINTS " << points.size() << " double\n";
    for (const auto& p : points) o.vec(p) << '\n';
    o << "LINES " << segments.size() << ' ' << 3 * segments.size() << '\n';
    for (const auto& s : segments) o << "2 " << s[0] << ' ' << s[1] << '\n';
    o << "CELL_DATA " << segments.size() << '\n' << "SCALARS valence int 1\n" << "LOOKUP_TABLE default\n";
    for (const int v : valences) o << v << '\n';
    writeFile(path, o.str());
}

} // namespace HexEx
