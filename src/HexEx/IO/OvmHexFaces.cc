/// @file OvmHexFaces.cc
/// Face and edge numbering of all-hex OpenVolumeMesh models (OvmHexFaces.hh). Loop 6h + i is
/// quad i of hex h. One parallel pass over the vertices, each looking at the corners of the
/// hexes around it, matches the quads whose smallest vertex it is (the neighbour loop) and
/// finds the owner of every edge whose smaller vertex it is: the smallest hex with that edge,
/// whose smaller quad through it is the edge's first occurrence. A face's first loop is the
/// smaller of its loops; faces are numbered in order of first loops (count per chunk,
/// prefix, number), edges in order of first loop and position (the same), and a second pass
/// over the vertices writes every edge's halfedge into the first loops of its faces.

#include "OvmHexFaces.hh"

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

/// One hex edge seen from the smaller of its two vertices: the larger vertex, the hex, its local edge.
struct EdgeUse {
    int other;  ///< the larger vertex
    int hex;    ///< the hex
    int edge;   ///< its local edge (index into kEdges)
    /// Order by larger vertex, then hex.
    bool operator<(const EdgeUse& o) const { return other != o.other ? other < o.other : hex < o.hex; }
};

/// The corners (8 h + local index) around every vertex, in hex order.
struct CornerStars {
    std::vector<int> start;   ///< per vertex the first entry of corner (and the end)
    std::vector<int> corner;  ///< 8 h + local index, grouped by vertex
    /// Counting sort of the corners of @p mesh by vertex.
    explicit CornerStars(const HexMesh& mesh) : start(mesh.vertices.size() + 1, 0), corner(8 * mesh.hexes.size()) {
        for (const auto& hx : mesh.hexes)
            for (const int v : hx) ++start[static_cast<std::size_t>(v) + 1];
        for (std::size_t v = 0; v + 1 < start.size(); ++v) start[v + 1] += start[v];
        std::vector<int> fill(start.begin(), start.end() - 1);
        for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
            for (int k = 0; k < 8; ++k)
                corner[static_cast<std::size_t>(fill[static_cast<std::size_t>(mesh.hexes[h][static_cast<std::size_t>(k)])]++)] =
                    static_cast<int>(8 * h) + k;
    }
};

/// The hex edges whose smaller vertex is @p v, sorted by (larger vertex, hex): one run per edge.
void edgeUses(const HexMesh& mesh, const CornerStars& st, std::size_t v, std::vector<EdgeUse>& uses) {
    uses.clear();
    for (int s = st.start[v]; s < st.start[v + 1]; ++s) {
        const int c = st.corner[static_cast<std::size_t>(s)], h = c / 8, k = c % 8;
        const auto& hx = mesh.hexes[static_cast<std::size_t>(h)];
        for (const int m : kT.cornerNext[k]) {
            const int u = hx[static_cast<std::size_t>(m)];
            if (u > static_cast<int>(v)) uses.push_back({u, h, kT.edgeOf[k][m]});
        }
    }
    std::sort(uses.begin(), uses.end());
}

} // namespace

bool ovmHexFaces(const HexMesh& mesh, int threads, OvmFaces& out) {
    const std::size_t nHex = mesh.hexes.size(), nLoops = 6 * nHex, nv = mesh.vertices.size();
    if (!mesh.polyhedra.empty() || nHex > static_cast<std::size_t>(INT_MAX / 12)) return false;  // halffaces fit in int
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
    const CornerStars st(mesh);

    // Per vertex v: the quads whose smallest vertex is v, matched by their other three
    // vertices (neighbour loop or -1), and the owner of every edge whose smaller vertex is
    // v: the smallest hex with the edge, whose smaller quad through it is the edge's first
    // loop (bit 4 i + j of owned[h]: quad i, position j).
    std::vector<int> nb(nLoops);
    std::vector<std::uint32_t> owned(nHex, 0);
    parallelChunks(nv, vChunks, [&](int c, std::size_t v0, std::size_t v1) {
        struct Quad {  // a loop and its other three vertices, sorted
            int loop, a, b, d;
        };
        std::vector<Quad> quads;
        std::vector<EdgeUse> uses;
        for (std::size_t v = v0; v < v1; ++v) {
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
            for (std::size_t x = 0; x < quads.size(); ++x) {
                int found = -1, matches = 0;
                for (std::size_t y = 0; y < quads.size(); ++y)
                    if (y != x && quads[x].a == quads[y].a && quads[x].b == quads[y].b && quads[x].d == quads[y].d) {
                        found = quads[y].loop;
                        ++matches;
                    }
                if (matches > 1) ok[static_cast<std::size_t>(c)] = 0;
                nb[static_cast<std::size_t>(quads[x].loop)] = found;
            }
            edgeUses(mesh, st, v, uses);
            for (std::size_t r = 0; r < uses.size(); ++r) {
                if (r > 0 && uses[r].other == uses[r - 1].other) continue;
                const int e = uses[r].edge, i = kT.edgeFaces[e][0];
                int j = 0;
                while (kT.edgeAt[i][j] != e) ++j;
                __atomic_fetch_or(&owned[static_cast<std::size_t>(uses[r].hex)], 1u << (4 * i + j), __ATOMIC_RELAXED);
            }
        }
    });
    if (!allOk()) return false;

    // Faces: number the first loops (no neighbour or a later one) in loop order, then give
    // every second loop its halfface.
    const auto first = [&](std::size_t l) { return nb[l] < 0 || static_cast<std::size_t>(nb[l]) > l; };
    std::vector<std::size_t> base(static_cast<std::size_t>(chunks), 0);
    parallelChunks(nHex, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        std::size_t n = 0;
        for (std::size_t l = 6 * h0; l < 6 * h1; ++l) n += first(l);
        base[static_cast<std::size_t>(c)] = n;
    });
    const std::size_t nFaces = prefix(base);
    std::vector<int>& hf = out.halffaces;
    hf.resize(nLoops);
    std::vector<std::uint8_t> firstMask(nHex, 0);  // per hex: bit i if loop 6h + i is a first loop
    parallelChunks(nHex, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        std::size_t f = base[static_cast<std::size_t>(c)];
        for (std::size_t l = 6 * h0; l < 6 * h1; ++l)
            if (first(l)) {
                hf[l] = static_cast<int>(2 * f++);
                firstMask[l / 6] = static_cast<std::uint8_t>(firstMask[l / 6] | 1u << (l % 6));
            }
    });
    parallelChunks(nHex, chunks, [&](int, std::size_t h0, std::size_t h1) {
        for (std::size_t l = 6 * h0; l < 6 * h1; ++l) {
            if (first(l)) continue;
            const std::size_t s = static_cast<std::size_t>(nb[l]);
            // 0 if loop l runs like its first loop s at l's first vertex, 1 if against it.
            const int v0 = loopVertex(l, 0);
            int k = 0;
            while (k < 4 && loopVertex(s, k) != v0) ++k;
            hf[l] = hf[s] + (loopVertex(s, k + 1) == loopVertex(l, 1) ? 0 : 1);
        }
    });

    // Edges: numbered in order of their first loop and position (count, prefix, rank of the
    // owner bit); per vertex again, every edge writes its halfedge into the first loops of
    // all faces through it.
    std::vector<std::size_t> edgeBase(nHex + 1);
    parallelChunks(nHex, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        std::size_t n = 0;
        for (std::size_t h = h0; h < h1; ++h) n += static_cast<std::size_t>(__builtin_popcount(owned[h]));
        base[static_cast<std::size_t>(c)] = n;
    });
    const std::size_t nEdges = prefix(base);
    if (nEdges > static_cast<std::size_t>(INT_MAX / 2)) return false;
    parallelChunks(nHex, chunks, [&](int c, std::size_t h0, std::size_t h1) {
        std::size_t n = base[static_cast<std::size_t>(c)];
        for (std::size_t h = h0; h < h1; ++h) {
            edgeBase[h] = n;
            n += static_cast<std::size_t>(__builtin_popcount(owned[h]));
        }
    });
    out.edges.resize(nEdges);
    IntLists& fh = out.faceHalfedges;
    fh.offsets.resize(nFaces + 1);
    fh.values.resize(4 * nFaces);
    parallelChunks(nFaces + 1, chunksFor(nFaces, threads), [&](int, std::size_t f0, std::size_t f1) {
        for (std::size_t f = f0; f < f1; ++f) fh.offsets[f] = 4 * f;
    });
    parallelChunks(nv, vChunks, [&](int, std::size_t v0, std::size_t v1) {
        std::vector<EdgeUse> uses;
        for (std::size_t v = v0; v < v1; ++v) {
            edgeUses(mesh, st, v, uses);
            int he = 0, a = 0;
            for (std::size_t r = 0; r < uses.size(); ++r) {
                if (r == 0 || uses[r].other != uses[r - 1].other) {
                    const std::size_t h = static_cast<std::size_t>(uses[r].hex);
                    const int e = uses[r].edge, i = kT.edgeFaces[e][0];
                    int j = 0;
                    while (kT.edgeAt[i][j] != e) ++j;
                    const int bit = 4 * i + j;
                    const std::size_t id = edgeBase[h] + static_cast<std::size_t>(__builtin_popcount(owned[h] & ((1u << bit) - 1u)));
                    const std::size_t l = 6 * h + static_cast<std::size_t>(i);
                    a = loopVertex(l, j);
                    out.edges[id] = {{a, loopVertex(l, j + 1)}};
                    he = static_cast<int>(2 * id);
                }
                const int e2 = uses[r].edge;
                const std::uint8_t fm = firstMask[static_cast<std::size_t>(uses[r].hex)];
                for (const int i2 : kT.edgeFaces[e2]) {
                    if (!(fm >> i2 & 1u)) continue;
                    const std::size_t l2 = 6 * static_cast<std::size_t>(uses[r].hex) + static_cast<std::size_t>(i2);
                    int j2 = 0;
                    while (kT.edgeAt[i2][j2] != e2) ++j2;
                    fh.values[static_cast<std::size_t>(hf[l2]) * 2 + static_cast<std::size_t>(j2)] = he + (loopVertex(l2, j2) == a ? 0 : 1);
                }
            }
        }
    });
    return true;
}

} // namespace HexEx
