/// @file VertexPreimageChoice.cc
/// Choice among several preimages of a vertex's grid point (see VertexPreimageChoice.hh).

#include "VertexPreimageChoice.hh"

#include <algorithm>
#include <cmath>

namespace HexEx {

double minScaledJacobian(const HexMesh& mesh, const std::array<int, 8>& h) {
    // The three neighbours of each VTK corner, in right-handed order.
    static const int nb[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7}, {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
    double best = 1.0;
    for (int i = 0; i < 8; ++i) {
        const Vec3d p = mesh.vertices[static_cast<std::size_t>(h[static_cast<std::size_t>(i)])];
        const Vec3d a = mesh.vertices[static_cast<std::size_t>(h[static_cast<std::size_t>(nb[i][0])])] - p;
        const Vec3d b = mesh.vertices[static_cast<std::size_t>(h[static_cast<std::size_t>(nb[i][1])])] - p;
        const Vec3d c = mesh.vertices[static_cast<std::size_t>(h[static_cast<std::size_t>(nb[i][2])])] - p;
        const double len = a.norm() * b.norm() * c.norm();
        if (!(len > 0)) return -2.0;
        best = std::min(best, ((a % b) | c) / len);
    }
    return best;
}

long chooseVertexPreimages(HexMesh& mesh, const VertexCandidates& candidates) {
    const std::size_t nc = candidates.vertex.size();
    if (nc == 0) return 0;
    // Incident hexes of the listed vertices only.
    std::vector<int> slot(mesh.vertices.size(), -1);
    for (std::size_t k = 0; k < nc; ++k) slot[static_cast<std::size_t>(candidates.vertex[k])] = static_cast<int>(k);
    std::vector<int> off(nc + 1, 0);
    for (const auto& h : mesh.hexes)
        for (int v : h)
            if (slot[static_cast<std::size_t>(v)] >= 0) ++off[static_cast<std::size_t>(slot[static_cast<std::size_t>(v)]) + 1];
    for (std::size_t k = 0; k < nc; ++k) off[k + 1] += off[k];
    std::vector<int> inc(static_cast<std::size_t>(off.back()));
    {
        std::vector<int> fill(off.begin(), off.end() - 1);
        for (std::size_t c = 0; c < mesh.hexes.size(); ++c)
            for (int v : mesh.hexes[c]) {
                const int s = slot[static_cast<std::size_t>(v)];
                if (s >= 0) inc[static_cast<std::size_t>(fill[static_cast<std::size_t>(s)]++)] = static_cast<int>(c);
            }
    }
    for (int sweep = 0; sweep < 2; ++sweep)
        for (std::size_t k = 0; k < nc; ++k) {
            const auto v = static_cast<std::size_t>(candidates.vertex[k]);
            if (off[k] == off[k + 1]) continue;  // no incident hex: keep the first candidate
            int best = -1;
            double bestQ = 0;
            for (int c = candidates.offset[k]; c < candidates.offset[k + 1]; ++c) {
                mesh.vertices[v] = candidates.position[static_cast<std::size_t>(c)];
                double q = 1.0;
                for (int j = off[k]; j < off[k + 1]; ++j)
                    q = std::min(q, minScaledJacobian(mesh, mesh.hexes[static_cast<std::size_t>(inc[static_cast<std::size_t>(j)])]));
                if (best < 0 || q > bestQ) {
                    best = c;
                    bestQ = q;
                }
                // The others only if no preferred candidate keeps the hexes uninverted.
                if (c + 1 == candidates.offset[k] + candidates.preferred[k] && bestQ > 0) break;
            }
            mesh.vertices[v] = candidates.position[static_cast<std::size_t>(best)];
        }
    long changed = 0;
    for (std::size_t k = 0; k < nc; ++k)
        if (mesh.vertices[static_cast<std::size_t>(candidates.vertex[k])] !=
            candidates.position[static_cast<std::size_t>(candidates.offset[k])])
            ++changed;
    return changed;
}

} // namespace HexEx
