#include "DartExtraction.hh"

#include "../Core/Error.hh"
#include "../Core/Parallel.hh"
#include "FacePlanes.hh"
#include "FoldCancellation.hh"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif
#include <new>
#include <optional>
#include <string>

namespace HexEx {

const std::array<std::array<AxisDir, 3>, 48>& allFrames() {
    static const auto frames = [] {
        std::array<std::array<AxisDir, 3>, 48> f{};
        int n = 0;
        for (int a = 0; a < 6; ++a)
            for (int b = 0; b < 6; ++b)
                for (int c = 0; c < 6; ++c)
                    if (a / 2 != b / 2 && b / 2 != c / 2 && a / 2 != c / 2)
                        f[n++] = {static_cast<AxisDir>(a), static_cast<AxisDir>(b), static_cast<AxisDir>(c)};
        return f;
    }();
    return frames;
}

long DartSet::find(int t, const Vec3i& z, const std::array<AxisDir, 3>& d) const {
    return findInTet(dense_slot.empty() ? -1 : dense_slot[static_cast<std::size_t>(t)], tet_begin[static_cast<std::size_t>(t)],
                     tet_begin[static_cast<std::size_t>(t) + 1], z, d);
}

std::vector<TetSoS> buildTetSoS(const CornerParams& params, int threads) {
    std::vector<TetSoS> out(params.size());
    parallelChunks(params.size(), threads, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t c = b; c < e; ++c) out[c] = TetSoS(params[c]);
    });
    return out;
}

GridBox gridBox(const TetSoS& T, std::size_t c) {
    Vec3d lo = T.p[0], hi = T.p[0];
    for (int i = 1; i < 4; ++i) {
        lo.minimize(T.p[i]);
        hi.maximize(T.p[i]);
    }
    GridBox box;
    box.points = 1;
    for (int a = 0; a < 3; ++a) {
        // (Also false for NaN.)
        if (!(std::fabs(lo[a]) <= 1e9 && std::fabs(hi[a]) <= 1e9))
            throw InputError("tet " + std::to_string(c) + ": parameter out of range (|u| > 1e9 or not finite)");
        // ceil and floor by the truncating conversion (exact below 2^31; no libm calls).
        const int tl = static_cast<int>(lo[a]), th = static_cast<int>(hi[a]);
        box.lo[a] = tl + (static_cast<double>(tl) < lo[a] ? 1 : 0);
        box.hi[a] = th - (static_cast<double>(th) > hi[a] ? 1 : 0);
        box.points *= std::max(0, box.hi[a] - box.lo[a] + 1);
    }
    return box;
}

long DartSet::occurrence(int t, const Vec3i& z) const {
    const int slot = dense_slot.empty() ? -1 : dense_slot[static_cast<std::size_t>(t)];
    if (slot < 0) return -1;
    const DenseIndex& di = dense[static_cast<std::size_t>(slot)];
    if (di.flags.empty()) return -1;
    const long l = di.local(z);
    if (l < 0 || !(di.flags[static_cast<std::size_t>(l)] & 1)) return -1;
    return di.occ_base + l;
}

void DartSet::occurrencePoint(long occ, int& tet, Vec3i& z) const {
    const auto it = std::upper_bound(dense.begin(), dense.end(), occ,
                                     [](long o, const DenseIndex& di) { return o < di.occ_base; });
    const DenseIndex& di = *(it - 1);
    long l = occ - di.occ_base;
    z[2] = di.lo[2] + static_cast<int>(l % di.dims[2]);
    l /= di.dims[2];
    z[1] = di.lo[1] + static_cast<int>(l % di.dims[1]);
    z[0] = di.lo[0] + static_cast<int>(l / di.dims[1]);
    tet = di.tet;
}

std::array<int, 4> DartSet::pointSides(int t, const TetSoS& T, const Vec3i& z) const {
    const int slot = dense_slot.empty() ? -1 : dense_slot[static_cast<std::size_t>(t)];
    if (slot >= 0) {
        const DenseIndex& di = dense[static_cast<std::size_t>(slot)];
        const long l = di.flags.empty() ? -1 : di.local(z);
        if (l >= 0 && (di.flags[static_cast<std::size_t>(l)] & 1)) {
            std::array<int, 4> oz;
            for (int j = 0; j < 4; ++j) oz[static_cast<std::size_t>(j)] = ((di.flags[static_cast<std::size_t>(l)] >> (4 + j)) & 1) ? 0 : T.vol;
            return oz;
        }
    }
    return T.sides(Vec3d(z[0], z[1], z[2]));
}

namespace {
/// Fills the flags of a tet's dense index: which box points lie in the closed image (and on
/// which faces) and, with @p implicit (proper tets only), which may be implicit-cell corners
/// and which unit cells are implicit (all 8 corners usable: the closed image is convex, so
/// it contains the cell). Costs O(log) predicates per row instead of four per point.
/// Returns the number of cells marked implicit.
long markBoxFlags(const TetSoS& T, FaceMask usable, DartSet::DenseIndex& di, bool implicit) {
    di.implicit_marks = implicit;
    const int dx = di.dims[0], dy = di.dims[1], dz = di.dims[2];
    di.flags.assign(static_cast<std::size_t>(dx) * static_cast<std::size_t>(dy) * static_cast<std::size_t>(dz), 0);
    // o_j is affine along a line of the box: its signs along the line are s(first), then at
    // most one zero, then s(last). Exact signs at the line ends and a binary search for the
    // change replace one predicate per point by O(log n) per line. The lines run along the
    // longest axis of the box (a needle's box is long in one direction only).
    const std::size_t stride[3] = {static_cast<std::size_t>(dy) * static_cast<std::size_t>(dz), static_cast<std::size_t>(dz), 1};
    const int ra = dz >= dx && dz >= dy ? 2 : (dy >= dx ? 1 : 0);  // line axis (z on ties: contiguous)
    const int ob = ra == 0 ? 1 : 0, oc = ra == 2 ? 1 : 2;          // the other two axes
    const int n = di.dims[ra];
    std::vector<int> sign(static_cast<std::size_t>(n) * 4);
    const FacePlanes F(T);
    for (int ib = 0; ib < di.dims[ob]; ++ib)
        for (int ic = 0; ic < di.dims[oc]; ++ic) {
            int p[3];
            p[ob] = ib;
            p[oc] = ic;
            auto side = [&](int j, int k) {
                p[ra] = k;
                return F.side(j, Vec3d(di.lo[0] + p[0], di.lo[1] + p[1], di.lo[2] + p[2]));
            };
            bool lineOutside = false;
            for (int j = 0; j < 4 && !lineOutside; ++j) {
                int* sj = sign.data() + static_cast<std::size_t>(j) * static_cast<std::size_t>(n);
                const int s0 = side(j, 0), s1 = n > 1 ? side(j, n - 1) : s0;
                if (s0 == s1) {  // constant along the line (zero twice: identically zero)
                    if (s0 == -T.vol) lineOutside = true;
                    std::fill(sj, sj + n, s0);
                    continue;
                }
                // First index whose sign differs from s0 (the sign at n-1 differs).
                int a = 0, b = n - 1;
                while (b - a > 1) {
                    const int m = a + (b - a) / 2;
                    (side(j, m) == s0 ? a : b) = m;
                }
                std::fill(sj, sj + b, s0);
                std::fill(sj + b, sj + n, s1);
                if (s0 != 0 && b < n - 1 && side(j, b) == 0) sj[b] = 0;
            }
            if (lineOutside) continue;
            const std::size_t base = static_cast<std::size_t>(ib) * stride[ob] + static_cast<std::size_t>(ic) * stride[oc];
            for (int k = 0; k < n; ++k) {
                unsigned fl = 1;
                for (int j = 0; j < 4 && fl; ++j) {
                    const int sk = sign[static_cast<std::size_t>(j) * static_cast<std::size_t>(n) + static_cast<std::size_t>(k)];
                    if (sk == -T.vol) fl = 0;
                    else if (sk == 0) fl |= 16u << j;
                }
                if (implicit && fl && ((fl >> 4) & ~static_cast<unsigned>(usable)) == 0) fl |= 4;
                di.flags[base + static_cast<std::size_t>(k) * stride[ra]] = static_cast<std::uint8_t>(fl);
            }
        }
    if (!implicit) return 0;
    // A cell is implicit if its 8 corners all have bit 2 (value 4): one AND of the 8 flag
    // bytes at fixed offsets (x-major layout); setting bit 1 (value 2) leaves the bits read.
    const std::size_t sy = static_cast<std::size_t>(dz), sx = static_cast<std::size_t>(dy) * sy;
    long marked = 0;
    for (int x = 0; x + 1 < dx; ++x)
        for (int y = 0; y + 1 < dy; ++y) {
            std::uint8_t* p = di.flags.data() + (static_cast<std::size_t>(x) * dy + y) * dz;
            for (int zc = 0; zc + 1 < dz; ++zc, ++p) {
                const unsigned cell = (p[0] & p[1] & p[sy] & p[sy + 1] & p[sx] & p[sx + 1] & p[sx + sy] & p[sx + sy + 1] & 4u) >> 1;
                *p |= static_cast<std::uint8_t>(cell);  // bit 1 where implicit
                marked += cell >> 1;
            }
        }
    return marked;
}
} // namespace

namespace {
/// Per octant o (bit a set: the cell lies on the -a side of the point): the frames (bits of
/// allFrames()) whose cell is that octant's, i.e. whose directions point to -a exactly for
/// the bits a of o.
std::array<std::uint64_t, 8> octantFrameMasks() {
    std::array<std::uint64_t, 8> masks{};
    const auto& frames = allFrames();
    for (std::size_t f = 0; f < frames.size(); ++f) {
        unsigned octant = 0;
        for (AxisDir x : frames[f])
            if (dirSign(x) < 0) octant |= 1u << dirAxis(x);
        masks[octant] |= std::uint64_t(1) << f;
    }
    return masks;
}

/// All 48 frames.
constexpr std::uint64_t kAllFrames = (std::uint64_t(1) << 48) - 1;

/// Frames (bit fi of allFrames()) for which the symbolic side of a face through the point
/// (TetSoS::sosSide() with oz = 0) is +1 (`pos`) or -1 (`neg`), per sign pattern of the
/// face's gradient: index (g0 + 1) * 9 + (g1 + 1) * 3 + (g2 + 1).
struct FrameSideMasks {
    std::uint64_t pos[27] = {};  ///< frames on the positive side
    std::uint64_t neg[27] = {};  ///< frames on the negative side
};

const FrameSideMasks& frameSideMasks() {
    static const FrameSideMasks masks = [] {
        FrameSideMasks m;
        const auto& frames = allFrames();
        for (int code = 0; code < 27; ++code) {
            const int g[3] = {code / 9 - 1, (code / 3) % 3 - 1, code % 3 - 1};
            for (std::size_t fi = 0; fi < frames.size(); ++fi) {
                int s = 0;
                for (AxisDir d : frames[fi])
                    if (s == 0) s = dirSign(d) * g[dirAxis(d)];
                if (s > 0) m.pos[code] |= std::uint64_t(1) << fi;
                if (s < 0) m.neg[code] |= std::uint64_t(1) << fi;
            }
        }
        return m;
    }();
    return masks;
}

/// The frames of a point with face signs @p oz (none opposite to the volume's sign) that
/// tet @p T contains: bit fi set iff T.contains(oz, frames[fi]...).
std::uint64_t containedFrames(const TetSoS& T, const std::array<int, 4>& oz) {
    const FrameSideMasks& m = frameSideMasks();
    std::uint64_t mask = kAllFrames;
    for (int j = 0; j < 4; ++j) {
        if (oz[static_cast<std::size_t>(j)] != 0) continue;
        const int code = (T.g[j][0] + 1) * 9 + (T.g[j][1] + 1) * 3 + (T.g[j][2] + 1);
        mask &= T.vol > 0 ? m.pos[code] : m.neg[code];
    }
    return mask;
}

/// Signs of the four face functions of one tet (TetSoS::side()) at grid points of its box.
/// At a corner of the tet the signs need no arithmetic (TetSoS::sides()' rule: the faces
/// through the corner are zero, the opposite one has the volume's sign). Elsewhere, when
/// every corner is FacePlanes::smallDyadic() (a multiple of 1/64 of magnitude at most 512;
/// the box's grid points are then too), the doubles are exact: the corner differences are
/// multiples of 2^-6 below 2^10, the cross product n = (b - a) x (c - a) multiples of
/// 2^-12 below 2^21, the terms of (x - a) . n multiples of 2^-18 below 2^31 and their sum
/// below 2^33: an integer of at most 51 bits in units of 2^-18, so its sign is the exact
/// sign, without a filter. A face is set up when a point first needs it (most points
/// outside a tet are decided by one or two faces). Other tets go through FacePlanes
/// (filter, exact fallback).
class BoxFaceSigns {
public:
    /// For tet @p T (which must outlive this object).
    explicit BoxFaceSigns(const TetSoS& T) : T_(T) {}

    /// The signs at the grid point (@p x, @p y, @p zc); false as soon as one is opposite to
    /// the volume's sign (outside; @p oz is then incomplete). @p interior: all four are
    /// non-zero. (The coordinates come in registers: a point stored in pieces by the caller
    /// and loaded whole here stalled the store forwarding, a third of this function's time
    /// on pig x2.)
    bool sides(int x, int y, int zc, std::array<int, 4>& oz, bool& interior) {
        const Vec3d zp(x, y, zc);
        for (int k = 0; k < 4; ++k)
            if (zp[0] == T_.p[k][0] && zp[1] == T_.p[k][1] && zp[2] == T_.p[k][2]) {
                oz = {0, 0, 0, 0};
                oz[static_cast<std::size_t>(k)] = T_.vol;
                interior = false;
                return true;
            }
        if (mode_ == Mode::Unknown) {
            mode_ = FacePlanes::smallDyadic(T_.p[0]) && FacePlanes::smallDyadic(T_.p[1]) &&
                            FacePlanes::smallDyadic(T_.p[2]) && FacePlanes::smallDyadic(T_.p[3])
                        ? Mode::Exact
                        : Mode::Planes;
            if (mode_ == Mode::Planes) planes_.emplace(T_);
        }
        interior = true;
        for (int j = 0; j < 4; ++j) {
            const int s = mode_ == Mode::Exact ? exactSide(j, zp) : planes_->side(j, zp);
            if (s == -T_.vol) return false;
            oz[static_cast<std::size_t>(j)] = s;
            interior = interior && s != 0;
        }
        return true;
    }

private:
    enum class Mode : unsigned char { Unknown, Exact, Planes };

    /// o_j(x) = (-1)^(3-j) det(b - a, c - a, x - a), (a, b, c) the corners other than j in
    /// index order (as in FacePlanes), exactly.
    int exactSide(int j, const Vec3d& x) {
        if (!((ready_ >> j) & 1)) {
            const int a = j == 0 ? 1 : 0, b = j <= 1 ? 2 : 1, c = j <= 2 ? 3 : 2;
            const Vec3d u = T_.p[b] - T_.p[a], v = T_.p[c] - T_.p[a];
            n_[j] = Vec3d(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
            base_[j] = a;
            ready_ |= 1u << j;
        }
        const Vec3d& p = T_.p[base_[j]];
        const double det = (x[0] - p[0]) * n_[j][0] + (x[1] - p[1]) * n_[j][1] + (x[2] - p[2]) * n_[j][2];
        const int s = (det > 0) - (det < 0);
        return (3 - j) % 2 == 0 ? s : -s;
    }

    const TetSoS& T_;
    Mode mode_ = Mode::Unknown;
    unsigned ready_ = 0;                // bit j: face j of an exact tet is set up
    int base_[4];                       // corner a of face j
    Vec3d n_[4];                        // (b - a) x (c - a) of face j, exact
    std::optional<FacePlanes> planes_;  // tets that are not exact, at their first non-corner point
};

/// Forces inlining where the compiler knows how (GCC, Clang): pointFrames() runs once per
/// grid point of every box; left out of line it cost the cylinder v6 map's darts stage 10 %
/// (288 tets with dense indices: 0.24 s against 0.21 s at 1 thread).
#if defined(__GNUC__)
#define HEXEX_DARTS_INLINE inline __attribute__((always_inline))
#else
#define HEXEX_DARTS_INLINE inline
#endif

/// The frames (bits of allFrames()) of the darts of tet @p T at grid point (x, y, zc), box
/// index @p l of the dense index @p di (if any; its flags, if any, decide membership and
/// implicit octants); else @p S (at that point of its row) gives the face signs.
HEXEX_DARTS_INLINE std::uint64_t pointFrames(const TetSoS& T, BoxFaceSigns& S, const DartSet::DenseIndex* di, int x, int y, int zc,
                          std::size_t l, const std::array<std::uint64_t, 8>& octantFrames) {
    std::array<int, 4> oz;
    bool interior = true;
    std::uint64_t allowed = kAllFrames;
    if (di && !di->flags.empty()) {
        // The signs were found while marking the implicit cells.
        const std::uint8_t fl = di->flags[l];
        if (!(fl & 1)) return 0;
        for (int j = 0; j < 4; ++j) oz[static_cast<std::size_t>(j)] = ((fl >> (4 + j)) & 1) ? 0 : T.vol;
        interior = (fl >> 4) == 0;
        if (di->implicit_marks) {
            if (x > di->lo[0] && y > di->lo[1] && zc > di->lo[2]) {
                // All 8 cells around z have their lower corner in the box: their flags lie at
                // fixed offsets below l (x-major: x strides dims[1] * dims[2], y dims[2]).
                const std::size_t sy = static_cast<std::size_t>(di->dims[2]);
                const std::size_t sx = static_cast<std::size_t>(di->dims[1]) * sy;
                const std::uint8_t* f = di->flags.data() + l;
                for (unsigned o = 0; o < 8; ++o)
                    if (*(f - ((o & 1) ? sx : 0) - ((o & 2) ? sy : 0) - ((o & 4) ? 1 : 0)) & 2) allowed &= ~octantFrames[o];
            } else {
                for (unsigned o = 0; o < 8; ++o) {
                    const long lc = di->local(Vec3i(x - static_cast<int>(o & 1), y - static_cast<int>((o >> 1) & 1), zc - static_cast<int>(o >> 2)));
                    if (lc >= 0 && (di->flags[static_cast<std::size_t>(lc)] & 2)) allowed &= ~octantFrames[o];
                }
            }
        }
        if (allowed == 0) return 0;  // every cell around z is implicit
    } else if (!S.sides(x, y, zc, oz, interior)) {
        return 0;  // outside
    }
    // The frames the tet contains there: one mask per face through z (no per-frame tests).
    return interior ? allowed : allowed & containedFrames(T, oz);
}

/// Writes the darts of tet @p tet (sign @p sign) at @p z with the frames of @p frames, in
/// frame order, to @p out; returns the end.
Dart* writeFrames(Dart* out, int tet, const Vec3i& z, signed char sign, std::uint64_t frames) {
    const auto& all = allFrames();
    const int x = z[0], y = z[1], zc = z[2];
    // Field by field into the output: a prototype dart whose frame was stored in pieces and
    // then copied whole stalled the store forwarding at every dart (two thirds of the
    // extraction loop's time on pig x2).
    for (; frames; frames &= frames - 1, ++out) {
        out->tet = tet;
        out->z[0] = x;
        out->z[1] = y;
        out->z[2] = zc;
        out->d = all[static_cast<std::size_t>(__builtin_ctzll(frames))];
        out->sign = sign;
    }
    return out;
}

/// Visits the grid points of @p box in x-major order: row(darts so far) before every row of
/// constant (x, y), and per point with darts point(z, frames), where frames (bits of
/// allFrames()) are the darts of tet @p T there; returns their number. With a dense index
/// @p di, appends its offsets (one per box point: the darts before it, and
/// the total).
template <class Row, class Point>
std::size_t visitTetDarts(const TetSoS& T, const GridBox& box, DartSet::DenseIndex* di,
                          const std::array<std::uint64_t, 8>& octantFrames, Row&& row, Point&& point) {
    BoxFaceSigns S(T);
    std::uint32_t counted = 0;
    std::size_t l = 0;  // local index of (x, y, zc) in the box
    for (int x = box.lo[0]; x <= box.hi[0]; ++x)
        for (int y = box.lo[1]; y <= box.hi[1]; ++y) {
            row(counted);
            for (int zc = box.lo[2]; zc <= box.hi[2]; ++zc, ++l) {
                if (di) di->offset.push_back(counted);
                const std::uint64_t frames = pointFrames(T, S, di, x, y, zc, l, octantFrames);
                if (!frames) continue;
                point(Vec3i(x, y, zc), frames);
                counted += static_cast<std::uint32_t>(__builtin_popcountll(frames));
            }
        }
    if (di) di->offset.push_back(counted);
    return counted;
}

/// Writes the darts of tet @p c (key order) to @p out. With a dense index, its offsets
/// (from the counting pass) skip the points without darts and give the points with all 48
/// at once; other points repeat the counting pass's tests.
void writeTetDarts(const TetSoS& T, int c, const GridBox& box, const DartSet::DenseIndex* di,
                   const std::array<std::uint64_t, 8>& octantFrames, Dart* out) {
    const signed char sign = static_cast<signed char>(T.vol);
    if (!di) {
        visitTetDarts(T, box, nullptr, octantFrames, [](std::uint32_t) {},
                      [&](const Vec3i& z, std::uint64_t frames) { out = writeFrames(out, c, z, sign, frames); });
        return;
    }
    BoxFaceSigns S(T);
    std::size_t l = 0;
    for (int x = box.lo[0]; x <= box.hi[0]; ++x)
        for (int y = box.lo[1]; y <= box.hi[1]; ++y)
            for (int zc = box.lo[2]; zc <= box.hi[2]; ++zc, ++l) {
                const std::uint32_t n = di->offset[l + 1] - di->offset[l];
                if (n == 0) continue;
                const Vec3i z(x, y, zc);
                out = writeFrames(out, c, z, sign, n == 48 ? kAllFrames : pointFrames(T, S, di, x, y, zc, l, octantFrames));
            }
}

/// Where one chunk of the extraction writes its darts (extractInRegions()): its region of
/// the one dart array while the darts fit, then a vector of its own.
class DartWriter {
public:
    /// A writer into [@p begin, @p end).
    DartWriter(Dart* begin, Dart* end) : at_(begin), end_(end) {}
    /// Writes the darts of tet @p tet (sign @p sign) at @p z with the frames of @p frames.
    void write(int tet, const Vec3i& z, int sign, std::uint64_t frames) {
        const auto k = static_cast<std::size_t>(__builtin_popcountll(frames));
        if (overflow_.empty() && static_cast<std::size_t>(end_ - at_) >= k) {
            at_ = writeFrames(at_, tet, z, static_cast<signed char>(sign), frames);
            return;
        }
        const std::size_t old = overflow_.size();
        overflow_.resize(old + k);
        writeFrames(overflow_.data() + old, tet, z, static_cast<signed char>(sign), frames);
    }
    /// One past the last dart written into the region.
    Dart* regionEnd() const { return at_; }
    /// The darts that did not fit into the region (in order after them).
    DartVector& overflow() { return overflow_; }

private:
    Dart* at_;
    Dart* end_;
    DartVector overflow_;
};

/// Gives the pages of @p v beyond its size back to the system (the regions' margins that
/// were written before the darts moved down): they would stay resident for as long as the
/// darts live. Only where the system has madvise(); elsewhere they stay.
void releaseTail(DartVector& v) {
#if defined(__linux__)
    const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
    const auto from = (reinterpret_cast<std::uintptr_t>(v.data() + v.size()) + page - 1) / page * page;
    const auto to = reinterpret_cast<std::uintptr_t>(v.data() + v.capacity()) / page * page;
    if (page > 0 && to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_DONTNEED);
#else
    (void)v;
#endif
}

/// A guess of the darts of tets [b, e): 48 per unit cell of their parameter volume (maps
/// without flipped tets; implicit cells and the domain's boundary only make it smaller).
double expectedDarts(const std::vector<TetSoS>& tets, std::size_t b, std::size_t e) {
    double v = 0;
    for (std::size_t c = b; c < e; ++c) {
        const Vec3d* p = tets[c].p;
        if (tets[c].vol == 0 || !p) continue;
        v += std::abs(tetVolume6(p[0], p[1], p[2], p[3])) / 6;
    }
    return 48 * v;
}

/// The extraction of a map without flipped tets on several threads, without joining copies:
/// each chunk of tets (parallelChunks()) gets a region of one dart array, sized without
/// zeroing from expectedDarts() with a margin, and @p body(k, b, e, writer) writes chunk k's
/// darts there in order; the regions are then moved together (each down, in order: pages
/// already touched) and the array cut to the total. A chunk whose darts outgrow its region
/// goes on in a vector of its own; then all are joined into a new array (the guess is short
/// only by more than its margin). Returns false (nothing done) if the guessed array is too
/// large to ask for; then the caller extracts as before. Sets @p out.darts.
template <class Body>
bool extractInRegions(const std::vector<TetSoS>& tets, int chunks, DartSet& out, Body&& body) {
    const std::size_t n = tets.size();
    std::vector<double> guess(static_cast<std::size_t>(chunks), 0.0);
    parallelChunks(n, chunks, [&](int k, std::size_t b, std::size_t e) { guess[static_cast<std::size_t>(k)] = expectedDarts(tets, b, e); });
    // At most 2^28 darts (5 GiB of address space; the guess overshoots where implicit cells
    // have no darts, and only the pages written are ever touched).
    constexpr double kMostDarts = 268435456.0;
    std::vector<std::size_t> start(static_cast<std::size_t>(chunks) + 1, 0);
    double size = 0;
    for (std::size_t k = 0; k < guess.size(); ++k) {
        size += std::ceil(1.03 * guess[k]) + 4096;  // a margin for the chunk's boundary
        if (!(size <= kMostDarts)) return false;    // (also a non-finite guess)
        start[k + 1] = static_cast<std::size_t>(size);
    }
    DartVector all;
    try {
        all.resize(start.back());  // default-initialized: only the pages written are touched
    } catch (const std::bad_alloc&) {
        return false;
    }
    std::vector<DartWriter> writers;
    writers.reserve(static_cast<std::size_t>(chunks));
    for (std::size_t k = 0; k < guess.size(); ++k) writers.emplace_back(all.data() + start[k], all.data() + start[k + 1]);
    parallelChunks(n, chunks, [&](int k, std::size_t b, std::size_t e) { body(k, b, e, writers[static_cast<std::size_t>(k)]); });
    std::size_t total = 0;
    bool spilled = false;
    for (std::size_t k = 0; k < writers.size(); ++k) {
        total += static_cast<std::size_t>(writers[k].regionEnd() - (all.data() + start[k])) + writers[k].overflow().size();
        spilled = spilled || !writers[k].overflow().empty();
    }
    if (spilled) {
        // The guess fell short by more than the margin somewhere: join into a new array.
        DartVector joined;
        joined.resize(total);
        Dart* to = joined.data();
        for (std::size_t k = 0; k < writers.size(); ++k) {
            to = std::copy(all.data() + start[k], writers[k].regionEnd(), to);
            to = std::copy(writers[k].overflow().begin(), writers[k].overflow().end(), to);
        }
        out.darts = std::move(joined);
        return true;
    }
    // Chunk k's darts go right after those before it, never above its region's start: the
    // regions moved down in order overwrite only darts already moved. The pages they leave
    // behind are given back (releaseTail()).
    // Apart (implicit cells leave much of the guessed room empty), a region is copied by all
    // threads, as the joining path does.
    Dart* to = all.data();
    for (std::size_t k = 0; k < writers.size(); ++k) {
        const Dart* from = all.data() + start[k];
        const auto m = static_cast<std::size_t>(writers[k].regionEnd() - from);
        if (static_cast<std::size_t>(from - to) >= m)
            parallelChunks(m, chunks, [&](int, std::size_t b, std::size_t e) { std::copy(from + b, from + e, to + b); });
        else if (to != from)
            std::memmove(static_cast<void*>(to), from, m * sizeof(Dart));
        to += m;
    }
    all.resize(total);
    releaseTail(all);
    out.darts = std::move(all);
    return true;
}
} // namespace

DartSet extractDarts(const std::vector<TetSoS>& tets, int threads, double max_points, bool implicit_cells,
                     const std::vector<FaceMask>* usable_faces, double expected_cells, std::size_t max_darts,
                     const std::vector<int>* chart_component) {
    std::atomic<std::size_t> extracted{0};  // all chunks together, for the cap
    constexpr std::size_t kCapCheck = 1u << 16;  // darts of one tet before its own count is checked against the cap
    const std::size_t n = tets.size();
    const int chunks = std::max(1, threads);
    std::vector<std::vector<DartSet::DenseIndex>> denseParts(static_cast<std::size_t>(chunks));
    // Implicit cells marked per chunk (counted where they are marked: a serial pass over the
    // dense flags afterwards took 6 ms of the cylinder v6's stage).
    std::vector<long> implicitCells(static_cast<std::size_t>(chunks), 0);
    constexpr double kDenseMinPoints = kDenseIndexMinPoints;  // smaller tets: binary search is as fast
    std::vector<std::size_t> count(n, 0);  // darts per tet
    const std::array<std::uint64_t, 8> octantFrames = octantFrameMasks();
    auto capError = [&] {
        return ResourceError("dart extraction stopped after more than " + std::to_string(max_darts) +
                             " darts, the most the memory budget allows");
    };
    // With flipped tets the counting pass comes first: the dense indices then get their
    // in-image and on-face flags by rows (a few predicates per row instead of four per
    // point), which both passes read.
    const bool folds = std::any_of(tets.begin(), tets.end(), [](const TetSoS& T) { return T.vol < 0; });
    const bool rowSigns = folds;
    // The tet's grid box and, for a large image, its dense index (with the implicit-cell
    // flags); null for a small tet.
    auto prepareTet = [&](int k, std::size_t c, GridBox& box) -> DartSet::DenseIndex* {
        const TetSoS& T = tets[c];
        box = gridBox(T, c);
        if (box.points > max_points)
            throw InputError("tet " + std::to_string(c) + ": parameter image spans " + std::to_string(box.points) +
                             " grid points (limit " + std::to_string(max_points) + ")");
        if (box.points < kDenseMinPoints) return nullptr;
        auto& di = denseParts[static_cast<std::size_t>(k)].emplace_back();
        di.tet = static_cast<int>(c);
        for (int a = 0; a < 3; ++a) {
            di.lo[a] = box.lo[a];
            di.dims[a] = box.hi[a] - box.lo[a] + 1;
        }
        di.offset.reserve(static_cast<std::size_t>(box.points) + 1);
        if (implicit_cells && T.vol > 0)
            implicitCells[static_cast<std::size_t>(k)] += markBoxFlags(T, usable_faces ? (*usable_faces)[c] : FaceMask(0), di, true);
        else if (rowSigns) markBoxFlags(T, FaceMask(0), di, false);
        return &di;
    };
    auto capCheck = [&](std::uint32_t sofar) {
        // A tet with a huge image must not run on far beyond the budget.
        if (sofar > kCapCheck && extracted.load(std::memory_order_relaxed) + sofar > max_darts) throw capError();
    };
    auto counted = [&](std::size_t c, std::size_t cnt) {
        count[c] = cnt;
        if (extracted.fetch_add(cnt, std::memory_order_relaxed) + cnt > max_darts) throw capError();
    };
    DartSet s;
    if (!folds) {
        // Chunk k's darts in order, each point's to emit(tet, z, sign, frames).
        auto extractChunk = [&](int k, std::size_t b, std::size_t e, auto&& emit) {
            for (std::size_t c = b; c < e; ++c) {
                const TetSoS& T = tets[c];
                if (T.vol == 0) continue;
                GridBox box;
                DartSet::DenseIndex* di = prepareTet(k, c, box);
                const int tet = static_cast<int>(c);
                counted(c, visitTetDarts(T, box, di, octantFrames, capCheck,
                                         [&](const Vec3i& z, std::uint64_t frames) { emit(tet, z, T.vol, frames); }));
            }
        };
        // Without flipped tets every unit cell has its 48 darts once: the volume predicts the
        // count. On several threads each chunk writes into its own region of one array
        // (extractInRegions()); on one, or if that array is too large to ask for, chunk 0
        // reserves room for all (untouched reserved memory costs no RSS) and the other
        // chunks' darts are appended to it. One pass either way.
        if (chunks == 1 || !extractInRegions(tets, chunks, s, [&](int k, std::size_t b, std::size_t e, DartWriter& out) {
                extractChunk(k, b, e, [&](int tet, const Vec3i& z, int sign, std::uint64_t frames) { out.write(tet, z, sign, frames); });
            })) {
            std::vector<DartVector> parts(static_cast<std::size_t>(chunks));
            parallelChunks(n, chunks, [&](int k, std::size_t b, std::size_t e) {
                auto& out = parts[static_cast<std::size_t>(k)];
                const double cells = k == 0 ? expected_cells : expected_cells * static_cast<double>(e - b) / static_cast<double>(n);
                try {
                    out.reserve(static_cast<std::size_t>(std::min(50.0 * std::max(0.0, cells) + 4096.0, 64.0 * 1024 * 1024)));
                } catch (const std::bad_alloc&) {  // the estimate is only a hint
                }
                extractChunk(k, b, e, [&](int tet, const Vec3i& z, int sign, std::uint64_t frames) {
                    const std::size_t at = out.size();
                    out.resize(at + static_cast<std::size_t>(__builtin_popcountll(frames)));
                    writeFrames(out.data() + at, tet, z, static_cast<signed char>(sign), frames);
                });
            });
            std::size_t total = 0;
            for (const auto& p : parts) total += p.size();
            s.darts = std::move(parts[0]);
            // The other chunks' darts are appended by all threads (sized without zeroing: the
            // copies touch the new pages in parallel), each thread an equal share of the range.
            const std::size_t head = s.darts.size();
            s.darts.resize(total);
            parallelChunks(total - head, chunks, [&](int, std::size_t b, std::size_t e) {
                std::size_t at = 0;  // start of part k in the appended range
                for (std::size_t k = 1; k < parts.size(); ++k) {
                    const std::size_t lo = std::max(b, at), hi = std::min(e, at + parts[k].size());
                    if (lo < hi) std::copy(parts[k].begin() + static_cast<long>(lo - at), parts[k].begin() + static_cast<long>(hi - at),
                                           s.darts.begin() + static_cast<long>(head + lo));
                    at += parts[k].size();
                }
            });
        }
        s.tet_begin.assign(n + 1, 0);
        for (std::size_t c = 0; c < n; ++c) s.tet_begin[c + 1] = s.tet_begin[c] + count[c];
    } else {
        // With folds the count is not predictable (fold layers multiply it), and growing and
        // joining buffers briefly held two to three times the darts, the peak of the whole
        // extraction. So two passes over the same enumeration: the first counts every tet's
        // darts (points strictly inside without going through their frames) and builds the
        // dense indices, the second writes the darts straight to their place in one array
        // allocated at the exact size.
        // With cheap folds the cap applies to the darts left after the cancellation: the
        // counting pass allocates nothing per dart, and a fold that cancels must not be
        // refused for the darts it would have had.
        const bool capAfterCancel = chart_component != nullptr;
        // The points with darts of the small tets (no dense index: fewer than
        // kDenseIndexMinPoints box points), one word each in tet and box order: the frames
        // (bits 0..47) and the point's index in the tet's box (bits 48..63). The writing pass
        // expands them instead of testing every box point of the tet again (it cost a third
        // of the stage on folded maps); both passes give chunk k the same tets.
        std::vector<std::vector<std::uint64_t>> smallPoints(static_cast<std::size_t>(chunks));
        parallelChunks(n, chunks, [&](int k, std::size_t b, std::size_t e) {
            for (std::size_t c = b; c < e; ++c) {
                if (tets[c].vol == 0) continue;
                GridBox box;
                DartSet::DenseIndex* di = prepareTet(k, c, box);
                auto& points = smallPoints[static_cast<std::size_t>(k)];
                auto keep = [&](const Vec3i& z, std::uint64_t frames) {
                    if (di) return;  // dense indices have their offsets
                    const int dy = box.hi[1] - box.lo[1] + 1, dz = box.hi[2] - box.lo[2] + 1;
                    const auto l = static_cast<std::uint64_t>(((z[0] - box.lo[0]) * dy + (z[1] - box.lo[1])) * dz + (z[2] - box.lo[2]));
                    points.push_back(frames | l << 48);
                };
                if (capAfterCancel)
                    count[c] = visitTetDarts(tets[c], box, di, octantFrames, [](std::uint32_t) {}, keep);
                else
                    counted(c, visitTetDarts(tets[c], box, di, octantFrames, capCheck, keep));
            }
        });
        if (chart_component) {
            std::vector<DartSet::DenseIndex*> all;
            for (auto& part : denseParts)
                for (auto& di : part) all.push_back(&di);
            s.n_cancelled = cancelFoldPoints(tets, *chart_component, all, count);
        }
        s.tet_begin.assign(n + 1, 0);
        for (std::size_t c = 0; c < n; ++c) s.tet_begin[c + 1] = s.tet_begin[c] + count[c];
        if (capAfterCancel && s.tet_begin[n] > max_darts) throw capError();
        std::vector<std::size_t>().swap(count);
        s.darts.resize(s.tet_begin[n]);  // default-initialized: no pass over the memory
        parallelChunks(n, chunks, [&](int k, std::size_t b, std::size_t e) {
            std::size_t nextDense = 0;  // the chunk's dense indices, in tet order
            auto& dense = denseParts[static_cast<std::size_t>(k)];
            const std::vector<std::uint64_t>& points = smallPoints[static_cast<std::size_t>(k)];
            std::size_t nextPoint = 0;  // the chunk's small-tet points, in tet order
            for (std::size_t c = b; c < e; ++c) {
                const TetSoS& T = tets[c];
                if (T.vol == 0) continue;
                const DartSet::DenseIndex* di =
                    nextDense < dense.size() && dense[nextDense].tet == static_cast<int>(c) ? &dense[nextDense++] : nullptr;
                const GridBox box = gridBox(T, c);
                if (di) {
                    writeTetDarts(T, static_cast<int>(c), box, di, octantFrames, s.darts.data() + s.tet_begin[c]);
                    continue;
                }
                // The tet's recorded points, until its count is written (each has a dart).
                const int dy = box.hi[1] - box.lo[1] + 1, dz = box.hi[2] - box.lo[2] + 1;
                Dart* out = s.darts.data() + s.tet_begin[c];
                Dart* const end = s.darts.data() + s.tet_begin[c + 1];
                while (out != end) {
                    const std::uint64_t r = points[nextPoint++];
                    const int l = static_cast<int>(r >> 48);
                    const Vec3i z(box.lo[0] + l / (dy * dz), box.lo[1] + (l / dz) % dy, box.lo[2] + l % dz);
                    out = writeFrames(out, static_cast<int>(c), z, static_cast<signed char>(T.vol), r & kAllFrames);
                }
            }
        });
    }
    s.dense_slot.assign(n, -1);
    for (auto& part : denseParts)
        for (auto& di : part) {
            s.dense_slot[static_cast<std::size_t>(di.tet)] = static_cast<int>(s.dense.size());
            di.occ_base = s.n_occurrences;
            s.n_occurrences += static_cast<long>(di.offset.size()) - 1;
            s.dense.push_back(std::move(di));
        }
    for (long cells : implicitCells) s.n_implicit_cells += cells;
    return s;
}

} // namespace HexEx
