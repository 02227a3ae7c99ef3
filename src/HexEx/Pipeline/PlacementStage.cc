#include "PlacementStage.hh"

#include "../Core/Parallel.hh"
#include "GridPointPosition.hh"

namespace HexEx {

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
    parallelChunks(nd, threads, [&](int k, std::size_t b, std::size_t e) {
        int run = runsInChunk[static_cast<std::size_t>(k)] - 1;  // a run continued from the previous chunk
        for (std::size_t d = b; d < e; ++d) {
            if (!alive[d]) continue;
            const Dart& D = ds.darts[d];
            const auto dk = static_cast<std::size_t>(newIndex[d]);
            geo.handedness[dk] = static_cast<signed char>(frameHandedness(D.d[0], D.d[1], D.d[2]));
            if (runStart(d)) {
                ++run;
                auto& bhf = geo.placement.boundary_hf[static_cast<std::size_t>(run)];
                bhf = {-1, -1, -1};
                geo.placement.position[static_cast<std::size_t>(run)] = gridPointPosition(*in.mesh, *in.tets, ds, D.tet, D.z, &bhf);
            }
            geo.placement.point[dk] = run;
        }
    });
    if (in.heir && !in.heir->empty()) {
        // Removed regular darts with an heir: one extra placed point per (tet, grid point)
        // run and heir, in dart order.
        int lastTet = -1, lastHeir = -1;
        Vec3i lastZ(0, 0, 0);
        for (const auto& [d, h] : *in.heir) {
            const Dart& D = ds.darts[static_cast<std::size_t>(d)];
            const bool flipped = D.sign < 0;
            if (D.tet == lastTet && samePoint(D.z, lastZ) && h == lastHeir) continue;
            lastTet = D.tet;
            lastZ = D.z;
            lastHeir = h;
            std::array<int, 3> bhf = {-1, -1, -1};
            geo.placement.position.push_back(gridPointPosition(*in.mesh, *in.tets, ds, D.tet, D.z, &bhf));
            geo.placement.boundary_hf.push_back(bhf);
            geo.placement.extra_dart.push_back(newIndex[static_cast<std::size_t>(h)]);
            geo.placement.extra_point.push_back(static_cast<int>(geo.placement.position.size()) - 1);
            geo.placement.extra_flipped.push_back(flipped ? 1 : 0);
        }
    }
    return geo;
}

} // namespace HexEx
