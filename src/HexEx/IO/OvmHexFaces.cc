/// @file OvmHexFaces.cc
/// Face and edge numbering of all-hex OpenVolumeMesh models (OvmHexFaces.hh). Loop 6h + i is
/// quad i of hex h. The quads are filed by their smallest vertex (16-byte records: the other
/// three vertices sorted and the loop) in compressed-row buckets built from counts, by
/// vertex-range chunks that each read the hexes in order; a sort in each small bucket matches
/// them (the neighbour loop). The hex edges are then filed the same way by their smaller vertex
/// (8 bytes: the larger vertex and 12 h + local edge, in the same buffer); sorted, the first use
/// of an edge is its owner: the smallest hex with it, whose smaller quad through it is the
/// edge's first occurrence; every hex edge keeps a reference to its owner. A face's first loop
/// is the smaller of its loops; faces are numbered in order of first loops (count per chunk,
/// prefix, number; the halffaces overwrite the neighbour loops in place), edges in order of
/// first loop and position (the same), and a last pass over the hexes, in face order, writes
/// the edges and every face's halfedges.

#include "OvmHexFaces.hh"

#include "../Core/DefaultInitAllocator.hh"
#include "../Core/Parallel.hh"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <memory>
#include <vector>

namespace HexEx {

namespace {

using detail::kOvmHexFaces;

/// Hex edges of the VTK order as local vertex pairs.
constexpr int kEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                               {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

/// Local tables derived from kOvmHexFaces and kEdges.
struct HexTables {
    int edgeOf[8][8];      ///< local edge of a local vertex pair, or -1
    int edgeFaces[12][2];  ///< the two quads through each edge, smaller index first
    int edgeAt[6][4];      ///< edge from position j to j + 1 of quad i
    int faceMask[6];       ///< local vertex bits of each quad
    int cornerFaces[8][3]; ///< the three quads through each corner
    int cornerNext[8][3];  ///< the three corners joined to each corner by an edge

    constexpr HexTables() : edgeOf{}, edgeFaces{}, edgeAt{}, faceMask{}, cornerFaces{}, cornerNext{} {
        for (auto& row : edgeOf)
            for (int& x : row) x = -1;
        for (int e = 0; e < 12; ++e) edgeOf[kEdges[e][0]][kEdges[e][1]] = edgeOf[kEdges[e][1]][kEdges[e][0]] = e;
        int n[12] = {};
        for (int i = 0; i < 6; ++i) {
            faceMask[i] = 0;
            for (int j = 0; j < 4; ++j) {
                faceMask[i] |= 1 << kOvmHexFaces[i][j];
                const int e = edgeOf[kOvmHexFaces[i][j]][kOvmHexFaces[i][(j + 1) % 4]];
                edgeAt[i][j] = e;
                edgeFaces[e][n[e]++] = i;
            }
        }
        int nf[8] = {}, nn[8] = {};
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 4; ++j) {
                const int k = kOvmHexFaces[i][j];
                cornerFaces[k][nf[k]++] = i;
            }
        for (int e = 0; e < 12; ++e) {
            cornerNext[kEdges[e][0]][nn[kEdges[e][0]]++] = kEdges[e][1];
            cornerNext[kEdges[e][1]][nn[kEdges[e][1]]++] = kEdges[e][0];
        }
    }
};
constexpr HexTables kT;

/// Fewer hexes than this are handled on one thread.
constexpr std::size_t kParallelHexes = 20000;

int chunksFor(std::size_t n, int threads) { return n >= kParallelHexes ? std::max(1, threads) : 1; }

/// Exclusive prefix sums of per-chunk counts in place; @return the total.
std::size_t prefix(std::vector<std::size_t>& counts) {
    std::size_t sum = 0;
    for (auto& c : counts) {
        const std::size_t n = c;
        c = sum;
        sum += n;
    }
    return sum;
}

/// Records filed in buckets by a vertex, compressed-row: the records of vertex v are
/// rec[start[v]] to rec[start[v + 1]] - 1.
/// The records live in a buffer that the caller gives (the quads' and then the edges'
/// buckets reuse one buffer: pages touched once, not twice).
template <class Rec>
struct VertexBuckets {
    std::vector<int> start;  ///< per vertex its first record (and the end)
    Rec* rec;                ///< the records, grouped by vertex (in the caller's buffer)

    /// Files @p perHex items of every hex of @p nHex: item i of hex h goes to the bucket of
    /// vertex key(h, i) as make(h, i). Chunk c of @p vChunks owns a range of vertices, reads
    /// all hexes (in order, which the prefetcher follows) and files the items of its vertices
    /// only: no atomics, and a bucket holds its records in hex order for any thread count.
    /// @p buffer must hold perHex * nHex records.
    template <class Key, class Make>
    VertexBuckets(void* buffer, std::size_t nHex, std::size_t nv, int vChunks, int perHex, Key&& key, Make&& make)
        : start(nv + 1, 0), rec(static_cast<Rec*>(buffer)) {
        parallelChunks(nv, vChunks, [&](int, std::size_t v0, std::size_t v1) {
            for (std::size_t h = 0; h < nHex; ++h)
                for (int i = 0; i < perHex; ++i) {
                    const std::size_t v = static_cast<std::size_t>(key(h, i));
                    if (v >= v0 && v < v1) ++start[v + 1];
                }
        });
        for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
        std::vector<int, DefaultInitAllocator<int>> pos(start.begin(), start.end() - 1);
        parallelChunks(nv, vChunks, [&](int, std::size_t v0, std::size_t v1) {
            for (std::size_t h = 0; h < nHex; ++h)
                for (int i = 0; i < perHex; ++i) {
                    const std::size_t v = static_cast<std::size_t>(key(h, i));
                    if (v >= v0 && v < v1) rec[static_cast<std::size_t>(pos[v]++)] = make(h, i);
                }
        });
    }
    /// The records of vertex @p v.
    Rec* begin(std::size_t v) { return rec + start[v]; }
    /// The end of the records of vertex @p v.
    Rec* end(std::size_t v) { return rec + start[v + 1]; }
};

/// Sorts [@p b, @p e) by @p less: insertion sort for the usual few records, std::sort for
/// large buckets.
template <class Rec, class Less>
void sortBucket(Rec* b, Rec* e, Less less) {
    if (e - b > 32) {
        std::sort(b, e, less);
        return;
    }
    for (Rec* x = b + 1; x < e; ++x) {
        const Rec r = *x;
        Rec* y = x;
        for (; y > b && less(r, y[-1]); --y) *y = y[-1];
        *y = r;
    }
}

/// Number of set bits of @p x, inline (__builtin_popcount is a library call on a target
/// without the popcnt instruction, and it is called per halfedge).
inline int bitCount(std::uint32_t x) {
    x = x - ((x >> 1) & 0x55555555u);
    x = (x & 0x33333333u) + ((x >> 2) & 0x33333333u);
    return static_cast<int>((((x + (x >> 4)) & 0x0F0F0F0Fu) * 0x01010101u) >> 24);
}

/// Position of local edge @p e in its smaller quad kT.edgeFaces[e][0].
int firstPosition(int e) {
    const int i = kT.edgeFaces[e][0];
    int j = 0;
    while (kT.edgeAt[i][j] != e) ++j;
    return j;
}

} // namespace

bool ovmHexFaces(const HexMesh& mesh, int threads, OvmFaces& out) {
    const std::size_t nHex = mesh.hexes.size(), nLoops = 6 * nHex, nv = mesh.vertices.size();
    // Halffaces fit in int, owner references (32 h + bit) in 32 bits.
    if (!mesh.polyhedra.empty() || nHex > static_cast<std::size_t>(INT_MAX / 12) || nHex > (std::size_t(1) << 27)) return false;
    const int chunks = chunksFor(nHex, threads), vChunks = chunksFor(nv, threads);
    const auto loopVertex = [&](std::size_t l, int j) {
        return mesh.hexes[l / 6][static_cast<std::size_t>(kOvmHexFaces[l % 6][j & 3])];
    };
    std::vector<char> ok(static_cast<std::size_t>(std::max(chunks, vChunks)), 1);
    const auto allOk = [&] { return std::all_of(ok.begin(), ok.end(), [](char x) { return x != 0; }); };
    parallelChunks(nHex, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        for (std::size_t h = h0; h < h1; ++h)
            for (int i = 0; i < 8; ++i)
                for (int j = 0; j < i; ++j)
                    if (mesh.hexes[h][static_cast<std::size_t>(i)] == mesh.hexes[h][static_cast<std::size_t>(j)])
                        ok[static_cast<std::size_t>(c)] = 0;
    });
    if (!allOk()) return false;
    // A local edge's first occurrence in a hex is position j of quad i (4 i + j); the hex's
    // owned edges are numbered in that order, so each local edge gets its rank among them.
    int rankOf[12], rankPos[12];  // local edge -> rank; rank -> 4 i + j
    bool startsAtFirstEnd[12];    // the first occurrence runs from kEdges[e][0] to kEdges[e][1]
    for (int e = 0; e < 12; ++e) {
        const int pos = 4 * kT.edgeFaces[e][0] + firstPosition(e);
        rankOf[e] = 0;
        for (int f = 0; f < 12; ++f) rankOf[e] += 4 * kT.edgeFaces[f][0] + firstPosition(f) < pos ? 1 : 0;
        rankPos[rankOf[e]] = pos;
        startsAtFirstEnd[e] = kOvmHexFaces[pos / 4][pos % 4] == kEdges[e][0];
    }

    // Quads: filed by their smallest vertex with their other three vertices sorted, matched in
    // each bucket by a sort (neighbour loop or -1; more than two equal quads: not covered).
    std::vector<int> nb(nLoops);
    // One buffer for both kinds of records: 6 quads of 16 bytes or 12 edges of 8 bytes per hex.
    static_assert(sizeof(std::uint64_t) * 12 == 16 * 6, "records of a hex");
    std::unique_ptr<std::uint64_t[]> records(new std::uint64_t[12 * nHex]);  // not zeroed: every entry written
    {
        struct Quad {  // the other three vertices, sorted, and the loop
            int a, b, d, loop;
        };
        const auto quadKey = [&](std::size_t h, int i) {
            const auto& hx = mesh.hexes[h];
            const int* q = kOvmHexFaces[i];
            return std::min(std::min(hx[static_cast<std::size_t>(q[0])], hx[static_cast<std::size_t>(q[1])]),
                            std::min(hx[static_cast<std::size_t>(q[2])], hx[static_cast<std::size_t>(q[3])]));
        };
        const auto quadRec = [&](std::size_t h, int i) {
            const auto& hx = mesh.hexes[h];
            int w[4];
            for (int j = 0; j < 4; ++j) w[j] = hx[static_cast<std::size_t>(kOvmHexFaces[i][j])];
            int m = 0;
            for (int j = 1; j < 4; ++j)
                if (w[j] < w[m]) m = j;
            int x = w[(m + 1) & 3], y = w[(m + 2) & 3], z = w[(m + 3) & 3];
            if (x > y) std::swap(x, y);
            if (y > z) std::swap(y, z);
            if (x > y) std::swap(x, y);
            return Quad{x, y, z, static_cast<int>(6 * h) + i};
        };
        static_assert(sizeof(Quad) == 16, "quad record");
        VertexBuckets<Quad> qb(records.get(), nHex, nv, vChunks, 6, quadKey, quadRec);
        const auto less = [](const Quad& p, const Quad& q) {
            return p.a != q.a ? p.a < q.a : p.b != q.b ? p.b < q.b : p.d < q.d;
        };
        parallelChunks(nv, vChunks, [&](int c, std::size_t v0, std::size_t v1) {
            for (std::size_t v = v0; v < v1; ++v) {
                Quad* b = qb.begin(v);
                Quad* e = qb.end(v);
                sortBucket(b, e, less);
                for (Quad* x = b; x < e;) {
                    Quad* y = x + 1;
                    while (y < e && !less(*x, *y)) ++y;
                    if (y - x > 2) ok[static_cast<std::size_t>(c)] = 0;
                    const bool pair = y - x == 2;
                    nb[static_cast<std::size_t>(x[0].loop)] = pair ? x[1].loop : -1;
                    if (pair) nb[static_cast<std::size_t>(x[1].loop)] = x[0].loop;
                    x = y;
                }
            }
        });
    }
    if (!allOk()) return false;

    // Edges: every hex edge filed by its smaller vertex as (larger vertex, 2 (12 h + local
    // edge) + 1 if kEdges' first end is the smaller vertex); sorted, an edge's uses lie together
    // and its first is the smallest hex with it, the owner, whose smaller quad through it is the
    // edge's first loop. Per hex, ownInfo holds the edges it owns (bit r for rank r), whether
    // each one's first occurrence starts at its smaller vertex (bit 12 + r) and, from below, its
    // first edge number (bits 32-63): the halfedges then need one look-up in the owner's
    // entry. Every hex edge gets a reference to its owner (16 owner hex + rank), so that the
    // halfedges can be filled hex by hex in face order.
    std::vector<std::uint64_t> ownInfo(nHex, 0);
    std::vector<std::uint32_t, DefaultInitAllocator<std::uint32_t>> ownerRef(12 * nHex);  // every entry written, no zeroing
    {
        const auto edgeKey = [&](std::size_t h, int e) {
            const auto& hx = mesh.hexes[h];
            return std::min(hx[static_cast<std::size_t>(kEdges[e][0])], hx[static_cast<std::size_t>(kEdges[e][1])]);
        };
        const auto edgeRec = [&](std::size_t h, int e) {
            const auto& hx = mesh.hexes[h];
            const int u = std::max(hx[static_cast<std::size_t>(kEdges[e][0])], hx[static_cast<std::size_t>(kEdges[e][1])]);
            const bool firstSmaller = hx[static_cast<std::size_t>(kEdges[e][0])] < hx[static_cast<std::size_t>(kEdges[e][1])];
            return static_cast<std::uint64_t>(u) << 32 |
                   static_cast<std::uint64_t>(2 * (12 * h + static_cast<std::size_t>(e)) + (firstSmaller ? 1 : 0));
        };
        VertexBuckets<std::uint64_t> eb(records.get(), nHex, nv, vChunks, 12, edgeKey, edgeRec);
        parallelChunks(nv, vChunks, [&](int, std::size_t v0, std::size_t v1) {
            for (std::size_t v = v0; v < v1; ++v) {
                std::uint64_t* b = eb.begin(v);
                std::uint64_t* e = eb.end(v);
                sortBucket(b, e, [](std::uint64_t p, std::uint64_t q) { return p < q; });
                for (std::uint64_t* x = b; x < e;) {
                    const std::uint32_t id = static_cast<std::uint32_t>(*x) >> 1;
                    const bool firstSmaller = (*x & 1u) != 0;
                    const std::uint32_t oh = id / 12, eo = id % 12, r = static_cast<std::uint32_t>(rankOf[eo]);
                    const bool startsSmaller = startsAtFirstEnd[eo] == firstSmaller;
                    __atomic_fetch_or(&ownInfo[oh], (std::uint64_t(1) << r) | (std::uint64_t(startsSmaller ? 1 : 0) << (12 + r)),
                                      __ATOMIC_RELAXED);
                    const std::uint32_t ref = 16u * oh + r;
                    const std::uint64_t u = *x >> 32;
                    for (; x < e && *x >> 32 == u; ++x) ownerRef[static_cast<std::uint32_t>(*x) >> 1] = ref;
                }
            }
        });
    }
    records.reset();

    // Faces: number the first loops (no neighbour or a later one) in loop order, then give
    // every second loop its halfface. The halffaces overwrite the neighbour loops in place:
    // a first loop's neighbour is not needed again, a second loop reads its own before.
    const auto first = [&](std::size_t l) { return nb[l] < 0 || static_cast<std::size_t>(nb[l]) > l; };
    std::vector<std::size_t> base(static_cast<std::size_t>(chunks), 0);
    std::vector<std::uint8_t> firstMask(nHex, 0);  // per hex: bit i if loop 6h + i is a first loop
    parallelChunks(nHex, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        std::size_t n = 0;
        for (std::size_t l = 6 * h0; l < 6 * h1; ++l)
            if (first(l)) {
                ++n;
                firstMask[l / 6] = static_cast<std::uint8_t>(firstMask[l / 6] | 1u << (l % 6));
            }
        base[static_cast<std::size_t>(c)] = n;
    });
    const std::size_t nFaces = prefix(base);
    const auto isFirst = [&](std::size_t l) { return (firstMask[l / 6] >> (l % 6) & 1u) != 0; };
    std::vector<int>& hf = out.halffaces;
    hf = std::move(nb);
    parallelChunks(nHex, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        std::size_t f = base[static_cast<std::size_t>(c)];
        for (std::size_t l = 6 * h0; l < 6 * h1; ++l)
            if (isFirst(l)) hf[l] = static_cast<int>(2 * f++);
    });
    parallelChunks(nHex, chunks, [&](int, std::size_t h0, std::size_t h1) {
        for (std::size_t l = 6 * h0; l < 6 * h1; ++l) {
            if (isFirst(l)) continue;
            const std::size_t s = static_cast<std::size_t>(hf[l]);  // still the neighbour loop
            // 0 if loop l runs like its first loop s at l's first vertex, 1 if against it.
            const int v0 = loopVertex(l, 0);
            int k = 0;
            while (k < 4 && loopVertex(s, k) != v0) ++k;
            hf[l] = hf[s] + (loopVertex(s, k + 1) == loopVertex(l, 1) ? 0 : 1);
        }
    });

    // Edges: numbered in order of their first loop and position (count, prefix, rank); then
    // hex by hex, every owner writes its edges and every first loop its halfedges (looked up
    // through the owner references).
    const auto ownedMask = [](std::uint64_t info) { return static_cast<std::uint32_t>(info & 0xFFFu); };
    parallelChunks(nHex, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        std::size_t n = 0;
        for (std::size_t h = h0; h < h1; ++h) n += static_cast<std::size_t>(bitCount(ownedMask(ownInfo[h])));
        base[static_cast<std::size_t>(c)] = n;
    });
    const std::size_t nEdges = prefix(base);
    if (nEdges > static_cast<std::size_t>(INT_MAX / 2)) return false;
    parallelChunks(nHex, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        std::size_t n = base[static_cast<std::size_t>(c)];
        for (std::size_t h = h0; h < h1; ++h) {
            const std::uint64_t info = ownInfo[h];
            ownInfo[h] = info | static_cast<std::uint64_t>(n) << 32;  // n < INT_MAX / 2
            n += static_cast<std::size_t>(bitCount(ownedMask(info)));
        }
    });
    out.edges.resize(nEdges);
    IntLists& fh = out.faceHalfedges;
    fh.offsets.resize(nFaces + 1);
    fh.values.resize(4 * nFaces);
    parallelChunks(nFaces + 1, chunksFor(nFaces, threads), [&](int, std::size_t f0, std::size_t f1) {
        for (std::size_t f = f0; f < f1; ++f) fh.offsets[f] = 4 * f;
    });
    parallelChunks(nHex, chunks, [&](int, std::size_t h0, std::size_t h1) {
        for (std::size_t h = h0; h < h1; ++h) {
            std::size_t id = static_cast<std::size_t>(ownInfo[h] >> 32);
            for (std::uint32_t bits = ownedMask(ownInfo[h]); bits != 0; bits &= bits - 1) {
                const int pos = rankPos[__builtin_ctz(bits)], i = pos / 4, j = pos % 4;
                const std::size_t l = 6 * h + static_cast<std::size_t>(i);
                out.edges[id++] = {{loopVertex(l, j), loopVertex(l, j + 1)}};
            }
            for (int i = 0; i < 6; ++i) {
                if (!(firstMask[h] >> i & 1u)) continue;
                const std::size_t l = 6 * h + static_cast<std::size_t>(i);
                int* values = &fh.values[2 * static_cast<std::size_t>(hf[l])];
                for (int j = 0; j < 4; ++j) {
                    const std::uint32_t ref = ownerRef[12 * h + static_cast<std::size_t>(kT.edgeAt[i][j])];
                    const std::uint64_t info = ownInfo[ref / 16];
                    const std::uint32_t r = ref % 16;
                    const std::size_t id = static_cast<std::size_t>(info >> 32) +
                                           static_cast<std::size_t>(bitCount(ownedMask(info) & ((1u << r) - 1u)));
                    const bool startsSmaller = (info >> (12 + r) & 1u) != 0;
                    const bool fromSmaller = loopVertex(l, j) < loopVertex(l, j + 1);
                    values[j] = static_cast<int>(2 * id) + (fromSmaller == startsSmaller ? 0 : 1);
                }
            }
        }
    });
    return true;
}

} // namespace HexEx
