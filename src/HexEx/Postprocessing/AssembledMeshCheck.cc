/// @file AssembledMeshCheck.cc
/// Implementation of checkAssembledHexes(): counting sorts by vertex, small sorts per bucket.

#include "AssembledMeshCheck.hh"

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

AssembledMeshCheck checkAssembledHexes(const HexMesh& mesh) {
    AssembledMeshCheck r;
    const long nv = static_cast<long>(mesh.vertices.size());
    const long nh = static_cast<long>(mesh.hexes.size());
    const auto& H = mesh.hexes;
    if (nv == 0) {
        r.repeated_corner_hexes = nh;
        return r;
    }

    std::vector<char> good(static_cast<std::size_t>(nh), 0);
    for (long h = 0; h < nh; ++h) {
        const auto& c = H[static_cast<std::size_t>(h)];
        bool ok = true;
        for (int i = 0; i < 8 && ok; ++i) {
            ok = c[i] >= 0 && c[i] < nv;
            for (int j = 0; j < i && ok; ++j) ok = c[i] != c[j];
        }
        if (ok)
            good[static_cast<std::size_t>(h)] = 1;
        else
            ++r.repeated_corner_hexes;
    }

    // Quads (face f of hex h is item 6h+f; faces of bad hexes go to bucket 0 and are skipped).
    auto quadKey = [&](long q) {
        const auto& c = H[static_cast<std::size_t>(q / 6)];
        const int* f = kHexFaces[q % 6];
        std::array<int, 4> k{{c[f[0]], c[f[1]], c[f[2]], c[f[3]]}};
        std::sort(k.begin(), k.end());
        return k;
    };
    std::vector<int> smallest(static_cast<std::size_t>(6 * nh), 0);  // bucket of each quad item
    for (long h = 0; h < nh; ++h) {
        if (!good[static_cast<std::size_t>(h)]) continue;
        const auto& c = H[static_cast<std::size_t>(h)];
        for (int f = 0; f < 6; ++f) {
            const int* l = kHexFaces[f];
            smallest[static_cast<std::size_t>(6 * h + f)] = std::min(std::min(c[l[0]], c[l[1]]), std::min(c[l[2]], c[l[3]]));
        }
    }
    std::vector<long> start, order;
    bucketByVertex(nv, 6 * nh, [&](long q) { return smallest[static_cast<std::size_t>(q)]; }, start, order);
    std::vector<int>().swap(smallest);
    std::vector<std::pair<std::array<int, 4>, long>> bucket;
    std::vector<long> boundary;  // quad items in exactly one hex
    for (long v = 0; v < nv; ++v) {
        bucket.clear();
        for (long i = start[static_cast<std::size_t>(v)]; i < start[static_cast<std::size_t>(v) + 1]; ++i) {
            const long q = order[static_cast<std::size_t>(i)];
            if (good[static_cast<std::size_t>(q / 6)]) bucket.push_back({quadKey(q), q});
        }
        std::sort(bucket.begin(), bucket.end());
        for (std::size_t i = 0; i < bucket.size();) {
            std::size_t j = i + 1;
            while (j < bucket.size() && bucket[j].first == bucket[i].first) ++j;
            ++r.quads;
            if (j - i == 1) {
                ++r.boundary_quads;
                boundary.push_back(bucket[i].second);
            } else if (j - i > 2) {
                ++r.quads_shared_by_more_than_two;
            }
            i = j;
        }
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
