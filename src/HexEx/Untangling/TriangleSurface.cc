/// @file TriangleSurface.cc
/// Boundary triangles of tet meshes and hex meshes.

#include "TriangleSurface.hh"

#include "../Mesh/HexArcs.hh"
#include "../Mesh/TetMesh.hh"

#include <algorithm>
#include <cstdint>

namespace HexEx {

namespace {

/// A face key (sorted vertex indices) with the index of the face it came from.
template <std::size_t N>
struct FaceKey {
    std::array<int, N> key;
    std::size_t face;
};

/// Indices of the faces whose sorted key occurs exactly once.
template <std::size_t N>
std::vector<std::size_t> uniqueFaces(std::vector<FaceKey<N>>& keys) {
    // Element-wise comparisons (std::array's operators call memcmp, which dominated this
    // sort on 100k-hex meshes).
    std::sort(keys.begin(), keys.end(), [](const FaceKey<N>& a, const FaceKey<N>& b) {
        for (std::size_t i = 0; i < N; ++i)
            if (a.key[i] != b.key[i]) return a.key[i] < b.key[i];
        return a.face < b.face;
    });
    auto same = [](const FaceKey<N>& a, const FaceKey<N>& b) {
        for (std::size_t i = 0; i < N; ++i)
            if (a.key[i] != b.key[i]) return false;
        return true;
    };
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < keys.size();) {
        std::size_t j = i + 1;
        while (j < keys.size() && same(keys[j], keys[i])) ++j;
        if (j == i + 1) out.push_back(keys[i].face);
        i = j;
    }
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

TriangleSurface tetMeshBoundary(const TetMesh& mesh) {
    TriangleSurface s;
    s.points.reserve(mesh.n_vertices());
    for (std::size_t v = 0; v < mesh.n_vertices(); ++v) s.points.push_back(mesh.position(VertexHandle(static_cast<int>(v))));
    auto addHalfface = [&](HalfFaceHandle hf) {
        const auto t = mesh.halfface_vertices(hf);
        s.triangles.push_back({{t[0].idx(), t[1].idx(), t[2].idx()}});
    };
    if (mesh.has_adjacency()) {
        for (std::size_t h = 0; h < mesh.n_halffaces(); ++h) {
            const HalfFaceHandle hf(static_cast<int>(h));
            if (mesh.is_boundary(hf)) addHalfface(hf);
        }
        return s;
    }
    std::vector<FaceKey<3>> keys;
    keys.reserve(mesh.n_halffaces());
    for (std::size_t h = 0; h < mesh.n_halffaces(); ++h) {
        const auto t = mesh.halfface_vertices(HalfFaceHandle(static_cast<int>(h)));
        std::array<int, 3> k = {{t[0].idx(), t[1].idx(), t[2].idx()}};
        std::sort(k.begin(), k.end());
        keys.push_back({k, h});
    }
    for (const std::size_t h : uniqueFaces(keys)) addHalfface(HalfFaceHandle(static_cast<int>(h)));
    return s;
}

TriangleSurface hexMeshBoundary(const HexMesh& mesh) {
    TriangleSurface s;
    s.points = mesh.vertices;
    std::vector<FaceKey<4>> keys;
    keys.reserve(6 * mesh.hexes.size());
    for (std::size_t c = 0; c < mesh.hexes.size(); ++c)
        for (std::size_t f = 0; f < 6; ++f) {
            std::array<int, 4> k;
            for (int i = 0; i < 4; ++i) k[static_cast<std::size_t>(i)] = mesh.hexes[c][static_cast<std::size_t>(HexArcs::kHexFaces[f][i])];
            std::sort(k.begin(), k.end());
            keys.push_back({k, 6 * c + f});
        }
    for (const std::size_t id : uniqueFaces(keys)) {
        const auto& h = mesh.hexes[id / 6];
        const int* f = HexArcs::kHexFaces[id % 6];
        const int q0 = h[static_cast<std::size_t>(f[0])], q1 = h[static_cast<std::size_t>(f[1])];
        const int q2 = h[static_cast<std::size_t>(f[2])], q3 = h[static_cast<std::size_t>(f[3])];
        s.triangles.push_back({{q0, q1, q2}});
        s.triangles.push_back({{q0, q2, q3}});
    }
    return s;
}

} // namespace HexEx
