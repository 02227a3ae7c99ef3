/// @file AssembledMeshCheck.cc
/// Implementation of checkAssembledHexes(): counting sorts by vertex, small sorts per bucket;
/// the hex and quad passes in parallel chunks.

#include "AssembledMeshCheck.hh"

#include "../Core/Parallel.hh"
#include "../Mesh/HexMeshCheck.hh"

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace HexEx {

namespace {

/// Items 0..n-1 ordered by the vertex @p vertexOf gives them (a counting sort: linear in
/// @p nv + n). Bucket v is order[start[v] .. start[v+1]).
template <class VertexOf>
void bucketByVertex(long nv, long n, VertexOf vertexOf, std::vector<long>& start, std::vector<long>& order) {
    start.assign(static_cast<std::size_t>(nv) + 1, 0);
    for (long i = 0; i < n; ++i) ++start[static_cast<std::size_t>(vertexOf(i)) + 1];
    for (long v = 0; v < nv; ++v) start[static_cast<std::size_t>(v) + 1] += start[static_cast<std::size_t>(v)];
    std::vector<long> next(start.begin(), start.end() - 1);
    order.resize(static_cast<std::size_t>(n));
    for (long i = 0; i < n; ++i) order[static_cast<std::size_t>(next[static_cast<std::size_t>(vertexOf(i))]++)] = i;
}

/// The same as bucketByVertex() on @p chunks threads (atomic slots: the order within a bucket
/// varies, so callers must not depend on it).
template <class VertexOf>
void bucketByVertexParallel(long nv, long n, int chunks, VertexOf vertexOf, std::vector<long>& start, std::vector<long>& order) {
    start.assign(static_cast<std::size_t>(nv) + 1, 0);
    long* count = start.data() + 1;
    parallelChunks(static_cast<std::size_t>(n), chunks, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i) __atomic_fetch_add(&count[vertexOf(static_cast<long>(i))], 1L, __ATOMIC_RELAXED);
    });
    for (long v = 0; v < nv; ++v) start[static_cast<std::size_t>(v) + 1] += start[static_cast<std::size_t>(v)];
    std::vector<long> next(start.begin(), start.end() - 1);
    order.resize(static_cast<std::size_t>(n));
    parallelChunks(static_cast<std::size_t>(n), chunks, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i) {
            const long slot = __atomic_fetch_add(&next[static_cast<std::size_t>(vertexOf(static_cast<long>(i)))], 1L, __ATOMIC_RELAXED);
            order[static_cast<std::size_t>(slot)] = static_cast<long>(i);
        }
    });
}

/// Fewer hexes than this are checked on one thread.
constexpr long kParallelHexes = 20000;

} // namespace

bool AssembledMeshCheck::agrees(long dart_quads, long dart_boundary_quads) const {
    return repeated_corner_hexes == 0 && quads_shared_by_more_than_two == 0 && nonmanifold_boundary_edges == 0 &&
           nonmanifold_boundary_vertices == 0 && quads == dart_quads && boundary_quads == dart_boundary_quads;
}

std::string AssembledMeshCheck::warning(long dart_quads, long dart_boundary_quads) const {
    if (agrees(dart_quads, dart_boundary_quads)) return {};
    std::string w = "the vertex identification broke the mesh the valid map describes:";
    auto item = [&w](long n, const char* what) {
        if (n != 0) w += " " + std::to_string(n) + " " + what + ";";
    };
    item(repeated_corner_hexes, "hexes with a repeated vertex");
    item(quads_shared_by_more_than_two, "quads shared by more than two hexes");
    if (quads != dart_quads || boundary_quads != dart_boundary_quads)
        w += " " + std::to_string(quads) + " distinct quads (" + std::to_string(boundary_quads) + " on the boundary) where the map has " +
             std::to_string(dart_quads) + " (" + std::to_string(dart_boundary_quads) + ");";
    item(nonmanifold_boundary_edges, "non-manifold boundary edges");
    item(nonmanifold_boundary_vertices, "pinched boundary vertices");
    w.back() = ' ';
    w += "(distinct vertices of the map were merged)";
    return w;
}

AssembledMeshCheck checkAssembledHexes(const HexMesh& mesh, int threads) {
    AssembledMeshCheck r;
    const long nv = static_cast<long>(mesh.vertices.size());
    const long nh = static_cast<long>(mesh.hexes.size());
    const auto& H = mesh.hexes;
    if (nv == 0) {
        r.repeated_corner_hexes = nh;
        return r;
    }
    const int chunks = nh >= kParallelHexes ? std::max(1, threads) : 1;

    std::vector<char> good(static_cast<std::size_t>(nh), 0);
    std::vector<long> repeated(static_cast<std::size_t>(chunks), 0);
    parallelChunks(static_cast<std::size_t>(nh), chunks, [&](int k, std::size_t h0, std::size_t h1) {
        for (std::size_t h = h0; h < h1; ++h) {
            const auto& c = H[h];
            bool ok = true;
            for (int i = 0; i < 8 && ok; ++i) {
                ok = c[i] >= 0 && c[i] < nv;
                for (int j = 0; j < i && ok; ++j) ok = c[i] != c[j];
            }
            if (ok)
                good[h] = 1;
            else
                ++repeated[static_cast<std::size_t>(k)];
        }
    });
    for (const long n : repeated) r.repeated_corner_hexes += n;

    // Quads (face f of hex h is item 6h+f; faces of bad hexes go to bucket 0 and are skipped).
    auto quadKey = [&](long q) {
        const auto& c = H[static_cast<std::size_t>(q / 6)];
        const int* f = kHexFaces[q % 6];
        std::array<int, 4> k{{c[f[0]], c[f[1]], c[f[2]], c[f[3]]}};
        std::sort(k.begin(), k.end());
        return k;
    };
    std::vector<int> smallest(static_cast<std::size_t>(6 * nh), 0);  // bucket of each quad item
    parallelChunks(static_cast<std::size_t>(nh), chunks, [&](int, std::size_t h0, std::size_t h1) {
        for (std::size_t h = h0; h < h1; ++h) {
            if (!good[h]) continue;
            const auto& c = H[h];
            for (int f = 0; f < 6; ++f) {
                const int* l = kHexFaces[f];
                smallest[6 * h + static_cast<std::size_t>(f)] = std::min(std::min(c[l[0]], c[l[1]]), std::min(c[l[2]], c[l[3]]));
            }
        }
    });
    std::vector<long> start, order;
    bucketByVertexParallel(nv, 6 * nh, chunks, [&](long q) { return smallest[static_cast<std::size_t>(q)]; }, start, order);
    std::vector<int>().swap(smallest);
    // Per chunk of vertices: counts and the boundary quads in vertex order (a bucket is sorted
    // by key and item, so the order within it does not matter); concatenated in chunk order.
    struct ChunkQuads {
        long quads = 0, boundary_quads = 0, shared_by_more = 0;
        std::vector<long> boundary;
    };
    std::vector<ChunkQuads> parts(static_cast<std::size_t>(chunks));
    parallelChunks(static_cast<std::size_t>(nv), chunks, [&](int k, std::size_t v0, std::size_t v1) {
        ChunkQuads& part = parts[static_cast<std::size_t>(k)];
        std::vector<std::pair<std::array<int, 4>, long>> bucket;
        for (std::size_t v = v0; v < v1; ++v) {
            bucket.clear();
            for (long i = start[v]; i < start[v + 1]; ++i) {
                const long q = order[static_cast<std::size_t>(i)];
                if (good[static_cast<std::size_t>(q / 6)]) bucket.push_back({quadKey(q), q});
            }
            std::sort(bucket.begin(), bucket.end());
            for (std::size_t i = 0; i < bucket.size();) {
                std::size_t j = i + 1;
                while (j < bucket.size() && bucket[j].first == bucket[i].first) ++j;
                ++part.quads;
                if (j - i == 1) {
                    ++part.boundary_quads;
                    part.boundary.push_back(bucket[i].second);
                } else if (j - i > 2) {
                    ++part.shared_by_more;
                }
                i = j;
            }
        }
    });
    std::vector<long> boundary;  // quad items in exactly one hex
    for (auto& part : parts) {
        r.quads += part.quads;
        r.boundary_quads += part.boundary_quads;
        r.quads_shared_by_more_than_two += part.shared_by_more;
        boundary.insert(boundary.end(), part.boundary.begin(), part.boundary.end());
        std::vector<long>().swap(part.boundary);
    }

    // Boundary edges (item 4b+i: edge i of boundary quad b) by their smaller vertex, and
    // boundary corners (item 4b+i: corner i of b) by their vertex.
    auto loopVertex = [&](long b, int i) {
        const long q = boundary[static_cast<std::size_t>(b)];
        return H[static_cast<std::size_t>(q / 6)][kHexFaces[q % 6][i & 3]];
    };
    const long ne = 4 * static_cast<long>(boundary.size());
    bucketByVertex(
        nv, ne, [&](long e) { return std::min(loopVertex(e / 4, static_cast<int>(e % 4)), loopVertex(e / 4, static_cast<int>(e % 4) + 1)); },
        start, order);
    std::vector<int> others;
    for (long v = 0; v < nv; ++v) {
        others.clear();
        for (long i = start[static_cast<std::size_t>(v)]; i < start[static_cast<std::size_t>(v) + 1]; ++i) {
            const long e = order[static_cast<std::size_t>(i)];
            others.push_back(std::max(loopVertex(e / 4, static_cast<int>(e % 4)), loopVertex(e / 4, static_cast<int>(e % 4) + 1)));
        }
        std::sort(others.begin(), others.end());
        for (std::size_t i = 0; i < others.size();) {
            std::size_t j = i + 1;
            while (j < others.size() && others[j] == others[i]) ++j;
            if (j - i != 2) ++r.nonmanifold_boundary_edges;
            i = j;
        }
    }

    // Fans: the corners at v link its two neighbours in the quad; one fan iff connected.
    bucketByVertex(nv, ne, [&](long c) { return loopVertex(c / 4, static_cast<int>(c % 4)); }, start, order);
    std::vector<int> parent;
    for (long v = 0; v < nv; ++v) {
        const long s = start[static_cast<std::size_t>(v)], t = start[static_cast<std::size_t>(v) + 1];
        if (t - s == 0) continue;
        others.clear();
        for (long i = s; i < t; ++i) {
            const long c = order[static_cast<std::size_t>(i)];
            others.push_back(loopVertex(c / 4, static_cast<int>(c % 4) + 3));
            others.push_back(loopVertex(c / 4, static_cast<int>(c % 4) + 1));
        }
        std::sort(others.begin(), others.end());
        others.erase(std::unique(others.begin(), others.end()), others.end());
        parent.resize(others.size());
        for (std::size_t k = 0; k < parent.size(); ++k) parent[k] = static_cast<int>(k);
        auto find = [&](int x) {
            while (parent[static_cast<std::size_t>(x)] != x) x = parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
            return x;
        };
        auto local = [&](int u) { return static_cast<int>(std::lower_bound(others.begin(), others.end(), u) - others.begin()); };
        long components = static_cast<long>(others.size());
        for (long i = s; i < t; ++i) {
            const long c = order[static_cast<std::size_t>(i)];
            const int x = find(local(loopVertex(c / 4, static_cast<int>(c % 4) + 3)));
            const int y = find(local(loopVertex(c / 4, static_cast<int>(c % 4) + 1)));
            if (x != y) {
                parent[static_cast<std::size_t>(x)] = y;
                --components;
            }
        }
        if (components > 1) ++r.nonmanifold_boundary_vertices;
    }
    return r;
}

} // namespace HexEx
