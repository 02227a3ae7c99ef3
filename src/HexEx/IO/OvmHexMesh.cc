/// @file OvmHexMesh.cc
/// Hex meshes into and out of the OpenVolumeMesh model (OvmModel.hh).

#include "OvmModel.hh"

#include "../Mesh/HexMeshCheck.hh"
#include "VtkCells.hh"

#include <algorithm>
#include <optional>

namespace HexEx {

namespace {

/// Faces of a VTK-ordered hex, outward, in the order the hexahedral kernel of
/// OpenVolumeMesh creates them (bottom, top, then the sides around the bottom).
constexpr int kOvmHexFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                    {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
/// The kernel's halfface order (pairs of opposite faces) as indices into kOvmHexFaces.
constexpr int kOvmHexOrder[6] = {0, 1, 5, 3, 4, 2};

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

OvmFlatMesh ovmFlatFromHexMesh(const HexMesh& mesh, int threads) {
    detail::checkCellIndices(mesh);
    OvmFlatMesh m;
    m.vertices = &mesh.vertices;
    m.topology = mesh.polyhedra.empty() ? OvmTopology::Hexahedral : OvmTopology::Polyhedral;
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
    OvmFaces faces = buildOvmFaces(loops, static_cast<int>(mesh.vertices.size()), threads);
    loops = IntLists();
    m.edges = std::move(faces.edges);
    m.faces = std::move(faces.faceHalfedges);
    m.cells.reserve(mesh.hexes.size() + mesh.polyhedra.size(), faces.halffaces.size());
    std::size_t next = 0;  // first loop of the current cell
    for (std::size_t c = 0; c < mesh.hexes.size(); ++c, next += 6) {
        int hf[6];
        for (int i = 0; i < 6; ++i) hf[i] = faces.halffaces[next + static_cast<std::size_t>(kOvmHexOrder[i])];
        m.cells.add(hf, hf + 6);
    }
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
