#include "ConnectionTracing.hh"

#include "../Core/Error.hh"
#include "../Core/Parallel.hh"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <limits>
#include <string>
#include "../Predicates/ExactPredicates.hh"

#include <utility>

namespace HexEx {

namespace {

/// A dart description (grid point and frame) in the chart of the current tet.
struct Desc {
    Vec3i z;
    std::array<AxisDir, 3> d;
};

// The walks below write their descriptions field by field and read them field by field:
// a vector stored in pieces and then loaded whole stalls the store forwarding, which was
// the hottest spot of a trace (Rotation::apply(), GridTransform::apply(), dirVec() and
// stepAlong() build their results per component).

/// out = alpha_i*((z, d)), the expected partner's description (@p out holds neither).
void setAlphaStar(int i, const Vec3i& z, const std::array<AxisDir, 3>& d, Desc& out) {
    const AxisDir d0 = d[0], d1 = d[1], d2 = d[2];
    out.z = i == 0 ? stepAlong(z, d0) : z;
    out.d[0] = i == 0 ? dirNeg(d0) : i == 1 ? d1 : d0;
    out.d[1] = i == 1 ? d0 : i == 2 ? d2 : d1;
    out.d[2] = i == 2 ? d1 : i == 3 ? dirNeg(d2) : d2;
}

/// out = alpha_i*(s), the expected partner's description (@p out is not @p s).
void setAlphaStar(int i, const Desc& s, Desc& out) { setAlphaStar(i, s.z, s.d, out); }

/// s = g(s), in place.
void transformDesc(const GridTransform& g, Desc& s) {
    s.z = g.apply(s.z);
    for (int k = 0; k < 3; ++k) s.d[static_cast<std::size_t>(k)] = g.applyDir(s.d[static_cast<std::size_t>(k)]);
}

int signOf(double x) { return (x > 0) - (x < 0); }

/// Sign of orient3d(P, Q, a, b) for the line P = z + e^2 e2 + e^3 e3, Q = P + D:
/// det(D, a-z, b-z) - e^2 h (b-a).e3 + e^3 h (b-a).e2 with h the handedness of (D, e2, e3).
/// The handedness h is only needed for ties; it is computed then.
/// If @p tie is given, it is set when the sign depended on e2 or e3.
int lineEdgeSign(const Vec3d& z, AxisDir D, AxisDir e2, AxisDir e3, const Vec3d& a, const Vec3d& b, bool* tie = nullptr) {
    const int t0 = dirSign(D) * orient2dAxis(z, a, b, dirAxis(D));
    if (t0 != 0) return t0;
    if (tie) *tie = true;
    const int h = frameHandedness(D, e2, e3);
    const int t2 = -h * dirSign(e3) * signOf(b[dirAxis(e3)] - a[dirAxis(e3)]);
    if (t2 != 0) return t2;
    return h * dirSign(e2) * signOf(b[dirAxis(e2)] - a[dirAxis(e2)]);
}

/// The face through which the rotation at z leaves tet T first: the candidate whose
/// inward normal is the most clockwise with respect to the rotation (d_from -> d_to).
/// `normal_axis` is the axis the rotation plane is perpendicular to (for the cross sign),
/// `offset` the direction that breaks exact ties (alpha_1 only).
int firstRotationalExit(const TetSoS& T, const int* cand, int n, AxisDir normal_axis, int h, AxisDir offset) {
    int best = cand[0];
    for (int k = 1; k < n; ++k) {
        const int a = cand[k], b = best;
        const int x = h * T.gradCrossSign(a, b, normal_axis);
        bool aFirst;
        if (x != 0) {
            aFirst = x > 0;
        } else {
            // Both faces meet the rotation plane in the same line (their common edge lies in
            // it): the path passes the edge on the offset side, leaving through the face that
            // rises towards that side. Face a's vertex off the common edge is corner b.
            int c = 0;
            while (c == a || c == b) ++c;
            aFirst = dirSign(offset) * signOf(T.p[b][dirAxis(offset)] - T.p[c][dirAxis(offset)]) > 0;
        }
        if (aFirst) best = a;
    }
    return best;
}

/// Signs of the face functions of one tet at one grid point, as far as they are known: the
/// rotational exit faces of every dart of a run (one tet, one grid point) need the same
/// signs, so a run keeps them (exact signs: the same values as computing them again).
struct PointSides {
    std::array<int, 4> oz{};  ///< oz[j]: sign of o_j at the point, where bit j of #have is set
    unsigned have = 0;        ///< bits 0..3: oz[j] known; bit 4: the corner test was done
};

/// Exit face (local index) of a non-degenerate tet for the trace of type i, or -1.
/// For i == 0, @p tie (if given) is set when the choice depended on s.d[1] or s.d[2].
/// For i > 0, @p known (if given) holds what is known of the signs of the four face
/// functions at s.z (DartSet::pointSides()) and receives the ones computed here.
int exitFace(int i, const TetSoS& T, const Desc& s, int entry, bool* tie = nullptr, PointSides* known = nullptr) {
    const AxisDir d0 = s.d[0], d1 = s.d[1], d2 = s.d[2];
    int cand[4], n = 0;
    if (i == 0) {
        const Vec3d z = toVec3d(s.z);
        for (int j = 0; j < 4; ++j) {
            if (j == entry) continue;
            if (T.vol * dirSign(d0) * T.g[j][dirAxis(d0)] >= 0) continue;  // not leaving along d0
            cand[n++] = j;
        }
        if (n == 1) return cand[0];  // the only face the line can leave through
        // Edge signs are antisymmetric in (a, b) and shared by adjacent faces: each of the
        // six edges is evaluated at most once (index: a < b, sign for the pair (a, b)).
        int edgeSign[4][4];
        bool known[4][4] = {};
        auto sign = [&](int a, int b) {
            const int lo = a < b ? a : b, hi = a < b ? b : a;
            if (!known[lo][hi]) {
                edgeSign[lo][hi] = lineEdgeSign(z, d0, d1, d2, T.p[lo], T.p[hi], tie);
                known[lo][hi] = true;
            }
            return a < b ? edgeSign[lo][hi] : -edgeSign[lo][hi];
        };
        for (int k = 0; k < n; ++k) {
            const int j = cand[k];
            int o[3], m = 0;
            for (int q = 0; q < 4; ++q)
                if (q != j) o[m++] = q;
            const int s0 = sign(o[0], o[1]);
            const int s1 = sign(o[1], o[2]);
            const int s2 = sign(o[2], o[0]);
            if (s0 == s1 && s1 == s2 && s0 != 0) return j;
        }
        return -1;
    }
    // A candidate face passes through z (o_j(z) = 0) and meets the gradient conditions of
    // the trace type; the conditions are tested first, the face functions only where they
    // hold (an alpha_3 trace usually has one such face, an alpha_2 trace two).
    PointSides local;
    PointSides& ps = known ? *known : local;
    std::array<int, 4>& oz = ps.oz;
    const Vec3d z = toVec3d(s.z);
    if ((ps.have & 0xF) != 0xF && !(ps.have & 0x10)) {
        ps.have |= 0x10;
        for (int k = 0; k < 4; ++k)
            if (z == T.p[k]) {  // at a corner: every other face passes through z (TetSoS::sides())
                oz = {0, 0, 0, 0};
                oz[static_cast<std::size_t>(k)] = T.vol;
                ps.have |= 0xF;
                break;
            }
    }
    unsigned& have = ps.have;
    for (int j = 0; j < 4; ++j) {
        if (j == entry) continue;
        const int g0 = T.g[j][dirAxis(d0)], g1 = T.g[j][dirAxis(d1)], g2 = T.g[j][dirAxis(d2)];
        const bool fits = i == 1 ? (g0 != 0 || g1 != 0) : i == 2 ? g0 == 0 : (g0 == 0 && g1 == 0 && T.vol * dirSign(d2) * g2 > 0);
        if (!fits) continue;
        if (!((have >> j) & 1)) {
            oz[static_cast<std::size_t>(j)] = T.side(j, z);
            have |= 1u << j;
        }
        if (oz[static_cast<std::size_t>(j)] == 0) cand[n++] = j;
    }
    if (n == 0) return -1;
    if (i == 3) return cand[0];
    const int h = frameHandedness(d0, d1, d2);
    if (i == 1) return firstRotationalExit(T, cand, n, d2, h, d2);
    return firstRotationalExit(T, cand, n, d0, h, d2);
}

/// Sign of orient2d(a, b, z + e*d1 + e^2*d2 + e^3*d3) in the projection dropping axis k.
/// If @p tie is given, it is set when the sign depended on d2 or d3.
int orient2dSoS(const Vec3d& a, const Vec3d& b, const Vec3d& z, const std::array<AxisDir, 3>& d, int k,
                bool* tie = nullptr) {
    const int o = orient2dAxis(a, b, z, k);
    if (o != 0) return o;
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    for (int q = 0; q < 3; ++q) {
        const AxisDir x = d[static_cast<std::size_t>(q)];
        if (q > 0 && tie) *tie = true;
        const int ax = dirAxis(x);
        int s = 0;
        if (ax == i) s = -signOf(b[j] - a[j]) * dirSign(x);
        if (ax == j) s = signOf(b[i] - a[i]) * dirSign(x);
        if (s != 0) return s;
    }
    return 0;
}

/// Exit face of a degenerate (zero-volume) tet. Its image is flat: with outward face
/// orientation, the faces split into two sides tiling the same region. A path entering
/// through a face of one side leaves through the face of the other side that contains the
/// crossing point (z, ties broken by the symbolic perturbation of the start dart).
/// @p tie (if given) is set when the choice depended on s.d[1] or s.d[2].
int exitFaceDegenerate(int i, const TetSoS& T, const Desc& s, int entry, const TetMesh& mesh, int tet,
                       bool* tie = nullptr) {
    const Vec3d z = toVec3d(s.z);
    Vec3d f[4][3];
    for (int j = 0; j < 4; ++j)
        for (int q = 0; q < 3; ++q) f[j][q] = T.p[TetMesh::kFaceCorners[j][q]];
    int axis = -1;
    for (int j = 0; j < 4 && axis < 0; ++j)
        for (int k = 0; k < 3; ++k)
            if (orient2dAxis(f[j][0], f[j][1], f[j][2], k) != 0) { axis = k; break; }
    auto meets = [&](int j) {
        return i == 0 ? triangleIntersectsSegment(f[j][0], f[j][1], f[j][2], z, z + toVec3d(dirVec(s.d[0])))
                      : triangleContainsPoint(f[j][0], f[j][1], f[j][2], z);
    };
    // vol == 0: all corners are coplanar; the faces are oriented within that plane.
    if (axis >= 0 && entry >= 0) {
        int side[4];
        for (int j = 0; j < 4; ++j) side[j] = orient2dAxis(f[j][0], f[j][1], f[j][2], axis);
        if (side[entry] != 0) {
            int cand[3], n = 0;
            for (int j = 0; j < 4; ++j)
                if (j != entry && side[j] == -side[entry] && meets(j)) cand[n++] = j;
            if (n == 1) return cand[0];
            for (int k = 0; k < n; ++k) {
                const int j = cand[k];
                const int o = side[j];
                if (orient2dSoS(f[j][0], f[j][1], z, s.d, axis, tie) == o && orient2dSoS(f[j][1], f[j][2], z, s.d, axis, tie) == o &&
                    orient2dSoS(f[j][2], f[j][0], z, s.d, axis, tie) == o)
                    return j;
            }
            if (n > 0) return cand[0];
        }
    }
    // Collapsed to a line or a point: any other interior face that meets the entity.
    for (int j = 0; j < 4; ++j)
        if (j != entry && meets(j) && !mesh.is_boundary(TetMesh::halfface(CellHandle(tet), j))) return j;
    for (int j = 0; j < 4; ++j)
        if (j != entry && meets(j)) return j;
    return -1;
}

constexpr int kMaxSteps = 4096;

} // namespace

int edgeTraceExitFace(const TetMesh& mesh, const TetSoS& T, int tet, const Vec3i& z, const std::array<AxisDir, 3>& d,
                      int entry) {
    const Desc s{z, d};
    return T.vol != 0 ? exitFace(0, T, s, entry) : exitFaceDegenerate(0, T, s, entry, mesh, tet);
}

namespace {

long encodeImplicitPartner(long occurrence) { return -2 - occurrence; }

/// The signs of the four face functions of tet @p t at @p z from its dense index's flags
/// (as DartSet::pointSides()), if it has them and z lies in the closed image; else false.
/// Only tried once per @p ps (bit 5 of PointSides::have), and not if the signs are known.
/// @p slot is the tet's DartSet::dense_slot entry.
bool flaggedSides(const DartSet& set, int slot, const TetSoS& T, const Vec3i& z, PointSides& ps) {
    if ((ps.have & 0xF) == 0xF || (ps.have & 0x20)) return false;
    ps.have |= 0x20;
    std::array<int, 4>& oz = ps.oz;
    if (slot < 0) return false;
    const DartSet::DenseIndex& di = set.dense[static_cast<std::size_t>(slot)];
    const long l = di.flags.empty() ? -1 : di.local(z);
    if (l < 0 || !(di.flags[static_cast<std::size_t>(l)] & 1)) return false;
    const unsigned fl = di.flags[static_cast<std::size_t>(l)];
    for (int j = 0; j < 4; ++j) oz[static_cast<std::size_t>(j)] = ((fl >> (4 + j)) & 1) ? 0 : T.vol;
    ps.have |= 0xF;
    return true;
}

/// Number of distinct frame codes (frameCode()).
constexpr int kFrameCodes = 216;
/// A table index for a frame (d1, d2, d3): each direction is one of 6 values.
int frameCode(const std::array<AxisDir, 3>& d) { return (d[0] * 6 + d[1]) * 6 + d[2]; }
/// Entries of a run table (see traceOne()): no dart with that frame, or several.
constexpr int kNoDart = -1, kSeveralDarts = -2;

/// What a trace needs of a tet before it knows whether it goes on from there: the range of
/// its darts, its dense index and its volume sign, in one record (DartSet::tet_begin,
/// DartSet::dense_slot and TetSoS::vol are three arrays: three cache misses per tet entered).
struct TetDarts {
    std::uint32_t begin;  ///< first dart (DartSet::tet_begin)
    std::uint32_t end;    ///< one past the last dart
    std::int32_t dense;   ///< DartSet::dense_slot, or -1
    std::int32_t vol;     ///< TetSoS::vol
};

/// The records of all tets (darts are fewer than INT_MAX: traceConnections() checks).
std::vector<TetDarts> tetDartRecords(const std::vector<TetSoS>& tets, const DartSet& set, int threads) {
    std::vector<TetDarts> rec(tets.size());
    parallelChunks(tets.size(), threads, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t t = b; t < e; ++t)
            rec[t] = TetDarts{static_cast<std::uint32_t>(set.tet_begin[t]), static_cast<std::uint32_t>(set.tet_begin[t + 1]),
                              set.dense_slot.empty() ? -1 : set.dense_slot[t], tets[t].vol};
    });
    return rec;
}

/// Starts loading the darts of a tet without a dense index that a trace has just entered:
/// the binary search that follows (findDart(), pointRange()) would otherwise wait for its
/// probes' cache lines one after another (at most 8 lines, 25 darts, are asked for).
inline void prefetchTetDarts(const DartSet& set, const TetDarts& r) {
    if (r.dense >= 0) return;
    const auto lo = reinterpret_cast<std::uintptr_t>(set.darts.data() + r.begin) & ~std::uintptr_t{63};
    const auto hi = std::min(reinterpret_cast<std::uintptr_t>(set.darts.data() + r.end), lo + 512);
    for (std::uintptr_t a = lo; a < hi; a += 64) __builtin_prefetch(reinterpret_cast<const void*>(a));
}

/// Tets without a dense index with at most this many darts are searched front to back
/// (pointRange(), findDart()): a trace's lookup in the next tet waits for its darts' cache
/// lines, and a binary search asks for them one after another where a scan streams them
/// (connect 2-4 % cheaper on pig x2 and the folded pigs; no dense tet has fewer than 64
/// box points, and the small ones rarely have more darts).
constexpr std::uint32_t kScanDarts = 64;

/// DartSet::find() with the tet's record. In key order the first dart with the point and
/// the frame is the one the binary search finds.
inline long findDart(const DartSet& set, const TetDarts& r, const Vec3i& z, const std::array<AxisDir, 3>& d) {
    if (r.dense < 0 && r.end - r.begin <= kScanDarts) {
        for (std::size_t k = r.begin; k < r.end; ++k) {
            const Dart& x = set.darts[k];
            if (samePoint(x.z, z) && sameFrame(x.d, d)) return static_cast<long>(k);
        }
        return -1;
    }
    return set.findInTet(r.dense, r.begin, r.end, z, d);
}

/// DartSet::implicitCell() with the tet's record.
inline bool implicitIn(const DartSet& set, const TetDarts& r, const Vec3i& z, const std::array<AxisDir, 3>& d) {
    return set.implicitInSlot(r.dense, z, d);
}

/// Traces alpha_i of @p dart. @p run, if given, maps frame codes to the darts of the same
/// tet at the dart's grid point (kNoDart / kSeveralDarts), replacing the local scan.
/// @p runSides, if given, holds what is known of the face signs of the dart's tet at its
/// grid point (shared by the traces of a run; i > 0 only) and receives the ones computed.
/// @p rec: tetDartRecords().
long traceOne(const TetMesh& mesh, const Transitions& tr, const std::vector<TetSoS>& tets, const DartSet& set,
              const TetDarts* rec, long dart, int i, long& steps, const int* run = nullptr, PointSides* runSides = nullptr) {
    const Dart& D = set.darts[static_cast<std::size_t>(dart)];
    int t = D.tet;
    int s = rec[t].vol;
    // desc[a] is the start, desc[a ^ 1] the target: a change of flippedness swaps them by
    // flipping a.
    Desc desc[2];
    int a = 0;
    desc[0].z = D.z;
    desc[0].d = D.d;
    // From the dart itself, not from desc[0]: its frame was just stored in pieces, and
    // reading it back across them stalls the store forwarding.
    setAlphaStar(i, D.z, D.d, desc[1]);
    const Desc& want = desc[1];  // the target before the first step
    int entry = -1;
    // First look among the darts of the same tet at the same grid point: they are stored
    // contiguously around this dart (alpha_1..alpha_3 partners usually are there).
    const int known = run && samePoint(want.z, D.z) ? run[frameCode(want.d)] : kSeveralDarts;
    if (known >= 0) return known;
    // alpha_1 and alpha_2 keep the dart's unit cell, which its own tet never marks implicit
    // (the extraction stores no dart of such a cell): only alpha_3 needs the test here.
    if (known == kNoDart) {
        if (i == 3 && implicitIn(set, rec[t], want.z, want.d)) return encodeImplicitPartner(set.occurrence(t, want.z));
    } else if (samePoint(want.z, D.z)) {
        const std::size_t lo = rec[t].begin, hi = rec[t].end;
        for (std::size_t k = static_cast<std::size_t>(dart); k-- > lo && samePoint(set.darts[k].z, D.z);)
            if (sameFrame(set.darts[k].d, want.d)) return static_cast<long>(k);
        for (std::size_t k = static_cast<std::size_t>(dart) + 1; k < hi && samePoint(set.darts[k].z, D.z); ++k)
            if (sameFrame(set.darts[k].d, want.d)) return static_cast<long>(k);
        if (i == 3 && implicitIn(set, rec[t], want.z, want.d)) return encodeImplicitPartner(set.occurrence(t, want.z));
    }
    // Cancelled fold points passed on the way (each occurrence at most once per direction).
    long passed = 0;
    const long maxPassed = 2 * set.n_cancelled + 2;
    for (int step = 0; step < kMaxSteps; ++step) {
        const TetDarts& R = rec[t];
        const TetSoS& T = tets[static_cast<std::size_t>(t)];
        Desc& start = desc[a];
        Desc& target = desc[a ^ 1];
        if (R.vol != 0 && (step > 0 || !samePoint(target.z, D.z))) {
            const long found = findDart(set, R, target.z, target.d);
            if (found >= 0) return found;
            if (implicitIn(set, R, target.z, target.d)) return encodeImplicitPartner(set.occurrence(t, target.z));
            const int cancelled = i == 0 ? set.cancelledPoint(t, target.z) : 0;
            if (cancelled == 1 ||
                (cancelled == 2 && T.contains(set.pointSides(t, T, target.z), target.d[0], target.d[1], target.d[2]))) {
                // The edge's end is a cancelled fold point (FoldCancellation.hh): go on along
                // the line as the dart there would, to the next grid point, in this tet first.
                // Annihilation would have joined this dart to the one found that way.
                if (++passed > maxPassed) return kUnconnected;
                if (cancelled == 1) {
                    // A run of points along the line that this tet owns entirely and that are
                    // cancelled: none has a dart in any tet, and at each the walk would go on
                    // the same way; jump to the last of them (a needle's walk passes
                    // thousands of such points in one large tet).
                    const Vec3i u = dirVec(dirNeg(target.d[0]));
                    for (Vec3i next = target.z + u; set.cancelledPoint(t, next) == 1; next += u) {
                        if (++passed > maxPassed) return kUnconnected;
                        target.z = next;
                    }
                }
                start.z = target.z;
                start.d[0] = dirNeg(target.d[0]);
                start.d[1] = target.d[1];
                start.d[2] = target.d[2];
                setAlphaStar(0, start, target);
                --step;
                continue;
            }
        }
        int f;
        if (T.vol == 0) {
            f = exitFaceDegenerate(i, T, start, entry, mesh, t);
        } else if (i == 0) {
            f = exitFace(0, T, start, entry);
        } else {  // the face signs at the pivot point, from the dense index's flags where it has them
            // At step 0 the trace is in the dart's tet at the dart's point (i > 0 never
            // passes cancelled points): the run's signs apply.
            PointSides here;
            PointSides& ps = step == 0 && runSides ? *runSides : here;
            flaggedSides(set, R.dense, T, start.z, ps);
            f = exitFace(i, T, start, entry, nullptr, &ps);
        }
        if (f < 0) return kUnconnected;
        const HalfFaceHandle hf = TetMesh::halfface(CellHandle(t), f);
        const HalfFaceHandle opp = mesh.opposite_halfface(hf);
        if (!opp.is_valid()) return i == 3 ? dart : kUnconnected;
        const GridTransform& g = tr.halfface[hf.uidx()];
        if (!g.is_identity()) {
            transformDesc(g, start);
            transformDesc(g, target);
        }
        t = TetMesh::cell(opp).idx();
        entry = TetMesh::opposite_corner(opp);
        ++steps;
        prefetchTetDarts(set, rec[t]);
        const int sv = rec[t].vol;
        if (sv != 0 && sv != s) {
            a ^= 1;
            s = sv;
        }
    }
    return kUnconnected;
}

/// Most darts that share one alpha_0 walk: the 8 frames (d2, d3) that go with one d1.
constexpr int kMaxGroup = 8;
/// The darts of tet @p t at grid point @p z, [first, second) (empty if none), in key order:
/// the first one with a frame is the one DartSet::find() returns for it.
std::pair<std::size_t, std::size_t> pointRange(const DartSet& set, const TetDarts& r, const Vec3i& z) {
    const std::size_t base = r.begin;
    const int slot = r.dense;
    if (slot >= 0) {
        const DartSet::DenseIndex& di = set.dense[static_cast<std::size_t>(slot)];
        const long l = di.local(z);
        if (l < 0) return {0, 0};
        return {base + di.offset[static_cast<std::size_t>(l)], base + di.offset[static_cast<std::size_t>(l) + 1]};
    }
    const Dart* first = set.darts.data() + base;
    const Dart* last = set.darts.data() + r.end;
    const Dart* lo = first;
    if (r.end - r.begin <= kScanDarts) {  // (an absent point gives an empty range either way)
        while (lo != last && !samePoint(lo->z, z)) ++lo;
    } else {
        lo = std::lower_bound(first, last, z, [](const Dart& x, const Vec3i& p) {
            for (int k = 0; k < 3; ++k)
                if (x.z[k] != p[k]) return x.z[k] < p[k];
            return false;
        });
    }
    const Dart* hi = lo;
    while (hi != last && samePoint(hi->z, z)) ++hi;
    return {static_cast<std::size_t>(lo - set.darts.data()), static_cast<std::size_t>(hi - set.darts.data())};
}

/// alpha_0 of the darts [b, e) (at most kMaxGroup) of one tet at one grid point that share
/// d1. As long as no predicate on the way ties (none depends on d2, d3: see the tie flags
/// of exitFace() and exitFaceDegenerate()), their traces visit the same tets under the same
/// transforms and swaps and differ only in the lookups. So the edge z -> z + d1 is walked
/// once for all of them, and each dart is looked up in every tet until found, exactly as
/// traceOne() would. At a tie, the exit face is chosen per dart and the walk splits into
/// one walk per face taken, each going on from there.
/// Writes for dart b + k: out[k] its alpha_0, stepsOut[k] the steps traceOne() would count,
/// split[k] = 1 if it left the first walk at a tie (else 0).
void traceEdgeGroup(const TetMesh& mesh, const Transitions& tr, const std::vector<TetSoS>& tets, const DartSet& set,
                    const TetDarts* rec, std::size_t b, std::size_t e, long* out, long* stepsOut, unsigned char* split) {
    const int n = static_cast<int>(e - b);
    std::array<AxisDir, 2> tail[kMaxGroup];  // (d2, d3) of each dart, in the chart of its walk
    for (int k = 0; k < n; ++k) {
        const auto& d = set.darts[b + static_cast<std::size_t>(k)].d;
        tail[k] = {d[1], d[2]};
        split[k] = 0;
    }
    /// The state of a walk, shared by the darts in `members` (a bit mask of group slots).
    struct Walk {
        unsigned members;
        int t, s, entry, step;
        Vec3i sz, tz;    // start and target grid point (d2, d3 are the same in both)
        AxisDir sd, td;  // start and target d1
    };
    const Dart& D0 = set.darts[b];
    Walk stack[kMaxGroup];  // a split leaves at most n - 1 walks waiting
    int waiting = 0;
    // The walk being followed (the first one built in place: a copy out of the stack right
    // after building it there would stall the store forwarding).
    Walk w{(1u << n) - 1, D0.tet, rec[D0.tet].vol, -1, 0,
           D0.z, stepAlong(D0.z, D0.d[0]), D0.d[0], dirNeg(D0.d[0])};
    auto resolve = [&](unsigned m, long link, int step) {
        for (int k = 0; k < n; ++k)
            if (m >> k & 1) {
                out[k] = link;
                stepsOut[k] = step;
            }
    };
    // Leaves the current tet of @p w through face @p f (traceOne()'s step); false (members
    // resolved) if there is no face or the boundary is reached.
    auto cross = [&](Walk& w, int f) {
        if (f < 0) {
            resolve(w.members, kUnconnected, w.step);
            return false;
        }
        const HalfFaceHandle hf = TetMesh::halfface(CellHandle(w.t), f);
        const HalfFaceHandle opp = mesh.opposite_halfface(hf);
        if (!opp.is_valid()) {
            resolve(w.members, kUnconnected, w.step);
            return false;
        }
        const GridTransform& g = tr.halfface[hf.uidx()];
        if (!g.is_identity()) {
            w.sz = g.apply(w.sz);
            w.tz = g.apply(w.tz);
            w.sd = g.applyDir(w.sd);
            w.td = g.applyDir(w.td);
            for (int k = 0; k < n; ++k)
                if (w.members >> k & 1) tail[k] = {g.applyDir(tail[k][0]), g.applyDir(tail[k][1])};
        }
        w.t = TetMesh::cell(opp).idx();
        w.entry = TetMesh::opposite_corner(opp);
        ++w.step;
        prefetchTetDarts(set, rec[w.t]);
        const int sv = rec[w.t].vol;
        if (sv != 0 && sv != w.s) {
            std::swap(w.sz, w.tz);
            std::swap(w.sd, w.td);
            w.s = sv;
        }
        return true;
    };
    for (;;) {
        for (;;) {
            if (w.step == kMaxSteps) {
                resolve(w.members, kUnconnected, kMaxSteps);
                break;
            }
            const TetSoS& T = tets[static_cast<std::size_t>(w.t)];
            const TetDarts& R = rec[w.t];
            if (R.vol != 0) {
                // The point's darts are in key order, so those with d1 == w.td (the only ones
                // a member can match) are one contiguous part of them: found once for all
                // members; the first match there is the first in the whole range.
                // A point with all 48 frames holds each once, in allFrames() order: a member's
                // dart is at its frameIndex() (checked; a mismatch scans as the others do).
                auto range = pointRange(set, R, w.tz);
                const std::size_t full = range.second - range.first == 48 ? range.first : ~std::size_t{0};
                if (full == ~std::size_t{0}) {
                    while (range.first < range.second && set.darts[range.first].d[0] < w.td) ++range.first;
                    std::size_t sub = range.first;
                    while (sub < range.second && set.darts[sub].d[0] == w.td) ++sub;
                    range.second = sub;
                }
                for (int k = 0; k < n; ++k) {
                    if (!(w.members >> k & 1)) continue;
                    const std::array<AxisDir, 3> want{w.td, tail[k][0], tail[k][1]};
                    long found = -1;  // as set.find(w.t, w.tz, want)
                    if (full != ~std::size_t{0}) {
                        const std::size_t x = full + static_cast<std::size_t>(frameIndex(want));
                        if (sameFrame(set.darts[x].d, want)) found = static_cast<long>(x);
                    }
                    for (std::size_t x = range.first; x < range.second && found < 0; ++x)
                        if (sameFrame(set.darts[x].d, want)) found = static_cast<long>(x);
                    if (found < 0) {
                        if (!implicitIn(set, R, w.tz, want)) continue;
                        found = encodeImplicitPartner(set.occurrence(w.t, w.tz));
                    }
                    resolve(1u << k, found, w.step);
                    w.members &= ~(1u << k);
                }
                if (!w.members) break;
            }
            // Exit face: the first member's frame serves all as long as nothing ties.
            int first = 0;
            while (!(w.members >> first & 1)) ++first;
            const bool alone = (w.members & (w.members - 1)) == 0;
            auto exitOf = [&](int k, bool* tie) {
                const Desc cur{w.sz, {w.sd, tail[k][0], tail[k][1]}};
                return T.vol != 0 ? exitFace(0, T, cur, w.entry, tie) : exitFaceDegenerate(0, T, cur, w.entry, mesh, w.t, tie);
            };
            bool tie = false;
            const int f = exitOf(first, alone ? nullptr : &tie);
            if (tie) {  // members that leave through another face go on as walks of their own
                unsigned other[4] = {0, 0, 0, 0}, failed = 0;
                for (int k = first + 1; k < n; ++k) {
                    if (!(w.members >> k & 1)) continue;
                    const int fk = exitOf(k, nullptr);
                    if (fk == f) continue;
                    if (fk < 0) failed |= 1u << k;
                    else other[fk] |= 1u << k;
                    w.members &= ~(1u << k);
                }
                for (int k = first + 1; k < n; ++k)
                    if ((failed | other[0] | other[1] | other[2] | other[3]) >> k & 1) split[k] = 1;
                if (failed) resolve(failed, kUnconnected, w.step);
                for (int j = 0; j < 4; ++j)
                    if (other[j]) {
                        Walk part = w;
                        part.members = other[j];
                        if (cross(part, j)) stack[waiting++] = part;
                    }
            }
            if (!cross(w, f)) break;
        }
        if (waiting == 0) break;
        w = stack[--waiting];
    }
}

} // namespace

namespace {

/// Links back into deferred partners waiting for their entry to arrive in the cache (a ring
/// of the last kSize writes; the oldest is done when a new one comes).
struct BackQueue {
    static constexpr unsigned kSize = 8;  ///< writes in flight
    int* slot[kSize];                     ///< the partner's entry
    int mine[kSize];                      ///< the finder
    unsigned n = 0;                       ///< writes queued since the last flush
};

/// Darts per block of the tracing passes (parallelBlocks()).
constexpr std::size_t kTraceBlock = 4096;

/// Calls body(worker, begin, end) for the blocks of @p block consecutive indices of [0, n),
/// which @p workers threads take in turn (worker 0 on the calling thread): the cost per dart
/// varies a lot along the dart array (implicit cells, long walks), so equal contiguous
/// chunks leave one thread idle. Results must not depend on which worker takes a block.
template <class Body>
void parallelBlocks(std::size_t n, int workers, std::size_t block, Body&& body) {
    std::atomic<std::size_t> next{0};
    parallelChunks(static_cast<std::size_t>(workers), workers, [&](int k, std::size_t, std::size_t) {
        for (;;) {
            const std::size_t b = next.fetch_add(block, std::memory_order_relaxed);
            if (b >= n) break;
            body(k, b, std::min(n, b + block));
        }
    });
}

} // namespace

std::vector<DartLinks> traceConnections(const TetMesh& mesh, const Transitions& tr,
                                                  const std::vector<TetSoS>& tets, const DartSet& darts,
                                                  int threads, TraceStats& stats,
                                                  const std::function<void(double)>& progress, bool shareEdgeTraces) {
    const std::size_t n = darts.darts.size();
    if (n >= static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw InputError("too many darts (" + std::to_string(n) + ") for 32-bit dart indices");
    // Each link is traced from one of its two darts where the frames tell which: pass 1
    // traces alpha_i only from the darts that are not deferred for i, a found partner that
    // is deferred gets the link back at once (the smallest dart that found it), and pass 2
    // traces whatever is still pending (partners seen through a transition that changes the
    // frame's orientation, boundaries, failures). A regular dart is deferred for alpha_0 if
    // d1 points in the negative axis direction of its chart, for alpha_3 if d3 does, for
    // alpha_1 if d1 > d2 (direction codes) and for alpha_2 if d2 > d3; the two darts of a
    // link within one chart and of one sign have (d1, -d1), (-d3, d3), swapped (d1, d2) or
    // swapped (d2, d3), so exactly one of them is deferred. An anti dart is deferred in the
    // opposite cases: a link between a regular and an anti dart joins the same frame at
    // the same grid point (the walk crosses the fold and comes back), so with the same
    // rule both would be traced (or both deferred). Where every traced link is mutual
    // (the report's asymmetric_links is 0), the links are exactly those of tracing every
    // dart itself; a one-sided link can end up mutual here where that would have cut it.
    constexpr int kPending = std::numeric_limits<int>::min();
    // Every entry starts pending: deferred entries are written only by links back (an
    // atomic minimum) and by their own dart's implicit-cell answer (only over kPending),
    // entries that are not deferred only by their own dart, so pass 1 needs no second
    // pass for the links back and no thread reads an entry another one writes.
    std::vector<DartLinks> alpha(n, DartLinks{kPending, kPending, kPending, kPending});
    const int workers = std::max(1, threads);
    const std::vector<TetDarts> rec = tetDartRecords(tets, darts, workers);
    std::vector<TraceStats> part(static_cast<std::size_t>(workers));
    // The rule for all four links of a dart at once (bit i: deferred for alpha_i; an odd
    // direction code points in the negative axis direction).
    auto deferMask = [&](std::size_t d) {
        const Dart& D = darts.darts[d];
        const unsigned f0 = D.d[0], f1 = D.d[1], f2 = D.d[2];
        const unsigned m = (f0 & 1u) | (f0 > f1 ? 2u : 0u) | (f1 > f2 ? 4u : 0u) | ((f2 & 1u) << 3);
        return D.sign < 0 ? m ^ 0xFu : m;
    };
    // One bit of deferMask(d), spelled out: this one runs per link on the hot path, where
    // computing all four bits measured dearer. The two must state the same rule.
    auto deferred = [&](std::size_t d, int i) {
        const Dart& D = darts.darts[d];
        const auto& f = D.d;
        const bool upper = i == 0 ? dirSign(f[0]) < 0 : i == 1 ? f[0] > f[1] : i == 2 ? f[1] > f[2] : dirSign(f[2]) < 0;
        return upper != (D.sign < 0);
    };
    // The link back into a deferred partner: it takes the smallest dart that found it (as a
    // pass in dart order after pass 1 would write first); a value below kUnconnected there
    // is kPending or its own implicit-cell answer, which a link back replaces (pass 2 would
    // not have traced it).
    auto writeBack = [&](int* slot, int mine) {
        if (workers == 1) {  // no other writer: a locked exchange would only stall the walks
            if (*slot < kUnconnected || *slot > mine) *slot = mine;
            return;
        }
        int cur = __atomic_load_n(slot, __ATOMIC_RELAXED);
        while ((cur < kUnconnected || cur > mine) &&
               !__atomic_compare_exchange_n(slot, &cur, mine, true, __ATOMIC_RELAXED, __ATOMIC_RELAXED)) {
        }
    };
    // The partner's entry is usually far away in the link array: the write is queued behind
    // a prefetch and done a few links later (BackQueue). The result does not depend on the
    // order of these writes: an entry ends as the smallest finder if any wrote it, else as
    // its dart's implicit answer (written only over kPending), else kPending.
    auto linkBack = [&](BackQueue& q, std::size_t d, int i, long p) {
        if (p < 0 || static_cast<std::size_t>(p) == d || !deferred(static_cast<std::size_t>(p), i)) return;
        int* slot = &alpha[static_cast<std::size_t>(p)][i];
        __builtin_prefetch(slot, 1);
        const unsigned at = q.n++ % BackQueue::kSize;
        if (q.n > BackQueue::kSize) writeBack(q.slot[at], q.mine[at]);
        q.slot[at] = slot;
        q.mine[at] = static_cast<int>(d);
    };
    auto flushBacks = [&](BackQueue& q) {
        const unsigned m = std::min(q.n, BackQueue::kSize);
        for (unsigned x = 0; x < m; ++x) writeBack(q.slot[x], q.mine[x]);
        q.n = 0;
    };
    auto record = [&](TraceStats& st, BackQueue& q, std::size_t d, int i, long p) {
        alpha[d][i] = static_cast<int>(p);
        if (p == kUnconnected) ++st.unconnected[i];
        else if (i == 3 && p == static_cast<long>(d)) ++st.boundary_alpha3;
        linkBack(q, d, i, p);
    };
    // Walks that pass cancelled fold points are traced per dart (traceOne() handles them).
    shareEdgeTraces = shareEdgeTraces && darts.n_cancelled == 0;
    const auto& D = darts.darts;
    auto sameRun = [&](std::size_t x, std::size_t y) { return D[x].tet == D[y].tet && samePoint(D[x].z, D[y].z); };
    parallelBlocks(n, workers, kTraceBlock, [&](int k, std::size_t b, std::size_t e) {
        // Local copy: per-worker counters next to each other would share cache lines.
        TraceStats st = part[static_cast<std::size_t>(k)];
        if (k == 0 && progress) progress(0.8 * static_cast<double>(b) / static_cast<double>(n));
        // The darts of one tet at one grid point (a run) are contiguous: a table from frame
        // code to dart answers the lookups of alpha_1..alpha_3 partners there.
        std::array<int, kFrameCodes> run;
        run.fill(kNoDart);
        std::size_t runB = b, runE = b;
        PointSides runSides;  // face signs of the run's tet at its point, as far as computed
        BackQueue backs;
        // The current group for shared alpha_0 walks (traceEdgeGroup()): darts [groupB, groupE).
        std::size_t groupB = b, groupE = b;
        long groupLink[kMaxGroup], groupSteps[kMaxGroup];
        unsigned char groupSplit[kMaxGroup];
        for (std::size_t d = b; d < e; ++d) {
            if (d >= runE) {
                for (std::size_t x = runB; x < runE; ++x) run[static_cast<std::size_t>(frameCode(D[x].d))] = kNoDart;
                runB = d;
                runSides = PointSides{};
                while (runB > 0 && sameRun(runB - 1, d)) --runB;
                runE = d + 1;
                while (runE < n && sameRun(runE, d)) ++runE;
                for (std::size_t x = runB; x < runE; ++x) {
                    int& slot = run[static_cast<std::size_t>(frameCode(D[x].d))];
                    slot = slot == kNoDart ? static_cast<int>(x) : kSeveralDarts;
                }
            }
            const auto& f = D[d].d;
            const unsigned defMask = deferMask(d);
            for (int i = 0; i < 4; ++i) {
                const bool def = (defMask >> i & 1) != 0;
                if (def && i == 0) continue;  // stays pending until a link back or pass 2
                if (i == 0 && shareEdgeTraces) {  // one walk for the darts of this run with this d1
                    if (d >= groupE) {
                        groupB = d;
                        while (groupB > runB && D[groupB - 1].d[0] == f[0]) --groupB;
                        groupE = d + 1;
                        while (groupE < runE && D[groupE].d[0] == f[0]) ++groupE;
                        if (groupE - groupB <= 1 || groupE - groupB > static_cast<std::size_t>(kMaxGroup)) groupE = groupB;
                        else traceEdgeGroup(mesh, tr, tets, darts, rec.data(), groupB, groupE, groupLink, groupSteps, groupSplit);
                    }
                    if (d < groupE) {
                        const std::size_t g = d - groupB;
                        record(st, backs, d, 0, groupLink[g]);
                        st.steps += groupSteps[g];
                        ++st.shared_alpha0;
                        st.split_alpha0 += groupSplit[g];
                        continue;
                    }
                }
                if (i > 0) {  // partner at the same grid point: usually in this run
                    const std::array<AxisDir, 3> want = i == 1   ? std::array<AxisDir, 3>{f[1], f[0], f[2]}
                                                        : i == 2 ? std::array<AxisDir, 3>{f[0], f[2], f[1]}
                                                                 : std::array<AxisDir, 3>{f[0], f[1], dirNeg(f[2])};
                    const int hit = run[static_cast<std::size_t>(frameCode(want))];
                    // No dart with that frame in the run but an implicit cell there: the
                    // answer traceOne() gives at once, with or without the run table. Only
                    // alpha_3 can get it: alpha_1 and alpha_2 keep the dart's unit cell, and a
                    // tet stores no dart of a cell its flags mark implicit (the extraction
                    // drops those octants), so the test would be false.
                    const bool implicit =
                        i == 3 && hit == kNoDart && implicitIn(darts, rec[static_cast<std::size_t>(D[d].tet)], D[d].z, want);
                    if (def) {
                        // What pass 2 would trace: only the implicit answer is known here,
                        // and a link back still takes precedence over it.
                        if (implicit) {
                            int* slot = &alpha[d][i];
                            const int answer = static_cast<int>(encodeImplicitPartner(darts.occurrence(D[d].tet, D[d].z)));
                            int cur = kPending;
                            if (workers == 1) {
                                if (*slot == kPending) *slot = answer;
                            } else {
                                __atomic_compare_exchange_n(slot, &cur, answer, false, __ATOMIC_RELAXED, __ATOMIC_RELAXED);
                            }
                        }
                        continue;
                    }
                    if (hit >= 0) {
                        // The partner is in this run: same tet, same sign, a frame the rule
                        // defers where this dart's is not (see above), and its entry is next
                        // to this one, so the link back needs neither the rule nor the queue.
                        alpha[d][i] = hit;
                        writeBack(&alpha[static_cast<std::size_t>(hit)][i], static_cast<int>(d));
                        continue;
                    }
                    if (implicit) {
                        alpha[d][i] = static_cast<int>(encodeImplicitPartner(darts.occurrence(D[d].tet, D[d].z)));
                        continue;
                    }
                }
                record(st, backs, d, i, traceOne(mesh, tr, tets, darts, rec.data(), static_cast<long>(d), i, st.steps, run.data(), &runSides));
            }
        }
        flushBacks(backs);
        part[static_cast<std::size_t>(k)] = st;
    });
    // Pass 2: the entries still pending (no link back came, no implicit answer).
    std::vector<TraceStats> part2(static_cast<std::size_t>(workers));
    parallelBlocks(n, workers, kTraceBlock, [&](int k, std::size_t b, std::size_t e) {
        TraceStats st = part2[static_cast<std::size_t>(k)];
        PointSides runSides;  // of the run (tet, grid point) of dart `last`
        std::size_t last = e;
        for (std::size_t d = b; d < e; ++d)
            for (int i = 0; i < 4; ++i)
                if (alpha[d][i] == kPending) {
                    if (last == e || !sameRun(last, d)) runSides = PointSides{};
                    last = d;
                    const long p = traceOne(mesh, tr, tets, darts, rec.data(), static_cast<long>(d), i, st.steps, nullptr, &runSides);
                    alpha[d][i] = static_cast<int>(p);
                    if (p == kUnconnected) ++st.unconnected[i];
                    else if (i == 3 && p == static_cast<long>(d)) ++st.boundary_alpha3;
                }
        part2[static_cast<std::size_t>(k)] = st;
    });
    part.insert(part.end(), part2.begin(), part2.end());
    for (const auto& p : part) {
        for (int i = 0; i < 4; ++i) stats.unconnected[i] += p.unconnected[i];
        stats.boundary_alpha3 += p.boundary_alpha3;
        stats.steps += p.steps;
        stats.shared_alpha0 += p.shared_alpha0;
        stats.split_alpha0 += p.split_alpha0;
    }
    return alpha;
}

} // namespace HexEx
