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

#include "../Core/BitCount.hh"
#include "../Core/DefaultInitAllocator.hh"
#include "../Core/Parallel.hh"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

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

/// Counts of items filed in buckets by a vertex, for compressed-row buckets: the bucket of
/// vertex v is [start[v], start[v + 1]).
struct BucketCount {
    int perHex;              ///< items per hex
    std::vector<int> start;  ///< per vertex its first record (and the end)
};

/// The smallest and the largest vertex of a hex.
inline std::pair<int, int> vertexSpan(const std::array<int, 8>& hx) {
    int lo = hx[0], hi = hx[0];
    for (std::size_t k = 1; k < 8; ++k) {
        lo = std::min(lo, hx[k]);
        hi = std::max(hi, hx[k]);
    }
    return {lo, hi};
}

/// Calls item(h, i, v) for every item i of every hex h of @p hexes whose key v = key(h, i)
/// is in [@p v0, @p v1), hexes in order. A hex none of whose vertices is in the range is
/// skipped, one with all of them in it needs no test per item (the keys are hex vertices):
/// with the vertex ranges of several threads each thread computes the keys of the hexes
/// that touch its range only.
template <class Key, class Item>
void forItemsInRange(const std::vector<std::array<int, 8>>& hexes, int perHex, std::size_t v0, std::size_t v1, Key&& key,
                     Item&& item) {
    const std::size_t nHex = hexes.size();
    for (std::size_t h = 0; h < nHex; ++h) {
        const auto [lo, hi] = vertexSpan(hexes[h]);
        const std::size_t l = static_cast<std::size_t>(lo), u = static_cast<std::size_t>(hi);
        if (u < v0 || l >= v1) continue;
        if (l >= v0 && u < v1) {
            for (int i = 0; i < perHex; ++i) item(h, i, static_cast<std::size_t>(key(h, i)));
        } else {
            for (int i = 0; i < perHex; ++i) {
                const std::size_t v = static_cast<std::size_t>(key(h, i));
                if (v >= v0 && v < v1) item(h, i, v);
            }
        }
    }
}

/// Counts the items of every hex of @p hexes for both @p a and @p b in one pass over the
/// hexes (keys @p keyA and @p keyB, hex vertices). Chunk c of @p vChunks owns a range of
/// vertices and reads the hexes in order (which the prefetcher follows): no atomics.
/// Without @p countA only @p b is counted (@p a is left empty).
template <class KeyA, class KeyB>
void countBuckets(const std::vector<std::array<int, 8>>& hexes, std::size_t nv, int vChunks, BucketCount& a, KeyA&& keyA,
                  BucketCount& b, KeyB&& keyB, bool countA = true) {
    if (countA) a.start.assign(nv + 1, 0);
    b.start.assign(nv + 1, 0);
    parallelChunks(nv, vChunks, [&](int, std::size_t v0, std::size_t v1) {
        if (countA) forItemsInRange(hexes, a.perHex, v0, v1, keyA, [&](std::size_t, int, std::size_t v) { ++a.start[v + 1]; });
        forItemsInRange(hexes, b.perHex, v0, v1, keyB, [&](std::size_t, int, std::size_t v) { ++b.start[v + 1]; });
    });
    for (std::size_t v = 0; v < nv; ++v) {
        if (countA) a.start[v + 1] += a.start[v];
        b.start[v + 1] += b.start[v];
    }
}

/// Files the items counted in @p count into @p rec (perHex records per hex, the caller's
/// buffer): item i of hex h goes to the bucket of vertex key(h, i) as make(h, i). Chunk c of
/// @p vChunks files the items of its vertex range only (a bucket holds its records in hex
/// order for any thread count).
template <class Rec, class Key, class Make>
void fileRecords(Rec* rec, const BucketCount& count, const std::vector<std::array<int, 8>>& hexes, std::size_t nv,
                 int vChunks, Key&& key, Make&& make) {
    std::vector<int, DefaultInitAllocator<int>> pos(count.start.begin(), count.start.end() - 1);
    parallelChunks(nv, vChunks, [&](int, std::size_t v0, std::size_t v1) {
        forItemsInRange(hexes, count.perHex, v0, v1, key,
                        [&](std::size_t h, int i, std::size_t v) { rec[static_cast<std::size_t>(pos[v]++)] = make(h, i); });
    });
}

/// Gives the whole pages of the consumed records [@p b, @p e) back to the system (Linux; a
/// no-op elsewhere): they are not read again before the buffer is freed, and the arrays that
/// grow meanwhile then do not raise the peak memory.
inline void releasePages(const void* b, const void* e) {
#if defined(__linux__) && defined(MADV_DONTNEED)
    static_assert(sizeof(std::uintptr_t) >= sizeof(void*), "pointer as integer");
    const std::uintptr_t page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
    const std::uintptr_t lo = (reinterpret_cast<std::uintptr_t>(b) + page - 1) / page * page;
    const std::uintptr_t hi = reinterpret_cast<std::uintptr_t>(e) / page * page;
    if (hi > lo) madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_DONTNEED);
#else
    (void)b;
    (void)e;
#endif
}

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

/// Position of local edge @p e in quad @p i (one of kT.edgeFaces[e]).
int positionIn(int i, int e) {
    int j = 0;
    while (kT.edgeAt[i][j] != e) ++j;
    return j;
}

/// Position of local edge @p e in its smaller quad kT.edgeFaces[e][0].
int firstPosition(int e) { return positionIn(kT.edgeFaces[e][0], e); }

/// Per hex, during the numbering (see ovmHexFaces()): bits 0-11 the edges it owns by rank,
/// bits 24-29 its first loops, bits 32-63 first its first face number, later its first edge
/// number.
constexpr int kFirstLoopShift = 24;

} // namespace

bool ovmHexFaces(const HexMesh& mesh, int threads, OvmFaces& out, HexFaceNeighbours* neighbours) {
    const std::size_t nHex = mesh.hexes.size(), nLoops = 6 * nHex, nv = mesh.vertices.size();
    // Halffaces fit in int, owner references with their orientation (2 (16 h + rank) + 1) in 32 bits.
    if (!mesh.polyhedra.empty() || nHex > static_cast<std::size_t>(INT_MAX / 12) || nHex > (std::size_t(1) << 27)) return false;
    const int chunks = chunksFor(nHex, threads), vChunks = chunksFor(nv, threads);
    const auto loopVertex = [&](std::size_t l, int j) {
        return mesh.hexes[l / 6][static_cast<std::size_t>(kOvmHexFaces[l % 6][j & 3])];
    };
    std::vector<char> ok(static_cast<std::size_t>(std::max(chunks, vChunks)), 1);
    const auto allOk = [&] { return std::all_of(ok.begin(), ok.end(), [](char x) { return x != 0; }); };
    parallelChunks(nHex, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        // Every pair of the 8 corners is k and k + r (mod 8) for some r in 1-4: no branches.
        bool repeated = false;
        for (std::size_t h = h0; h < h1; ++h) {
            const auto& x = mesh.hexes[h];
            for (std::size_t r = 1; r <= 4; ++r)
                for (std::size_t k = 0; k < 8; ++k) repeated |= x[k] == x[(k + r) & 7];
        }
        if (repeated) ok[static_cast<std::size_t>(c)] = 0;
    });
    if (!allOk()) return false;
    // A local edge's first occurrence in a hex is position j of quad i (4 i + j); the hex's
    // owned edges are numbered in that order, so each local edge gets its rank among them.
    int rankOf[12], rankPos[12];  // local edge -> rank; rank -> 4 i + j
    bool startsAtFirstEnd[12];    // the first occurrence runs from kEdges[e][0] to kEdges[e][1]
    int slotOf[12][2];            // position of local edge e in quad kT.edgeFaces[e][k]
    bool runsFromFirstEnd[12][2]; // quad kT.edgeFaces[e][k] runs along e from kEdges[e][0]
    for (int e = 0; e < 12; ++e) {
        const int pos = 4 * kT.edgeFaces[e][0] + firstPosition(e);
        rankOf[e] = 0;
        for (int f = 0; f < 12; ++f) rankOf[e] += 4 * kT.edgeFaces[f][0] + firstPosition(f) < pos ? 1 : 0;
        rankPos[rankOf[e]] = pos;
        startsAtFirstEnd[e] = kOvmHexFaces[pos / 4][pos % 4] == kEdges[e][0];
        for (int k = 0; k < 2; ++k) {
            slotOf[e][k] = positionIn(kT.edgeFaces[e][k], e);
            runsFromFirstEnd[e][k] = kOvmHexFaces[kT.edgeFaces[e][k]][slotOf[e][k]] == kEdges[e][0];
        }
    }

    // The buckets of the quads (by their smallest vertex) and of the hex edges (by their
    // smaller vertex), counted in one pass over the hexes.
    const auto quadKey = [&](std::size_t h, int i) {
        const auto& hx = mesh.hexes[h];
        const int* q = kOvmHexFaces[i];
        return std::min(std::min(hx[static_cast<std::size_t>(q[0])], hx[static_cast<std::size_t>(q[1])]),
                        std::min(hx[static_cast<std::size_t>(q[2])], hx[static_cast<std::size_t>(q[3])]));
    };
    const auto edgeKey = [&](std::size_t h, int e) {
        const auto& hx = mesh.hexes[h];
        return std::min(hx[static_cast<std::size_t>(kEdges[e][0])], hx[static_cast<std::size_t>(kEdges[e][1])]);
    };
    // With a neighbour table (loop 6h + i is face i of hex h in both) the quads need no buckets.
    const bool table = neighbours != nullptr && neighbours->items.size() == nLoops;
    BucketCount quadCount{6, {}}, edgeCount{12, {}};
    countBuckets(mesh.hexes, nv, vChunks, quadCount, quadKey, edgeCount, edgeKey, !table);

    // Quads: filed by their smallest vertex with their other three vertices sorted, matched in
    // each bucket by a sort (neighbour loop or -1; more than two equal quads: not covered).
    DefaultInitVector<int> nb;
    if (table) nb.swap(neighbours->items);
    else nb.resize(nLoops);  // every entry written by the matching
    // One buffer for both kinds of records: 6 quads of 16 bytes or 12 edges of 8 bytes per hex.
    static_assert(sizeof(std::uint64_t) * 12 == 16 * 6, "records of a hex");
    std::unique_ptr<std::uint64_t[]> records(new std::uint64_t[12 * nHex]);  // not zeroed: every entry written
    if (!table) {
        struct Quad {  // the other three vertices, sorted, and the loop
            int a, b, d, loop;
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
        Quad* qb = reinterpret_cast<Quad*>(records.get());
        fileRecords(qb, quadCount, mesh.hexes, nv, vChunks, quadKey, quadRec);
        const auto less = [](const Quad& p, const Quad& q) {
            return p.a != q.a ? p.a < q.a : p.b != q.b ? p.b < q.b : p.d < q.d;
        };
        parallelChunks(nv, vChunks, [&](int c, std::size_t v0, std::size_t v1) {
            for (std::size_t v = v0; v < v1; ++v) {
                Quad* b = qb + quadCount.start[v];
                Quad* e = qb + quadCount.start[v + 1];
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
    quadCount.start = std::vector<int>();
    if (!allOk()) return false;

    // Faces: a face's first loop is the smaller of its loops (no neighbour or a later one);
    // faces are numbered in order of first loops (count per chunk, prefix, number), then every
    // second loop gets its halfface. The halffaces overwrite the neighbour loops in place: a
    // first loop's neighbour is not needed again, a second loop reads its own before. Per hex,
    // info holds its first loops and its first face number (see kFirstLoopShift).
    std::vector<std::uint64_t, DefaultInitAllocator<std::uint64_t>> info(nHex);  // every entry written
    std::vector<std::size_t> faceBase(static_cast<std::size_t>(chunks), 0);
    parallelChunks(nHex, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        std::size_t n = 0;
        for (std::size_t h = h0; h < h1; ++h) {
            std::uint32_t mask = 0;
            for (std::size_t i = 0; i < 6; ++i) {
                const std::size_t l = 6 * h + i;
                if (nb[l] < 0 || static_cast<std::size_t>(nb[l]) > l) mask |= 1u << i;
            }
            info[h] = static_cast<std::uint64_t>(mask) << kFirstLoopShift;
            n += static_cast<std::size_t>(bitCount32(mask));
        }
        faceBase[static_cast<std::size_t>(c)] = n;
    });
    const std::size_t nFaces = prefix(faceBase);
    const auto firstLoops = [](std::uint64_t x) { return static_cast<std::uint32_t>(x >> kFirstLoopShift) & 0x3Fu; };
    DefaultInitVector<int>& hf = out.halffaces;
    hf = std::move(nb);
    parallelChunks(nHex, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        std::size_t f = faceBase[static_cast<std::size_t>(c)];
        for (std::size_t h = h0; h < h1; ++h) {
            info[h] |= static_cast<std::uint64_t>(f) << 32;  // f < 2^30
            const std::uint32_t mask = firstLoops(info[h]);
            for (std::size_t i = 0; i < 6; ++i)
                if (mask >> i & 1u) hf[6 * h + i] = static_cast<int>(2 * f++);
        }
    });
    parallelChunks(nHex, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        for (std::size_t h = h0; h < h1; ++h) {
            const std::uint32_t mask = firstLoops(info[h]);
            for (std::size_t i = 0; i < 6; ++i) {
                if (mask >> i & 1u) continue;
                const std::size_t l = 6 * h + i;
                const std::size_t s = static_cast<std::size_t>(hf[l]);  // still the neighbour loop
                // 0 if loop l runs like its first loop s at l's first vertex, 1 if against it.
                const int v0 = loopVertex(l, 0);
                int k = 0;
                while (k < 4 && loopVertex(s, k) != v0) ++k;
                const bool along = loopVertex(s, k + 1) == loopVertex(l, 1);
                hf[l] = hf[s] + (along ? 0 : 1);
                // The same cycle as s, either way round: the quads' sides are edges of both
                // hexes. (For quads matched by their vertex sets the vertex opposite l's first
                // one decides it; a neighbour table's pairs are compared in full.)
                const bool same = k < 4 && loopVertex(s, k + 2) == loopVertex(l, 2) &&
                                  loopVertex(s, k + (along ? 3 : 1)) == loopVertex(l, 3) &&
                                  (along || loopVertex(s, k + 3) == loopVertex(l, 1));
                if (!same) ok[static_cast<std::size_t>(c)] = 0;
            }
        }
    });
    if (!allOk()) return false;

    // Edges: every hex edge filed by its smaller vertex as (larger vertex, 2 (12 h + local
    // edge) + 1 if kEdges' first end is the smaller vertex); sorted, an edge's uses lie together
    // and its first is the smallest hex with it, the owner, whose smaller quad through it is the
    // edge's first occurrence (a first loop: its neighbour, a larger hex, has the edge too, as
    // the quads' cycles agree).
    // The owner gets the edge's bit in its info (rank r: bit r); every use writes the owner
    // reference with the halfedge's orientation (2 (16 owner hex + rank) + 1 if the quad runs
    // along the edge against its first occurrence) into the halfedge slots of its quads that
    // are first loops (the face's halfedge list, in place), where the last pass turns it into
    // the halfedge.
    IntLists& fh = out.faceHalfedges;
    fh.resizeUniform(nFaces, 4);
    {
        const auto edgeRec = [&](std::size_t h, int e) {
            const auto& hx = mesh.hexes[h];
            const int u = std::max(hx[static_cast<std::size_t>(kEdges[e][0])], hx[static_cast<std::size_t>(kEdges[e][1])]);
            const bool firstSmaller = hx[static_cast<std::size_t>(kEdges[e][0])] < hx[static_cast<std::size_t>(kEdges[e][1])];
            return static_cast<std::uint64_t>(u) << 32 |
                   static_cast<std::uint64_t>(2 * (12 * h + static_cast<std::size_t>(e)) + (firstSmaller ? 1 : 0));
        };
        std::uint64_t* eb = records.get();
        fileRecords(eb, edgeCount, mesh.hexes, nv, vChunks, edgeKey, edgeRec);
        int* slots = fh.values.data();
        parallelChunks(nv, vChunks, [&](int, std::size_t v0, std::size_t v1) {
            // The records of this range are consumed in order; their pages go back to the system
            // in steps of 8 MiB while fh.values fills (the pages at the range's ends stay).
            constexpr std::size_t kReleaseStep = std::size_t(1) << 20;  // records of 8 bytes
            std::uint64_t* released = eb + edgeCount.start[v0];
            for (std::size_t v = v0; v < v1; ++v) {
                std::uint64_t* b = eb + edgeCount.start[v];
                std::uint64_t* e = eb + edgeCount.start[v + 1];
                if (static_cast<std::size_t>(b - released) >= kReleaseStep) {
                    releasePages(released, b);
                    released = b;
                }
                sortBucket(b, e, [](std::uint64_t p, std::uint64_t q) { return p < q; });
                for (std::uint64_t* x = b; x < e;) {
                    const std::uint32_t id = static_cast<std::uint32_t>(*x) >> 1;
                    const bool firstSmaller = (*x & 1u) != 0;
                    const std::uint32_t oh = id / 12, eo = id % 12, r = static_cast<std::uint32_t>(rankOf[eo]);
                    const bool startsSmaller = startsAtFirstEnd[eo] == firstSmaller;
                    __atomic_fetch_or(&info[oh], std::uint64_t(1) << r, __ATOMIC_RELAXED);
                    const std::uint32_t ref = 2u * (16u * oh + r);
                    const std::uint64_t u = *x >> 32;
                    for (; x < e && *x >> 32 == u; ++x) {
                        const std::uint32_t use = static_cast<std::uint32_t>(*x) >> 1, h = use / 12, le = use % 12;
                        const bool useFirstSmaller = (*x & 1u) != 0;
                        // Bits 24-63 of info are not changed while the edges are filed.
                        const std::uint64_t hi = __atomic_load_n(&info[h], __ATOMIC_RELAXED);
                        const std::uint32_t mask = firstLoops(hi);
                        const std::size_t f = static_cast<std::size_t>(hi >> 32);
                        for (int k = 0; k < 2; ++k) {
                            const int i = kT.edgeFaces[le][k];
                            // The quad runs along the edge from its smaller vertex, or not.
                            const bool fromSmaller = runsFromFirstEnd[le][k] == useFirstSmaller;
                            if (mask >> i & 1u)
                                slots[4 * (f + static_cast<std::size_t>(bitCount32(mask & ((1u << i) - 1u)))) +
                                      static_cast<std::size_t>(slotOf[le][k])] =
                                    static_cast<int>(ref + (fromSmaller == startsSmaller ? 0u : 1u));
                        }
                    }
                }
            }
        });
    }
    records.reset();
    edgeCount.start = std::vector<int>();

    // Edges: numbered in order of their first loop and position (count, prefix, rank; the
    // first edge number replaces the first face number in info); then hex by hex, every owner
    // writes its edges and every first loop turns its owner references into halfedges.
    const auto ownedMask = [](std::uint64_t x) { return static_cast<std::uint32_t>(x & 0xFFFu); };
    std::vector<std::size_t> edgeBase(static_cast<std::size_t>(chunks), 0);
    parallelChunks(nHex, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        std::size_t n = 0;
        for (std::size_t h = h0; h < h1; ++h) n += static_cast<std::size_t>(bitCount32(ownedMask(info[h])));
        edgeBase[static_cast<std::size_t>(c)] = n;
    });
    const std::size_t nEdges = prefix(edgeBase);
    if (nEdges > static_cast<std::size_t>(INT_MAX / 2)) return false;
    parallelChunks(nHex, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        std::size_t n = edgeBase[static_cast<std::size_t>(c)];
        for (std::size_t h = h0; h < h1; ++h) {
            const std::uint64_t x = info[h];
            info[h] = (x & 0xFFFFFFFFu) | static_cast<std::uint64_t>(n) << 32;  // n < INT_MAX / 2
            n += static_cast<std::size_t>(bitCount32(ownedMask(x)));
        }
    });
    out.edges.resize(nEdges);
    parallelChunks(nHex, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        std::size_t f = faceBase[static_cast<std::size_t>(c)];
        for (std::size_t h = h0; h < h1; ++h) {
            const std::uint64_t own = info[h];
            std::size_t id = static_cast<std::size_t>(own >> 32);
            for (std::uint32_t bits = ownedMask(own); bits != 0; bits &= bits - 1) {
                const int pos = rankPos[__builtin_ctz(bits)], i = pos / 4, j = pos % 4;
                const std::size_t l = 6 * h + static_cast<std::size_t>(i);
                out.edges[id++] = {{loopVertex(l, j), loopVertex(l, j + 1)}};
            }
            const std::uint32_t mask = firstLoops(own);
            for (int i = 0; i < 6; ++i) {
                if (!(mask >> i & 1u)) continue;
                int* values = &fh.values[4 * f++];
                for (int j = 0; j < 4; ++j) {
                    const std::uint32_t ref = static_cast<std::uint32_t>(values[j]);  // 2 (16 owner + rank) + orientation
                    const std::uint64_t x = info[ref / 32];
                    const std::uint32_t r = ref / 2 % 16;
                    const std::size_t e = static_cast<std::size_t>(x >> 32) +
                                          static_cast<std::size_t>(bitCount32(ownedMask(x) & ((1u << r) - 1u)));
                    values[j] = static_cast<int>(2 * e + (ref & 1u));
                }
            }
        }
    });
    return true;
}

} // namespace HexEx
