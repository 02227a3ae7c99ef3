#include "TriangleDarts.hh"

#include "../Core/Error.hh"
#include "../Core/Parallel.hh"
#include "../Predicates/ExactPredicates.hh"
#include "PlanarOrientation.hh"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <tuple>

namespace HexEx {

namespace {
/// Sign of (b - a) x d for an axis direction d: exact (a comparison of two coordinates).
int crossEdgeDir(const Vec2d& a, const Vec2d& b, AxisDir d) {
    auto sgn = [](double lo, double hi) { return lo < hi ? 1 : (lo > hi ? -1 : 0); };
    switch (d) {
        case 0: return sgn(b[1], a[1]);  // d = +u: -(b_v - a_v)
        case 1: return sgn(a[1], b[1]);  // d = -u
        case 2: return sgn(a[0], b[0]);  // d = +v: b_u - a_u
        default: return sgn(b[0], a[0]); // d = -v
    }
}

/// Order of darts within a triangle: grid point (v, then u), then frame.
auto dartKey(int x, int y, AxisDir d1, AxisDir d2) { return std::make_tuple(y, x, d1, d2); }
} // namespace

bool triangleOwnsDart(const std::array<Vec2d, 3>& p, int sign, int x, int y, AxisDir d1, AxisDir d2) {
    for (int i = 0; i < 3; ++i) {
        const Vec2d& a = p[(i + 1) % 3];
        const Vec2d& b = p[(i + 2) % 3];
        int o = sign * orient2dUV(a, b, x, y);
        if (o == 0) o = sign * crossEdgeDir(a, b, d1);
        if (o == 0) o = sign * crossEdgeDir(a, b, d2);
        if (o <= 0) return false;
    }
    return true;
}

namespace {
/// triangleOwnsDart() for a point whose edge orientations (times the sign) are known:
/// @p dirSign[i][d] is sign * ((b - a) x d) for edge i and direction d, used where o[i] == 0.
bool ownsFrame(const int o[3], const int dirSign[3][4], AxisDir d1, AxisDir d2) {
    for (int i = 0; i < 3; ++i) {
        if (o[i] > 0) continue;
        int t = dirSign[i][d1];
        if (t == 0) t = dirSign[i][d2];
        if (t <= 0) return false;
    }
    return true;
}
} // namespace

TriDartSet extractTriDarts(const TriParams& params, const std::vector<signed char>& sign, double max_points, int threads) {
    const std::size_t nf = params.size();
    const int chunks = std::max(1, threads);
    // Guard: bounding-box grid points of all triangles. The sum is taken per chunk; while
    // it stays below 2^52 every partial sum is an exact integer, so it equals the
    // sequential sum (otherwise that is recomputed). The chunks' unsigned parametric areas
    // size their dart buffers (about 8 darts per unit of area).
    auto boxPoints = [&](std::size_t f) {
        const auto& p = params[f];
        const double w = std::floor(std::max({p[0][0], p[1][0], p[2][0]})) - std::ceil(std::min({p[0][0], p[1][0], p[2][0]})) + 1;
        const double h = std::floor(std::max({p[0][1], p[1][1], p[2][1]})) - std::ceil(std::min({p[0][1], p[1][1], p[2][1]})) + 1;
        return w > 0 && h > 0 ? w * h : 0.0;
    };
    std::vector<double> chunkPoints(static_cast<std::size_t>(chunks), 0), chunkArea(static_cast<std::size_t>(chunks), 0);
    parallelChunks(nf, chunks, [&](int k, std::size_t fb, std::size_t fe) {
        double pts = 0, area = 0;
        for (std::size_t f = fb; f < fe; ++f) {
            if (!sign[f]) continue;
            pts += boxPoints(f);
            const auto& p = params[f];
            area += std::fabs((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]));
        }
        chunkPoints[static_cast<std::size_t>(k)] = pts;
        chunkArea[static_cast<std::size_t>(k)] = 0.5 * area;
    });
    double points = 0;
    for (double c : chunkPoints) points += c;
    if (!(points <= 4503599627370496.0)) {  // 2^52
        points = 0;
        for (std::size_t f = 0; f < nf; ++f)
            if (sign[f]) points += boxPoints(f);
    }
    if (!(points <= max_points))
        throw InputError("parameter map too large: the triangles' parameter images span " + std::to_string(points) +
                         " grid points (limit " + std::to_string(max_points) + ")");
    std::vector<TriDartVector> parts(static_cast<std::size_t>(chunks));
    std::vector<std::vector<int>> counts(static_cast<std::size_t>(chunks));
    parallelChunks(nf, chunks, [&](int k, std::size_t fb, std::size_t fe) {
        auto& out = parts[static_cast<std::size_t>(k)];
        auto& cnt = counts[static_cast<std::size_t>(k)];
        cnt.assign(fe - fb, 0);
        // Chunk 0's buffer becomes the result: room for all darts (address space only
        // until written), so only the other chunks' darts are copied.
        double area = 0;
        for (int c = k == 0 ? 0 : k; c < (k == 0 ? chunks : k + 1); ++c) area += chunkArea[static_cast<std::size_t>(c)];
        out.reserve(static_cast<std::size_t>(std::min(8.5 * area, 8.0 * points)) + 64);
        for (std::size_t f = fb; f < fe; ++f) {
            const int s = sign[f];
            if (!s) continue;
            const auto& p = params[f];
            const int x0 = static_cast<int>(std::ceil(std::min({p[0][0], p[1][0], p[2][0]})));
            const int x1 = static_cast<int>(std::floor(std::max({p[0][0], p[1][0], p[2][0]})));
            const int y0 = static_cast<int>(std::ceil(std::min({p[0][1], p[1][1], p[2][1]})));
            const int y1 = static_cast<int>(std::floor(std::max({p[0][1], p[1][1], p[2][1]})));
            const std::size_t before = out.size();
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x) {
                    // o[i]: side of z to edge i (opposite corner i), times the orientation.
                    int o[3];
                    bool outside = false, inside = true;
                    const int corner = p[0][0] == x && p[0][1] == y ? 0 : p[1][0] == x && p[1][1] == y ? 1
                                     : p[2][0] == x && p[2][1] == y ? 2 : -1;
                    if (corner >= 0) {
                        // At a corner: on the two edges there, on the inner side of the third
                        // (its orientation is the triangle's): what the predicate would say.
                        o[corner] = 1;
                        o[(corner + 1) % 3] = o[(corner + 2) % 3] = 0;
                        inside = false;
                    } else {
                        for (int i = 0; i < 3 && !outside; ++i) {
                            o[i] = s * orient2dUV(p[(i + 1) % 3], p[(i + 2) % 3], x, y);
                            if (o[i] < 0) outside = true;
                            if (o[i] == 0) inside = false;
                        }
                        if (outside) continue;
                    }
                    int dirSign[3][4] = {};
                    if (!inside)
                        for (int i = 0; i < 3; ++i)
                            if (o[i] == 0)
                                for (AxisDir d = 0; d < 4; ++d) dirSign[i][d] = s * crossEdgeDir(p[(i + 1) % 3], p[(i + 2) % 3], d);
                    for (AxisDir d1 = 0; d1 < 4; ++d1) {
                        const int other = 1 - dirAxis(d1);
                        for (int side = 0; side < 2; ++side) {
                            const AxisDir d2 = static_cast<AxisDir>(2 * other + side);
                            if (!inside && !ownsFrame(o, dirSign, d1, d2)) continue;
                            TriDart d;
                            d.tri = static_cast<int>(f);
                            d.x = x;
                            d.y = y;
                            d.d1 = d1;
                            d.d2 = d2;
                            d.sign = static_cast<signed char>(s);
                            out.push_back(d);
                        }
                    }
                }
            cnt[f - fb] = static_cast<int>(out.size() - before);
        }
    });
    TriDartSet ds;
    std::size_t total = 0;
    for (const auto& part : parts) total += part.size();
    if (total > static_cast<std::size_t>(INT32_MAX / 2)) throw InputError("parameter map too large: too many darts");
    // Offsets and the concatenation, each chunk copying its own part.
    ds.offset.resize(nf + 1);  // every entry is written below, by the chunk of its triangle
    ds.offset[0] = 0;
    std::vector<std::size_t> first(static_cast<std::size_t>(chunks) + 1, 0);
    for (int k = 0; k < chunks; ++k)
        first[static_cast<std::size_t>(k) + 1] = first[static_cast<std::size_t>(k)] + parts[static_cast<std::size_t>(k)].size();
    const std::size_t n0 = parts[0].size();
    ds.darts = std::move(parts[0]);
    ds.darts.resize(total);
    std::vector<long> anti(static_cast<std::size_t>(chunks), 0);
    parallelChunks(nf, chunks, [&](int k, std::size_t fb, std::size_t) {
        auto& part = parts[static_cast<std::size_t>(k)];
        if (k > 0)
            std::copy(part.begin(), part.end(), ds.darts.begin() + static_cast<std::ptrdiff_t>(first[static_cast<std::size_t>(k)]));
        int o = static_cast<int>(first[static_cast<std::size_t>(k)]);
        std::size_t f = fb;
        for (int c : counts[static_cast<std::size_t>(k)]) {
            o += c;
            ds.offset[++f] = o;
        }
        const auto b = ds.darts.begin() + static_cast<std::ptrdiff_t>(first[static_cast<std::size_t>(k)]);
        const auto e = k > 0 ? b + static_cast<std::ptrdiff_t>(part.size()) : b + static_cast<std::ptrdiff_t>(n0);
        for (auto d = b; d != e; ++d)
            if (d->sign < 0) ++anti[static_cast<std::size_t>(k)];
        TriDartVector().swap(part);
    });
    for (long a : anti) ds.anti += a;
    return ds;
}

int findTriDart(const TriDartSet& ds, int f, int x, int y, AxisDir d1, AxisDir d2) {
    const auto b = ds.darts.begin() + ds.offset[static_cast<std::size_t>(f)];
    const auto e = ds.darts.begin() + ds.offset[static_cast<std::size_t>(f) + 1];
    const auto key = dartKey(x, y, d1, d2);
    const auto it = std::lower_bound(b, e, key, [](const TriDart& d, const decltype(key)& k) {
        return dartKey(d.x, d.y, d.d1, d.d2) < k;
    });
    if (it == e || dartKey(it->x, it->y, it->d1, it->d2) != key) return -1;
    return static_cast<int>(it - ds.darts.begin());
}

} // namespace HexEx
