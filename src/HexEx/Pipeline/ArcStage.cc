#include "ArcStage.hh"

#include "../Core/Parallel.hh"
#include "HexElementNumbering.hh"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace HexEx {

namespace {

/// A patch whose signed parametric area differs from 1 by more than this is incomplete.
constexpr double kAreaTolerance = 1e-9;

/// Asks the CPU to load @p p's cache line early (the walks below jump around big arrays).
inline void prefetch(const void* p) {
#if defined(__GNUC__)
    __builtin_prefetch(p);
#else
    (void)p;
#endif
}

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
            std::fill(&table_[0][0][0], &table_[0][0][0] + 8 * 6 * 6, -1);
            // Local (corner, frame) of every dart of the cell, by a walk over alpha_0..alpha_2
            // from the hex's dart at corner 0 with frame (+x, +y, +z).
            struct State {
                int dart, corner;
                std::array<AxisDir, 3> d;
            };
            const auto& L = in.map->links();
            constexpr int kCellDarts = 48;
            State todo[kCellDarts];
            int n = 0;
            todo[n++] = {(*in.hex_darts)[h], 0, {makeDir(0, 1), makeDir(1, 1), makeDir(2, 1)}};
            // Darts met so far: a small open-addressing set (a cell has at most 48 darts;
            // a linear scan over them dominated the stage).
            constexpr unsigned kSlots = 128;
            int met[kSlots];
            std::fill(met, met + kSlots, -1);
            auto metSlot = [&](int d) -> int& {  // d's slot, or the empty one where it goes
                unsigned i = (static_cast<unsigned>(d) * 2654435761u) >> 25;
                while (met[i] != d && met[i] >= 0) i = (i + 1) & (kSlots - 1);
                return met[i];
            };
            auto seen = [&](int d) { return metSlot(d) == d; };
            metSlot((*in.hex_darts)[h]) = (*in.hex_darts)[h];
            for (int k = 0; k < n; ++k) {
                const State s = todo[k];
                int& slot = table_[s.corner][s.d[0]][s.d[1]];
                if (slot < 0) slot = s.dart;
                for (int i = 0; i < 3 && n < kCellDarts; ++i) {
                    State x = s;
                    x.dart = L[static_cast<std::size_t>(s.dart)][i];
                    if (x.dart < 0 || seen(x.dart)) continue;
                    if (i == 0) {
                        x.corner = cornerAlong(s.corner, s.d[0]);
                        if (x.corner < 0) continue;
                        x.d[0] = dirNeg(s.d[0]);
                    } else {
                        std::swap(x.d[i - 1], x.d[i]);
                    }
                    todo[n++] = x;
                    metSlot(x.dart) = x.dart;
                    prefetch(&L[static_cast<std::size_t>(x.dart)]);  // its links are read when it is popped
                }
            }
            in_ = &in;
            return;
        }
        // Implicit cell: all corners are occurrences in one tet, whose chart gives the frame.
        if (!in.implicit || h - nExplicit >= in.implicit->cells.size()) return;  // no starts (tet_ stays -1)
        const auto& cell = in.implicit->cells[h - nExplicit];
        for (int c = 0; c < 8; ++c) occurrence(in, cell[static_cast<std::size_t>(c)], tet_, z_[c]);
        for (int k = 0; k < 3; ++k) {
            const Vec3i step = z_[k == 0 ? 1 : k == 1 ? 3 : 4] - z_[0];
            for (int a = 0; a < 3; ++a)
                if (step[a] != 0) axis_[k] = makeDir(a, step[a]);
        }
    }

    /// The start at corner @p c with frame (d0, d1, d2) (local directions); tet -1 if the hex
    /// has no such dart.
    ArcStart at(int c, AxisDir d0, AxisDir d1, AxisDir d2) const {
        ArcStart s;
        if (explicit_) {
            const int md = table_[c][d0][d1];
            if (md < 0) return s;
            const Dart& D = in_->darts->darts[static_cast<std::size_t>((*in_->map_dart_origin)[static_cast<std::size_t>(md)])];
            s.tet = D.tet;
            s.z = D.z;
            s.d = D.d;
            return s;
        }
        auto img = [&](AxisDir d) { return dirSign(d) > 0 ? axis_[dirAxis(d)] : dirNeg(axis_[dirAxis(d)]); };
        s.tet = tet_;
        s.z = z_[c];
        s.d = {img(d0), img(d1), img(d2)};
        return s;
    }

private:
    /// Tet and grid point of an occurrence id (the dense index holding it).
    static void occurrence(const ArcInput& in, long occ, int& tet, Vec3i& z) {
        const auto& dense = in.darts->dense;
        auto it = std::upper_bound(dense.begin(), dense.end(), occ,
                                   [](long o, const DartSet::DenseIndex& di) { return o < di.occ_base; });
        const DartSet::DenseIndex& di = *(it - 1);
        long l = occ - di.occ_base;
        z[2] = di.lo[2] + static_cast<int>(l % di.dims[2]);
        l /= di.dims[2];
        z[1] = di.lo[1] + static_cast<int>(l % di.dims[1]);
        z[0] = di.lo[0] + static_cast<int>(l / di.dims[1]);
        tet = di.tet;
    }

    bool explicit_ = false;
    const ArcInput* in_ = nullptr;
    int table_[8][6][6];
    int tet_ = -1;
    Vec3i z_[8];
    AxisDir axis_[3] = {0, 2, 4};
};

/// Results of one chunk of hexes, in order.
struct ChunkResult {
    std::vector<std::size_t> arc_size;  ///< points per owned edge (0 = failed)
    std::vector<Vec3d> arc_points;
    std::vector<std::size_t> patch_size;  ///< triangles per owned face (0 = failed)
    std::vector<std::array<int, 3>> triangles;  ///< indices local to the chunk's points
    std::vector<Vec3d> patch_points;
};

} // namespace

std::vector<int> mapDartOrigins(const std::vector<int>& new_index, int n_alive) {
    std::vector<int> origin(static_cast<std::size_t>(n_alive), -1);
    for (std::size_t d = 0; d < new_index.size(); ++d)
        if (new_index[d] >= 0) origin[static_cast<std::size_t>(new_index[d])] = static_cast<int>(d);
    return origin;
}

HexArcs arcStage(const ArcInput& in) {
    HexArcs out;
    const auto& hexes = in.hexes->hexes;
    const std::size_t nh = hexes.size();
    // Edge and face ids by first appearance; the first hex that has one traces it.
    HexElementOwners edgeOwner, faceOwner;
    numberHexEdgesAndFaces(*in.hexes, in.threads, out, edgeOwner, faceOwner);
    // Trace in parallel chunks of hexes; the edges and faces a chunk owns are consecutive ids.
    const int chunks = std::max(1, std::min(in.threads, static_cast<int>(nh / 64) + 1));
    std::vector<ChunkResult> parts(static_cast<std::size_t>(chunks));
    parallelChunks(nh, chunks, [&](int part, std::size_t hb, std::size_t he) {
        ChunkResult& R = parts[static_cast<std::size_t>(part)];
        const std::size_t e0 = std::lower_bound(edgeOwner.begin(), edgeOwner.end(), std::make_pair(static_cast<int>(hb), -1)) - edgeOwner.begin();
        const std::size_t f0 = std::lower_bound(faceOwner.begin(), faceOwner.end(), std::make_pair(static_cast<int>(hb), -1)) - faceOwner.begin();
        std::size_t e = e0, f = f0;
        std::vector<ArcStart> from;  // reused per face
        PatchScratch scratch;        // the floods' working memory, reused per face
        // Generous reservations (untouched pages cost nothing): no copies while growing.
        R.patch_points.reserve(64 * 6 * (he - hb));
        R.triangles.reserve(32 * 6 * (he - hb));
        R.arc_points.reserve(8 * 12 * (he - hb));
        for (std::size_t h = hb; h < he; ++h) {
            if ((e >= edgeOwner.size() || edgeOwner[e].first != static_cast<int>(h)) &&
                (f >= faceOwner.size() || faceOwner[f].first != static_cast<int>(h)))
                continue;
            const HexStarts starts(in, h);
            for (; e < edgeOwner.size() && edgeOwner[e].first == static_cast<int>(h); ++e) {
                const int k = edgeOwner[e].second;
                const int ca = HexArcs::kHexEdges[k][0], cb = HexArcs::kHexEdges[k][1];
                const AxisDir d0 = localDir(ca, cb);
                const int a1 = (dirAxis(d0) + 1) % 3, a2 = (dirAxis(d0) + 2) % 3;
                ArcStart s = starts.at(ca, d0, inward(ca, a1), inward(ca, a2));
                if (s.tet < 0) s = starts.at(ca, d0, inward(ca, a2), inward(ca, a1));
                const std::size_t before = R.arc_points.size();
                if (s.tet >= 0) traceEdgeArc(*in.mesh, *in.transitions, *in.tets, s, R.arc_points);
                R.arc_size.push_back(R.arc_points.size() - before);
            }
            for (; f < faceOwner.size() && faceOwner[f].first == static_cast<int>(h); ++f) {
                const int k = faceOwner[f].second;
                const int* q = HexArcs::kHexFaces[k];
                auto cornerStart = [&](int i) {  // corner q[i], d0 to q[i+1], d1 to q[i-1]
                    const int c = q[i], n = q[(i + 1) % 4], p = q[(i + 3) % 4];
                    const AxisDir d0 = localDir(c, n), d1 = localDir(c, p);
                    return starts.at(c, d0, d1, inward(c, 3 - dirAxis(d0) - dirAxis(d1)));
                };
                from.assign(1, cornerStart(0));
                const std::size_t pointsBefore = R.patch_points.size(), trisBefore = R.triangles.size();
                double area = 0;
                bool ok = traceFacePatch(*in.mesh, *in.transitions, *in.tets, from, R.patch_points, R.triangles, area, scratch) &&
                          std::abs(area - 1) <= kAreaTolerance;
                if (!ok) {
                    // A fold may have cut the preimage into pieces: flood from all four corners.
                    for (int i = 1; i < 4; ++i) from.push_back(cornerStart(i));
                    R.patch_points.resize(pointsBefore);
                    R.triangles.resize(trisBefore);
                    ok = traceFacePatch(*in.mesh, *in.transitions, *in.tets, from, R.patch_points, R.triangles, area, scratch) &&
                         std::abs(area - 1) <= kAreaTolerance;
                }
                if (!ok) {
                    R.patch_points.resize(pointsBefore);
                    R.triangles.resize(trisBefore);
                }
                R.patch_size.push_back(R.triangles.size() - trisBefore);
            }
        }
    });

    // Concatenate in chunk order (a single chunk is moved; otherwise each chunk is freed
    // once copied, so the peak is the output plus one chunk).
    std::size_t nArc = 0, nPatch = 0, nTri = 0;
    for (const ChunkResult& R : parts) {
        nArc += R.arc_points.size();
        nPatch += R.patch_points.size();
        nTri += R.triangles.size();
    }
    if (parts.size() == 1) {
        out.arc_points = std::move(parts[0].arc_points);
        out.patch_points = std::move(parts[0].patch_points);
        out.patch_triangles = std::move(parts[0].triangles);
    } else {
        out.arc_points.reserve(nArc);
        out.patch_points.reserve(nPatch);
        out.patch_triangles.reserve(nTri);
    }
    out.arc_offset.reserve(out.edges.size() + 1);
    out.patch_offset.reserve(out.faces.size() + 1);
    out.arc_offset.assign(1, 0);
    out.patch_offset.assign(1, 0);
    for (ChunkResult& R : parts) {
        for (std::size_t k = 0; k < R.arc_size.size(); ++k) {
            if (R.arc_size[k] == 0) out.failed_edges.push_back(static_cast<int>(out.arc_offset.size() - 1));
            out.arc_offset.push_back(out.arc_offset.back() + R.arc_size[k]);
        }
        for (std::size_t k = 0; k < R.patch_size.size(); ++k) {
            if (R.patch_size[k] == 0) out.failed_faces.push_back(static_cast<int>(out.patch_offset.size() - 1));
            out.patch_offset.push_back(out.patch_offset.back() + R.patch_size[k]);
        }
        if (parts.size() == 1) continue;
        out.arc_points.insert(out.arc_points.end(), R.arc_points.begin(), R.arc_points.end());
        const int base = static_cast<int>(out.patch_points.size());
        for (auto t : R.triangles) out.patch_triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
        out.patch_points.insert(out.patch_points.end(), R.patch_points.begin(), R.patch_points.end());
        R = ChunkResult();  // free the chunk
    }
    return out;
}

} // namespace HexEx
