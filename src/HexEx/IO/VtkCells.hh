#pragma once
/// @file VtkCells.hh
/// @ingroup io
/// Cell helpers shared by the hex mesh readers and writers: VTK cell types into HexMesh
/// cells, signed volumes, index checks.

#include "../Mesh/HexMesh.hh"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace HexEx {
namespace detail {

/// Signed volume (times 6) of a closed polyhedron given by face loops over @p pts.
inline double signedVolume6(const std::vector<Vec3d>& pts, const std::vector<std::vector<int>>& faces) {
    if (faces.empty() || faces[0].empty()) return 0;
    const Vec3d c = pts[faces[0][0]];
    double v = 0;
    for (const auto& f : faces)
        for (std::size_t i = 1; i + 1 < f.size(); ++i) v += ((pts[f[0]] - c) % (pts[f[i]] - c)) | (pts[f[i + 1]] - c);
    return v;
}

/// Throws std::invalid_argument if a cell of @p mesh references a vertex out of range,
/// a polyhedron has no faces or a face has fewer than three vertices.
inline void checkCellIndices(const HexMesh& mesh) {
    const long nv = static_cast<long>(mesh.vertices.size());
    const auto bad = [&](const std::string& what, std::size_t c, long v) {
        throw std::invalid_argument(what + " " + std::to_string(c) + " references vertex " + std::to_string(v) +
                                    " (mesh has " + std::to_string(nv) + " vertices)");
    };
    for (std::size_t c = 0; c < mesh.hexes.size(); ++c)
        for (const int v : mesh.hexes[c])
            if (v < 0 || v >= nv) bad("hex", c, v);
    for (std::size_t c = 0; c < mesh.polyhedra.size(); ++c) {
        if (mesh.polyhedra[c].faces.empty())
            throw std::invalid_argument("polyhedron " + std::to_string(c) + " has no faces");
        for (const auto& f : mesh.polyhedra[c].faces) {
            if (f.size() < 3)
                throw std::invalid_argument("polyhedron " + std::to_string(c) + " has a face with " +
                                            std::to_string(f.size()) + " vertices");
            for (const int v : f)
                if (v < 0 || v >= nv) bad("polyhedron", c, v);
        }
    }
}

/// Distinct vertices of a polyhedron in order of first appearance.
inline std::vector<int> polyVertices(const Polyhedron& p) {
    std::vector<int> out;
    for (const auto& f : p.faces)
        for (const int v : f)
            if (std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
    return out;
}

/// Adds VTK cells to a HexMesh whose vertices are already set. Hexahedra (12) and voxels
/// (11) become hexes; tetrahedra (10), wedges (13), pyramids (14) and polyhedra (42, face
/// stream `[nFaces, n0, ids..., n1, ...]`) become polyhedra; polygons (5, 7, 9) become a
/// one-face polyhedron each, or are grouped into one polyhedron per group id.
class VtkCellAdder {
public:
    /// Adds to @p mesh.
    explicit VtkCellAdder(HexMesh& mesh) : mesh_(mesh) {}

    /// Adds cell @p cell of VTK @p type with the @p n point ids @p ids (for type 42 the
    /// @p streamLen values of @p stream are its faces); @p group >= 0 joins polygons into
    /// one polyhedron. @return an error text ("cell N: reason"), empty if the cell was added.
    std::string add(long long cell, long long type, const long long* ids, std::size_t n, const long long* stream = nullptr,
                    std::size_t streamLen = 0, long long group = -1) {
        const std::string where = "cell " + std::to_string(cell) + ": ";
        static const std::map<long long, std::size_t> kSizes = {{5, 3}, {7, 0}, {9, 4},  {10, 4}, {11, 8},
                                                                {12, 8}, {13, 6}, {14, 5}, {42, 0}};
        const auto it = kSizes.find(type);
        if (it == kSizes.end()) return where + "unsupported VTK cell type " + std::to_string(type);
        if (it->second && n != it->second)
            return where + "cell type " + std::to_string(type) + " needs " + std::to_string(it->second) +
                   " points, got " + std::to_string(n);
        std::vector<int> v;
        std::string err;
        if (!points(ids, n, v, where + "point index ", err)) return err;
        if (type == 12 || type == 11) {
            std::array<int, 8> h{};
            std::copy(v.begin(), v.end(), h.begin());
            if (type == 11) {  // voxel: x fastest, then y, then z
                std::swap(h[2], h[3]);
                std::swap(h[6], h[7]);
            }
            mesh_.hexes.push_back(h);
            return {};
        }
        Polyhedron p;
        if (type == 42) {
            std::size_t k = 0;
            const long long nf = streamLen ? stream[k++] : 0;
            if (nf < 1 || static_cast<std::size_t>(nf) > streamLen) return where + "invalid polyhedron face count " + std::to_string(nf);
            for (long long f = 0; f < nf; ++f) {
                const long long m = k < streamLen ? stream[k++] : -1;
                if (m < 3 || static_cast<std::size_t>(m) > streamLen - k)
                    return where + "invalid polyhedron face size " + std::to_string(m);
                if (!points(stream + k, static_cast<std::size_t>(m), p.faces.emplace_back(), where + "face point index ", err))
                    return err;
                k += static_cast<std::size_t>(m);
            }
            if (k != streamLen) return where + "polyhedron face stream has " + std::to_string(streamLen - k) + " extra values";
            for (const auto& f : p.faces)
                for (const int x : f)
                    if (n && std::find(v.begin(), v.end(), x) == v.end())
                        return where + "face point " + std::to_string(x) + " is not in the cell's connectivity";
            mesh_.polyhedra.push_back(std::move(p));
            return {};
        }
        if (type == 5 || type == 7 || type == 9) {
            if (v.size() < 3) return where + "polygon with fewer than 3 points";
            if (group < 0) {
                p.faces = {v};
                mesh_.polyhedra.push_back(std::move(p));
            } else {
                const auto g = groups_.emplace(group, mesh_.polyhedra.size()).first;
                if (g->second == mesh_.polyhedra.size()) mesh_.polyhedra.emplace_back();
                mesh_.polyhedra[g->second].faces.push_back(v);
            }
            return {};
        }
        if (type == 10) p.faces = {{v[0], v[2], v[1]}, {v[0], v[1], v[3]}, {v[1], v[2], v[3]}, {v[2], v[0], v[3]}};
        if (type == 13)
            p.faces = {{v[0], v[2], v[1]}, {v[3], v[4], v[5]}, {v[0], v[1], v[4], v[3]}, {v[1], v[2], v[5], v[4]},
                       {v[2], v[0], v[3], v[5]}};
        if (type == 14)
            p.faces = {{v[0], v[3], v[2], v[1]}, {v[0], v[1], v[4]}, {v[1], v[2], v[4]}, {v[2], v[3], v[4]}, {v[3], v[0], v[4]}};
        if (signedVolume6(mesh_.vertices, p.faces) < 0)
            for (auto& f : p.faces) std::reverse(f.begin(), f.end());
        mesh_.polyhedra.push_back(std::move(p));
        return {};
    }

private:
    /// Copies @p n point ids into @p out; false (with @p err) if one is out of range.
    bool points(const long long* ids, std::size_t n, std::vector<int>& out, const std::string& what, std::string& err) const {
        const long long nv = static_cast<long long>(mesh_.vertices.size());
        for (std::size_t i = 0; i < n; ++i) {
            if (ids[i] < 0 || ids[i] >= nv) {
                err = what + std::to_string(ids[i]) + " out of range [0, " + std::to_string(nv) + ")";
                return false;
            }
            out.push_back(static_cast<int>(ids[i]));
        }
        return true;
    }

    HexMesh& mesh_;
    std::map<long long, std::size_t> groups_;
};

} // namespace detail
} // namespace HexEx
