#include "HexElementNumbering.hh"

#include "../Core/Parallel.hh"

#include <algorithm>
#include <array>
#include <cstdint>

namespace HexEx {

namespace {

/// Sorted vertex set of a face, packed for comparison (an edge's fits one word).
struct Key {
    std::uint64_t k0, k1;
    bool operator==(const Key& o) const { return k0 == o.k0 && k1 == o.k1; }
};

std::uint64_t pack(int a, int b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

/// For every occurrence (o = hex * Per + local index) the first occurrence with the same
/// vertex set. Occurrences are grouped by their smallest vertex, in occurrence order (a
/// counting sort); within its group (a dozen entries) an occurrence's first one is the
/// earliest entry with the same key.
template <int Per, class K, class KeyOf>
std::vector<int> firstOccurrences(const HexMesh& hm, std::size_t nVertices, int threads, KeyOf&& keyOf) {
    const std::size_t nh = hm.hexes.size(), n = Per * nh;
    std::vector<K> keys(n);
    std::vector<int> minVertex(n);
    parallelChunks(nh, threads, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t h = b; h < e; ++h)
            for (int k = 0; k < Per; ++k) keyOf(hm.hexes[h], k, keys[Per * h + static_cast<std::size_t>(k)], minVertex[Per * h + static_cast<std::size_t>(k)]);
    });
    // Counting sort by smallest vertex, stable, in parallel: each chunk counts its
    // occurrences per vertex, then writes them after those of the earlier chunks.
    const std::size_t chunks = static_cast<std::size_t>(std::max(1, std::min<int>(threads, static_cast<int>(std::max<std::size_t>(nh, 1)))));
    std::vector<std::vector<int>> count(chunks, std::vector<int>(nVertices, 0));
    parallelChunks(nh, static_cast<int>(chunks), [&](int part, std::size_t b, std::size_t e) {
        std::vector<int>& c = count[static_cast<std::size_t>(part)];
        for (std::size_t o = Per * b; o < Per * e; ++o) ++c[static_cast<std::size_t>(minVertex[o])];
    });
    std::vector<int> begin(nVertices + 1, 0);
    for (std::size_t v = 0; v < nVertices; ++v) {
        int at = begin[v];
        for (std::size_t t = 0; t < chunks; ++t) {
            const int c = count[t][v];
            count[t][v] = at;  // now: where chunk t writes its first occurrence at v
            at += c;
        }
        begin[v + 1] = at;
    }
    std::vector<int> order(n);
    std::vector<K> grouped(n);  // keys in group order, for a contiguous search
    parallelChunks(nh, static_cast<int>(chunks), [&](int part, std::size_t b, std::size_t e) {
        std::vector<int>& fill = count[static_cast<std::size_t>(part)];
        for (std::size_t o = Per * b; o < Per * e; ++o) {
            const int p = fill[static_cast<std::size_t>(minVertex[o])]++;
            order[static_cast<std::size_t>(p)] = static_cast<int>(o);
            grouped[static_cast<std::size_t>(p)] = keys[o];
        }
    });
    std::vector<int> first(n);
    parallelChunks(nVertices, threads, [&](int, std::size_t vb, std::size_t ve) {
        for (std::size_t v = vb; v < ve; ++v)
            for (int p = begin[v]; p < begin[v + 1]; ++p) {
                int q = begin[v];
                while (!(grouped[static_cast<std::size_t>(q)] == grouped[static_cast<std::size_t>(p)])) ++q;  // stops at p at the latest
                first[static_cast<std::size_t>(order[static_cast<std::size_t>(p)])] = order[static_cast<std::size_t>(q)];
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
    int maxVertex = -1;
    for (const auto& h : hexes)
        for (int v : h) maxVertex = std::max(maxVertex, v);
    const std::size_t nVertices = static_cast<std::size_t>(maxVertex + 1);

    std::vector<int> id;
    const std::vector<int> firstEdge = firstOccurrences<12, std::uint64_t>(hm, nVertices, threads, [](const std::array<int, 8>& h, int k, std::uint64_t& key, int& minV) {
        const int a = h[static_cast<std::size_t>(HexArcs::kHexEdges[k][0])], b = h[static_cast<std::size_t>(HexArcs::kHexEdges[k][1])];
        key = pack(std::min(a, b), std::max(a, b));
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

    const std::vector<int> firstFace = firstOccurrences<6, Key>(hm, nVertices, threads, [](const std::array<int, 8>& h, int k, Key& key, int& minV) {
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
