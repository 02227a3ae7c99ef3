/// @file AssembledMeshCheck.cc
/// Implementation of checkAssembledHexes(): counting sorts by vertex, small sorts per bucket;
/// the hex and quad passes in parallel chunks (quads as compact records, one per face); the
/// boundary's edges and corners radix-sorted by vertex and checked in chunks of vertices.

#include "AssembledMeshCheck.hh"

#include "../Core/BitCount.hh"
#include "../Core/DefaultInitAllocator.hh"
#include "../Core/Parallel.hh"
#include "../Mesh/HexMeshCheck.hh"
#include "../Mesh/HexFaceNeighbours.hh"

#include <algorithm>
#include <array>
#include <cstdint>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <utility>
#include <vector>

namespace HexEx {

namespace {

/// An item (a boundary edge or corner) under a vertex.
struct VertexItem {
    int vertex;  ///< the vertex it is grouped under
    long item;   ///< the item
};

/// Sorts @p items by vertex (all in [0, @p nv)), stably: a radix sort by 11 bits at a time
/// (as many passes as @p nv needs); @p scratch has the same size.
void sortByVertex(std::vector<VertexItem>& items, std::vector<VertexItem>& scratch, long nv) {
    constexpr int kBits = 11;
    constexpr std::size_t kBuckets = std::size_t(1) << kBits;
    int bits = 0;
    while (bits < 63 && (1L << bits) < nv) ++bits;
    std::vector<std::size_t> count(kBuckets);
    for (int shift = 0; shift < bits; shift += kBits) {
        std::fill(count.begin(), count.end(), 0);
        auto digit = [shift](const VertexItem& x) { return (static_cast<std::size_t>(x.vertex) >> shift) & (kBuckets - 1); };
        for (const VertexItem& x : items) ++count[digit(x)];
        std::size_t at = 0;
        for (std::size_t& c : count) {
            const std::size_t n = c;
            c = at;
            at += n;
        }
        for (const VertexItem& x : items) scratch[count[digit(x)]++] = x;
        items.swap(scratch);
    }
}

/// Fewer hexes than this are checked on one thread.
constexpr long kParallelHexes = 20000;

/// Largest number of chunks of hexes that count and file the quads (each has its own slot
/// per vertex: 4 or 8 bytes per vertex and chunk).
constexpr int kMaxSlotChunks = 4;

/// A quad of a valid hex, filed under its smallest vertex: the other three vertices in
/// increasing order and the quad item (face f of hex h is item 6h+f).
template <class Item>
struct QuadRecord {
    int k1, k2, k3;  ///< the vertices after the smallest, increasing
    Item item;       ///< 6h+f

    /// Order by the vertex set, then by item.
    bool operator<(const QuadRecord& o) const {
        if (k1 != o.k1) return k1 < o.k1;
        if (k2 != o.k2) return k2 < o.k2;
        if (k3 != o.k3) return k3 < o.k3;
        return item < o.item;
    }
    /// Same vertex set.
    bool sameQuad(const QuadRecord& o) const { return k1 == o.k1 && k2 == o.k2 && k3 == o.k3; }
};

/// What distinctQuads() finds.
struct QuadPass {
    long repeated_corner_hexes = 0;  ///< hexes with an out-of-range or repeated vertex index
    long quads = 0;                  ///< distinct quads of the valid hexes
    long boundary_quads = 0;         ///< of those, in exactly one hex
    long shared_by_more = 0;         ///< in three or more hexes
    std::vector<long> boundary;      ///< the items of the boundary quads, by smallest vertex, then vertex set
    long twin_faces_skipped = 0;     ///< twin faces not filed (their partner's record stands for them)
    long private_twin_pairs = 0;     ///< twin pairs not filed at all (four private vertices: one interior quad each)
    long twin_pairs_found = 0;       ///< filed twin faces whose partner face was found (neighbour table)
    bool neighbours_complete = true; ///< false if the neighbour table could not be filled
};

/// Faces of twin pairs (checkAssembledHexes()): the face of the pair in the first set is
/// filed as two occurrences of its quad, the one in the second set (its opposite face
/// number: 0-1, 2-4, 5-3) is not filed.
constexpr unsigned kTwinFiled = (1u << 1) | (1u << 3) | (1u << 4);
constexpr unsigned kTwinSkipped = (1u << 0) | (1u << 2) | (1u << 5);

/// Twin-face bits of the hexes (see checkAssembledHexes()); none if @p twins is null.
struct TwinFaces {
    const std::vector<unsigned char>* twins = nullptr;  ///< per hex from first on
    std::size_t first = 0;                              ///< the first hex with bits
    /// Per hex from first on its corner occurrences (ImplicitCells::cells), or null.
    const DefaultInitVector<std::array<int, 8>>* corners = nullptr;
    /// Per vertex one bit: set if the vertex is private (checkAssembledHexes()), or null.
    const std::vector<std::uint64_t>* private_vertices = nullptr;
    /// The twin bits of hex @p h.
    unsigned of(std::size_t h) const {
        return twins && h >= first && h - first < twins->size() ? (*twins)[h - first] : 0u;
    }
    /// True if vertex @p v is private.
    bool isPrivate(int v) const {
        const auto w = static_cast<std::size_t>(v) >> 6;
        return w < private_vertices->size() && (((*private_vertices)[w] >> (v & 63)) & 1u);
    }
    /// The faces of hex @p h (corners @p c) that are not filed: the twin faces of the second
    /// set (kTwinSkipped) and the twin faces of the first set (kTwinFiled) whose four vertices
    /// are private.
    unsigned unfiled(std::size_t h, const std::array<int, 8>& c) const;
    /// The face item 6h' + f' of the twin of filed face @p f (1, 3 or 4) of hex @p h, or -1 if
    /// it is not found. The cells are unit cells of boxes with corners c, c + X, c + X + Y,
    /// c + Y, c + Z, ... (Z = 1), in increasing corner 0: the neighbour across face 1 (+z), 3
    /// (+x), 4 (+y) is the cell whose corner 0 is corner 4, 1, 3 of this one, at most that
    /// many occurrences, hence cells, further on; its face 0, 5, 2 is the twin. @p hint is
    /// the cell index found last for this face (the next cell's partner is usually the next
    /// cell): tried first, then a binary search; updated. Needs corners (checked by the caller).
    long partner(std::size_t h, int f, std::size_t& hint) const {
        const auto& C = *corners;
        const std::size_t i = h - first;
        const int c0 = C[i][0];
        const int target = f == 1 ? C[i][4] : f == 3 ? C[i][1] : C[i][3];
        const int opposite = f == 1 ? 0 : f == 3 ? 5 : 2;
        if (target <= c0) return -1;
        // Corner 0 == target in (i, i + (target - c0)]: the hint's next cell, else a binary search.
        std::size_t lo = i + 1, hi = std::min(C.size(), i + 1 + static_cast<std::size_t>(target - c0));
        if (hint + 1 >= lo && hint + 1 < hi && C[hint + 1][0] == target) lo = hi = hint + 1;
        while (lo < hi) {
            const std::size_t mid = lo + (hi - lo) / 2;
            if (C[mid][0] < target) lo = mid + 1;
            else hi = mid;
        }
        if (lo >= C.size() || C[lo][0] != target || !(((*twins)[lo] >> opposite) & 1u)) return -1;
        hint = lo;
        return 6 * static_cast<long>(first + lo) + opposite;
    }
};

unsigned TwinFaces::unfiled(std::size_t h, const std::array<int, 8>& c) const {
    const unsigned t = of(h);
    unsigned r = t & kTwinSkipped;
    if (!private_vertices) return r;
    for (unsigned m = t & kTwinFiled; m != 0; m &= m - 1) {
        const int f = __builtin_ctz(m);
        const int* l = kHexFaces[f];
        if (isPrivate(c[l[0]]) && isPrivate(c[l[1]]) && isPrivate(c[l[2]]) && isPrivate(c[l[3]])) r |= 1u << f;
    }
    return r;
}

/// Bit of distinctQuads()' per-hex face bits: the hex is valid.
constexpr unsigned char kGoodHex = 0x80;

/// True if the eight corners @p c are distinct vertex indices in [0, @p nv).
inline bool distinctInRange(const std::array<int, 8>& c, long nv) {
#if defined(__SSE2__)
    if (nv <= static_cast<long>(INT32_MAX)) {
        // Every pair once: within each half by rotations 1 and 2, across by the four
        // rotations of the second half.
        const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(c.data()));
        const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(c.data() + 4));
        const __m128i b1 = _mm_shuffle_epi32(b, 0x39), b2 = _mm_shuffle_epi32(b, 0x4e), b3 = _mm_shuffle_epi32(b, 0x93);
        __m128i eq = _mm_or_si128(_mm_cmpeq_epi32(a, _mm_shuffle_epi32(a, 0x39)), _mm_cmpeq_epi32(a, _mm_shuffle_epi32(a, 0x4e)));
        eq = _mm_or_si128(eq, _mm_or_si128(_mm_cmpeq_epi32(b, b1), _mm_cmpeq_epi32(b, b2)));
        eq = _mm_or_si128(eq, _mm_or_si128(_mm_cmpeq_epi32(a, b), _mm_cmpeq_epi32(a, b1)));
        eq = _mm_or_si128(eq, _mm_or_si128(_mm_cmpeq_epi32(a, b2), _mm_cmpeq_epi32(a, b3)));
        const __m128i zero = _mm_setzero_si128(), last = _mm_set1_epi32(static_cast<int>(nv - 1));
        // Out of range: 0 > c or c > nv - 1.
        eq = _mm_or_si128(eq, _mm_or_si128(_mm_cmpgt_epi32(zero, a), _mm_cmpgt_epi32(zero, b)));
        eq = _mm_or_si128(eq, _mm_or_si128(_mm_cmpgt_epi32(a, last), _mm_cmpgt_epi32(b, last)));
        return _mm_movemask_epi8(eq) == 0;
    }
#endif
    for (int i = 0; i < 8; ++i) {
        if (c[static_cast<std::size_t>(i)] < 0 || c[static_cast<std::size_t>(i)] >= nv) return false;
        for (int j = 0; j < i; ++j)
            if (c[static_cast<std::size_t>(i)] == c[static_cast<std::size_t>(j)]) return false;
    }
    return true;
}

/// The four sorted vertices of face @p f of hex @p c.
inline std::array<int, 4> sortedFace(const std::array<int, 8>& c, int f) {
    const int* l = kHexFaces[f];
    int a = c[l[0]], b = c[l[1]], x = c[l[2]], y = c[l[3]];
    if (a > b) std::swap(a, b);
    if (x > y) std::swap(x, y);
    if (a > x) std::swap(a, x);
    if (b > y) std::swap(b, y);
    if (b > x) std::swap(b, x);
    return {{a, b, x, y}};
}

/// The hexes' validity and their quads, counted by vertex set. Passes on @p chunks threads:
/// hexes (validity, quads per smallest vertex), then per part of the vertices (one, or two on
/// large meshes) hexes again (each quad's record into its vertex's bucket, at slots counted
/// per chunk of hexes: no atomics) and vertices (each bucket sorted by vertex set and item).
/// Per-chunk results are joined in part and chunk order: the result does not depend on the
/// thread count.
/// With @p tw, twin pairs are filed once with two occurrences; if a hex has a repeated
/// corner it returns after the first pass (repeated_corner_hexes > 0, nothing else counted)
/// so that the caller runs it again without @p tw.
///
/// With @p nb (6 entries per hex) every face of a valid hex gets its neighbour face item, or -1
/// on the boundary (quads in more than two hexes: unspecified); a filed twin face and its
/// partner are paired by TwinFaces::partner() in a pass over the twin hexes. Whether every
/// face got an entry: QuadPass::neighbours_complete and twin_pairs_found against
/// twin_faces_skipped.
template <class Item>
QuadPass distinctQuads(const HexMesh& mesh, int chunks, const TwinFaces& tw, int* nb) {
    QuadPass r;
    const long nv = static_cast<long>(mesh.vertices.size());
    const long nh = static_cast<long>(mesh.hexes.size());
    const auto& H = mesh.hexes;
    // Per hex: kGoodHex if it is valid, and the bits of the faces it files (written for every hex).
    DefaultInitVector<unsigned char> filed(static_cast<std::size_t>(nh));
    // Per chunk of hexes its own count per vertex (no atomic increments); they become the
    // chunk's next free slot per vertex below, so the chunks fill their records without
    // atomics too (the records of a bucket in chunk order, then hex order). At most
    // kMaxSlotChunks such arrays, so that the memory does not grow with the thread count.
    const int hexChunks = std::min(chunks, kMaxSlotChunks);
    std::vector<long> repeated(static_cast<std::size_t>(hexChunks), 0), skippedTwins(static_cast<std::size_t>(hexChunks), 0),
        privatePairs(static_cast<std::size_t>(hexChunks), 0);
    std::vector<Item> start(static_cast<std::size_t>(nv) + 1, 0);
    std::vector<std::vector<Item>> slot(static_cast<std::size_t>(hexChunks));
    parallelChunks(static_cast<std::size_t>(nh), hexChunks, [&](int k, std::size_t h0, std::size_t h1) {
        std::vector<Item>& cnt = slot[static_cast<std::size_t>(k)];
        cnt.assign(static_cast<std::size_t>(nv), 0);
        for (std::size_t h = h0; h < h1; ++h) {
            const auto& c = H[h];
            if (!distinctInRange(c, nv)) {
                filed[h] = 0;
                ++repeated[static_cast<std::size_t>(k)];
                continue;
            }
            const unsigned skipped = tw.unfiled(h, c);
            filed[h] = static_cast<unsigned char>(kGoodHex | (~skipped & 63u));
            skippedTwins[static_cast<std::size_t>(k)] += bitCount32(skipped & kTwinSkipped);
            privatePairs[static_cast<std::size_t>(k)] += bitCount32(skipped & kTwinFiled);
            for (int f = 0; f < 6; ++f) {
                if ((skipped >> f) & 1) continue;
                const int* l = kHexFaces[f];
                const int v = std::min(std::min(c[l[0]], c[l[1]]), std::min(c[l[2]], c[l[3]]));
                ++cnt[static_cast<std::size_t>(v)];
            }
        }
    });
    for (const long n : repeated) r.repeated_corner_hexes += n;
    for (const long n : skippedTwins) r.twin_faces_skipped += n;
    for (const long n : privatePairs) r.private_twin_pairs += n;
    if (tw.twins && r.repeated_corner_hexes > 0) return r;
    // The twin pairs' neighbour entries, cell by cell (the partners of consecutive cells are
    // mostly consecutive): every filed twin face and its partner. The quad groups below leave
    // these entries alone (a filed twin face alone in its group is such a pair).
    if (nb && tw.twins) {
        const std::size_t nTwins = tw.corners && tw.corners->size() == tw.twins->size() ? tw.twins->size() : 0;
        if (nTwins != tw.twins->size()) r.neighbours_complete = false;
        std::vector<long> found(static_cast<std::size_t>(chunks), 0);
        std::vector<char> missed(static_cast<std::size_t>(chunks), 0);
        parallelChunks(nTwins, chunks, [&](int k, std::size_t b, std::size_t e) {
            std::size_t hint[6] = {b, b, b, b, b, b};
            for (std::size_t i = b; i < e; ++i) {
                const std::size_t h = tw.first + i;
                const unsigned filed = tw.of(h) & kTwinFiled;
                for (unsigned m = filed; m != 0; m &= m - 1) {
                    const int f = __builtin_ctz(m);
                    const long t = tw.partner(h, f, hint[f]);
                    if (t < 0) {
                        missed[static_cast<std::size_t>(k)] = 1;
                        continue;
                    }
                    nb[6 * h + static_cast<std::size_t>(f)] = static_cast<int>(t);
                    nb[static_cast<std::size_t>(t)] = static_cast<int>(6 * h + static_cast<std::size_t>(f));
                    ++found[static_cast<std::size_t>(k)];
                }
            }
        });
        for (const long n : found) r.twin_pairs_found += n;
        for (const char x : missed)
            if (x) r.neighbours_complete = false;
    }
    // Bucket starts, and each chunk's first slot in every bucket (counts turned into offsets).
    for (long v = 0; v < nv; ++v) {
        Item at = start[static_cast<std::size_t>(v)];
        for (std::vector<Item>& cnt : slot) {
            const Item n = cnt[static_cast<std::size_t>(v)];
            cnt[static_cast<std::size_t>(v)] = at;
            at += n;
        }
        start[static_cast<std::size_t>(v) + 1] = at;
    }
    // Records of the quads filed under vertices [vb[p], vb[p+1]) for part p: two parts of about
    // equal size on large meshes, so that the records take no more memory than the quad items
    // and their vertex keys did before.
    const std::size_t total = static_cast<std::size_t>(start.back());
    const int nParts = total > (std::size_t(1) << 20) ? 2 : 1;
    std::vector<long> vb(static_cast<std::size_t>(nParts) + 1, nv);
    vb[0] = 0;
    for (int p = 1; p < nParts; ++p)
        vb[static_cast<std::size_t>(p)] =
            std::lower_bound(start.begin(), start.end(), static_cast<Item>(total * static_cast<std::size_t>(p) / static_cast<std::size_t>(nParts))) -
            start.begin();
    std::size_t largest = 0;
    for (int p = 0; p < nParts; ++p)
        largest = std::max(largest, static_cast<std::size_t>(start[static_cast<std::size_t>(vb[static_cast<std::size_t>(p) + 1])] -
                                                             start[static_cast<std::size_t>(vb[static_cast<std::size_t>(p)])]));
    // Every record read is written first: sized without zeroing.
    DefaultInitVector<QuadRecord<Item>> rec(largest);
    // Per chunk of vertices: counts and the boundary quads in vertex order, concatenated in
    // chunk order (and part order).
    struct ChunkQuads {
        long quads = 0, boundary_quads = 0, shared_by_more = 0;
        std::vector<long> boundary;
    };
    std::vector<ChunkQuads> parts(static_cast<std::size_t>(chunks) * static_cast<std::size_t>(nParts));
    for (int p = 0; p < nParts; ++p) {
        const long lo = vb[static_cast<std::size_t>(p)], hi = vb[static_cast<std::size_t>(p) + 1];
        const Item offset = start[static_cast<std::size_t>(lo)];
        parallelChunks(static_cast<std::size_t>(nh), hexChunks, [&](int k, std::size_t h0, std::size_t h1) {
            Item* const next = slot[static_cast<std::size_t>(k)].data();
            for (std::size_t h = h0; h < h1; ++h) {
                for (unsigned m = filed[h] & 63u; m != 0; m &= m - 1) {
                    const auto& c = H[h];
                    const int f = __builtin_ctz(m);
                    const int* l = kHexFaces[f];
                    const int v = std::min(std::min(c[l[0]], c[l[1]]), std::min(c[l[2]], c[l[3]]));
                    if (v < lo || v >= hi) continue;
                    const std::array<int, 4> q = sortedFace(c, f);
                    rec[static_cast<std::size_t>(next[v]++ - offset)] = {q[1], q[2], q[3], static_cast<Item>(6 * h + static_cast<std::size_t>(f))};
                }
            }
        });
        parallelChunks(static_cast<std::size_t>(hi - lo), chunks, [&](int k, std::size_t v0, std::size_t v1) {
            ChunkQuads& part = parts[static_cast<std::size_t>(p) * static_cast<std::size_t>(chunks) + static_cast<std::size_t>(k)];
            for (std::size_t v = static_cast<std::size_t>(lo) + v0; v < static_cast<std::size_t>(lo) + v1; ++v) {
                QuadRecord<Item>* b = rec.data() + (start[v] - offset);
                QuadRecord<Item>* e = rec.data() + (start[v + 1] - offset);
                if (e - b <= 16) {  // buckets are small: insertion sort
                    for (QuadRecord<Item>* i = b + 1; i < e; ++i) {
                        const QuadRecord<Item> x = *i;
                        QuadRecord<Item>* j = i;
                        for (; j > b && x < *(j - 1); --j) *j = *(j - 1);
                        *j = x;
                    }
                } else {
                    std::sort(b, e);
                }
                // Occurrences of the quad: its records, a filed twin face counting twice.
                auto occurrences = [&](const QuadRecord<Item>& x) {
                    const auto item = static_cast<std::size_t>(x.item);
                    return 1 + ((tw.of(item / 6) & kTwinFiled) >> (item % 6) & 1);
                };
                for (QuadRecord<Item>* i = b; i < e;) {
                    QuadRecord<Item>* j = i + 1;
                    std::size_t n = tw.twins ? occurrences(*i) : 1;
                    for (; j < e && j->sameQuad(*i); ++j) n += tw.twins ? occurrences(*j) : 1;
                    ++part.quads;
                    if (n == 1) {
                        ++part.boundary_quads;
                        part.boundary.push_back(static_cast<long>(i->item));
                    } else if (n > 2) {
                        ++part.shared_by_more;
                    }
                    if (nb) {
                        // Each face item is written by the group of its quad only (a twin
                        // partner's face is not filed): no two chunks write one entry.
                        const auto a = static_cast<std::size_t>(i->item);
                        if (j - i == 2) {
                            const auto b = static_cast<std::size_t>(i[1].item);
                            nb[a] = static_cast<int>(b);
                            nb[b] = static_cast<int>(a);
                        } else if (j - i == 1 && n == 1) {
                            nb[a] = -1;
                        }  // a filed twin face alone (n == 2): written with its partner above
                    }
                    i = j;
                }
            }
        });
    }
    // A private twin pair is one interior quad, in no other hex (checkAssembledHexes()).
    r.quads += r.private_twin_pairs;
    for (auto& part : parts) {
        r.quads += part.quads;
        r.boundary_quads += part.boundary_quads;
        r.shared_by_more += part.shared_by_more;
        r.boundary.insert(r.boundary.end(), part.boundary.begin(), part.boundary.end());
        std::vector<long>().swap(part.boundary);
    }
    return r;
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

AssembledMeshCheck checkAssembledHexes(const HexMesh& mesh, int threads, const std::vector<unsigned char>* twin_faces,
                                       std::size_t first_twin_hex, HexFaceNeighbours* neighbours,
                                       const DefaultInitVector<std::array<int, 8>>* twin_corners,
                                       const std::vector<std::uint64_t>* private_vertices) {
    if (neighbours) *neighbours = HexFaceNeighbours{};
    AssembledMeshCheck r;
    const long nv = static_cast<long>(mesh.vertices.size());
    const long nh = static_cast<long>(mesh.hexes.size());
    const auto& H = mesh.hexes;
    if (nv == 0) {
        r.repeated_corner_hexes = nh;
        return r;
    }
    const int chunks = nh >= kParallelHexes ? std::max(1, threads) : 1;
    // Quad items: face f of hex h is item 6h+f; a 32-bit item index when it fits.
    // The neighbour table (int entries), every entry written by the quad pass; none if a
    // twin face could not be paired (no corners given).
    const bool wantTable = neighbours && 6 * nh <= static_cast<long>(INT32_MAX) && (!twin_faces || twin_corners);
    DefaultInitVector<int> table(wantTable ? static_cast<std::size_t>(6 * nh) : 0);
    int* const nb = wantTable ? table.data() : nullptr;
    auto quadPass = [&](const TwinFaces& tw) {
        return 6 * nh <= static_cast<long>(UINT32_MAX) ? distinctQuads<std::uint32_t>(mesh, chunks, tw, nb) : distinctQuads<long>(mesh, chunks, tw, nb);
    };
    QuadPass pass = quadPass(TwinFaces{twin_faces, first_twin_hex, twin_corners, twin_faces ? private_vertices : nullptr});
    // A hex with a repeated corner breaks the twin pairs' premise (both hexes counted):
    // the whole pass again without them.
    if (twin_faces && pass.repeated_corner_hexes > 0) pass = quadPass(TwinFaces{});
    // The table is complete if every hex is valid, no quad is in more than two hexes and every
    // twin face not filed was paired by its partner's record (each pairing writes one).
    if (wantTable && pass.repeated_corner_hexes == 0 && pass.shared_by_more == 0 && pass.neighbours_complete &&
        pass.twin_pairs_found == pass.twin_faces_skipped) {
        neighbours->items = std::move(table);
        neighbours->digest = hexMeshDigest(mesh, threads);
    }
    DefaultInitVector<int>().swap(table);
    r.repeated_corner_hexes = pass.repeated_corner_hexes;
    r.quads = pass.quads;
    r.boundary_quads = pass.boundary_quads;
    r.quads_shared_by_more_than_two = pass.shared_by_more;
    const std::vector<long>& boundary = pass.boundary;  // quad items in exactly one hex

    // Boundary edges (item 4b+i: edge i of boundary quad b) grouped by their smaller vertex,
    // and boundary corners (item 4b+i: corner i of b) by their vertex: only the boundary's
    // items are sorted (by vertex), no array per vertex of the mesh.
    auto loopVertex = [&](long b, int i) {
        const long q = boundary[static_cast<std::size_t>(b)];
        return H[static_cast<std::size_t>(q / 6)][kHexFaces[q % 6][i & 3]];
    };
    const long ne = 4 * static_cast<long>(boundary.size());
    std::vector<VertexItem> items(static_cast<std::size_t>(ne)), scratch(static_cast<std::size_t>(ne));
    // Per chunk of the sorted items (cut at group starts) a count, summed in chunk order;
    // perGroup(first, end, others, parent) gets the chunk's scratch vectors.
    const int itemChunks = ne >= 65536 ? chunks : 1;
    auto sumOverGroups = [&](auto perGroup) {
        std::vector<long> perChunk(static_cast<std::size_t>(itemChunks), 0);
        parallelChunks(items.size(), itemChunks, [&](int k, std::size_t b, std::size_t e) {
            std::vector<int> others, parent;
            auto sameGroup = [&](std::size_t x) { return x > 0 && x < items.size() && items[x].vertex == items[x - 1].vertex; };
            while (sameGroup(b)) ++b;  // the group was started by the chunk before
            while (sameGroup(e)) ++e;  // finish the last group
            for (std::size_t g = b; g < e;) {
                std::size_t h = g + 1;
                while (h < e && items[h].vertex == items[g].vertex) ++h;
                perChunk[static_cast<std::size_t>(k)] += perGroup(g, h, others, parent);
                g = h;
            }
        });
        long n = 0;
        for (const long x : perChunk) n += x;
        return n;
    };

    // Edges: per smaller vertex, each larger end must come exactly twice.
    for (long e = 0; e < ne; ++e)
        items[static_cast<std::size_t>(e)] = {std::min(loopVertex(e / 4, static_cast<int>(e % 4)), loopVertex(e / 4, static_cast<int>(e % 4) + 1)), e};
    sortByVertex(items, scratch, nv);
    r.nonmanifold_boundary_edges = sumOverGroups([&](std::size_t g, std::size_t h, std::vector<int>& others, std::vector<int>&) {
        others.clear();
        for (std::size_t i = g; i < h; ++i) {
            const long e = items[i].item;
            others.push_back(std::max(loopVertex(e / 4, static_cast<int>(e % 4)), loopVertex(e / 4, static_cast<int>(e % 4) + 1)));
        }
        std::sort(others.begin(), others.end());
        long bad = 0;
        for (std::size_t i = 0; i < others.size();) {
            std::size_t j = i + 1;
            while (j < others.size() && others[j] == others[i]) ++j;
            if (j - i != 2) ++bad;
            i = j;
        }
        return bad;
    });

    // Fans: the corners at v link its two neighbours in the quad; one fan iff connected.
    for (long c = 0; c < ne; ++c) items[static_cast<std::size_t>(c)] = {loopVertex(c / 4, static_cast<int>(c % 4)), c};
    sortByVertex(items, scratch, nv);
    r.nonmanifold_boundary_vertices = sumOverGroups([&](std::size_t g, std::size_t h, std::vector<int>& others, std::vector<int>& parent) -> long {
        others.clear();
        for (std::size_t i = g; i < h; ++i) {
            const long c = items[i].item;
            others.push_back(loopVertex(c / 4, static_cast<int>(c % 4) + 3));
            others.push_back(loopVertex(c / 4, static_cast<int>(c % 4) + 1));
        }
        std::sort(others.begin(), others.end());
        others.erase(std::unique(others.begin(), others.end()), others.end());
        parent.resize(others.size());
        for (std::size_t q = 0; q < parent.size(); ++q) parent[q] = static_cast<int>(q);
        auto find = [&](int x) {
            while (parent[static_cast<std::size_t>(x)] != x) x = parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
            return x;
        };
        auto local = [&](int u) { return static_cast<int>(std::lower_bound(others.begin(), others.end(), u) - others.begin()); };
        long components = static_cast<long>(others.size());
        for (std::size_t i = g; i < h; ++i) {
            const long c = items[i].item;
            const int x = find(local(loopVertex(c / 4, static_cast<int>(c % 4) + 3)));
            const int y = find(local(loopVertex(c / 4, static_cast<int>(c % 4) + 1)));
            if (x != y) {
                parent[static_cast<std::size_t>(x)] = y;
                --components;
            }
        }
        return components > 1 ? 1 : 0;
    });
    return r;
}

} // namespace HexEx
