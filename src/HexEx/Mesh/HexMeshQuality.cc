/// @file HexMeshQuality.cc
/// Scaled Jacobians of hexahedra.

#include "HexMeshQuality.hh"

#include "../Core/Parallel.hh"

#include <algorithm>
#include <cmath>

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

double hexScaledJacobian(const std::array<Vec3d, 8>& p) {
    double worst = 1.0;
    for (const auto& f : kHexCornerFrames) {
        const Vec3d& o = p[f[0]];
        worst = std::min(worst, cornerScaledJacobian(p[f[1]] - o, p[f[2]] - o, p[f[3]] - o));
    }
    return worst;
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
        std::array<Vec3d, 8> p;
        for (std::size_t h = b; h < e; ++h)
            if (hexCorners(mesh, mesh.hexes[h], p)) {
                sj[h] = hexScaledJacobian(p);
                validity[h] = classifyHexValidity(p);
            }
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
