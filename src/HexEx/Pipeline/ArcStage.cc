#include "ArcStage.hh"

#include "../Core/HugePages.hh"
#include "../Core/Parallel.hh"
#include "../Core/Prefetch.hh"
#include "HexElementNumbering.hh"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <optional>

namespace HexEx {

namespace {

/// A patch whose signed parametric area differs from 1 by more than this is incomplete.
constexpr double kAreaTolerance = 1e-9;

/// Local cube coordinates of the 8 hex corners (VTK order).
constexpr int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

int cornerAt(const int c[3]) {
    for (int k = 0; k < 8; ++k)
        if (kCorner[k][0] == c[0] && kCorner[k][1] == c[1] && kCorner[k][2] == c[2]) return k;
    return -1;
}

/// The corner reached from corner @p c along local direction @p d (-1 outside the cube).
int cornerAlong(int c, AxisDir d) {
    int x[3] = {kCorner[c][0], kCorner[c][1], kCorner[c][2]};
    x[dirAxis(d)] += dirSign(d);
    return cornerAt(x);
}

/// Local direction from corner @p a to the adjacent corner @p b.
AxisDir localDir(int a, int b) {
    for (int k = 0; k < 3; ++k)
        if (kCorner[a][k] != kCorner[b][k]) return makeDir(k, kCorner[b][k] - kCorner[a][k]);
    return 0;
}

/// Local direction into the cube along axis @p k at corner @p c.
AxisDir inward(int c, int k) { return makeDir(k, kCorner[c][k] == 0 ? 1 : -1); }

/// Where walks start in one hex: from the darts of an explicit hex, or from the one tet of
/// an implicit cell.
class HexStarts {
public:
    HexStarts(const ArcInput& in, std::size_t h) {
        const std::size_t nExplicit = in.hex_darts ? in.hex_darts->size() : 0;
        if (h < nExplicit) {
            explicit_ = true;
            in_ = &in;
            std::fill(&table_[0][0][0], &table_[0][0][0] + 8 * 6 * 6, -1);
            std::fill(met_, met_ + kSlots, -1);
            push({(*in.hex_darts)[h], 0, {makeDir(0, 1), makeDir(1, 1), makeDir(2, 1)}});
            return;
        }
        // Implicit cell: all corners are occurrences in one tet, whose chart gives the frame.
        if (!in.implicit || h - nExplicit >= in.implicit->cells.size()) return;  // no starts (tet_ stays -1)
        const auto& cell = in.implicit->cells[h - nExplicit];
        for (int c = 0; c < 8; ++c) in.darts->occurrencePoint(cell[static_cast<std::size_t>(c)], tet_, z_[c]);
        for (int k = 0; k < 3; ++k) {
            const Vec3i step = z_[k == 0 ? 1 : k == 1 ? 3 : 4] - z_[0];
            for (int a = 0; a < 3; ++a)
                if (step[a] != 0) axis_[k] = makeDir(a, step[a]);
        }
    }

    /// The start at corner @p c with frame (d0, d1, d2) (local directions); tet -1 if the hex
    /// has no such dart.
    ArcStart at(int c, AxisDir d0, AxisDir d1, AxisDir d2) {
        if (explicit_) return fromMapDart(*in_, mapDart(c, d0, d1));
        ArcStart s;
        auto img = [&](AxisDir d) { return dirSign(d) > 0 ? axis_[dirAxis(d)] : dirNeg(axis_[dirAxis(d)]); };
        s.tet = tet_;
        s.z = z_[c];
        s.d = {img(d0), img(d1), img(d2)};
        return s;
    }

    /// True for a hex built from darts (else an implicit cell).
    bool isExplicit() const { return explicit_; }

    /// Explicit hex: the map dart at corner @p c with frame (d0, d1, ...), -1 if none.
    int mapDart(int c, AxisDir d0, AxisDir d1) {
        // Walk on only as far as needed: most hexes need a few of their 48 darts.
        while (table_[c][d0][d1] < 0 && popped_ < n_) expand(todo_[popped_++]);
        return table_[c][d0][d1];
    }

    /// The start given by map dart @p md (tet -1 if md < 0): its extracted dart.
    static ArcStart fromMapDart(const ArcInput& in, int md) {
        ArcStart s;
        if (md < 0) return s;
        const Dart& D = in.darts->darts[static_cast<std::size_t>((*in.map_dart_origin)[static_cast<std::size_t>(md)])];
        s.tet = D.tet;
        s.z = D.z;
        s.d = D.d;
        return s;
    }

private:
    // The darts of an explicit hex get their local (corner, frame) by a breadth-first walk
    // over alpha_0..alpha_2 from the hex's dart at corner 0 with frame (+x, +y, +z); a state
    // keeps the first dart that reaches it. The walk runs lazily (see at()): stopping
    // early does not change what it has assigned, as the order of the walk is fixed.
    struct State {
        int dart, corner;
        std::array<AxisDir, 3> d;
    };
    static constexpr int kCellDarts = 48;  ///< darts of a hex cell
    static constexpr unsigned kSlots = 128;  ///< size of the set of darts met (power of 2)

    /// Slot of dart @p d in the set of darts met, or the empty slot where it goes.
    int& metSlot(int d) {
        unsigned i = (static_cast<unsigned>(d) * 2654435761u) >> 25;
        while (met_[i] != d && met_[i] >= 0) i = (i + 1) & (kSlots - 1);
        return met_[i];
    }

    void push(const State& x) {
        todo_[n_++] = x;
        metSlot(x.dart) = x.dart;
        int& slot = table_[x.corner][x.d[0]][x.d[1]];
        if (slot < 0) slot = x.dart;
        prefetch(&in_->map->links()[static_cast<std::size_t>(x.dart)]);  // its links are read when it is expanded
    }

    /// Queues the unmet darts linked to @p s by alpha_0, alpha_1, alpha_2.
    void expand(const State& s) {
        const auto& L = in_->map->links();
        for (int i = 0; i < 3 && n_ < kCellDarts; ++i) {
            State x = s;
            x.dart = L[static_cast<std::size_t>(s.dart)][i];
            if (x.dart < 0 || metSlot(x.dart) == x.dart) continue;
            if (i == 0) {
                x.corner = cornerAlong(s.corner, s.d[0]);
                if (x.corner < 0) continue;
                x.d[0] = dirNeg(s.d[0]);
            } else {
                std::swap(x.d[i - 1], x.d[i]);
            }
            push(x);
        }
    }

    State todo_[kCellDarts];
    int n_ = 0, popped_ = 0;
    int met_[kSlots];

    bool explicit_ = false;
    const ArcInput* in_ = nullptr;
    int table_[8][6][6];
    int tet_ = -1;
    Vec3i z_[8];
    AxisDir axis_[3] = {0, 2, 4};
};

/// Results of one block of hexes, in order: sizes per owned edge and face, and the points
/// and triangles (triangle indices relative to the block's first patch point).
struct BlockResult {
    std::vector<std::size_t> arc_size;  ///< points per owned edge (0 = failed)
    std::vector<Vec3d> arc_points;
    std::vector<std::size_t> patch_size;  ///< triangles per owned face (0 = failed)
    std::vector<std::array<int, 3>> triangles;
    std::vector<Vec3d> patch_points;
    bool done = false;  ///< traced, not yet appended to the output

    void clear() {
        arc_size.clear();
        arc_points.clear();
        patch_size.clear();
        triangles.clear();
        patch_points.clear();
        done = false;
    }
};

/// Working memory of one thread, reused for all its hexes.
struct TraceScratch {
    std::vector<int> startDarts;  ///< map darts of the first starts of a block's explicit hexes
    std::vector<ArcStart> from;  ///< starts of one face's flood
    PatchScratch patch;          ///< the floods' working memory
};

/// Local start of the arc of hex edge @p k: its first corner, the direction along it, and
/// the two inward directions in the preferred (first) and the other order.
struct EdgeStartState {
    int corner;
    AxisDir d0, d1, d2;
};
EdgeStartState edgeStartState(int k) {
    const int ca = HexArcs::kHexEdges[k][0], cb = HexArcs::kHexEdges[k][1];
    const AxisDir d0 = localDir(ca, cb);
    const int a1 = (dirAxis(d0) + 1) % 3, a2 = (dirAxis(d0) + 2) % 3;
    return {ca, d0, inward(ca, a1), inward(ca, a2)};
}

/// Local start of the patch of hex face @p k from its loop corner @p i: the corner, d0
/// towards the next corner of the loop, d1 towards the previous one, d2 into the hex.
EdgeStartState faceStartState(int k, int i) {
    const int* q = HexArcs::kHexFaces[k];
    const int c = q[i], n = q[(i + 1) % 4], p = q[(i + 3) % 4];
    const AxisDir d0 = localDir(c, n), d1 = localDir(c, p);
    return {c, d0, d1, inward(c, 3 - dirAxis(d0) - dirAxis(d1))};
}

/// Traces the edges and faces owned by hexes [hb, he) into @p R (appending). @p e0 and
/// @p f0 are the first edge and face ids owned by a hex >= hb.
void traceBlock(const ArcInput& in, const HexElementOwners& edgeOwner, const HexElementOwners& faceOwner,
                std::size_t hb, std::size_t he, std::size_t e0, std::size_t f0, TraceScratch& S, BlockResult& R) {
    const std::size_t nExplicit = in.hex_darts ? in.hex_darts->size() : 0;
    auto owns = [&](std::size_t h, std::size_t e, std::size_t f) {
        return (e < edgeOwner.size() && edgeOwner[e].first == static_cast<int>(h)) ||
               (f < faceOwner.size() && faceOwner[f].first == static_cast<int>(h));
    };
    // Pass 1: the map darts the walks of the block's explicit hexes start from (the first
    // choice of each edge, corner 0 of each face's loop). Their extracted darts are two
    // dependent memory reads away: ask for all of them early (pass 2), use them in pass 3.
    S.startDarts.clear();
    std::size_t e = e0, f = f0;
    for (std::size_t h = hb; h < he && h < nExplicit; ++h) {
        if (!owns(h, e, f)) continue;
        HexStarts starts(in, h);
        for (; e < edgeOwner.size() && edgeOwner[e].first == static_cast<int>(h); ++e) {
            const EdgeStartState st = edgeStartState(edgeOwner[e].second);
            S.startDarts.push_back(starts.mapDart(st.corner, st.d0, st.d1));
        }
        for (; f < faceOwner.size() && faceOwner[f].first == static_cast<int>(h); ++f) {
            const EdgeStartState st = faceStartState(faceOwner[f].second, 0);
            S.startDarts.push_back(starts.mapDart(st.corner, st.d0, st.d1));
        }
        if (h + 1 < nExplicit) prefetch(&in.map->links()[static_cast<std::size_t>((*in.hex_darts)[h + 1])]);
    }
    for (int md : S.startDarts)
        if (md >= 0) prefetch(&(*in.map_dart_origin)[static_cast<std::size_t>(md)]);
    for (int md : S.startDarts)
        if (md >= 0) prefetch(&in.darts->darts[static_cast<std::size_t>((*in.map_dart_origin)[static_cast<std::size_t>(md)])]);
    // Pass 3: the walks.
    std::size_t next = 0;  // next entry of S.startDarts
    e = e0;
    f = f0;
    for (std::size_t h = hb; h < he; ++h) {
        if (!owns(h, e, f)) continue;
        const bool isExplicit = h < nExplicit;
        // The hex's starts beyond those of pass 1 (implicit cells, fallbacks, retries).
        std::optional<HexStarts> more;
        auto starts = [&]() -> HexStarts& {
            if (!more) more.emplace(in, h);
            return *more;
        };
        for (; e < edgeOwner.size() && edgeOwner[e].first == static_cast<int>(h); ++e) {
            const EdgeStartState st = edgeStartState(edgeOwner[e].second);
            ArcStart s = isExplicit ? HexStarts::fromMapDart(in, S.startDarts[next++]) : starts().at(st.corner, st.d0, st.d1, st.d2);
            if (s.tet < 0) s = starts().at(st.corner, st.d0, st.d2, st.d1);
            const std::size_t before = R.arc_points.size();
            if (s.tet >= 0) traceEdgeArc(*in.mesh, *in.transitions, *in.tets, s, R.arc_points);
            R.arc_size.push_back(R.arc_points.size() - before);
        }
        for (; f < faceOwner.size() && faceOwner[f].first == static_cast<int>(h); ++f) {
            const int k = faceOwner[f].second;
            auto cornerStart = [&](int i) {
                const EdgeStartState st = faceStartState(k, i);
                return starts().at(st.corner, st.d0, st.d1, st.d2);
            };
            S.from.assign(1, isExplicit ? HexStarts::fromMapDart(in, S.startDarts[next++]) : cornerStart(0));
            const std::size_t pointsBefore = R.patch_points.size(), trisBefore = R.triangles.size();
            double area = 0;
            bool ok = traceFacePatch(*in.mesh, *in.transitions, *in.tets, S.from, R.patch_points, R.triangles, area, S.patch) &&
                      std::abs(area - 1) <= kAreaTolerance;
            if (!ok) {
                // A fold may have cut the preimage into pieces: flood from all four corners.
                for (int i = 1; i < 4; ++i) S.from.push_back(cornerStart(i));
                R.patch_points.resize(pointsBefore);
                R.triangles.resize(trisBefore);
                ok = traceFacePatch(*in.mesh, *in.transitions, *in.tets, S.from, R.patch_points, R.triangles, area, S.patch) &&
                     std::abs(area - 1) <= kAreaTolerance;
            }
            if (!ok) {
                R.patch_points.resize(pointsBefore);
                R.triangles.resize(trisBefore);
            }
            R.patch_size.push_back(R.triangles.size() - trisBefore);
        }
    }
}

/// Reserves room for @p more elements in @p v, extrapolating the final size from the
/// fraction @p done of the work (one or two reallocations instead of repeated doubling).
template <class T>
void reserveFor(std::vector<T>& v, std::size_t more, double done) {
    const std::size_t need = v.size() + more;
    if (need <= v.capacity()) return;
    const double estimate = done > 0 ? static_cast<double>(need) / done * 1.05 : 0.0;
    v.reserve(std::max({need, 2 * v.capacity(), static_cast<std::size_t>(estimate)}));
    adviseHugePages(v.data() + v.size(), (v.capacity() - v.size()) * sizeof(T));
}

/// Appends block @p R (traced hexes up to @p hexesDone of @p nh) to the output.
void append(BlockResult& R, std::size_t hexesDone, std::size_t nh, HexArcs& out) {
    for (std::size_t k = 0; k < R.arc_size.size(); ++k) {
        if (R.arc_size[k] == 0) out.failed_edges.push_back(static_cast<int>(out.arc_offset.size() - 1));
        out.arc_offset.push_back(out.arc_offset.back() + R.arc_size[k]);
    }
    for (std::size_t k = 0; k < R.patch_size.size(); ++k) {
        if (R.patch_size[k] == 0) out.failed_faces.push_back(static_cast<int>(out.patch_offset.size() - 1));
        out.patch_offset.push_back(out.patch_offset.back() + R.patch_size[k]);
    }
    const double done = static_cast<double>(hexesDone) / static_cast<double>(std::max<std::size_t>(nh, 1));
    reserveFor(out.arc_points, R.arc_points.size(), done);
    reserveFor(out.patch_points, R.patch_points.size(), done);
    reserveFor(out.patch_triangles, R.triangles.size(), done);
    out.arc_points.insert(out.arc_points.end(), R.arc_points.begin(), R.arc_points.end());
    const int base = static_cast<int>(out.patch_points.size());
    for (const auto& t : R.triangles) out.patch_triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    out.patch_points.insert(out.patch_points.end(), R.patch_points.begin(), R.patch_points.end());
}

} // namespace

std::vector<int> mapDartOrigins(const std::vector<int>& new_index, int n_alive) {
    std::vector<int> origin(static_cast<std::size_t>(n_alive), -1);
    for (std::size_t d = 0; d < new_index.size(); ++d)
        if (new_index[d] >= 0) origin[static_cast<std::size_t>(new_index[d])] = static_cast<int>(d);
    return origin;
}

HexArcs arcStage(const ArcInput& in) {
    HexArcs out;
    const std::size_t nh = in.hexes->hexes.size();
    // Edge and face ids by first appearance; the first hex that has one traces it.
    HexElementOwners edgeOwner, faceOwner;
    numberHexEdgesAndFaces(*in.hexes, in.threads, out, edgeOwner, faceOwner);
    out.arc_offset.reserve(out.edges.size() + 1);
    out.patch_offset.reserve(out.faces.size() + 1);
    out.arc_offset.assign(1, 0);
    out.patch_offset.assign(1, 0);
    // Blocks of hexes, handed out to the threads one at a time (the cost per hex varies a
    // lot across a mesh) and appended to the output in block order as soon as all earlier
    // blocks are: the output does not depend on the thread count, and only the blocks
    // waiting for an earlier one are held twice.
    constexpr std::size_t kBlockHexes = 256;
    const std::size_t nBlocks = (nh + kBlockHexes - 1) / kBlockHexes;
    auto firstOwned = [&](const HexElementOwners& owner, std::size_t hb) {
        return static_cast<std::size_t>(std::lower_bound(owner.begin(), owner.end(), std::make_pair(static_cast<int>(hb), -1)) - owner.begin());
    };
    const int threads = static_cast<int>(std::max<std::size_t>(1, std::min<std::size_t>(static_cast<std::size_t>(in.threads), nBlocks)));
    if (threads == 1) {
        // One thread: trace straight into the output (triangle indices are then global).
        BlockResult R;
        R.arc_points.swap(out.arc_points);
        R.patch_points.swap(out.patch_points);
        R.triangles.swap(out.patch_triangles);
        TraceScratch S;
        for (std::size_t b = 0; b < nBlocks; ++b) {
            const std::size_t hb = b * kBlockHexes, he = std::min(nh, hb + kBlockHexes);
            R.arc_size.clear();
            R.patch_size.clear();
            const std::size_t arcs0 = R.arc_points.size(), points0 = R.patch_points.size(), tris0 = R.triangles.size();
            traceBlock(in, edgeOwner, faceOwner, hb, he, firstOwned(edgeOwner, hb), firstOwned(faceOwner, hb), S, R);
            // Room for the next blocks by extrapolation, before doubling would copy it all.
            const double done = static_cast<double>(he) / static_cast<double>(nh);
            reserveFor(R.arc_points, 2 * (R.arc_points.size() - arcs0), done);
            reserveFor(R.patch_points, 2 * (R.patch_points.size() - points0), done);
            reserveFor(R.triangles, 2 * (R.triangles.size() - tris0), done);
            BlockResult sizes;  // only the sizes: the points are in place already
            sizes.arc_size.swap(R.arc_size);
            sizes.patch_size.swap(R.patch_size);
            append(sizes, he, nh, out);
            R.arc_size.swap(sizes.arc_size);
            R.patch_size.swap(sizes.patch_size);
        }
        out.arc_points.swap(R.arc_points);
        out.patch_points.swap(R.patch_points);
        out.patch_triangles.swap(R.triangles);
        return out;
    }
    std::vector<BlockResult> blocks(nBlocks);
    std::vector<BlockResult> spare;  // cleared buffers of appended blocks, for reuse
    std::atomic<std::size_t> nextBlock{0};
    std::mutex lock;  // guards blocks[].done, spare, nextAppend and the output
    std::size_t nextAppend = 0;
    parallelChunks(static_cast<std::size_t>(threads), threads, [&](int, std::size_t, std::size_t) {
        TraceScratch S;
        BlockResult R;
        for (;;) {
            const std::size_t b = nextBlock++;
            if (b >= nBlocks) break;
            const std::size_t hb = b * kBlockHexes, he = std::min(nh, hb + kBlockHexes);
            traceBlock(in, edgeOwner, faceOwner, hb, he, firstOwned(edgeOwner, hb), firstOwned(faceOwner, hb), S, R);
            const std::lock_guard<std::mutex> guard(lock);
            R.done = true;
            blocks[b].clear();
            std::swap(blocks[b], R);
            if (!spare.empty()) {
                std::swap(R, spare.back());
                spare.pop_back();
            }
            for (; nextAppend < nBlocks && blocks[nextAppend].done; ++nextAppend) {
                BlockResult& A = blocks[nextAppend];
                append(A, std::min(nh, (nextAppend + 1) * kBlockHexes), nh, out);
                A.clear();
                spare.emplace_back();
                std::swap(spare.back(), A);
            }
        }
    });
    return out;
}

} // namespace HexEx
