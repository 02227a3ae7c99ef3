/// @file OvmHexMesh.cc
/// Hex meshes into and out of the OpenVolumeMesh model (OvmModel.hh).

#include "OvmModel.hh"

#include "../Mesh/HexMeshCheck.hh"
#include "../Core/Parallel.hh"
#include "OvmHexFaces.hh"
#include "VtkCells.hh"

#include <algorithm>
#include <optional>

namespace HexEx {

namespace {

using detail::kOvmHexFaces;
using detail::kOvmHexOrder;

/// From this many hexes on (and without polyhedra) faces and edges are numbered by
/// ovmHexFaces(): the same numbering as buildOvmFaces() with 1.57M hexes in 392 instead of
/// 669 MiB peak, at about the same CPU time on the cylinder and 1.8x its CPU time on a
/// 112K-hex mesh with one chart per hex (whose hexes around a vertex lie far apart).
constexpr std::size_t kPerVertexNumberingHexes = 500000;

/// True if loop @p f equals @p g up to a cyclic shift.
bool cyclicEqual(const std::vector<int>& f, const std::array<int, 4>& g) {
    if (f.size() != 4) return false;
    for (int s = 0; s < 4; ++s) {
        bool eq = true;
        for (int i = 0; i < 4 && eq; ++i) eq = f[(s + i) % 4] == g[i];
        if (eq) return true;
    }
    return false;
}

/// The VTK-ordered hex bounded by six outward quads (the first one is the bottom), if they form one.
std::optional<std::array<int, 8>> hexFromFaces(const std::vector<std::vector<int>>& faces) {
    if (faces.size() != 6 || std::any_of(faces.begin(), faces.end(), [](const auto& f) { return f.size() != 4; }))
        return std::nullopt;
    const auto& b = faces[0];  // outward bottom loop is 0 3 2 1
    std::array<int, 8> v{{b[0], b[3], b[2], b[1], -1, -1, -1, -1}};
    // The side face with the directed edge a->c is (a, c, x, y): sets the vertices above c and a.
    auto side = [&](int a, int c, int above_c, int above_a) {
        for (std::size_t k = 1; k < 6; ++k)
            for (int i = 0; i < 4; ++i)
                if (faces[k][i] == v[a] && faces[k][(i + 1) % 4] == v[c]) {
                    v[above_c] = faces[k][(i + 2) % 4];
                    v[above_a] = faces[k][(i + 3) % 4];
                    return true;
                }
        return false;
    };
    if (!side(0, 1, 5, 4) || !side(2, 3, 7, 6)) return std::nullopt;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < i; ++j)
            if (v[i] == v[j]) return std::nullopt;
    std::array<bool, 6> used{};
    for (const auto& lf : kHexFaces) {
        const std::array<int, 4> g{{v[lf[0]], v[lf[1]], v[lf[2]], v[lf[3]]}};
        bool found = false;
        for (std::size_t k = 0; k < 6 && !found; ++k)
            if (!used[k] && cyclicEqual(faces[k], g)) used[k] = found = true;
        if (!found) return std::nullopt;
    }
    return v;
}

/// Faces and edges of the cells of @p mesh by buildOvmFaces() on all cell loops.
OvmFaces ovmFacesOfCells(const HexMesh& mesh, int threads) {
    IntLists loops;
    std::size_t entries = 24 * mesh.hexes.size(), nLoops = 6 * mesh.hexes.size();
    for (const auto& p : mesh.polyhedra) {
        nLoops += p.faces.size();
        for (const auto& f : p.faces) entries += f.size();
    }
    loops.offsets.resize(nLoops + 1);
    loops.values.resize(entries);
    std::size_t at = 0, n = 0;  // entries and loops filled
    for (const auto& h : mesh.hexes)
        for (const auto& lf : kOvmHexFaces) {
            for (int k = 0; k < 4; ++k) loops.values[at++] = h[static_cast<std::size_t>(lf[k])];
            loops.offsets[++n] = at;
        }
    for (const auto& p : mesh.polyhedra)
        for (const auto& f : p.faces) {
            for (const int v : f) loops.values[at++] = v;
            loops.offsets[++n] = at;
        }
    return buildOvmFaces(loops, static_cast<int>(mesh.vertices.size()), threads);
}

} // namespace

HexMesh hexMeshFromOvm(const OvmModel& m) {
    m.checkTopology();
    HexMesh mesh;
    mesh.vertices = m.vertices;
    std::vector<std::vector<std::vector<int>>> cells(m.cells.size());
    double volume = 0;
    for (std::size_t c = 0; c < m.cells.size(); ++c) {
        for (const int hf : m.cells[c]) cells[c].push_back(m.halffaceLoop(hf));
        volume += detail::signedVolume6(mesh.vertices, cells[c]);
    }
    for (auto& cell : cells) {
        if (volume < 0)
            for (auto& f : cell) std::reverse(f.begin(), f.end());
        if (auto h = hexFromFaces(cell)) {
            mesh.hexes.push_back(*h);
        } else {
            mesh.polyhedra.emplace_back();
            mesh.polyhedra.back().faces = std::move(cell);
        }
    }
    return mesh;
}

OvmFlatMesh ovmFlatFromHexMesh(const HexMesh& mesh, int threads, HexFaceNeighbours* neighbours) {
    detail::checkCellIndices(mesh);
    OvmFlatMesh m;
    m.vertices = &mesh.vertices;
    m.topology = mesh.polyhedra.empty() ? OvmTopology::Hexahedral : OvmTopology::Polyhedral;
    OvmFaces faces;
    bool numbered = false;
    // A face-neighbour table from the assembly is used if it is the one of these hexes.
    const bool table = mesh.polyhedra.empty() && neighbours && !neighbours->items.empty() &&
                       hexFaceNeighboursFit(mesh, *neighbours, hexMeshDigest(mesh, threads), threads, false);
    if (table || (mesh.polyhedra.empty() && mesh.hexes.size() >= kPerVertexNumberingHexes)) {
        // Many hexes only, or a table: faces and edges per vertex, the numbering of
        // buildOvmFaces() with less memory (buildOvmFaces() remains for what ovmHexFaces()
        // does not cover).
        numbered = ovmHexFaces(mesh, threads, faces, table ? neighbours : nullptr);
    }
    if (neighbours) *neighbours = HexFaceNeighbours{};  // used up (or stale)
    if (!numbered) faces = ovmFacesOfCells(mesh, threads);
    m.edges = std::move(faces.edges);
    m.faces = std::move(faces.faceHalfedges);
    // The hexes' halffaces in the kernel's order, in parallel chunks. Without polyhedra the
    // loops' halffaces are reordered in place and become the cells' lists (no copy).
    const std::size_t nHex = mesh.hexes.size();
    const int chunks = nHex >= 20000 ? std::max(1, threads) : 1;
    if (mesh.polyhedra.empty()) {
        parallelChunks(nHex, chunks, [&](int, std::size_t c0, std::size_t c1) {
            for (std::size_t c = c0; c < c1; ++c) {
                int* h = faces.halffaces.data() + 6 * c;
                const int loop[6] = {h[0], h[1], h[2], h[3], h[4], h[5]};
                for (std::size_t i = 0; i < 6; ++i) h[i] = loop[kOvmHexOrder[i]];
            }
        });
        m.cells.values = std::move(faces.halffaces);
        m.cells.stride = 6;  // six halffaces per cell, no offsets
        return m;
    }
    m.cells.reserve(mesh.hexes.size() + mesh.polyhedra.size(), faces.halffaces.size());
    m.cells.offsets.resize(nHex + 1);
    m.cells.values.resize(6 * nHex);
    parallelChunks(nHex, chunks, [&](int, std::size_t c0, std::size_t c1) {
        for (std::size_t c = c0; c < c1; ++c) {
            m.cells.offsets[c + 1] = 6 * (c + 1);
            for (std::size_t i = 0; i < 6; ++i)
                m.cells.values[6 * c + i] = faces.halffaces[6 * c + static_cast<std::size_t>(kOvmHexOrder[i])];
        }
    });
    std::size_t next = 6 * nHex;  // first loop of the current cell
    for (const auto& p : mesh.polyhedra) {
        m.cells.add(faces.halffaces.begin() + static_cast<std::ptrdiff_t>(next),
                    faces.halffaces.begin() + static_cast<std::ptrdiff_t>(next + p.faces.size()));
        next += p.faces.size();
    }
    return m;
}

OvmModel ovmFromHexMesh(const HexMesh& mesh) {
    const OvmFlatMesh f = ovmFlatFromHexMesh(mesh);
    OvmModel m;
    m.vertices = mesh.vertices;
    m.topology = f.topology;
    m.edges = f.edges;
    for (std::size_t i = 0; i < f.faces.size(); ++i) m.faces.emplace_back(f.faces.begin(i), f.faces.end(i));
    for (std::size_t i = 0; i < f.cells.size(); ++i) m.cells.emplace_back(f.cells.begin(i), f.cells.end(i));
    return m;
}

} // namespace HexEx
