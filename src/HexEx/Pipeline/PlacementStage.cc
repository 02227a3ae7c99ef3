#include "PlacementStage.hh"

#include "../Core/Parallel.hh"
#include "GridPointPosition.hh"

#include <optional>

namespace HexEx {

namespace {

/// frameHandedness() of every frame of direction codes 0..5, indexed 36 a + 6 b + c: a table
/// lookup per dart instead of the axis and sign arithmetic (5.4 million darts on pig x2).
class HandednessTable {
public:
    HandednessTable() {
        for (int a = 0; a < 6; ++a)
            for (int b = 0; b < 6; ++b)
                for (int c = 0; c < 6; ++c)
                    table_[static_cast<std::size_t>(36 * a + 6 * b + c)] = static_cast<signed char>(
                        frameHandedness(static_cast<AxisDir>(a), static_cast<AxisDir>(b), static_cast<AxisDir>(c)));
    }
    /// frameHandedness(@p f[0], @p f[1], @p f[2]).
    signed char operator()(const std::array<AxisDir, 3>& f) const {
        if (f[0] > 5 || f[1] > 5 || f[2] > 5)  // not direction codes: as frameHandedness()
            return static_cast<signed char>(frameHandedness(f[0], f[1], f[2]));
        return table_[static_cast<std::size_t>(36 * f[0] + 6 * f[1] + f[2])];
    }

private:
    std::array<signed char, 216> table_{};
};

/// Positions of grid points taken one after the other (gridPointPosition()): the setup of a
/// tet (TetPointPositions) is made once for consecutive points in the same tet, and a point
/// equal to the one before is not computed again. The same numbers as gridPointPosition():
/// a position depends only on the tet and the point. (On folded maps the heirs' entries of
/// one point and tet come in a row, one per heir.)
class PointPlacer {
public:
    /// For the tets of @p mesh (@p tets, @p ds as for gridPointPosition()).
    PointPlacer(const TetMesh& mesh, const std::vector<TetSoS>& tets, const DartSet& ds) : mesh_(mesh), tets_(tets), ds_(ds) {}

    /// Position of grid point @p z of tet @p t into @p pos, its boundary halffaces into @p bhf.
    void place(int t, const Vec3i& z, Vec3d& pos, std::array<int, 3>& bhf) {
        if (t == tet_ && placed_ && samePoint(z, z_)) {
            pos = pos_;
            bhf = bhf_;
            return;
        }
        if (t != tet_) {
            at_.emplace(mesh_, tets_, ds_, t);
            tet_ = t;
        }
        bhf = {-1, -1, -1};
        pos = (*at_)(z, &bhf);
        z_ = z;
        pos_ = pos;
        bhf_ = bhf;
        placed_ = true;
    }

private:
    const TetMesh& mesh_;
    const std::vector<TetSoS>& tets_;
    const DartSet& ds_;
    std::optional<TetPointPositions> at_;  // setup of tet_
    int tet_ = -1;
    bool placed_ = false;  // z_, pos_, bhf_ hold the last point placed (in tet_)
    Vec3i z_;
    Vec3d pos_;
    std::array<int, 3> bhf_{};
};

} // namespace

DartGeometry placementStage(const PlacementInput& in) {
    const DartSet& ds = *in.darts;
    const std::vector<char>& alive = *in.alive;
    const std::vector<int>& newIndex = *in.new_index;
    const int threads = in.threads;
    const std::size_t nd = ds.darts.size();
    DartGeometry geo;
    geo.mesh = in.mesh;
    geo.handedness.resize(static_cast<std::size_t>(in.n_alive));
    // Darts are sorted by (tet, grid point): a run of alive darts at the same point shares
    // one placed point (position and boundary faces), computed once; every dart refers to
    // its run's point. Runs are counted per chunk, then numbered in order.
    auto runStart = [&](std::size_t d) {
        if (d == 0 || !alive[d - 1]) return true;
        const Dart& P = ds.darts[d - 1];
        const Dart& D = ds.darts[d];
        return P.tet != D.tet || !samePoint(P.z, D.z);
    };
    std::vector<int> runsInChunk(static_cast<std::size_t>(threads) + 1, 0);
    parallelChunks(nd, threads, [&](int k, std::size_t b, std::size_t e) {
        int n = 0;
        for (std::size_t d = b; d < e; ++d)
            if (alive[d] && runStart(d)) ++n;
        runsInChunk[static_cast<std::size_t>(k) + 1] = n;
    });
    for (std::size_t k = 0; k < static_cast<std::size_t>(threads); ++k) runsInChunk[k + 1] += runsInChunk[k];
    geo.placement.point.resize(static_cast<std::size_t>(in.n_alive));
    geo.placement.position.resize(static_cast<std::size_t>(runsInChunk.back()));
    geo.placement.boundary_hf.resize(static_cast<std::size_t>(runsInChunk.back()));
    const HandednessTable handedness;
    parallelChunks(nd, threads, [&](int k, std::size_t b, std::size_t e) {
        int run = runsInChunk[static_cast<std::size_t>(k)] - 1;  // a run continued from the previous chunk
        PointPlacer placer(*in.mesh, *in.tets, ds);
        for (std::size_t d = b; d < e; ++d) {
            if (!alive[d]) continue;
            const Dart& D = ds.darts[d];
            const auto dk = static_cast<std::size_t>(newIndex[d]);
            geo.handedness[dk] = handedness(D.d);
            if (runStart(d)) {
                ++run;
                placer.place(D.tet, D.z, geo.placement.position[static_cast<std::size_t>(run)],
                             geo.placement.boundary_hf[static_cast<std::size_t>(run)]);
            }
            geo.placement.point[dk] = run;
        }
    });
    if (in.heir && !in.heir->empty()) {
        // Removed regular darts with an heir: one extra placed point per (tet, grid point)
        // run and heir, in dart order. An entry is left out if it has the tet, point and heir
        // of the entry before it (equal to the last one kept: every entry left out equals
        // it), so chunks of the entries decide on their own: counted per chunk, then placed
        // from the chunk's prefix (the same points in the same order for any thread count).
        const std::vector<std::pair<int, int>>& heir = *in.heir;
        auto kept = [&](std::size_t k) {
            if (k == 0) return true;
            const Dart& D = ds.darts[static_cast<std::size_t>(heir[k].first)];
            const Dart& P = ds.darts[static_cast<std::size_t>(heir[k - 1].first)];
            return !(D.tet == P.tet && samePoint(D.z, P.z) && heir[k].second == heir[k - 1].second);
        };
        const std::size_t ne = heir.size();
        std::vector<std::size_t> keptBefore(static_cast<std::size_t>(threads) + 1, 0);
        parallelChunks(ne, threads, [&](int k, std::size_t b, std::size_t e) {
            std::size_t n = 0;
            for (std::size_t x = b; x < e; ++x) n += kept(x) ? 1 : 0;
            keptBefore[static_cast<std::size_t>(k) + 1] = n;
        });
        for (std::size_t k = 0; k < static_cast<std::size_t>(threads); ++k) keptBefore[k + 1] += keptBefore[k];
        const std::size_t first = geo.placement.position.size(), extras = keptBefore.back();
        geo.placement.position.resize(first + extras);
        geo.placement.boundary_hf.resize(first + extras);
        geo.placement.extra_dart.resize(extras);
        geo.placement.extra_point.resize(extras);
        geo.placement.extra_flipped.resize(extras);
        parallelChunks(ne, threads, [&](int k, std::size_t b, std::size_t e) {
            std::size_t x = keptBefore[static_cast<std::size_t>(k)];
            PointPlacer placer(*in.mesh, *in.tets, ds);
            for (std::size_t q = b; q < e; ++q) {
                if (!kept(q)) continue;
                const auto [d, h] = heir[q];
                const Dart& D = ds.darts[static_cast<std::size_t>(d)];
                placer.place(D.tet, D.z, geo.placement.position[first + x], geo.placement.boundary_hf[first + x]);
                geo.placement.extra_dart[x] = newIndex[static_cast<std::size_t>(h)];
                geo.placement.extra_point[x] = static_cast<int>(first + x);
                geo.placement.extra_flipped[x] = D.sign < 0 ? 1 : 0;
                ++x;
            }
        });
    }
    return geo;
}

} // namespace HexEx
