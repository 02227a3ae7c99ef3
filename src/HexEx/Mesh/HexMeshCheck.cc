/// @file HexMeshCheck.cc
/// Implementation of checkHexMesh(): faces and edges are identified by sorting keys.

#include "HexMeshCheck.hh"

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace HexEx {

const int kHexFaces[6][4] = {
    {0, 3, 2, 1},  // bottom
    {4, 5, 6, 7},  // top
    {0, 1, 5, 4},  // front
    {1, 2, 6, 5},  // right
    {2, 3, 7, 6},  // back
    {3, 0, 4, 7},  // left
};

namespace {

/// Key of an undirected edge.
inline std::uint64_t edgeKey(int a, int b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

/// A face occurrence: its loop (vertex ids), stored in a flat pool.
struct FaceRef {
    std::size_t begin;  ///< offset of the loop in the pool
    int size;           ///< number of vertices
};

} // namespace

HexMeshCheckResult checkHexMesh(const HexMesh& mesh) {
    HexMeshCheckResult r;
    r.hexes = static_cast<long>(mesh.hexes.size());
    r.non_hex_cells = static_cast<long>(mesh.polyhedra.size());
    r.cells = r.hexes + r.non_hex_cells;
    r.vertices = static_cast<long>(mesh.vertices.size());
    const long nv = r.vertices;
    auto inRange = [nv](int v) { return v >= 0 && v < nv; };

    // Face occurrences: small faces (3 or 4 vertices) as sorted, -1-padded keys; larger
    // faces in a map. Each entry keeps a representative loop for the boundary edges.
    std::vector<int> pool;
    std::vector<std::pair<std::array<int, 4>, FaceRef>> small;
    std::map<std::vector<int>, std::pair<long, FaceRef>> large;
    small.reserve(mesh.hexes.size() * 6);

    auto addFace = [&](const int* loop, int n) {
        FaceRef ref{pool.size(), n};
        pool.insert(pool.end(), loop, loop + n);
        if (n <= 4) {
            std::array<int, 4> key{{-1, -1, -1, -1}};
            std::copy(loop, loop + n, key.begin());
            std::sort(key.begin(), key.end());
            small.push_back({key, ref});
        } else {
            std::vector<int> key(loop, loop + n);
            std::sort(key.begin(), key.end());
            auto it = large.find(key);
            if (it == large.end())
                large.emplace(std::move(key), std::make_pair(1L, ref));
            else
                ++it->second.first;
        }
    };

    for (const auto& h : mesh.hexes) {
        bool ok = true;
        for (int i = 0; i < 8 && ok; ++i) {
            ok = inRange(h[i]);
            for (int j = 0; j < i && ok; ++j) ok = h[i] != h[j];
        }
        if (!ok) {
            ++r.invalid_cells;
            continue;
        }
        for (const auto& f : kHexFaces) {
            const int loop[4] = {h[f[0]], h[f[1]], h[f[2]], h[f[3]]};
            addFace(loop, 4);
        }
    }
    for (const auto& p : mesh.polyhedra) {
        bool ok = !p.faces.empty();
        for (const auto& f : p.faces) {
            if (f.size() < 3) ok = false;
            for (std::size_t i = 0; i < f.size() && ok; ++i) {
                ok = inRange(f[i]);
                for (std::size_t j = 0; j < i && ok; ++j) ok = f[i] != f[j];
            }
            if (!ok) break;
        }
        if (!ok) {
            ++r.invalid_cells;
            continue;
        }
        for (const auto& f : p.faces) addFace(f.data(), static_cast<int>(f.size()));
    }

    // Count faces by incidence.
    std::vector<FaceRef> boundary;
    auto classify = [&](long count, const FaceRef& ref) {
        ++r.faces;
        if (ref.size == 4) ++r.quads;
        if (count == 1) {
            ++r.boundary_faces;
            if (ref.size == 4) ++r.boundary_quads;
            boundary.push_back(ref);
        } else if (count > 2) {
            ++r.quads_shared_by_more_than_two;
        }
    };
    std::sort(small.begin(), small.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t i = 0; i < small.size();) {
        std::size_t j = i + 1;
        while (j < small.size() && small[j].first == small[i].first) ++j;
        classify(static_cast<long>(j - i), small[i].second);
        i = j;
    }
    for (const auto& kv : large) classify(kv.second.first, kv.second.second);

    // Edges of all faces, and boundary edges with their multiplicity.
    std::vector<std::uint64_t> edges;
    edges.reserve(pool.size());
    for (const auto& s : small) {
        const FaceRef& f = s.second;
        for (int i = 0; i < f.size; ++i)
            edges.push_back(edgeKey(pool[f.begin + i], pool[f.begin + (i + 1) % f.size]));
    }
    for (const auto& kv : large) {
        const FaceRef& f = kv.second.second;
        for (int i = 0; i < f.size; ++i)
            edges.push_back(edgeKey(pool[f.begin + i], pool[f.begin + (i + 1) % f.size]));
    }
    std::sort(edges.begin(), edges.end());
    r.edges = static_cast<long>(std::unique(edges.begin(), edges.end()) - edges.begin());

    std::vector<std::uint64_t> bedges;
    for (const FaceRef& f : boundary)
        for (int i = 0; i < f.size; ++i)
            bedges.push_back(edgeKey(pool[f.begin + i], pool[f.begin + (i + 1) % f.size]));
    std::sort(bedges.begin(), bedges.end());
    for (std::size_t i = 0; i < bedges.size();) {
        std::size_t j = i + 1;
        while (j < bedges.size() && bedges[j] == bedges[i]) ++j;
        if (j - i != 2) ++r.nonmanifold_boundary_edges;
        i = j;
    }

    // Fans around boundary vertices: the boundary corners at v link its two neighbours in
    // the face; the links form one connected graph iff the faces around v form one fan.
    struct Corner {
        int v, a, b;
    };
    std::vector<Corner> corners;
    for (const FaceRef& f : boundary)
        for (int i = 0; i < f.size; ++i)
            corners.push_back({pool[f.begin + i], pool[f.begin + (i + f.size - 1) % f.size],
                               pool[f.begin + (i + 1) % f.size]});
    std::sort(corners.begin(), corners.end(), [](const Corner& x, const Corner& y) { return x.v < y.v; });
    std::vector<int> ids, parent;
    for (std::size_t i = 0; i < corners.size();) {
        std::size_t j = i;
        ids.clear();
        while (j < corners.size() && corners[j].v == corners[i].v) {
            ids.push_back(corners[j].a);
            ids.push_back(corners[j].b);
            ++j;
        }
        std::sort(ids.begin(), ids.end());
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
        parent.resize(ids.size());
        for (std::size_t k = 0; k < parent.size(); ++k) parent[k] = static_cast<int>(k);
        auto find = [&](int x) {
            while (parent[x] != x) x = parent[x] = parent[parent[x]];
            return x;
        };
        auto local = [&](int v) {
            return static_cast<int>(std::lower_bound(ids.begin(), ids.end(), v) - ids.begin());
        };
        long components = static_cast<long>(ids.size());
        for (std::size_t k = i; k < j; ++k) {
            const int x = find(local(corners[k].a)), y = find(local(corners[k].b));
            if (x != y) {
                parent[x] = y;
                --components;
            }
        }
        if (components > 1) ++r.nonmanifold_boundary_vertices;
        i = j;
    }

    r.euler_characteristic = r.vertices - r.edges + r.faces - (r.cells - r.invalid_cells);
    r.quality = computeQuality(mesh);
    r.valid_all_hex = r.cells > 0 && r.non_hex_cells == 0 && r.invalid_cells == 0 &&
                      r.quads_shared_by_more_than_two == 0 && r.nonmanifold_boundary_edges == 0 &&
                      r.nonmanifold_boundary_vertices == 0;
    return r;
}

} // namespace HexEx
