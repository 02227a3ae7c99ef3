#include "ProvenanceStage.hh"

#include "../Core/Parallel.hh"

#include <algorithm>
#include <cmath>
#include <limits>

namespace HexEx {

namespace {

/// Steps a centre walk may take before it gives up (only defective maps need many).
constexpr int kMaxWalkSteps = 512;

/// Barycentric coordinates @p l of @p u in the tet with the corner parameters @p p (l[j]
/// belongs to corner j, negative beyond the face opposite it); false for a flat tet.
bool barycentric(const Vec3d* p, const Vec3d& u, double l[4]) {
    const auto det = [](const Vec3d& x, const Vec3d& y, const Vec3d& z) {
        return x[0] * (y[1] * z[2] - y[2] * z[1]) - x[1] * (y[0] * z[2] - y[2] * z[0]) + x[2] * (y[0] * z[1] - y[1] * z[0]);
    };
    const Vec3d a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0], r = u - p[0];
    const double d = det(a, b, c);
    if (d == 0 || !std::isfinite(d)) return false;
    l[1] = det(r, b, c) / d;
    l[2] = det(a, r, c) / d;
    l[3] = det(a, b, r) / d;
    l[0] = 1 - l[1] - l[2] - l[3];
    return true;
}

/// Walks from tet @p tet along the segment from @p p (a point of that tet's closed image)
/// to the point @p c (both in that tet's chart; @p c perturbed by e d[0] + e^2 d[1] +
/// e^3 d[2] for the final containment test) through the halfface transitions: each step
/// leaves through the face the segment crosses first. Returns the tet whose image contains
/// @p c, @p c then in that tet's chart, or -1 (and @p c unspecified) if the walk meets the
/// boundary or runs out of steps. A flat tet (zero parametric volume) is crossed into the
/// neighbour that holds the segment's continuation best.
int locate(const ProvenanceInput& in, int tet, Vec3d& c, Vec3d p, std::array<AxisDir, 3> d) {
    int entry = -1;  // local face the walk came in through
    for (int step = 0; step < kMaxWalkSteps; ++step) {
        const TetSoS& T = (*in.tets)[static_cast<std::size_t>(tet)];
        if (!T.p) return -1;
        const std::array<int, 4> oz = T.sides(c);
        if (T.contains(oz, d[0], d[1], d[2])) return tet;
        double lc[4], lp[4];
        int exit = -1;
        double first = 2, deepest = 0;
        const bool flat = !barycentric(T.p, c, lc) || !barycentric(T.p, p, lp);
        if (flat) {
            // A flat tet (zero parametric volume): the segment passes through it; leave into
            // the neighbour that holds the point just after p best (largest smallest
            // barycentric coordinate).
            const Vec3d q = p + (c - p) * 1e-4;
            double best = -std::numeric_limits<double>::infinity();
            for (int j = 0; j < 4; ++j) {
                if (j == entry) continue;
                const HalfFaceHandle hf = TetMesh::halfface(CellHandle(tet), j);
                const HalfFaceHandle opp = in.mesh->opposite_halfface(hf);
                if (!opp.is_valid()) continue;
                const TetSoS& N = (*in.tets)[static_cast<std::size_t>(TetMesh::cell(opp).idx())];
                double l[4];
                if (!N.p || !barycentric(N.p, in.transitions->halfface[hf.uidx()].apply(q), l)) continue;
                const double m = std::min(std::min(l[0], l[1]), std::min(l[2], l[3]));
                if (m > best) {
                    best = m;
                    exit = j;
                }
            }
            if (exit < 0) return -1;
            first = 0;
        }
        // The face the segment p -> c crosses first among those with c beyond them (ties: the
        // one c is farthest beyond).
        for (int j = 0; j < 4 && !flat; ++j) {
            if (j == entry || !(lc[j] < 0)) continue;
            const double a = std::max(0.0, lp[j]);
            const double t = a / (a - lc[j]);
            if (t < first - 1e-12 || (t <= first + 1e-12 && lc[j] < deepest)) {
                first = t;
                deepest = lc[j];
                exit = j;
            }
        }
        if (exit < 0) {
            // c lies on the tet in floating point but outside by the exact test: leave through
            // a face whose perturbed side is wrong.
            for (int j = 0; j < 4 && exit < 0; ++j)
                if (j != entry && T.sosSide(j, oz[static_cast<std::size_t>(j)], d[0], d[1], d[2]) != T.vol) exit = j;
            if (exit < 0) return -1;
            first = 1;
        }
        p = p + (c - p) * std::min(first, 1.0);
        const HalfFaceHandle hf = TetMesh::halfface(CellHandle(tet), exit);
        const HalfFaceHandle opp = in.mesh->opposite_halfface(hf);
        if (!opp.is_valid()) return -1;
        const GridTransform g = in.transitions->halfface[hf.uidx()];
        c = g.apply(c);
        p = g.apply(p);
        for (AxisDir& x : d) x = g.applyDir(x);
        tet = TetMesh::cell(opp).idx();
        entry = TetMesh::opposite_corner(opp);
    }
    return -1;
}

} // namespace

HexProvenance provenanceStage(const ProvenanceInput& in) {
    HexProvenance out;
    const std::vector<std::array<int, 8>>& hexes = in.hexes->hexes;
    const std::size_t nh = hexes.size();
    const std::size_t nExplicit = in.hex_darts ? in.hex_darts->size() : 0;
    const auto& L = in.map->links();
    const auto dartOf = [&](int md) -> const Dart& {
        return in.darts->darts[static_cast<std::size_t>((*in.map_dart_origin)[static_cast<std::size_t>(md)])];
    };
    out.hex_source_tet.assign(nh, -1);
    out.hex_grid_cell.assign(nh, {0, 0, 0});

    // Hexes: each on its own (parallel, the result per hex does not depend on the chunks).
    parallelChunks(nh, in.threads, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t h = b; h < e; ++h) {
            if (h < nExplicit) {
                const Dart& D = dartOf((*in.hex_darts)[h]);
                const Vec3i s = dirVec(D.d[0]) + dirVec(D.d[1]) + dirVec(D.d[2]);
                const Vec3d centre(D.z[0] + 0.5 * s[0], D.z[1] + 0.5 * s[1], D.z[2] + 0.5 * s[2]);
                Vec3d c = centre;
                int tet = locate(in, D.tet, c, toVec3d(D.z), D.d);
                if (tet < 0) {
                    tet = D.tet;
                    c = centre;
                }
                out.hex_source_tet[h] = tet;
                // c is a cell centre: its coordinates are exactly half-integers.
                for (int k = 0; k < 3; ++k) out.hex_grid_cell[h][static_cast<std::size_t>(k)] = static_cast<int>(std::floor(c[k]));
            } else if (in.implicit && h - nExplicit < in.implicit->cells.size()) {
                // Implicit cell: all corners are grid points of one tet's image.
                const auto& cell = in.implicit->cells[h - nExplicit];
                int tet = -1;
                std::array<int, 3> lo = {0, 0, 0};
                for (std::size_t k = 0; k < 8; ++k) {
                    Vec3i z;
                    in.darts->occurrencePoint(cell[k], tet, z);
                    for (int a = 0; a < 3; ++a)
                        lo[static_cast<std::size_t>(a)] = k == 0 ? z[a] : std::min(lo[static_cast<std::size_t>(a)], z[a]);
                }
                out.hex_source_tet[h] = tet;
                out.hex_grid_cell[h] = lo;
            }
        }
    });

    // Vertices: from the first hex corner at each (hexes in order, corners in VTK order).
    const std::size_t nv = in.hexes->vertices.size();
    out.vertex_source_tet.assign(nv, -1);
    out.vertex_grid_coords.assign(nv, {0, 0, 0});
    const auto a = [&](int d, int i) { return L[static_cast<std::size_t>(d)][i]; };
    for (std::size_t h = 0; h < nh; ++h) {
        const std::array<int, 8>& hex = hexes[h];
        bool allKnown = true;
        for (int v : hex)
            if (out.vertex_source_tet[static_cast<std::size_t>(v)] < 0) allKnown = false;
        if (allKnown) continue;
        if (h < nExplicit) {
            // The corner darts in the order the assembly reads the corners (assembleHexMesh()).
            const int d0 = (*in.hex_darts)[h];
            const int d1 = a(d0, 0), d3 = a(a(d0, 1), 0), d2 = a(a(d1, 1), 0);
            const auto up = [&](int d) { return a(a(a(d, 2), 1), 0); };
            const int corner[8] = {d0, d1, d2, d3, up(d0), up(d1), up(d2), up(d3)};
            for (std::size_t k = 0; k < 8; ++k) {
                const std::size_t v = static_cast<std::size_t>(hex[k]);
                if (out.vertex_source_tet[v] >= 0) continue;
                const Dart& D = dartOf(corner[k]);
                out.vertex_source_tet[v] = D.tet;
                out.vertex_grid_coords[v] = {D.z[0], D.z[1], D.z[2]};
            }
        } else if (in.implicit && h - nExplicit < in.implicit->cells.size()) {
            const auto& cell = in.implicit->cells[h - nExplicit];
            for (std::size_t k = 0; k < 8; ++k) {
                const std::size_t v = static_cast<std::size_t>(hex[k]);
                if (out.vertex_source_tet[v] >= 0) continue;
                int tet = -1;
                Vec3i z;
                in.darts->occurrencePoint(cell[k], tet, z);
                out.vertex_source_tet[v] = tet;
                out.vertex_grid_coords[v] = {z[0], z[1], z[2]};
            }
        }
    }
    return out;
}

} // namespace HexEx
