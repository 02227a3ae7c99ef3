#include "ImplicitCellPath.hh"

#include "../Core/Parallel.hh"
#include "GridPointPosition.hh"

#include <algorithm>

namespace HexEx {

namespace {
/// Pairs of occurrences that are one grid point seen from both tets of an interior face:
/// points on face j of a dense tet that may be implicit-cell corners, mapped through the
/// face's transition into the neighbour (found once, from the smaller halfface).
std::vector<std::pair<int, int>> joinOccurrencesAcrossFaces(const TetMesh& mesh, const Transitions& tr, const DartSet& ds,
                                                            int threads) {
    const int chunks = std::max(1, threads);
    std::vector<std::vector<std::pair<int, int>>> parts(static_cast<std::size_t>(chunks));
    parallelChunks(ds.dense.size(), chunks, [&](int k, std::size_t b, std::size_t e) {
        auto& out = parts[static_cast<std::size_t>(k)];
        for (std::size_t s = b; s < e; ++s) {
            const DartSet::DenseIndex& di = ds.dense[s];
            if (di.flags.empty()) continue;
            for (int j = 0; j < 4; ++j) {
                const HalfFaceHandle hf = TetMesh::halfface(CellHandle(di.tet), j);
                const HalfFaceHandle opp = mesh.opposite_halfface(hf);
                if (!opp.is_valid() || opp.idx() < hf.idx()) continue;
                const int nb = TetMesh::cell(opp).idx();
                const GridTransform& g = tr.halfface[hf.uidx()];
                std::size_t l = 0;
                for (int x = 0; x < di.dims[0]; ++x)
                    for (int y = 0; y < di.dims[1]; ++y)
                        for (int zc = 0; zc < di.dims[2]; ++zc, ++l) {
                            const unsigned fl = di.flags[l];
                            if (!(fl & 4) || !((fl >> (4 + j)) & 1)) continue;
                            const Vec3i z(di.lo[0] + x, di.lo[1] + y, di.lo[2] + zc);
                            const long o = ds.occurrence(nb, g.apply(z));
                            if (o >= 0) out.emplace_back(static_cast<int>(di.occ_base + static_cast<long>(l)), static_cast<int>(o));
                        }
            }
        }
    });
    std::vector<std::pair<int, int>> all;
    for (auto& p : parts) all.insert(all.end(), p.begin(), p.end());
    return all;
}

/// Work item of the implicit-cell enumeration: one x-slab of a dense box.
struct Slab {
    std::size_t dense, x;               ///< dense index and x layer
    long count = 0, boundary_quads = 0; ///< implicit cells and their boundary faces in the slab
};

/// Counts the implicit cells of @p sl (and their boundary faces), or with @p fill writes
/// them to @p cells from position @p at, and their twin faces to @p twins.
void visitSlab(const TetMesh& mesh, const DartSet& ds, Slab& sl, bool fill, std::size_t at,
               DefaultInitVector<std::array<int, 8>>& cells, std::vector<unsigned char>& twins) {
    const DartSet::DenseIndex& di = ds.dense[sl.dense];
    unsigned boundaryFaces = 0;
    for (int j = 0; j < 4; ++j)
        if (mesh.is_boundary(TetMesh::halfface(CellHandle(di.tet), j))) boundaryFaces |= 1u << j;
    const int dy = di.dims[1], dz = di.dims[2];
    const int X = dy * dz, Y = dz, Z = 1;
    const int step[3] = {X, Y, Z};
    const std::size_t l0 = sl.x * static_cast<std::size_t>(X);
    for (std::size_t l = l0; l < l0 + static_cast<std::size_t>(X); ++l) {
        if (!(di.flags[l] & 2)) continue;
        if (fill) {
            const int c = static_cast<int>(di.occ_base) + static_cast<int>(l);
            // Neighbouring cells in the box (a cell's corners are in the box, so l + X,
            // l + Y, l + Z are too): faces 5/3 at x = 0/1, 2/4 at y = 0/1, 0/1 at z = 0/1.
            const std::size_t lx = l - l0;
            const bool lowY = lx / static_cast<std::size_t>(dz) == 0, lowZ = lx % static_cast<std::size_t>(dz) == 0;
            auto cellAt = [&](std::size_t q) { return (di.flags[q] & 2) != 0; };
            unsigned twin = 0;
            if (sl.x > 0 && cellAt(l - static_cast<std::size_t>(X))) twin |= 1u << 5;
            if (cellAt(l + static_cast<std::size_t>(X))) twin |= 1u << 3;
            if (!lowY && cellAt(l - static_cast<std::size_t>(Y))) twin |= 1u << 2;
            if (cellAt(l + static_cast<std::size_t>(Y))) twin |= 1u << 4;
            if (!lowZ && cellAt(l - static_cast<std::size_t>(Z))) twin |= 1u << 0;
            if (cellAt(l + static_cast<std::size_t>(Z))) twin |= 1u << 1;
            twins[at] = static_cast<unsigned char>(twin);
            cells[at++] = {c, c + X, c + X + Y, c + Y, c + Z, c + X + Z, c + X + Y + Z, c + Y + Z};
            continue;
        }
        ++sl.count;
        if (!boundaryFaces) continue;
        // A face of the cell is on the boundary if its 4 corners share a boundary face.
        for (int a = 0; a < 3; ++a)
            for (int side = 0; side < 2; ++side) {
                unsigned common = boundaryFaces;
                for (int q = 0; q < 8; ++q) {
                    if (((q >> a) & 1) != side) continue;
                    std::size_t lq = l;
                    for (int k = 0; k < 3; ++k)
                        if ((q >> k) & 1) lq += static_cast<std::size_t>(step[k]);
                    common &= static_cast<unsigned>(di.flags[lq]) >> 4;
                }
                if (common) ++sl.boundary_quads;
            }
    }
}
} // namespace

std::vector<FaceMask> implicitCellFaces(const TetMesh& mesh, const std::vector<TetSoS>& tets) {
    std::vector<FaceMask> usable(tets.size(), 0);
    for (std::size_t c = 0; c < tets.size(); ++c)
        for (int j = 0; j < 4; ++j) {
            const HalfFaceHandle opp = mesh.opposite_halfface(TetMesh::halfface(CellHandle(static_cast<int>(c)), j));
            if (!opp.is_valid() || tets[TetMesh::cell(opp).uidx()].vol > 0) usable[c] = static_cast<FaceMask>(usable[c] | (1u << j));
        }
    return usable;
}

DefaultInitVector<int> implicitAlpha3Occurrences(const std::vector<DartLinks>& alpha, const std::vector<char>& alive,
                                            const std::vector<int>& newIndex, int n_alive, int threads) {
    // Every surviving dart has one new index: every entry is written (no zeroing pass).
    DefaultInitVector<int> occ(static_cast<std::size_t>(n_alive));
    parallelChunks(alpha.size(), threads, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t d = b; d < e; ++d) {
            if (!alive[d]) continue;
            const long o = implicitPartnerOccurrence(alpha[d][3]);
            occ[static_cast<std::size_t>(newIndex[d])] = o >= 0 ? static_cast<int>(o) : -1;
        }
    });
    return occ;
}

DefaultInitVector<int> implicitDartOccurrences(const DartSet& ds, const std::vector<char>& alive, const std::vector<int>& newIndex,
                                          int n_alive, int threads) {
    // Without occurrences (no dense box) every entry would be -1: none.
    if (ds.n_occurrences == 0) return {};
    // Every surviving dart has one new index: every entry is written (no zeroing pass).
    DefaultInitVector<int> occ(static_cast<std::size_t>(n_alive));
    // Darts are sorted by (tet, grid point): look the occurrence up once per run.
    parallelChunks(ds.darts.size(), threads, [&](int, std::size_t b, std::size_t e) {
        int o = -1;
        bool have = false;
        for (std::size_t d = b; d < e; ++d) {
            if (!alive[d]) continue;
            const Dart& D = ds.darts[d];
            const bool runStart = d == 0 || !alive[d - 1] || ds.darts[d - 1].tet != D.tet || !samePoint(ds.darts[d - 1].z, D.z);
            if (runStart || !have) {
                o = static_cast<int>(ds.occurrence(D.tet, D.z));
                have = true;
            }
            occ[static_cast<std::size_t>(newIndex[d])] = o;
        }
    });
    return occ;
}

void buildImplicitCells(const TetMesh& mesh, const Transitions& tr, const std::vector<TetSoS>& tets, const DartSet& ds,
                        int threads, ImplicitCells& out) {
    out.n_occurrences = ds.n_occurrences;
    // Work items are x-slabs of the dense boxes: counted, then filled at their prefix
    // offsets (the order is the sequential one for any thread count). The tet's chart is
    // right-handed (proper tets only), so the corners are in VTK order.
    std::vector<Slab> slabs;
    for (std::size_t s = 0; s < ds.dense.size(); ++s)
        if (!ds.dense[s].flags.empty())
            for (int x = 0; x < ds.dense[s].dims[0]; ++x) slabs.push_back({s, static_cast<std::size_t>(x)});
    parallelChunks(slabs.size(), threads, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t k = b; k < e; ++k) visitSlab(mesh, ds, slabs[k], false, 0, out.cells, out.twin_faces);
    });
    std::vector<std::size_t> slabStart(slabs.size() + 1, 0);
    for (std::size_t k = 0; k < slabs.size(); ++k) {
        slabStart[k + 1] = slabStart[k] + static_cast<std::size_t>(slabs[k].count);
        out.boundary_quads += slabs[k].boundary_quads;
    }
    out.cells.resize(slabStart.back());
    out.twin_faces.resize(slabStart.back());
    parallelChunks(slabs.size(), threads, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t k = b; k < e; ++k) visitSlab(mesh, ds, slabs[k], true, slabStart[k], out.cells, out.twin_faces);
    });
    out.joined_occurrences = joinOccurrencesAcrossFaces(mesh, tr, ds, threads);
    const TetMesh* m = &mesh;
    const std::vector<TetSoS>* ts = &tets;
    const DartSet* dp = &ds;
    out.position = [m, ts, dp](long occ) {
        int tet = 0;
        Vec3i z;
        dp->occurrencePoint(occ, tet, z);
        return gridPointPosition(*m, *ts, *dp, tet, z, nullptr);
    };
    // Ascending occurrences: the dense index is searched once, then followed forward
    // (the same grid points, hence the same positions, as occurrencePoint()).
    out.positions = [m, ts, dp](const long* occ, std::size_t n, Vec3d* pos) {
        if (n == 0) return;
        const std::vector<DartSet::DenseIndex>& dense = dp->dense;
        auto it = std::upper_bound(dense.begin(), dense.end(), occ[0],
                                   [](long o, const DartSet::DenseIndex& di) { return o < di.occ_base; }) - 1;
        // The tet's terms are taken once per run of occurrences in one tet (TetPointPositions).
        TetPointPositions at(*m, *ts, *dp, it->tet);
        for (std::size_t i = 0; i < n; ++i) {
            bool moved = false;
            while (it + 1 != dense.end() && (it + 1)->occ_base <= occ[i]) {
                ++it;
                moved = true;
            }
            const DartSet::DenseIndex& di = *it;
            if (moved) at = TetPointPositions(*m, *ts, *dp, di.tet);
            long l = occ[i] - di.occ_base;
            Vec3i z;
            z[2] = di.lo[2] + static_cast<int>(l % di.dims[2]);
            l /= di.dims[2];
            z[1] = di.lo[1] + static_cast<int>(l % di.dims[1]);
            z[0] = di.lo[0] + static_cast<int>(l / di.dims[1]);
            pos[i] = at(z);
        }
    };
}

} // namespace HexEx
