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

OvmModel ovmFromHexMesh(const HexMesh& mesh) {
    detail::checkCellIndices(mesh);
    OvmModel m;
    m.vertices = mesh.vertices;
    m.topology = mesh.polyhedra.empty() ? OvmTopology::Hexahedral : OvmTopology::Polyhedral;
    OvmBuilder faces(m);
    for (const auto& h : mesh.hexes) {
        int hf[6];
        for (int i = 0; i < 6; ++i) {
            const auto& lf = kOvmHexFaces[i];
            hf[i] = faces.halfface({h[lf[0]], h[lf[1]], h[lf[2]], h[lf[3]]});
        }
        auto& cell = m.cells.emplace_back();
        for (const int i : kOvmHexOrder) cell.push_back(hf[i]);
    }
    for (const auto& p : mesh.polyhedra) {
        auto& cell = m.cells.emplace_back();
        for (const auto& f : p.faces) cell.push_back(faces.halfface(f));
    }
    faces.finish();
    return m;
}

} // namespace HexEx
