/// @file TriangleSurfaceReader.cc
/// OpenMesh-based reader of triangle surfaces.

// OpenMesh's PropertyT<VectorT>::push_back() default-constructs an uninitialized vector,
// which GCC reports as -Wmaybe-uninitialized inside the standard library once inlined.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "TriangleSurfaceReader.hh"

#include "../Core/Error.hh"
#include "../Mesh/BoundarySurface.hh"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace HexEx {

namespace {
/// Mutes OpenMesh's logs (the readers announce progress and problems there) while alive.
class QuietLogs {
public:
    QuietLogs() : log_(::omlog().is_enabled()), err_(::omerr().is_enabled()) {
        ::omlog().disable();
        ::omerr().disable();
    }
    ~QuietLogs() {
        if (log_) ::omlog().enable();
        if (err_) ::omerr().enable();
    }
    QuietLogs(const QuietLogs&) = delete;
    QuietLogs& operator=(const QuietLogs&) = delete;

private:
    bool log_, err_;
};
} // namespace

TriangleSurface readTriangleSurface(const std::string& path) {
    if (!isSurfaceMeshPath(path))
        throw InputError(path + ": unknown surface format (expected .obj, .off, .ply or .stl)");
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": cannot read: is a directory");
    {
        std::ifstream probe(path, std::ios::binary);
        if (!probe) throw InputError(path + ": cannot open: " + std::strerror(errno));
    }
    SurfaceMesh mesh;
    bool ok = false;
    {
        QuietLogs quiet;
        OpenMesh::IO::Options ropt;
        ok = OpenMesh::IO::read_mesh(mesh, path, ropt);
    }
    if (!ok) throw InputError(path + ": OpenMesh could not read the surface mesh");
    TriangleSurface s;
    s.points.reserve(mesh.n_vertices());
    for (const auto v : mesh.vertices()) {
        const auto p = mesh.point(v);
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            throw InputError(path + ": vertex " + std::to_string(v.idx()) + " has a non-finite coordinate");
        s.points.emplace_back(p[0], p[1], p[2]);
    }
    for (const auto f : mesh.faces()) {
        std::vector<int> loop;
        for (const auto v : mesh.fv_range(f)) loop.push_back(v.idx());
        for (std::size_t i = 1; i + 1 < loop.size(); ++i) s.triangles.push_back({{loop[0], loop[i], loop[i + 1]}});
    }
    if (s.triangles.empty()) throw InputError(path + ": the surface has no faces");
    return s;
}

} // namespace HexEx
