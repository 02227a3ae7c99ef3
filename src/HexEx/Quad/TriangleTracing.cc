#include "TriangleTracing.hh"

#include "../Core/Parallel.hh"
#include "../Predicates/ExactPredicates.hh"

#include <algorithm>
#include <utility>

namespace HexEx {

namespace {

/// Steps after which a trace gives up (far more than any unit grid edge crosses in a
/// sensible map).
constexpr int kMaxSteps = 4096;

/// A dart description in the current chart.
struct Desc {
    int x, y;
    AxisDir d1, d2;
};

/// sign(a x b) of two axis directions.
int crossDirs(AxisDir a, AxisDir b) {
    const Vec3i u = dirVec(a), v = dirVec(b);
    const int c = u[0] * v[1] - u[1] * v[0];
    return (c > 0) - (c < 0);
}

/// Sign of (b - a) x d for an axis direction d (exact comparison).
int crossEdgeDir(const Vec3d& a, const Vec3d& b, AxisDir d) {
    auto sgn = [](double lo, double hi) { return lo < hi ? 1 : (lo > hi ? -1 : 0); };
    switch (d) {
        case 0: return sgn(b[1], a[1]);
        case 1: return sgn(a[1], b[1]);
        case 2: return sgn(a[0], b[0]);
        default: return sgn(b[0], a[0]);
    }
}

/// Side of point p of the perturbed line {q + e*off + s*dir}: sign(dir x (p - q - e off)).
int lineSide(const Vec3d& p, int qx, int qy, AxisDir dir, AxisDir off) {
    auto sgn = [](double lo, double hi) { return lo < hi ? 1 : (lo > hi ? -1 : 0); };
    int s = 0;
    switch (dir) {
        case 0: s = sgn(qy, p[1]); break;   // dir x (p-q) = p_v - q_v
        case 1: s = sgn(p[1], qy); break;
        case 2: s = sgn(p[0], qx); break;   // = -(p_u - q_u)
        default: s = sgn(qx, p[0]); break;
    }
    return s != 0 ? s : crossDirs(off, dir);
}

Desc mapDesc(const GridTransform& g, const Desc& d) {
    const Vec3i z = g.apply(Vec3i(d.x, d.y, 0));
    return {z[0], z[1], g.R.apply(d.d1), g.R.apply(d.d2)};
}

/// Everything a trace reads.
struct Tracer {
    const ParametrizedTriMesh& m;
    const TriAdjacency& adj;
    const TriParams& params;
    const TriTransitions& tr;
    const std::vector<signed char>& sign;
    const TriDartSet& ds;

    /// Partner or -1; @p boundary set if the trace left the surface.
    int lookup(int f, const Desc& d) const { return sign[static_cast<std::size_t>(f)] ? findTriDart(ds, f, d.x, d.y, d.d1, d.d2) : -1; }

    /// alpha_0 (i = 0) or alpha_2 (i = 2): walk along the perturbed grid line.
    int traceLine(int dart, int i, bool& boundary) const {
        const TriDart& s = ds.darts[static_cast<std::size_t>(dart)];
        Desc from{s.x, s.y, s.d1, s.d2}, to{};
        int qx = s.x, qy = s.y;
        AxisDir dir, off;
        if (i == 0) {
            const Vec3i e = dirVec(s.d1);
            to = {s.x + e[0], s.y + e[1], dirNeg(s.d1), s.d2};
            dir = s.d1;
            off = s.d2;
        } else {
            to = {s.x, s.y, s.d1, dirNeg(s.d2)};
            dir = dirNeg(s.d2);
            off = s.d1;
        }
        int f = s.tri, entry = -1, lastSign = s.sign;
        for (int step = 0; step < kMaxSteps; ++step) {
            const int r = lookup(f, to);
            if (r >= 0 && r != dart) return r;
            const auto& p = params[static_cast<std::size_t>(f)];
            const int sf = sign[static_cast<std::size_t>(f)];
            int exit = -1;
            for (int e = 0; e < 3 && exit < 0; ++e) {
                if (e == entry) continue;
                const Vec3d& a = p[(e + 1) % 3];
                const Vec3d& b = p[(e + 2) % 3];
                if (lineSide(a, qx, qy, dir, off) == lineSide(b, qx, qy, dir, off)) continue;
                if (entry < 0 && sf * crossEdgeDir(a, b, dir) >= 0) continue;  // start: the edge the line leaves through
                // The crossing must lie on the traced segment (between the two grid points).
                const int oa = orient2dAxis(a, b, Vec3d(from.x, from.y, 0), 2);
                const int ob = orient2dAxis(a, b, Vec3d(to.x, to.y, 0), 2);
                if (oa * ob > 0) return -1;
                exit = e;
            }
            if (exit < 0) return -1;
            const std::size_t h = 3 * static_cast<std::size_t>(f) + static_cast<std::size_t>(exit);
            const int o = adj.opposite[h];
            if (o < 0) {
                boundary = true;
                return -1;
            }
            const GridTransform& g = tr.halfedge[h];
            from = mapDesc(g, from);
            to = mapDesc(g, to);
            const Vec3i q = g.apply(Vec3i(qx, qy, 0));
            qx = q[0];
            qy = q[1];
            dir = g.R.apply(dir);
            off = g.R.apply(off);
            f = o / 3;
            entry = o % 3;
            const int sn = sign[static_cast<std::size_t>(f)];
            if (sn != 0 && sn != lastSign) {  // between proper and flipped: the walk runs backwards
                std::swap(from, to);
                dir = dirNeg(dir);
                lastSign = sn;
            }
        }
        return -1;
    }

    /// alpha_1: rotation about the grid point from d1 towards d2, around the fan of the mesh
    /// vertex at the point (or across the edge it lies on).
    int traceRotation(int dart) const {
        const TriDart& s = ds.darts[static_cast<std::size_t>(dart)];
        Desc from{s.x, s.y, s.d1, s.d2}, to{s.x, s.y, s.d2, s.d1};
        const int md = crossDirs(s.d1, s.d2) * s.sign;  // mesh direction of the rotation
        int f = s.tri, entry = -1, lastSign = s.sign, pivot = -1;
        for (int step = 0; step < kMaxSteps; ++step) {
            const int r = lookup(f, to);
            if (r >= 0 && r != dart) return r;
            const auto& p = params[static_cast<std::size_t>(f)];
            const Vec3d z(to.x, to.y, 0);
            int corner = -1;
            for (int k = 0; k < 3; ++k)
                if (p[k] == z && (corner < 0 || m.triangles[static_cast<std::size_t>(f)][k] == pivot)) corner = k;
            int exit = -1;
            if (corner >= 0) {
                pivot = m.triangles[static_cast<std::size_t>(f)][corner];
                const int e1 = (corner + 1) % 3, e2 = (corner + 2) % 3;
                exit = entry == e1 ? e2 : entry == e2 ? e1 : (md > 0 ? e1 : e2);
            } else {
                for (int e = 0; e < 3 && exit < 0; ++e) {
                    if (e == entry) continue;
                    const Vec3d& a = p[(e + 1) % 3];
                    const Vec3d& b = p[(e + 2) % 3];
                    if (orient2dAxis(a, b, z, 2) != 0) continue;
                    if (z[0] < std::min(a[0], b[0]) || z[0] > std::max(a[0], b[0]) || z[1] < std::min(a[1], b[1]) ||
                        z[1] > std::max(a[1], b[1]))
                        continue;
                    exit = e;
                }
            }
            if (exit < 0) return -1;
            const std::size_t h = 3 * static_cast<std::size_t>(f) + static_cast<std::size_t>(exit);
            const int o = adj.opposite[h];
            if (o < 0) return -1;
            const GridTransform& g = tr.halfedge[h];
            from = mapDesc(g, from);
            to = mapDesc(g, to);
            f = o / 3;
            entry = o % 3;
            const int sn = sign[static_cast<std::size_t>(f)];
            if (sn != 0 && sn != lastSign) {
                std::swap(from, to);
                lastSign = sn;
            }
        }
        return -1;
    }
};

} // namespace

std::vector<std::array<int, 4>> traceTriConnections(const ParametrizedTriMesh& m, const TriAdjacency& adj,
                                                    const TriParams& params, const TriTransitions& tr,
                                                    const std::vector<signed char>& sign, const TriDartSet& ds, int threads,
                                                    TriTraceStats* stats) {
    const std::size_t n = ds.darts.size();
    std::vector<std::array<int, 4>> links(n);
    const Tracer T{m, adj, params, tr, sign, ds};
    const int chunks = std::max(1, threads);
    parallelChunks(n, chunks, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t d = b; d < e; ++d) {
            const int di = static_cast<int>(d);
            bool boundary0 = false, boundary2 = false;
            links[d][0] = T.traceLine(di, 0, boundary0);
            links[d][1] = T.traceRotation(di);
            const int a2 = T.traceLine(di, 2, boundary2);
            links[d][2] = a2 >= 0 ? a2 : (boundary2 ? di : -1);
            links[d][3] = di;
        }
    });
    // Keep only mutual links (decided on the traced links, then applied).
    std::vector<std::array<char, 3>> drop(n, {0, 0, 0});
    parallelChunks(n, chunks, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t d = b; d < e; ++d)
            for (int i = 0; i < 3; ++i) {
                const int p = links[d][i];
                if (p >= 0 && p != static_cast<int>(d) && links[static_cast<std::size_t>(p)][i] != static_cast<int>(d)) drop[d][i] = 1;
            }
    });
    TriTraceStats st;
    for (std::size_t d = 0; d < n; ++d)
        for (int i = 0; i < 3; ++i) {
            if (drop[d][i]) {
                links[d][i] = -1;
                ++st.asymmetric;
            }
            if (links[d][i] < 0) ++st.unconnected;
        }
    if (stats) *stats = st;
    return links;
}

} // namespace HexEx
