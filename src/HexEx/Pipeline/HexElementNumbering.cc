#include "HexElementNumbering.hh"

#include "../Core/Parallel.hh"

#include <algorithm>
#include <array>
#include <cstdint>

namespace HexEx {

namespace {

/// Sorted vertex set of an edge or face, packed for comparison (faces use both words).
struct Key {
    std::uint64_t k0, k1;
    bool operator==(const Key& o) const { return k0 == o.k0 && k1 == o.k1; }
};

std::uint64_t pack(int a, int b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

/// Keys of the @p Per elements of every hex (occurrence o = hex * Per + local index), and
/// for every occurrence the first occurrence with the same key. The first one is found by
/// scanning, in hex order, the hexes at the element's smallest vertex: the first hex there
/// that has the key holds it first.
template <int Per, class KeyOf>
std::vector<int> firstOccurrences(const HexMesh& hm, const std::vector<int>& vhexBegin, const std::vector<int>& vhex,
                                  int threads, KeyOf&& keyOf) {
    const std::size_t nh = hm.hexes.size();
    std::vector<Key> keys(Per * nh);
    std::vector<int> minVertex(Per * nh);
    parallelChunks(nh, threads, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t h = b; h < e; ++h)
            for (int k = 0; k < Per; ++k) keyOf(hm.hexes[h], k, keys[Per * h + static_cast<std::size_t>(k)], minVertex[Per * h + static_cast<std::size_t>(k)]);
    });
    std::vector<int> first(Per * nh);
    parallelChunks(nh, threads, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t o = Per * b; o < Per * e; ++o) {
            const Key& key = keys[o];
            const std::size_t v = static_cast<std::size_t>(minVertex[o]);
            int found = static_cast<int>(o);
            for (int i = vhexBegin[v]; i < vhexBegin[v + 1] && found == static_cast<int>(o); ++i) {
                const std::size_t h = static_cast<std::size_t>(vhex[static_cast<std::size_t>(i)]);
                if (Per * h > o) break;  // only earlier occurrences can come first
                for (int k = 0; k < Per; ++k)
                    if (keys[Per * h + static_cast<std::size_t>(k)] == key) {
                        found = static_cast<int>(Per * h) + k;
                        break;
                    }
            }
            first[o] = found;
        }
    });
    return first;
}

/// Ids in order of first occurrence: owners (their own first occurrence) get the next id,
/// the others their owner's; in parallel by a count of owners per chunk. Returns the
/// owners; @p id receives the id of every occurrence.
HexElementOwners numberOccurrences(const std::vector<int>& first, int per, int threads, std::vector<int>& id) {
    const std::size_t n = first.size();
    id.resize(n);
    std::vector<std::size_t> count(static_cast<std::size_t>(threads) + 1, 0);
    parallelChunks(n, threads, [&](int part, std::size_t b, std::size_t e) {
        std::size_t c = 0;
        for (std::size_t o = b; o < e; ++o) c += first[o] == static_cast<int>(o);
        count[static_cast<std::size_t>(part) + 1] = c;
    });
    for (std::size_t k = 1; k < count.size(); ++k) count[k] += count[k - 1];
    HexElementOwners owners(count.back());
    parallelChunks(n, threads, [&](int part, std::size_t b, std::size_t e) {
        std::size_t next = count[static_cast<std::size_t>(part)];
        for (std::size_t o = b; o < e; ++o)
            if (first[o] == static_cast<int>(o)) {
                id[o] = static_cast<int>(next);
                owners[next++] = {static_cast<int>(o) / per, static_cast<int>(o) % per};
            }
    });
    // Owners come first, so every other occurrence's owner has its id now.
    parallelChunks(n, threads, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t o = b; o < e; ++o)
            if (first[o] != static_cast<int>(o)) id[o] = id[static_cast<std::size_t>(first[o])];
    });
    return owners;
}

} // namespace

void numberHexEdgesAndFaces(const HexMesh& hm, int threads, HexArcs& out, HexElementOwners& edge_owner,
                            HexElementOwners& face_owner) {
    const auto& hexes = hm.hexes;
    const std::size_t nh = hexes.size();
    // Hexes at each vertex, in hex order (a counting sort).
    int maxVertex = -1;
    for (const auto& h : hexes)
        for (int v : h) maxVertex = std::max(maxVertex, v);
    std::vector<int> vhexBegin(static_cast<std::size_t>(maxVertex) + 2, 0);
    for (const auto& h : hexes)
        for (int v : h) ++vhexBegin[static_cast<std::size_t>(v) + 1];
    for (std::size_t v = 1; v < vhexBegin.size(); ++v) vhexBegin[v] += vhexBegin[v - 1];
    std::vector<int> vhex(static_cast<std::size_t>(vhexBegin.back()));
    {
        std::vector<int> fill(vhexBegin.begin(), vhexBegin.end() - 1);
        for (std::size_t h = 0; h < nh; ++h)
            for (int v : hexes[h]) vhex[static_cast<std::size_t>(fill[static_cast<std::size_t>(v)]++)] = static_cast<int>(h);
    }

    std::vector<int> id;
    const std::vector<int> firstEdge = firstOccurrences<12>(hm, vhexBegin, vhex, threads, [](const std::array<int, 8>& h, int k, Key& key, int& minV) {
        const int a = h[static_cast<std::size_t>(HexArcs::kHexEdges[k][0])], b = h[static_cast<std::size_t>(HexArcs::kHexEdges[k][1])];
        key = {pack(std::min(a, b), std::max(a, b)), 0};
        minV = std::min(a, b);
    });
    edge_owner = numberOccurrences(firstEdge, 12, threads, id);
    out.hex_edges.resize(nh);
    out.edges.resize(edge_owner.size());
    parallelChunks(nh, threads, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t h = b; h < e; ++h)
            for (std::size_t k = 0; k < 12; ++k) {
                const int x = id[12 * h + k];
                out.hex_edges[h][k] = x;
                if (firstEdge[12 * h + k] == static_cast<int>(12 * h + k))
                    for (std::size_t q = 0; q < 2; ++q) out.edges[static_cast<std::size_t>(x)][q] = hexes[h][static_cast<std::size_t>(HexArcs::kHexEdges[k][q])];
            }
    });

    const std::vector<int> firstFace = firstOccurrences<6>(hm, vhexBegin, vhex, threads, [](const std::array<int, 8>& h, int k, Key& key, int& minV) {
        std::array<int, 4> v;
        for (std::size_t q = 0; q < 4; ++q) v[q] = h[static_cast<std::size_t>(HexArcs::kHexFaces[k][q])];
        std::sort(v.begin(), v.end());
        key = {pack(v[0], v[1]), pack(v[2], v[3])};
        minV = v[0];
    });
    face_owner = numberOccurrences(firstFace, 6, threads, id);
    out.hex_faces.resize(nh);
    out.hex_face_sign.resize(nh);
    out.faces.resize(face_owner.size());
    parallelChunks(nh, threads, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t h = b; h < e; ++h)
            for (std::size_t k = 0; k < 6; ++k) {
                const int x = id[6 * h + k];
                const bool owner = firstFace[6 * h + k] == static_cast<int>(6 * h + k);
                out.hex_faces[h][k] = x;
                out.hex_face_sign[h][k] = owner ? 1 : -1;
                if (owner)
                    for (std::size_t q = 0; q < 4; ++q) out.faces[static_cast<std::size_t>(x)][q] = hexes[h][static_cast<std::size_t>(HexArcs::kHexFaces[k][q])];
            }
    });
}

} // namespace HexEx
