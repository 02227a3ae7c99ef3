/// @file BoundarySurface.cc
/// Boundary faces of a HexMesh as an OpenMesh surface, written through OpenMesh's IO.

// OpenMesh's PropertyT<VectorT>::push_back() default-constructs an uninitialized vector,
// which GCC reports as -Wmaybe-uninitialized inside the standard library once inlined.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "BoundarySurface.hh"

#include "../Core/Error.hh"
#include "HexMeshCheck.hh"

#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <cstdint>
#include <unordered_map>
#include <stdexcept>
#include <system_error>

namespace HexEx {

namespace {

/// FNV-1a hash of a face key (sorted vertex indices).
struct FaceKeyHash {
    std::size_t operator()(const std::vector<int>& k) const {
        std::uint64_t h = 1469598103934665603ull;
        for (const int v : k) h = (h ^ static_cast<std::uint32_t>(v)) * 1099511628211ull;
        return static_cast<std::size_t>(h);
    }
};

/// Lower-case extension of @p path without the dot ("" if none).
std::string extensionOf(const std::string& path) {
    const std::string file = std::filesystem::path(path).filename().string();
    const std::size_t dot = file.rfind('.');
    if (dot == std::string::npos || dot == 0) return "";
    std::string ext = file.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

/// True if OpenMesh can attach the face @p vs to @p surface without a non-manifold
/// vertex or edge (every vertex on the boundary or isolated, every existing halfedge in the
/// face's direction still free).
bool canAttach(const SurfaceMesh& surface, const std::vector<SurfaceMesh::VertexHandle>& vs) {
    for (std::size_t i = 0; i < vs.size(); ++i) {
        if (!surface.is_boundary(vs[i])) return false;
        const auto he = surface.find_halfedge(vs[i], vs[(i + 1) % vs.size()]);
        if (he.is_valid() && !surface.is_boundary(he)) return false;
    }
    return true;
}

/// Mutes OpenMesh's informational log (the writers announce every file on it) while alive.
class QuietOmLog {
public:
    QuietOmLog() : was_(::omlog().is_enabled()) { ::omlog().disable(); }
    ~QuietOmLog() {
        if (was_) ::omlog().enable();
    }
    QuietOmLog(const QuietOmLog&) = delete;
    QuietOmLog& operator=(const QuietOmLog&) = delete;

private:
    bool was_;
};

} // namespace

SurfaceMesh boundarySurface(const HexMesh& mesh, BoundarySurfaceReport* report) {
    const long long nv = static_cast<long long>(mesh.vertices.size());
    auto checkIndex = [&](int v, const char* kind, std::size_t cell) {
        if (v < 0 || v >= nv)
            throw std::invalid_argument(std::string("boundarySurface: ") + kind + " " + std::to_string(cell) +
                                        " references vertex " + std::to_string(v) + " out of range [0, " +
                                        std::to_string(nv) + ")");
    };

    // All cell faces in cell order, counted by vertex set.
    std::vector<std::vector<int>> faces;
    faces.reserve(6 * mesh.hexes.size());
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
        for (const int v : mesh.hexes[h]) checkIndex(v, "hex", h);
        for (const auto& lf : kHexFaces)
            faces.push_back({mesh.hexes[h][lf[0]], mesh.hexes[h][lf[1]], mesh.hexes[h][lf[2]], mesh.hexes[h][lf[3]]});
    }
    for (std::size_t p = 0; p < mesh.polyhedra.size(); ++p)
        for (const auto& f : mesh.polyhedra[p].faces) {
            for (const int v : f) checkIndex(v, "polyhedron", p);
            faces.push_back(f);
        }
    std::unordered_map<std::vector<int>, int, FaceKeyHash> count;
    count.reserve(faces.size());
    std::vector<std::vector<int>> keys(faces.size());
    for (std::size_t i = 0; i < faces.size(); ++i) {
        keys[i] = faces[i];
        std::sort(keys[i].begin(), keys[i].end());
        ++count[keys[i]];
    }

    BoundarySurfaceReport rep;
    std::vector<std::size_t> boundary;
    std::vector<char> used(mesh.vertices.size(), 0);
    for (std::size_t i = 0; i < faces.size(); ++i) {
        if (count[keys[i]] != 1) continue;
        ++rep.boundary_faces;
        if (faces[i].size() == 4) ++rep.boundary_quads;
        const bool degenerate =
            keys[i].size() < 3 || std::adjacent_find(keys[i].begin(), keys[i].end()) != keys[i].end();
        if (degenerate) {
            ++rep.skipped_faces;
            continue;
        }
        boundary.push_back(i);
        for (const int v : faces[i]) used[static_cast<std::size_t>(v)] = 1;
    }

    SurfaceMesh surface;
    std::vector<SurfaceMesh::VertexHandle> vmap(mesh.vertices.size());
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        if (used[v]) vmap[v] = surface.add_vertex(mesh.vertices[v]);

    std::vector<SurfaceMesh::VertexHandle> vs;
    for (const std::size_t i : boundary) {
        vs.clear();
        for (const int v : faces[i]) vs.push_back(vmap[static_cast<std::size_t>(v)]);
        SurfaceMesh::FaceHandle fh;
        if (canAttach(surface, vs)) fh = surface.add_face(vs);
        if (!fh.is_valid()) {
            // Non-manifold configuration: keep the face on its own copies of the vertices.
            for (auto& vh : vs) {
                const SurfaceMesh::Point p = surface.point(vh);  // copy: add_vertex may reallocate the points
                vh = surface.add_vertex(p);
            }
            surface.add_face(vs);
            ++rep.split_faces;
        }
    }
    if (report) *report = rep;
    return surface;
}

bool isSurfaceMeshPath(const std::string& path) {
    const std::string ext = extensionOf(path);
    return ext == "obj" || ext == "off" || ext == "ply" || ext == "stl";
}

void writeSurfaceMesh(const std::string& path, const SurfaceMesh& surface) {
    if (!isSurfaceMeshPath(path)) {
        const std::string ext = extensionOf(path);
        throw InputError(path + ": unknown surface mesh format " + (ext.empty() ? "(no extension)" : "'." + ext + "'") +
                         " (expected .obj, .off, .ply or .stl)");
    }
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": cannot write: is a directory");
    {
        // Fail early with the system's reason (OpenMesh only reports failure).
        std::ofstream probe(path, std::ios::binary);
        if (!probe) throw InputError(path + ": cannot open for writing: " + std::strerror(errno));
    }
    // OpenMesh's exporters hand points to the writers in single precision: 9 significant
    // digits reproduce every float exactly.
    const std::streamsize precision = 9;
    QuietOmLog quiet;
    bool ok = false;
    if (extensionOf(path) == "stl") {
        SurfaceMesh tri = surface;
        tri.triangulate();
        ok = OpenMesh::IO::write_mesh(tri, path, OpenMesh::IO::Options::Default, precision);
    } else {
        ok = OpenMesh::IO::write_mesh(surface, path, OpenMesh::IO::Options::Default, precision);
    }
    if (!ok) throw InputError(path + ": writing the surface mesh failed");
}

std::vector<std::string> writeBoundarySurface(const std::string& path, const HexMesh& mesh) {
    if (!isSurfaceMeshPath(path)) writeSurfaceMesh(path, SurfaceMesh());  // throws the format error
    BoundarySurfaceReport rep;
    const SurfaceMesh surface = boundarySurface(mesh, &rep);
    writeSurfaceMesh(path, surface);
    std::vector<std::string> warnings;
    if (rep.split_faces > 0)
        warnings.push_back(path + ": " + std::to_string(rep.split_faces) +
                           " boundary faces would make the surface non-manifold and were written with their own "
                           "copies of their vertices");
    if (rep.skipped_faces > 0)
        warnings.push_back(path + ": " + std::to_string(rep.skipped_faces) +
                           " degenerate boundary faces (fewer than three distinct vertices) were left out");
    return warnings;
}

} // namespace HexEx
