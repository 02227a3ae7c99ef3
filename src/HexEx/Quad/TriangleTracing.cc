#include "TriangleTracing.hh"

#include "../Core/Parallel.hh"
#include "PlanarOrientation.hh"

#include <algorithm>
#include <cmath>
#include <utility>

namespace HexEx {

namespace {

/// Steps after which a trace gives up (far more than any unit grid edge crosses in a
/// sensible map).
constexpr int kMaxSteps = 4096;

/// sign(a x b) of two planar axis directions (0..3: +u, -u, +v, -v), as a table.
constexpr int kFrameTurn[4][4] = {{0, 0, 1, -1}, {0, 0, -1, 1}, {-1, 1, 0, 0}, {1, -1, 0, 0}};
/// Components of the planar axis directions.
constexpr int kDirU[4] = {1, -1, 0, 0}, kDirV[4] = {0, 0, 1, -1};

/// The exact orientation test (PlanarOrientation.hh).
inline int orient2d(const Vec2d& a, const Vec2d& b, double cu, double cv) { return orient2dUV(a, b, cu, cv); }

/// Sign of (b - a) x d for an axis direction d (exact comparison).
inline int crossEdgeDir(const Vec2d& a, const Vec2d& b, AxisDir d) {
    auto sgn = [](double lo, double hi) { return lo < hi ? 1 : (lo > hi ? -1 : 0); };
    switch (d) {
        case 0: return sgn(b[1], a[1]);
        case 1: return sgn(a[1], b[1]);
        case 2: return sgn(a[0], b[0]);
        default: return sgn(b[0], a[0]);
    }
}

/// A grid point and a direction in the current chart (integers).
struct Pt {
    int u, v;
};

/// Side of point p of the perturbed grid line {q + s*w} + (infinitesimal offset):
/// sign(w x (p - q)), or @p tie if p lies on the unperturbed line. Exact (q, q + w are
/// integer points).
inline int lineSide(const Vec2d& p, Pt q, Pt w, int tie) {
    int s;
    if (w.v == 0) {  // along u: w x (p - q) = w_u (p_v - q_v)
        s = p[1] > q.v ? w.u : (p[1] < q.v ? -w.u : 0);
    } else if (w.u == 0) {  // along v: w x (p - q) = -w_v (p_u - q_u)
        s = p[0] > q.u ? -w.v : (p[0] < q.u ? w.v : 0);
    } else {
        s = orient2d(Vec2d(q.u, q.v), Vec2d(q.u + w.u, q.v + w.v), p[0], p[1]);
    }
    return s != 0 ? s : tie;
}

/// sign((b - a) x w) for an edge (a, b) that contains the grid point q (exact): the sign of
/// (b - q) x w, or of (q - a) x w when b == q.
inline int crossEdgeThrough(const Vec2d& a, const Vec2d& b, Pt q, Pt w) {
    const Vec2d z(q.u, q.v), zw(q.u + w.u, q.v + w.v);
    if (b != z) return -orient2d(z, zw, b[0], b[1]);
    return orient2d(z, zw, a[0], a[1]);
}

/// A dart description in the current chart.
struct Desc {
    int x, y;
    AxisDir d1, d2;
};

Desc mapDesc(const PlanarTransform& g, const Desc& d) {
    Desc r{0, 0, g.applyDir(d.d1), g.applyDir(d.d2)};
    g.apply(d.x, d.y, r.x, r.y);
    return r;
}

/// Everything a trace reads.
struct Tracer {
    const ParametrizedTriMesh& m;
    const TriAdjacency& adj;
    const TriParams& params;
    const TriTransitions& tr;
    const std::vector<signed char>& sign;
    const TriDartSet& ds;

    /// Index of dart @p d of triangle @p f or -1 (degenerate triangles own no darts). Keys
    /// are unique per triangle, so a linear scan of a short range finds what the binary
    /// search of findTriDart() finds.
    int lookup(int f, const Desc& d) const {
        const int b = ds.offset[static_cast<std::size_t>(f)], e = ds.offset[static_cast<std::size_t>(f) + 1];
        if (e - b > 16) return findTriDart(ds, f, d.x, d.y, d.d1, d.d2);
        for (int k = b; k < e; ++k) {
            const TriDart& t = ds.darts[static_cast<std::size_t>(k)];
            if (t.x == d.x && t.y == d.y && t.d1 == d.d1 && t.d2 == d.d2) return k;
        }
        return -1;
    }

    /// alpha_i: walk from the dart's perturbed point z + e d1 + e^2 d2 to the partner's along
    /// a straight path, across triangles, and look the partner up in every triangle passed:
    /// alpha_0 runs along the grid edge (z + e^2 d2 + s d1), alpha_1 turns about z inside the
    /// quadrant (from z + e d1 + e^2 d2 towards z + e d2 + e^2 d1, direction d2 - d1) and
    /// alpha_2 crosses the grid edge (z + e d1 - s d2). The exit edge is the one the
    /// perturbed path crosses (in the start triangle the one it leaves through; afterwards
    /// the other crossed edge, which also steps across flat triangles). Between proper and
    /// flipped triangles the walk runs backwards (start and target swap), as in Algorithm 2.
    int trace(int dart, int i, bool& boundary) const {
        const TriDart& s = ds.darts[static_cast<std::size_t>(dart)];
        Desc from{s.x, s.y, s.d1, s.d2}, to{};
        Pt q{s.x, s.y}, w{};
        int tie = 0;
        const Pt e1{kDirU[s.d1], kDirV[s.d1]}, e2{kDirU[s.d2], kDirV[s.d2]};
        if (i == 0) {
            to = {s.x + e1.u, s.y + e1.v, dirNeg(s.d1), s.d2};
            w = e1;
            tie = kFrameTurn[s.d2][s.d1];
        } else if (i == 1) {
            to = {s.x, s.y, s.d2, s.d1};
            w = {e2.u - e1.u, e2.v - e1.v};
            tie = kFrameTurn[s.d1][s.d2];
        } else {
            to = {s.x, s.y, s.d1, dirNeg(s.d2)};
            w = {-e2.u, -e2.v};
            tie = kFrameTurn[s.d1][dirNeg(s.d2)];
        }
        int f = s.tri, entry = -1, lastSign = s.sign;
        for (int step = 0; step < kMaxSteps; ++step) {
            const int r = lookup(f, to);
            if (r >= 0 && r != dart) return r;
            const auto& p = params[static_cast<std::size_t>(f)];
            const int sf = sign[static_cast<std::size_t>(f)];
            // Sides of the three corners (each used by two edges).
            const int side[3] = {lineSide(p[0], q, w, tie), lineSide(p[1], q, w, tie), lineSide(p[2], q, w, tie)};
            int exit = -1;
            for (int e = 0; e < 3 && exit < 0; ++e) {
                if (e == entry) continue;
                const int ia = e == 2 ? 0 : e + 1, ib = e == 0 ? 2 : e - 1;
                if (side[ia] == side[ib]) continue;
                const Vec2d& a = p[static_cast<std::size_t>(ia)];
                const Vec2d& b = p[static_cast<std::size_t>(ib)];
                // In the start triangle alpha_0 leaves through the edge its direction crosses
                // outwards (a cheap exact test, so first).
                if (entry < 0 && i == 0 && sf * crossEdgeDir(a, b, s.d1) >= 0) continue;
                // The crossing must lie on the traced segment (between the two grid points;
                // on the edge through z for alpha_1 and alpha_2).
                const int oa = orient2d(a, b, from.x, from.y);
                if (i > 0 ? oa != 0 : oa * orient2d(a, b, to.x, to.y) > 0) continue;
                if (entry < 0 && i > 0 && sf * crossEdgeThrough(a, b, Pt{from.x, from.y}, w) >= 0) continue;
                exit = e;
            }
            if (exit < 0) return -1;
            const std::size_t h = 3 * static_cast<std::size_t>(f) + static_cast<std::size_t>(exit);
            const int o = adj.opposite[h];
            if (o < 0) {
                boundary = true;
                return -1;
            }
            if (!tr.is_identity(h)) {
                const PlanarTransform g = tr.at(h);
                from = mapDesc(g, from);
                to = mapDesc(g, to);
                Pt qn{}, wn{};
                g.apply(q.u, q.v, qn.u, qn.v);
                g.rotate(w.u, w.v, wn.u, wn.v);
                q = qn;
                w = wn;
            }
            f = o / 3;
            entry = o % 3;
            const int sn = sign[static_cast<std::size_t>(f)];
            if (sn != 0 && sn != lastSign) {  // between proper and flipped: the walk runs backwards
                std::swap(from, to);
                w = {-w.u, -w.v};
                tie = -tie;
                lastSign = sn;
            }
        }
        return -1;
    }
};

} // namespace

TriLinks traceTriConnections(const ParametrizedTriMesh& m, const TriAdjacency& adj,
                                                    const TriParams& params, const TriTransitions& tr,
                                                    const std::vector<signed char>& sign, const TriDartSet& ds, int threads,
                                                    TriTraceStats* stats) {
    const std::size_t n = ds.darts.size();
    const Tracer T{m, adj, params, tr, sign, ds};
    const int chunks = std::max(1, threads);
    // Partners have opposite frame orientation (relative to their triangle's sign), so each
    // link is traced once, from the dart whose frame turns counter-clockwise; the partner
    // gets the link back unless two darts claim it (then it traces itself, as do darts
    // nobody claimed). The mutual check below decides as if every dart had traced.
    auto counterClockwise = [&](std::size_t d) {
        const TriDart& t = ds.darts[d];
        return kFrameTurn[t.d1][t.d2] * t.sign > 0;
    };
    constexpr int kUntraced = -2, kContested = -3;
    // Sized without zeroing and set to kUntraced in parallel (each chunk touches its own
    // pages first), before any claim can write into another chunk's range.
    TriLinks links(n);
    parallelChunks(n, chunks, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t d = b; d < e; ++d) links[d] = {kUntraced, kUntraced, kUntraced};
    });
    auto traceInto = [&](std::size_t d, int i) {
        const int di = static_cast<int>(d);
        bool boundary = false;
        const int p = T.trace(di, i, boundary);
        links[d][static_cast<std::size_t>(i)] = p >= 0 ? p : (i == 2 && boundary ? di : -1);
        return p;
    };
    // Counter-clockwise darts trace and claim at once (the partner's dart record is still in
    // cache from the lookup). A claim is the only write to a clockwise dart's entry in this
    // pass and a dart's own entries are the only ones it reads: the entry ends as the
    // claimant if exactly one dart claimed it and as kContested if several did, whatever
    // the order (a compare-and-swap from kUntraced succeeds once; later claimants store
    // kContested).
    parallelChunks(n, chunks, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t d = b; d < e; ++d) {
            if (!counterClockwise(d)) continue;
            for (int i = 0; i < 3; ++i) {
                const int p = traceInto(d, i);
                if (p < 0 || p == static_cast<int>(d) || counterClockwise(static_cast<std::size_t>(p))) continue;
                int* back = &links[static_cast<std::size_t>(p)][static_cast<std::size_t>(i)];
                int expected = kUntraced;
                if (!__atomic_compare_exchange_n(back, &expected, static_cast<int>(d), false, __ATOMIC_RELAXED, __ATOMIC_RELAXED))
                    __atomic_store_n(back, kContested, __ATOMIC_RELAXED);
            }
        }
    });
    parallelChunks(n, chunks, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t d = b; d < e; ++d)
            for (int i = 0; i < 3; ++i)
                if (links[d][static_cast<std::size_t>(i)] < 0 && !counterClockwise(d)) traceInto(d, i);
    });
    // Keep only mutual links (decided on the traced links, then applied).
    std::vector<unsigned char, DefaultInitAllocator<unsigned char>> drop(n);  // every entry written below
    parallelChunks(n, chunks, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t d = b; d < e; ++d) {
            unsigned bits = 0;
            for (int i = 0; i < 3; ++i) {
                const int p = links[d][static_cast<std::size_t>(i)];
                if (p >= 0 && p != static_cast<int>(d) && links[static_cast<std::size_t>(p)][static_cast<std::size_t>(i)] != static_cast<int>(d))
                    bits |= 1u << i;
            }
            drop[d] = static_cast<unsigned char>(bits);
        }
    });
    std::vector<TriTraceStats> parts(static_cast<std::size_t>(chunks));
    parallelChunks(n, chunks, [&](int k, std::size_t b, std::size_t e) {
        TriTraceStats& c = parts[static_cast<std::size_t>(k)];
        for (std::size_t d = b; d < e; ++d)
            for (int i = 0; i < 3; ++i) {
                if (drop[d] & (1u << i)) {
                    links[d][static_cast<std::size_t>(i)] = -1;
                    ++c.asymmetric;
                }
                if (links[d][static_cast<std::size_t>(i)] < 0) ++c.unconnected;
            }
    });
    TriTraceStats st;
    for (const TriTraceStats& c : parts) {
        st.asymmetric += c.asymmetric;
        st.unconnected += c.unconnected;
    }
    if (stats) *stats = st;
    return links;
}

} // namespace HexEx
