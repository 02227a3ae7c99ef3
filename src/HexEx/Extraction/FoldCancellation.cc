#include "FoldCancellation.hh"

#include "../Core/Error.hh"
#include "../Core/UnionFind.hh"

#include <algorithm>
#include <cstdint>
#include <map>

namespace HexEx {

std::vector<int> identityChartComponents(const TetMesh& mesh, const Transitions& transitions) {
    const std::size_t n = mesh.n_cells();
    UnionFind uf(n);
    for (std::size_t c = 0; c < n; ++c)
        for (int f = 0; f < 4; ++f) {
            const HalfFaceHandle hf = TetMesh::halfface(CellHandle(static_cast<int>(c)), f);
            const HalfFaceHandle opp = mesh.opposite_halfface(hf);
            if (opp.is_valid() && transitions.halfface[hf.uidx()].is_identity())
                uf.unite(static_cast<int>(c), TetMesh::cell(opp).idx());
        }
    std::vector<int> comp(n);
    for (std::size_t c = 0; c < n; ++c) comp[c] = uf.find(static_cast<int>(c));  // the smallest tet (unite() keeps it)
    return comp;
}

bool mayCancelFoldPoints(const std::vector<TetSoS>& tets) {
    for (std::size_t c = 0; c < tets.size(); ++c) {
        const TetSoS& T = tets[c];
        if (T.vol >= 0) continue;
        if (!T.p) return true;
        try {
            if (gridBox(T, c).points >= kDenseIndexMinPoints) return true;
        } catch (const InputError&) {
            return true;  // non-finite or absurd parameters: the extraction reports them
        }
    }
    return false;
}

namespace {

/// An integer box [lo, hi] (empty if some hi < lo).
struct IntBox {
    long lo[3] = {0, 0, 0};  ///< smallest grid point
    long hi[3] = {-1, -1, -1};  ///< largest grid point
    /// Number of grid points.
    double points() const {
        double p = 1;
        for (int a = 0; a < 3; ++a) p *= static_cast<double>(std::max(0L, hi[a] - lo[a] + 1));
        return p;
    }
    /// Intersection with @p o.
    IntBox meet(const IntBox& o) const {
        IntBox b;
        for (int a = 0; a < 3; ++a) {
            b.lo[a] = std::max(lo[a], o.lo[a]);
            b.hi[a] = std::min(hi[a], o.hi[a]);
        }
        return b;
    }
    /// Local index of (x, y, z) in this box (x-major), assumed inside.
    std::size_t local(long x, long y, long z) const {
        return (static_cast<std::size_t>(x - lo[0]) * static_cast<std::size_t>(hi[1] - lo[1] + 1) + static_cast<std::size_t>(y - lo[1])) *
                   static_cast<std::size_t>(hi[2] - lo[2] + 1) +
               static_cast<std::size_t>(z - lo[2]);
    }
};

IntBox denseBox(const DartSet::DenseIndex& di) {
    IntBox b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = di.lo[a];
        b.hi[a] = static_cast<long>(di.lo[a]) + di.dims[a] - 1;
    }
    return b;
}

/// The integer box of tet @p t's parameter image.
IntBox tetBox(const TetSoS& T, std::size_t t) {
    const GridBox g = gridBox(T, t);
    IntBox b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = g.lo[a];
        b.hi[a] = g.hi[a];
    }
    return b;
}

/// Calls f(x, y, z) for every point of @p b.
template <class F>
void forEachPoint(const IntBox& b, F&& f) {
    for (long x = b.lo[0]; x <= b.hi[0]; ++x)
        for (long y = b.lo[1]; y <= b.hi[1]; ++y)
            for (long z = b.lo[2]; z <= b.hi[2]; ++z) f(x, y, z);
}

/// The frames (bit = index in allFrames()) that a tet with face signs @p oz at a grid point
/// owns there.
std::uint64_t frameMask(const TetSoS& T, const std::array<int, 4>& oz) {
    const auto& frames = allFrames();
    std::uint64_t m = 0;
    for (std::size_t f = 0; f < frames.size(); ++f)
        if (T.contains(oz, frames[f][0], frames[f][1], frames[f][2])) m |= std::uint64_t(1) << f;
    return m;
}
} // namespace

long cancelFoldPoints(const std::vector<TetSoS>& tets, const std::vector<int>& component,
                      const std::vector<DartSet::DenseIndex*>& dense, std::vector<std::size_t>& count,
                      std::size_t max_flipped) {
    constexpr std::uint32_t kAll = 48;
    constexpr std::uint64_t kAllFrames = (std::uint64_t(1) << 48) - 1;
    auto darts = [](const DartSet::DenseIndex& di, std::size_t l) { return di.offset[l + 1] - di.offset[l]; };
    // Per component with flipped dense tets: the box around them, and per grid point in it
    // the frames owned by proper and by flipped tets (a frame owned twice by one kind, or a
    // point in the box of a tet without dense index, makes the point "mixed").
    struct Region {
        IntBox box;
        double flipped_points = 0;
        std::vector<std::uint64_t> regular, anti;
        std::vector<char> mixed;
    };
    std::map<int, Region> regions;
    std::size_t flipped = 0;
    for (const DartSet::DenseIndex* di : dense) {
        if (tets[static_cast<std::size_t>(di->tet)].vol >= 0) continue;
        ++flipped;
        const IntBox b = denseBox(*di);
        auto [it, fresh] = regions.try_emplace(component[static_cast<std::size_t>(di->tet)]);
        Region& r = it->second;
        if (fresh) r.box = b;
        for (int a = 0; a < 3; ++a) {
            r.box.lo[a] = std::min(r.box.lo[a], b.lo[a]);
            r.box.hi[a] = std::max(r.box.hi[a], b.hi[a]);
        }
        r.flipped_points += b.points();
    }
    if (flipped == 0 || flipped > max_flipped) return 0;
    // The arrays span the region's box: skip regions where it would be much larger than the
    // flipped tets' own boxes (flipped tets far apart).
    for (auto it = regions.begin(); it != regions.end();) {
        if (it->second.box.points() > 4 * it->second.flipped_points + 1e6) it = regions.erase(it);
        else ++it;
    }
    if (regions.empty()) return 0;
    for (auto& [c, r] : regions) {
        const auto n = static_cast<std::size_t>(r.box.points());
        r.regular.assign(n, 0);
        r.anti.assign(n, 0);
        r.mixed.assign(n, 0);
    }
    std::vector<int> denseOf(tets.size(), -1);
    for (std::size_t k = 0; k < dense.size(); ++k) denseOf[static_cast<std::size_t>(dense[k]->tet)] = static_cast<int>(k);

    // Owners by every tet of the region's component. Degenerate tets own no darts. A small
    // tet (without dense index) makes its whole box mixed: conservative, and its box is small.
    for (std::size_t t = 0; t < tets.size(); ++t) {
        auto it = regions.find(component[t]);
        if (it == regions.end()) continue;
        Region& r = it->second;
        const TetSoS& T = tets[t];
        if (T.vol == 0) continue;
        if (denseOf[t] < 0) {
            if (!T.p) {  // no parameters known: cannot bound it
                r.mixed.assign(r.mixed.size(), 1);
                continue;
            }
            forEachPoint(tetBox(T, t).meet(r.box), [&](long x, long y, long z) { r.mixed[r.box.local(x, y, z)] = 1; });
            continue;
        }
        const DartSet::DenseIndex& di = *dense[static_cast<std::size_t>(denseOf[t])];
        const IntBox own = denseBox(di);
        forEachPoint(own.meet(r.box), [&](long x, long y, long z) {
            const std::uint32_t n = darts(di, own.local(x, y, z));
            if (n == 0) return;
            const std::size_t g = r.box.local(x, y, z);
            if (r.mixed[g]) return;
            std::uint64_t m = kAllFrames;
            if (n != kAll) {
                std::array<int, 4> oz;
                const std::size_t l = own.local(x, y, z);
                if (!di.flags.empty() && (di.flags[l] & 1))  // signs found by rows in the counting pass
                    for (int j = 0; j < 4; ++j) oz[static_cast<std::size_t>(j)] = ((di.flags[l] >> (4 + j)) & 1) ? 0 : T.vol;
                else
                    oz = T.sides(Vec3d(static_cast<double>(x), static_cast<double>(y), static_cast<double>(z)));
                m = frameMask(T, oz);
            }
            std::uint64_t& owned = T.vol > 0 ? r.regular[g] : r.anti[g];
            if (owned & m) r.mixed[g] = 1;
            owned |= m;
        });
    }
    // Cancelled: every frame has exactly one regular and one anti owner.
    long occurrences = 0;
    for (DartSet::DenseIndex* di : dense) {
        auto it = regions.find(component[static_cast<std::size_t>(di->tet)]);
        if (it == regions.end()) continue;
        const Region& r = it->second;
        const IntBox own = denseBox(*di);
        std::uint32_t removed = 0;
        forEachPoint(own.meet(r.box), [&](long x, long y, long z) {
            const std::size_t l = own.local(x, y, z);
            const std::size_t g = r.box.local(x, y, z);
            const std::uint32_t n = darts(*di, l);
            if (n == 0 || r.mixed[g] || r.regular[g] != kAllFrames || r.anti[g] != kAllFrames) return;
            if (di->cancelled.empty()) di->cancelled.assign(di->offset.size() - 1, false);
            di->cancelled[l] = true;
            if (n != kAll) {
                if (di->cancelled_partly.empty()) di->cancelled_partly.assign(di->offset.size() - 1, false);
                di->cancelled_partly[l] = true;
            }
            removed += n;
            ++occurrences;
        });
        if (removed == 0) continue;
        // The offsets without the cancelled points' darts.
        std::uint32_t acc = 0;
        for (std::size_t l = 0; l + 1 < di->offset.size(); ++l) {
            const std::uint32_t n = darts(*di, l);
            di->offset[l] = acc;
            if (!di->cancelled[l]) acc += n;
        }
        di->offset.back() = acc;
        count[static_cast<std::size_t>(di->tet)] -= removed;
    }
    return occurrences;
}

} // namespace HexEx
