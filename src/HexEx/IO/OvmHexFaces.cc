/// @file OvmHexFaces.cc
/// Face and edge numbering of all-hex OpenVolumeMesh models (OvmHexFaces.hh). Loop 6h + i is
/// quad i of hex h. One parallel pass over the vertices, each looking at the corners of the
/// hexes around it (prefetched a few vertices ahead), matches the quads whose smallest vertex
/// it is (the neighbour loop) and finds the owner of every edge whose smaller vertex it is:
/// the smallest hex with that edge, whose smaller quad through it is the edge's first
/// occurrence; every hex edge keeps a reference to its owner. A face's first loop is the
/// smaller of its loops; faces are numbered in order of first loops (count per chunk,
/// prefix, number; the halffaces overwrite the neighbour loops in place), edges in order of
/// first loop and position (the same), and a last pass over the hexes, in face order, writes
/// the edges and every face's halfedges.

#include "OvmHexFaces.hh"

#include "../Core/DefaultInitAllocator.hh"
#include "../Core/Parallel.hh"

#include <algorithm>
#include <climits>
#include <cstdint>
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

/// How many vertices ahead the per-vertex passes prefetch the hexes around a vertex (4 and 8
/// gave the same, 0 about 20 % more CPU time in the two per-vertex passes on the cylinder).
constexpr std::size_t kPrefetchAhead = 4;

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

/// The corners (8 h + local index) around every vertex (in no particular order within a vertex).
struct CornerStars {
    std::vector<int> start;   ///< per vertex the first entry of corner (and the end)
    std::vector<int, DefaultInitAllocator<int>> corner;  ///< 8 h + local index, grouped by vertex (every entry written)
    /// Counting sort of the corners of @p mesh by vertex, counted and filled on @p chunks threads
    /// (atomic slots: the order within a vertex varies, which no caller depends on).
    CornerStars(const HexMesh& mesh, int chunks) : start(mesh.vertices.size() + 1, 0), corner(8 * mesh.hexes.size()) {
        const std::size_t nHex = mesh.hexes.size();
        int* count = start.data() + 1;
        parallelChunks(nHex, chunks, [&](int, std::size_t h0, std::size_t h1) {
            for (std::size_t h = h0; h < h1; ++h)
                for (const int v : mesh.hexes[h]) __atomic_fetch_add(&count[v], 1, __ATOMIC_RELAXED);
        });
        for (std::size_t v = 0; v + 1 < start.size(); ++v) start[v + 1] += start[v];
        std::vector<int> fill(start.begin(), start.end() - 1);
        parallelChunks(nHex, chunks, [&](int, std::size_t h0, std::size_t h1) {
            for (std::size_t h = h0; h < h1; ++h)
                for (int k = 0; k < 8; ++k) {
                    const int slot = __atomic_fetch_add(&fill[static_cast<std::size_t>(mesh.hexes[h][static_cast<std::size_t>(k)])], 1,
                                                        __ATOMIC_RELAXED);
                    corner[static_cast<std::size_t>(slot)] = static_cast<int>(8 * h) + k;
                }
        });
    }
    /// Frees both arrays (the stars are needed by the first per-vertex pass only).
    void release() {
        std::vector<int>().swap(start);
        std::vector<int, DefaultInitAllocator<int>>().swap(corner);
    }
    /// Asks the cache for the hexes around vertex @p v (if it exists) ahead of their use: the
    /// per-vertex passes wait on these scattered loads otherwise.
    void prefetch(const HexMesh& mesh, std::size_t v) const {
        if (v + 1 >= start.size()) return;
        for (int s = start[v]; s < start[v + 1]; ++s)
            __builtin_prefetch(&mesh.hexes[static_cast<std::size_t>(corner[static_cast<std::size_t>(s)] / 8)]);
    }
};

/// The hex edges whose smaller vertex is one vertex v: per distinct edge (v, other) the
/// smallest hex with it and its local edge there, and every use of it.
struct VertexEdges {
    /// One hex edge through v: which distinct edge, the hex, its local edge.
    struct Use {
        int edgeIndex;  ///< index into other/hex/edge
        int hex;        ///< the hex
        int edge;       ///< its local edge (index into kEdges)
    };
    std::vector<int> other;  ///< per distinct edge its larger vertex
    std::vector<int> hex;    ///< per distinct edge the smallest hex with it
    std::vector<int> edge;   ///< per distinct edge its local edge in that hex
    std::vector<Use> uses;   ///< every use

    /// Collects the edges of vertex @p v from the corners around it (a linear search among
    /// the few distinct edges instead of sorting the uses).
    void collect(const HexMesh& mesh, const CornerStars& st, std::size_t v) {
        other.clear();
        hex.clear();
        edge.clear();
        uses.clear();
        for (int s = st.start[v]; s < st.start[v + 1]; ++s) {
            const int c = st.corner[static_cast<std::size_t>(s)], h = c / 8, k = c % 8;
            const auto& hx = mesh.hexes[static_cast<std::size_t>(h)];
            for (const int m : kT.cornerNext[k]) {
                const int u = hx[static_cast<std::size_t>(m)];
                if (u <= static_cast<int>(v)) continue;
                const int e = kT.edgeOf[k][m];
                std::size_t d = 0;
                while (d < other.size() && other[d] != u) ++d;
                if (d == other.size()) {
                    other.push_back(u);
                    hex.push_back(h);
                    edge.push_back(e);
                } else if (h < hex[d]) {
                    hex[d] = h;
                    edge[d] = e;
                }
                uses.push_back({static_cast<int>(d), h, e});
            }
        }
    }
};

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
    CornerStars st(mesh, chunks);

    // Per vertex v: the quads whose smallest vertex is v, matched by their other three
    // vertices (neighbour loop or -1), and the owner of every edge whose smaller vertex is
    // v: the smallest hex with the edge, whose smaller quad through it is the edge's first
    // loop (bit 4 i + j of owned[h]: quad i, position j). Every hex edge (12 h + local edge)
    // gets a reference to its owner (32 owner hex + bit), so that the halfedges can then be
    // filled hex by hex in face order instead of per vertex again (scattered over memory).
    std::vector<int> nb(nLoops);
    std::vector<std::uint32_t> owned(nHex, 0);
    std::vector<std::uint32_t, DefaultInitAllocator<std::uint32_t>> ownerRef(12 * nHex);  // every entry written, no zeroing
    parallelChunks(nv, vChunks, [&](int c, std::size_t v0, std::size_t v1) {
        struct Quad {  // a loop and its other three vertices, sorted
            int loop, a, b, d;
        };
        std::vector<Quad> quads;
        VertexEdges edges;
        for (std::size_t v = v0; v < v1; ++v) {
            st.prefetch(mesh, v + kPrefetchAhead);
            quads.clear();
            for (int s = st.start[v]; s < st.start[v + 1]; ++s) {
                const int cr = st.corner[static_cast<std::size_t>(s)], h = cr / 8, k = cr % 8;
                const auto& hx = mesh.hexes[static_cast<std::size_t>(h)];
                for (const int i : kT.cornerFaces[k]) {
                    int q[3], n = 0;
                    bool smallest = true;
                    for (int j = 0; j < 4; ++j) {
                        const int w = hx[static_cast<std::size_t>(kOvmHexFaces[i][j])];
                        if (w == static_cast<int>(v)) continue;
                        if (w < static_cast<int>(v)) smallest = false;
                        q[n++] = w;
                    }
                    if (!smallest) continue;
                    std::sort(q, q + 3);
                    quads.push_back({6 * h + i, q[0], q[1], q[2]});
                }
            }
            // Equal vertex triples lie next to each other once sorted (insertion sort: few quads).
            const auto less = [](const Quad& p, const Quad& q) {
                return p.a != q.a ? p.a < q.a : p.b != q.b ? p.b < q.b : p.d < q.d;
            };
            for (std::size_t x = 1; x < quads.size(); ++x)
                for (std::size_t y = x; y > 0 && less(quads[y], quads[y - 1]); --y) std::swap(quads[y], quads[y - 1]);
            for (std::size_t x = 0; x < quads.size();) {
                std::size_t y = x + 1;
                while (y < quads.size() && !less(quads[x], quads[y])) ++y;
                if (y - x > 2) ok[static_cast<std::size_t>(c)] = 0;
                const bool pair = y - x == 2;
                nb[static_cast<std::size_t>(quads[x].loop)] = pair ? quads[x + 1].loop : -1;
                if (pair) nb[static_cast<std::size_t>(quads[x + 1].loop)] = quads[x].loop;
                x = y;
            }
            edges.collect(mesh, st, v);
            for (std::size_t d = 0; d < edges.other.size(); ++d) {
                const int e = edges.edge[d], bit = 4 * kT.edgeFaces[e][0] + firstPosition(e);
                __atomic_fetch_or(&owned[static_cast<std::size_t>(edges.hex[d])], 1u << bit, __ATOMIC_RELAXED);
                edges.edge[d] = bit;  // from here on: the owner's bit
            }
            for (const auto& use : edges.uses) {
                const std::size_t d = static_cast<std::size_t>(use.edgeIndex);
                ownerRef[12 * static_cast<std::size_t>(use.hex) + static_cast<std::size_t>(use.edge)] =
                    32u * static_cast<std::uint32_t>(edges.hex[d]) + static_cast<std::uint32_t>(edges.edge[d]);
            }
        }
    });
    if (!allOk()) return false;
    st.release();

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

    // Edges: numbered in order of their first loop and position (count, prefix, rank of the
    // owner bit); then hex by hex, every owner writes its edges and every first loop its
    // halfedges (looked up through the owner references).
    std::vector<int, DefaultInitAllocator<int>> edgeBase(nHex);  // per hex its first owned edge (< INT_MAX / 2, checked)
    parallelChunks(nHex, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        std::size_t n = 0;
        for (std::size_t h = h0; h < h1; ++h) n += static_cast<std::size_t>(bitCount(owned[h]));
        base[static_cast<std::size_t>(c)] = n;
    });
    const std::size_t nEdges = prefix(base);
    if (nEdges > static_cast<std::size_t>(INT_MAX / 2)) return false;
    parallelChunks(nHex, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        std::size_t n = base[static_cast<std::size_t>(c)];
        for (std::size_t h = h0; h < h1; ++h) {
            edgeBase[h] = static_cast<int>(n);
            n += static_cast<std::size_t>(bitCount(owned[h]));
        }
    });
    out.edges.resize(nEdges);
    IntLists& fh = out.faceHalfedges;
    fh.offsets.resize(nFaces + 1);
    fh.values.resize(4 * nFaces);
    parallelChunks(nFaces + 1, chunksFor(nFaces, threads), [&](int, std::size_t f0, std::size_t f1) {
        for (std::size_t f = f0; f < f1; ++f) fh.offsets[f] = 4 * f;
    });
    const auto edgeId = [&](std::size_t h, int bit) {
        return static_cast<std::size_t>(edgeBase[h]) + static_cast<std::size_t>(bitCount(owned[h] & ((1u << bit) - 1u)));
    };
    parallelChunks(nHex, chunks, [&](int, std::size_t h0, std::size_t h1) {
        for (std::size_t h = h0; h < h1; ++h) {
            for (std::uint32_t bits = owned[h]; bits != 0; bits &= bits - 1) {
                const int bit = __builtin_ctz(bits), i = bit / 4, j = bit % 4;
                const std::size_t l = 6 * h + static_cast<std::size_t>(i);
                out.edges[edgeId(h, bit)] = {{loopVertex(l, j), loopVertex(l, j + 1)}};
            }
            for (int i = 0; i < 6; ++i) {
                if (!(firstMask[h] >> i & 1u)) continue;
                const std::size_t l = 6 * h + static_cast<std::size_t>(i);
                int* values = &fh.values[2 * static_cast<std::size_t>(hf[l])];
                for (int j = 0; j < 4; ++j) {
                    const std::uint32_t ref = ownerRef[12 * h + static_cast<std::size_t>(kT.edgeAt[i][j])];
                    const std::size_t oh = ref / 32;
                    const int bit = static_cast<int>(ref % 32);
                    const int start = loopVertex(6 * oh + static_cast<std::size_t>(bit / 4), bit % 4);
                    values[j] = static_cast<int>(2 * edgeId(oh, bit)) + (loopVertex(l, j) == start ? 0 : 1);
                }
            }
        }
    });
    return true;
}

} // namespace HexEx
