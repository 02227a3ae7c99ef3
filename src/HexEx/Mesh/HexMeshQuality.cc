/// @file HexMeshQuality.cc
/// Scaled Jacobians of hexahedra.

#include "HexMeshQuality.hh"

#include "../Core/Parallel.hh"
#include "PointPairs.hh"

#include <algorithm>
#include <cmath>
#include <limits>

namespace HexEx {

const std::array<std::array<int, 4>, 8> kHexCornerFrames = {{
    {{0, 1, 3, 4}},
    {{1, 2, 0, 5}},
    {{2, 3, 1, 6}},
    {{3, 0, 2, 7}},
    {{4, 7, 5, 0}},
    {{5, 4, 6, 1}},
    {{6, 5, 7, 2}},
    {{7, 6, 4, 3}},
}};

double cornerScaledJacobian(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double denom = la * lb * lc;
    if (!(denom > 0) || !std::isfinite(denom)) return 0.0;
    const double det = (a % b) | c;
    const double sj = det / denom;
    if (!std::isfinite(sj)) return 0.0;
    return std::clamp(sj, -1.0, 1.0);
}

namespace {

/// The 12 edges of a hex in VTK order, as (lower corner, upper corner).
constexpr int kHexEdgeCorners[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                        {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

/// Per corner frame of kHexCornerFrames (same rows), the edges of its three vectors.
constexpr int kFrameEdges[8][3] = {{0, 3, 8}, {1, 0, 9},  {2, 1, 10}, {3, 2, 11},
                                   {7, 4, 8}, {4, 5, 9},  {5, 6, 10}, {6, 7, 11}};

/// sqrt of @p n values, in place (two at a time where SSE2 is there: the same correctly
/// rounded results as std::sqrt).
inline void sqrtInPlace(double* x, int n) {
#if defined(__SSE2__)
    for (int i = 0; i + 1 < n; i += 2) _mm_storeu_pd(x + i, _mm_sqrt_pd(_mm_loadu_pd(x + i)));
    if (n % 2) x[n - 1] = std::sqrt(x[n - 1]);
#else
    for (int i = 0; i < n; ++i) x[i] = std::sqrt(x[i]);
#endif
}

} // namespace

double hexScaledJacobian(const std::array<Vec3d, 8>& p) {
    // The same doubles as the minimum of cornerScaledJacobian() over the 8 corner frames:
    // the corner vectors are the same differences, and each edge's length is computed once
    // (|p[j] - p[i]| and |p[i] - p[j]| have the same squares, hence the same bits).
    double len[12];
    for (int e = 0; e < 12; ++e) len[e] = (p[kHexEdgeCorners[e][1]] - p[kHexEdgeCorners[e][0]]).sqrnorm();
    sqrtInPlace(len, 12);
    double worst = 1.0;
    for (int k = 0; k < 8; ++k) {
        const auto& f = kHexCornerFrames[static_cast<std::size_t>(k)];
        const double denom = len[kFrameEdges[k][0]] * len[kFrameEdges[k][1]] * len[kFrameEdges[k][2]];
        double sj = 0.0;
        if (denom > 0 && std::isfinite(denom)) {
            const Vec3d& o = p[f[0]];
            const double det = ((p[f[1]] - o) % (p[f[2]] - o)) | (p[f[3]] - o);
            const double q = det / denom;
            if (std::isfinite(q)) sj = std::clamp(q, -1.0, 1.0);
        }
        worst = std::min(worst, sj);
    }
    return worst;
}

void hexScaledJacobianPair(const std::array<Vec3d, 8>& a, const std::array<Vec3d, 8>& b, double out[2]) {
#if defined(__SSE2__)
    // hexScaledJacobian()'s operations lane by lane. OpenMesh's sqrnorm() and dot product
    // are (x0 y0 + x1 y1) + x2 y2 (no leading 0 +: it would turn a -0 determinant into +0),
    // its cross product is (a1 b2 - a2 b1, a2 b0 - a0 b2, a0 b1 - a1 b0).
    PointPair p[8];
    loadHexPair(a, b, p);
    __m128d len[12];
    for (int e = 0; e < 12; ++e) {
        const PointPair d = p[kHexEdgeCorners[e][1]] - p[kHexEdgeCorners[e][0]];
        const __m128d s = _mm_add_pd(_mm_add_pd(_mm_mul_pd(d.x, d.x), _mm_mul_pd(d.y, d.y)), _mm_mul_pd(d.z, d.z));
        len[e] = _mm_sqrt_pd(s);
    }
    const __m128d zero = _mm_setzero_pd(), one = _mm_set1_pd(1.0), minus_one = _mm_set1_pd(-1.0);
    const __m128d largest = _mm_set1_pd(std::numeric_limits<double>::max());
    __m128d worst = one;
    for (int k = 0; k < 8; ++k) {
        const auto& f = kHexCornerFrames[static_cast<std::size_t>(k)];
        const PointPair& o = p[f[0]];
        const PointPair u = p[f[1]] - o, v = p[f[2]] - o, w = p[f[3]] - o;
        const __m128d cx = _mm_sub_pd(_mm_mul_pd(u.y, v.z), _mm_mul_pd(u.z, v.y));
        const __m128d cy = _mm_sub_pd(_mm_mul_pd(u.z, v.x), _mm_mul_pd(u.x, v.z));
        const __m128d cz = _mm_sub_pd(_mm_mul_pd(u.x, v.y), _mm_mul_pd(u.y, v.x));
        const __m128d det = _mm_add_pd(_mm_add_pd(_mm_mul_pd(cx, w.x), _mm_mul_pd(cy, w.y)), _mm_mul_pd(cz, w.z));
        const __m128d denom =
            _mm_mul_pd(_mm_mul_pd(len[kFrameEdges[k][0]], len[kFrameEdges[k][1]]), len[kFrameEdges[k][2]]);
        const __m128d q = _mm_div_pd(det, denom);
        // denom > 0 and finite, q finite (comparisons with NaN are false); else 0.
        const __m128d ok = _mm_and_pd(_mm_and_pd(_mm_cmpgt_pd(denom, zero), _mm_cmple_pd(denom, largest)),
                                      _mm_cmple_pd(absPair(q), largest));
        // std::clamp(q, -1, 1) and std::min(worst, sj) of finite values: ties keep the same bits.
        const __m128d sj = _mm_and_pd(ok, _mm_max_pd(_mm_min_pd(q, one), minus_one));
        worst = _mm_min_pd(sj, worst);
    }
    _mm_storeu_pd(out, worst);
#else
    out[0] = hexScaledJacobian(a);
    out[1] = hexScaledJacobian(b);
#endif
}

namespace {

/// The corners of hex @p h of @p mesh; false if an index is out of range.
bool hexCorners(const HexMesh& mesh, const std::array<int, 8>& h, std::array<Vec3d, 8>& p) {
    const long nv = static_cast<long>(mesh.vertices.size());
    for (int i = 0; i < 8; ++i) {
        if (h[i] < 0 || h[i] >= nv) return false;
        p[i] = mesh.vertices[h[i]];
    }
    return true;
}

/// Chunks for the per-hex loops: one for small meshes (thread start-up would dominate).
int hexChunks(const HexMesh& mesh, int threads) {
    return mesh.hexes.size() < 4096 ? 1 : resolveThreadCount(threads);
}

} // namespace

std::vector<double> scaledJacobians(const HexMesh& mesh) {
    std::vector<double> out(mesh.hexes.size(), 0.0);
    std::array<Vec3d, 8> p;
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
        if (hexCorners(mesh, mesh.hexes[h], p)) out[h] = hexScaledJacobian(p);
    return out;
}

std::vector<HexValidity> hexValidities(const HexMesh& mesh, int threads) {
    std::vector<HexValidity> out(mesh.hexes.size(), HexValidity::Invalid);
    parallelChunks(mesh.hexes.size(), hexChunks(mesh, threads), [&](int, std::size_t b, std::size_t e) {
        std::array<Vec3d, 8> p;
        for (std::size_t h = b; h < e; ++h)
            if (hexCorners(mesh, mesh.hexes[h], p)) out[h] = classifyHexValidity(p);
    });
    return out;
}

QualityStats computeQuality(const HexMesh& mesh, int threads) {
    QualityStats s;
    const std::size_t n = mesh.hexes.size();
    if (n == 0) return s;
    // One parallel pass for both per-hex figures; the sums run in hex order afterwards, so
    // the result does not depend on the thread count.
    std::vector<double> sj(n, 0.0);
    std::vector<HexValidity> validity(n, HexValidity::Invalid);
    parallelChunks(n, hexChunks(mesh, threads), [&](int, std::size_t b, std::size_t e) {
        std::array<Vec3d, 8> p, q;
        auto measure = [&](std::size_t h) {
            if (hexCorners(mesh, mesh.hexes[h], p)) {
                sj[h] = hexScaledJacobian(p);
                validity[h] = classifyHexValidity(p);
            }
        };
        // Two hexes at a time (the same values as one at a time).
        std::size_t h = b;
        for (; h + 1 < e; h += 2) {
            if (hexCorners(mesh, mesh.hexes[h], p) && hexCorners(mesh, mesh.hexes[h + 1], q)) {
                hexScaledJacobianPair(p, q, &sj[h]);
                classifyHexValidityPair(p, q, &validity[h]);
            } else {
                measure(h);
                measure(h + 1);
            }
        }
        if (h < e) measure(h);
    });
    double sum = 0, mn = sj.front();
    for (std::size_t h = 0; h < n; ++h) {
        const double x = sj[h];
        sum += x;
        mn = std::min(mn, x);
        if (x <= 0) ++s.inverted_hexes;
        if (validity[h] == HexValidity::Invalid) {
            if (s.invalid_hexes == 0) s.first_invalid_hex = static_cast<long>(h);
            ++s.invalid_hexes;
        } else if (validity[h] == HexValidity::Undecided) {
            ++s.undecided_hexes;
        }
    }
    s.min_scaled_jacobian = mn;
    s.mean_scaled_jacobian = sum / static_cast<double>(n);
    return s;
}

} // namespace HexEx
