/// @file OvmFaces.cc
/// Face and edge numbering of OpenVolumeMesh models (OvmFaces.hh). Items (halfface loops,
/// then edge occurrences) are bucketed by their smallest vertex with a counting sort that
/// copies each item's data next to the others of its bucket, so a bucket is compared in
/// one piece of memory. Buckets are small in a mesh: the first equal item is found by
/// comparing within a bucket (by sorting when it is large). Buckets are independent and
/// split among the threads; the numbering is one sequential pass in item order.

#include "OvmFaces.hh"

#include "../Core/Parallel.hh"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace HexEx {

namespace {

/// Buckets larger than this are sorted instead of compared pairwise.
constexpr std::size_t kPairwiseLimit = 32;
/// Fewer items than this are handled on one thread.
constexpr std::size_t kParallelItems = 200000;

/// Prefix sums of @p counts in place (counts[b] becomes the start of bucket b); @return the total.
std::size_t prefixSums(std::vector<std::size_t>& counts) {
    std::size_t sum = 0;
    for (auto& c : counts) {
        const std::size_t n = c;
        c = sum;
        sum += n;
    }
    return sum;
}

/// Sets first[i] for the @p n items of one bucket (in increasing item order, ids @p ids):
/// the first item of the bucket equal to item i (i itself if none), and flip[i] = dir(that, i).
/// same/less compare bucket positions; less is a strict weak order consistent with same.
template <class Same, class Less, class Dir>
void firstInBucket(const int* ids, std::size_t n, DefaultInitVector<int>& first, std::vector<std::uint8_t>& flip,
                   std::vector<std::size_t>& scratch, Same same, Less less, Dir dir) {
    if (n <= kPairwiseLimit) {
        std::size_t reps[kPairwiseLimit];  // positions of the bucket's first items
        std::size_t nReps = 0;
        for (std::size_t j = 0; j < n; ++j) {
            const std::size_t i = static_cast<std::size_t>(ids[j]);
            first[i] = ids[j];
            for (std::size_t r = 0; r < nReps; ++r)
                if (same(reps[r], j)) {
                    first[i] = ids[reps[r]];
                    flip[i] = dir(reps[r], j);
                    break;
                }
            if (first[i] == ids[j]) reps[nReps++] = j;
        }
        return;
    }
    scratch.resize(n);
    for (std::size_t j = 0; j < n; ++j) scratch[j] = j;
    std::sort(scratch.begin(), scratch.end(), [&](std::size_t x, std::size_t y) { return less(x, y) || (!less(y, x) && x < y); });
    for (std::size_t j = 0; j < n;) {
        const std::size_t head = scratch[j];
        first[static_cast<std::size_t>(ids[head])] = ids[head];
        std::size_t k = j + 1;
        for (; k < n && same(head, scratch[k]); ++k) {
            first[static_cast<std::size_t>(ids[scratch[k]])] = ids[head];
            flip[static_cast<std::size_t>(ids[scratch[k]])] = dir(head, scratch[k]);
        }
        j = k;
    }
}

/// Loops bucketed by their smallest vertex, each copied next to the others of its bucket.
struct LoopBuckets {
    std::vector<std::size_t> itemStart, valueStart;  // per bucket (and the end)
    std::vector<int> ids;                            // per position the loop
    std::vector<int> values;                         // the copied loops, in position order

    LoopBuckets(const IntLists& loops, int nVertices) {
        const std::size_t nb = static_cast<std::size_t>(nVertices);
        itemStart.assign(nb + 1, 0);
        valueStart.assign(nb + 1, 0);
        const auto low = [&](std::size_t i) { return static_cast<std::size_t>(*std::min_element(loops.begin(i), loops.end(i))); };
        for (std::size_t i = 0; i < loops.size(); ++i) {
            const std::size_t b = low(i);
            ++itemStart[b];
            valueStart[b] += loops.length(i);
        }
        ids.resize(prefixSums(itemStart));
        values.resize(prefixSums(valueStart));
        std::vector<std::size_t> fillItem(itemStart.begin(), itemStart.end() - 1), fillValue(valueStart.begin(), valueStart.end() - 1);
        for (std::size_t i = 0; i < loops.size(); ++i) {
            const std::size_t b = low(i);
            ids[fillItem[b]++] = static_cast<int>(i);
            std::copy(loops.begin(i), loops.end(i), values.begin() + static_cast<std::ptrdiff_t>(fillValue[b]));
            fillValue[b] += loops.length(i);
        }
    }
};

/// Finds the first equal loop of every loop (same vertex multiset) and its direction.
void firstLoops(const IntLists& loops, int nVertices, int threads, DefaultInitVector<int>& first, std::vector<std::uint8_t>& flip) {
    const LoopBuckets lb(loops, nVertices);
    const std::size_t nb = static_cast<std::size_t>(nVertices);
    parallelChunks(nb, loops.size() >= kParallelItems ? threads : 1, [&](int, std::size_t b0, std::size_t b1) {
        std::vector<std::size_t> start, scratch;
        std::vector<int> sorted;
        for (std::size_t b = b0; b < b1; ++b) {
            const std::size_t p0 = lb.itemStart[b], n = lb.itemStart[b + 1] - p0;
            if (n == 0) continue;
            const int* vals = lb.values.data() + lb.valueStart[b];
            start.resize(n + 1);
            start[0] = 0;
            for (std::size_t j = 0; j < n; ++j)
                start[j + 1] = start[j] + loops.length(static_cast<std::size_t>(lb.ids[p0 + j]));
            sorted.assign(vals, vals + start[n]);
            for (std::size_t j = 0; j < n; ++j)
                std::sort(sorted.begin() + static_cast<std::ptrdiff_t>(start[j]), sorted.begin() + static_cast<std::ptrdiff_t>(start[j + 1]));
            const auto len = [&](std::size_t j) { return start[j + 1] - start[j]; };
            const auto same = [&](std::size_t x, std::size_t y) {
                return len(x) == len(y) && std::equal(&sorted[start[x]], &sorted[start[x]] + len(x), &sorted[start[y]]);
            };
            const auto less = [&](std::size_t x, std::size_t y) {
                if (len(x) != len(y)) return len(x) < len(y);
                return std::lexicographical_compare(&sorted[start[x]], &sorted[start[x]] + len(x), &sorted[start[y]],
                                                    &sorted[start[y]] + len(y));
            };
            // 0 if loop y runs like loop x at y's first vertex, 1 if against it.
            const auto dir = [&](std::size_t x, std::size_t y) -> std::uint8_t {
                const int* s = vals + start[x];
                const int* l = vals + start[y];
                const std::size_t m = len(x);
                const std::size_t k = static_cast<std::size_t>(std::find(s, s + m, l[0]) - s);
                return s[(k + 1) % m] == l[1 % m] ? 0 : 1;
            };
            firstInBucket(lb.ids.data() + p0, n, first, flip, scratch, same, less, dir);
        }
    });
}

/// Finds the first equal occurrence of every edge occurrence of @p faces (a face = a loop of
/// @p loops given by @p faceLoop, occurrence offsets[f] + j = its j-th vertex pair) and
/// whether it runs the other way.
void firstEdges(const IntLists& loops, const std::vector<int>& faceLoop, const DefaultInitVector<std::size_t>& offsets,
                int nVertices, int threads, DefaultInitVector<int>& first, std::vector<std::uint8_t>& flip) {
    const std::size_t nb = static_cast<std::size_t>(nVertices);
    // Entry: (larger vertex << 1 | runs downward) << 32 | occurrence, bucketed by the smaller vertex.
    std::vector<std::size_t> start(nb + 1, 0);
    const auto forEach = [&](auto&& body) {
        for (std::size_t f = 0; f < faceLoop.size(); ++f) {
            const int* l = loops.begin(static_cast<std::size_t>(faceLoop[f]));
            const std::size_t len = offsets[f + 1] - offsets[f];
            for (std::size_t j = 0; j < len; ++j) body(offsets[f] + j, l[j], l[(j + 1) % len]);
        }
    };
    forEach([&](std::size_t, int a, int b) { ++start[static_cast<std::size_t>(std::min(a, b))]; });
    std::vector<std::uint64_t> entries(prefixSums(start));
    {
        std::vector<std::size_t> fill(start.begin(), start.end() - 1);
        forEach([&](std::size_t o, int a, int b) {
            const std::uint64_t key = static_cast<std::uint64_t>(std::max(a, b)) << 1 | (a > b ? 1u : 0u);
            entries[fill[static_cast<std::size_t>(std::min(a, b))]++] = key << 32 | static_cast<std::uint32_t>(o);
        });
    }
    parallelChunks(nb, entries.size() >= kParallelItems ? threads : 1, [&](int, std::size_t b0, std::size_t b1) {
        std::vector<int> ids;
        std::vector<std::size_t> scratch;
        for (std::size_t b = b0; b < b1; ++b) {
            const std::uint64_t* e = entries.data() + start[b];
            const std::size_t n = start[b + 1] - start[b];
            ids.resize(n);
            for (std::size_t j = 0; j < n; ++j) ids[j] = static_cast<int>(e[j] & 0xffffffffu);
            const auto same = [&](std::size_t x, std::size_t y) { return (e[x] >> 33) == (e[y] >> 33); };
            const auto less = [&](std::size_t x, std::size_t y) { return (e[x] >> 33) < (e[y] >> 33); };
            const auto dir = [&](std::size_t x, std::size_t y) -> std::uint8_t { return ((e[x] ^ e[y]) >> 32) & 1u; };
            firstInBucket(ids.data(), n, first, flip, scratch, same, less, dir);
        }
    });
}

} // namespace

OvmFaces buildOvmFaces(const IntLists& loops, int nVertices, int threads) {
    threads = std::max(1, threads);
    const std::size_t n = loops.size();
    if (n > static_cast<std::size_t>(INT_MAX / 2) || loops.values.size() > static_cast<std::size_t>(INT_MAX))
        throw std::invalid_argument("buildOvmFaces: too many faces (" + std::to_string(n) + " loops, " +
                                    std::to_string(loops.values.size()) + " entries)");
    for (std::size_t i = 0; i < n; ++i)
        if (loops.length(i) == 0) throw std::invalid_argument("buildOvmFaces: loop " + std::to_string(i) + " is empty");
    for (const int v : loops.values)
        if (v < 0 || v >= nVertices)
            throw std::invalid_argument("buildOvmFaces: vertex " + std::to_string(v) + " out of range [0, " +
                                        std::to_string(nVertices) + ")");
    OvmFaces out;
    // Faces: number the loops' faces in order of first use; key[i] becomes the halfface of loop i.
    DefaultInitVector<int> key(n, 0);
    std::vector<std::uint8_t> flip(n, 0);
    firstLoops(loops, nVertices, threads, key, flip);
    std::vector<int> faceLoop;  // per face its first loop
    for (std::size_t i = 0; i < n; ++i) {
        const int r = key[i];
        if (r == static_cast<int>(i)) {
            key[i] = 2 * static_cast<int>(faceLoop.size());
            faceLoop.push_back(r);
        } else {
            key[i] = key[static_cast<std::size_t>(r)] + flip[i];
        }
    }
    out.halffaces = std::move(key);

    // Edges: every consecutive vertex pair of every face, in face order.
    const std::size_t nf = faceLoop.size();
    IntLists& fh = out.faceHalfedges;
    fh.offsets.resize(nf + 1);
    fh.offsets[0] = 0;
    for (std::size_t f = 0; f < nf; ++f) fh.offsets[f + 1] = fh.offsets[f] + loops.length(static_cast<std::size_t>(faceLoop[f]));
    const std::size_t no = fh.offsets[nf];
    DefaultInitVector<int> he(no, 0);
    flip.assign(no, 0);
    firstEdges(loops, faceLoop, fh.offsets, nVertices, threads, he, flip);
    // Number the edges in order of first use; he[o] becomes the halfedge of occurrence o.
    for (std::size_t f = 0; f < nf; ++f) {
        const int* l = loops.begin(static_cast<std::size_t>(faceLoop[f]));
        const std::size_t len = fh.length(f);
        for (std::size_t j = 0; j < len; ++j) {
            const std::size_t o = fh.offsets[f] + j;
            const int r = he[o];
            if (r == static_cast<int>(o)) {
                he[o] = 2 * static_cast<int>(out.edges.size());
                out.edges.push_back({{l[j], l[(j + 1) % len]}});
            } else {
                he[o] = he[static_cast<std::size_t>(r)] + flip[o];
            }
        }
    }
    fh.values = std::move(he);
    return out;
}

} // namespace HexEx
