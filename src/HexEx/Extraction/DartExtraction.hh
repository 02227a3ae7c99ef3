#pragma once
/// @file DartExtraction.hh
/// @ingroup pipeline
/// Dart extraction (paper 4.3.1) with the symbolic-perturbation ownership rule: the dart
/// (z, d1, d2, d3) belongs to the tet whose parameter image contains z + e d1 + e^2 d2 + e^3 d3.
/// Darts of flipped tets are anti darts.

#include "../Mesh/ParametrizedTetMesh.hh"
#include "../Core/DefaultInitAllocator.hh"
#include "TetSoS.hh"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace HexEx {

/// A dart as extracted: hex corner z with frame (d1, d2, d3), seen from tet `tet`, in that
/// tet's chart. The edge runs along d1, the face spans d1, d2, the cell spans d1, d2, d3.
/// The members have no initializers on purpose: DartSet::darts is sized without a zeroing
/// pass and filled in parallel (a default-constructed Dart is indeterminate).
struct Dart {
    int tet;                       ///< owning tet
    Vec3i z;                       ///< grid point in the tet's chart
    std::array<AxisDir, 3> d;      ///< frame directions
    signed char sign;              ///< +1 regular dart, -1 anti dart
};

/// The dart array: a vector that sizes without zeroing (see DefaultInitAllocator).
using DartVector = std::vector<Dart, DefaultInitAllocator<Dart>>;

/// Equality of frames without std::array's memcmp (hot in lookups).
inline bool sameFrame(const std::array<AxisDir, 3>& a, const std::array<AxisDir, 3>& b) {
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}
/// Equality of grid points, component-wise.
inline bool samePoint(const Vec3i& a, const Vec3i& b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

/// Orders darts by (z, d1, d2, d3) within a tet.
inline bool dartKeyLess(const Vec3i& za, const std::array<AxisDir, 3>& da, const Vec3i& zb,
                        const std::array<AxisDir, 3>& db) {
    for (int k = 0; k < 3; ++k)
        if (za[k] != zb[k]) return za[k] < zb[k];
    // Lexicographic on the three direction codes, packed (std::array's operator< goes through memcmp).
    return ((da[0] << 16) | (da[1] << 8) | da[2]) < ((db[0] << 16) | (db[1] << 8) | db[2]);
}

/// All darts, grouped by tet (ascending) and sorted by key within a tet.
struct DartSet {
    DartVector darts;                   ///< the darts
    std::vector<std::size_t> tet_begin; ///< darts of tet t are [tet_begin[t], tet_begin[t+1])
    /// Tets with large parameter images get a dense index over their integer bounding box
    /// so that find() is O(1): box (lo, dims) and, per box point, the first dart there.
    struct DenseIndex {
        int tet = -1;                       ///< the tet
        int lo[3] = {0, 0, 0};              ///< smallest grid point of the box
        int dims[3] = {0, 0, 0};            ///< box size per axis
        std::vector<std::uint32_t> offset;  ///< per box point (x-major), first dart relative to tet_begin; one extra at the end
        /// Per box point: bit 0 = in the closed tet image, bit 1 = the unit cell with this
        /// lower corner is implicit (no darts stored), bit 2 = may be a corner of an implicit
        /// cell, bits 4..7 = lies on face j (o_j = 0). Empty unless implicit cells are on or
        /// the map has flipped tets (then bits 1 and 2 are never set).
        std::vector<std::uint8_t> flags;
        bool implicit_marks = false;        ///< bits 1 and 2 of #flags were computed
        long occ_base = 0;                  ///< first occurrence id of this box (see occurrence())
        /// Per box point: a cancelled fold point (FoldCancellation.hh), without darts. Empty
        /// if the tet has none.
        std::vector<bool> cancelled;
        /// Per box point: cancelled, and the tet owned only some of its frames there (the
        /// point is on its boundary). Empty if the tet has no such point.
        std::vector<bool> cancelled_partly;
        /// Local index of @p z in the box, or -1 outside.
        long local(const Vec3i& z) const {
            long l = 0;
            for (int k = 0; k < 3; ++k) {
                const int c = z[k] - lo[k];
                if (c < 0 || c >= dims[k]) return -1;
                l = l * dims[k] + c;
            }
            return l;
        }
    };
    std::vector<DenseIndex> dense;      ///< dense indices of the large tets
    std::vector<int> dense_slot;        ///< per tet: index into dense, or -1

    long n_occurrences = 0;             ///< total box points of the dense indices
    long n_implicit_cells = 0;          ///< unit cells produced without darts
    long n_cancelled = 0;               ///< (tet, grid point) occurrences cancelled as fold points (no darts)

    /// Index of the dart of tet @p t with key (z, d), or -1.
    long find(int t, const Vec3i& z, const std::array<AxisDir, 3>& d) const;
    /// find() for a caller that already has the tet's dense slot @p slot (dense_slot, or -1)
    /// and its dart range [@p begin, @p end) (tet_begin): the same index, without reading
    /// those two arrays again (the tracing keeps them in one record per tet).
    long findInTet(int slot, std::size_t begin, std::size_t end, const Vec3i& z, const std::array<AxisDir, 3>& d) const;
    /// Occurrence id of grid point @p z in the closed image of tet @p t (a vertex known
    /// without darts), or -1 if @p t has no dense index with flags or @p z is outside.
    long occurrence(int t, const Vec3i& z) const;
    /// Inverse of occurrence(): the tet @p tet and grid point @p z of occurrence id @p occ
    /// (0 <= occ < n_occurrences; the dense index holding it is the last with occ_base <= occ).
    void occurrencePoint(long occ, int& tet, Vec3i& z) const;
    /// Whether @p z is a cancelled fold point of tet @p t (its darts cancelled and not
    /// stored; the alpha_0 tracing walks through it): 0 no, 1 yes and @p t owned all 48
    /// frames there, 2 yes and @p t owned some of them (z on its boundary).
    int cancelledPoint(int t, const Vec3i& z) const {
        if (n_cancelled == 0) return 0;
        const int slot = dense_slot[static_cast<std::size_t>(t)];
        if (slot < 0) return 0;
        const DenseIndex& di = dense[static_cast<std::size_t>(slot)];
        if (di.cancelled.empty()) return 0;
        const long l = di.local(z);
        if (l < 0 || !di.cancelled[static_cast<std::size_t>(l)]) return 0;
        return !di.cancelled_partly.empty() && di.cancelled_partly[static_cast<std::size_t>(l)] ? 2 : 1;
    }
    /// Signs of the four face functions of tet @p t (data @p T) at grid point @p z: read from
    /// the dense index's flags when it has them and @p z is in the closed image, else
    /// computed (TetSoS::sides()).
    std::array<int, 4> pointSides(int t, const TetSoS& T, const Vec3i& z) const;
    /// True if the unit cell of the dart (z, d) in tet @p t is implicit (no darts stored).
    bool implicitCell(int t, const Vec3i& z, const std::array<AxisDir, 3>& d) const {
        return implicitInSlot(dense_slot.empty() ? -1 : dense_slot[static_cast<std::size_t>(t)], z, d);
    }
    /// implicitCell() for a caller that already has the tet's dense slot @p slot (or -1).
    bool implicitInSlot(int slot, const Vec3i& z, const std::array<AxisDir, 3>& d) const;
};

/// The 48 axis frames (d1, d2, d3) in lexicographic order.
const std::array<std::array<AxisDir, 3>, 48>& allFrames();

/// Tets whose integer grid box (gridBox()) has at least this many points get a dense index
/// (DartSet::DenseIndex); smaller ones are searched by binary search.
constexpr double kDenseIndexMinPoints = 64;

/// Integer bounding box [lo, hi] of a tet's parameter image and its number of grid points.
struct GridBox {
    int lo[3] = {0, 0, 0};  ///< smallest grid point
    int hi[3] = {0, 0, 0};  ///< largest grid point
    double points = 0;      ///< grid points in the box
};

/// The grid box of tet @p c (data @p T); throws InputError for non-finite or absurd
/// parameters (|u| > 1e9).
GridBox gridBox(const TetSoS& T, std::size_t c);

/// Per-tet symbolic-perturbation data for every tet (computed in parallel).
std::vector<TetSoS> buildTetSoS(const CornerParams& params, int threads);

/// Lower corner of the unit grid cell that the dart (z, d) spans.
inline Vec3i cellLowerCorner(const Vec3i& z, const std::array<AxisDir, 3>& d) {
    Vec3i c = z;
    for (AxisDir x : d)
        if (dirSign(x) < 0) --c[dirAxis(x)];
    return c;
}

/// Position of the frame @p d (three distinct axes) in allFrames(): d1 picks a block of 8,
/// d2 one of the 4 directions off d1's axis, d3 one of the 2 on the remaining axis. For a
/// frame that repeats an axis the value means nothing and may lie outside [0, 48).
inline int frameIndex(const std::array<AxisDir, 3>& d) {
    const int d1 = d[0], d2 = d[1];
    return d1 * 8 + (d2 - (dirAxis(d[1]) > dirAxis(d[0]) ? 2 : 0)) * 2 + (d[2] & 1);
}

/// Packed key of a frame, in the order of dartKeyLess().
inline int frameKey(const std::array<AxisDir, 3>& d) { return (d[0] << 16) | (d[1] << 8) | d[2]; }

inline long DartSet::findInTet(int slot, std::size_t begin, std::size_t end, const Vec3i& z,
                               const std::array<AxisDir, 3>& d) const {
    if (slot >= 0) {
        const DenseIndex& di = dense[static_cast<std::size_t>(slot)];
        const long l = di.local(z);
        if (l < 0) return -1;
        const std::size_t lo = begin + di.offset[static_cast<std::size_t>(l)];
        const std::size_t hi = begin + di.offset[static_cast<std::size_t>(l) + 1];
        // A point with all 48 frames holds each once, in allFrames() order (key order). The
        // index is in range for every proper frame; anything else falls back to the scan.
        const int fi = frameIndex(d);
        if (hi - lo == 48 && fi >= 0 && fi < 48) {
            const std::size_t k = lo + static_cast<std::size_t>(fi);
            if (sameFrame(darts[k].d, d)) return static_cast<long>(k);
        }
        // Key order: the first dart with the frame, if any, comes before any larger key.
        const int key = frameKey(d);
        for (std::size_t k = lo; k < hi; ++k) {
            const int kk = frameKey(darts[k].d);
            if (kk >= key) return kk == key ? static_cast<long>(k) : -1;
        }
        return -1;
    }
    const Dart* first = darts.data() + begin;
    const Dart* last = darts.data() + end;
    const Dart* it = std::lower_bound(first, last, 0, [&](const Dart& x, int) { return dartKeyLess(x.z, x.d, z, d); });
    if (it != last && samePoint(it->z, z) && sameFrame(it->d, d)) return it - darts.data();
    return -1;
}

inline bool DartSet::implicitInSlot(int slot, const Vec3i& z, const std::array<AxisDir, 3>& d) const {
    if (slot < 0) return false;
    const DenseIndex& di = dense[static_cast<std::size_t>(slot)];
    if (di.flags.empty()) return false;
    const long l = di.local(cellLowerCorner(z, d));
    return l >= 0 && (di.flags[static_cast<std::size_t>(l)] & 2);
}

/// Bit j of the per-tet masks passed to extractDarts(): grid points on face j may be
/// corners of implicit cells.
using FaceMask = std::uint8_t;

/// Extracts every dart of every non-degenerate tet. Deterministic for any thread count.
/// Throws InputError if a tet's parameter image is absurdly large (more than
/// @p max_points_per_tet grid points in its bounding box). With @p implicit_cells, unit
/// cells contained in the closed image of one large proper tet get no darts: they are
/// hexes by construction (only valid when no tet is flipped, so nothing can annihilate
/// them). A corner of such a cell must lie strictly inside the tet or on a face j with bit
/// j set in @p usable_faces[t] (the caller allows boundary faces and faces shared with a
/// proper tet, where vertices can be joined across; without masks only strictly interior
/// corners are used). @p expected_cells (e.g. the parametric volume) sizes the buffers of a
/// map without flipped tets; with flipped tets the darts are counted first and then
/// written in place (one exact allocation: fold layers make the count unpredictable).
/// With @p chart_component (identityChartComponents()) and flipped tets, cancelled fold
/// points get no darts (cancelFoldPoints(); DartSet::n_cancelled counts them).
/// Throws ResourceError as soon as more than @p max_darts darts have been extracted (the
/// outcome does not depend on the thread count: the total does not); with
/// @p chart_component (cheap folds) the darts left after the cancellation are checked,
/// after the counting pass and before any dart is stored.
DartSet extractDarts(const std::vector<TetSoS>& tets, int threads, double max_points_per_tet = 1e9,
                     bool implicit_cells = false, const std::vector<FaceMask>* usable_faces = nullptr,
                     double expected_cells = 0, std::size_t max_darts = static_cast<std::size_t>(-1),
                     const std::vector<int>* chart_component = nullptr);

} // namespace HexEx
