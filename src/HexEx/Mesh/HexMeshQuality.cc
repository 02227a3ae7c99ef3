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

std::vector<double> scaledJacobians(const HexMesh& mesh) {
    std::vector<double> out;
    out.reserve(mesh.hexes.size());
    const long nv = static_cast<long>(mesh.vertices.size());
    for (const auto& h : mesh.hexes) {
        std::array<Vec3d, 8> p;
        bool ok = true;
        for (int i = 0; i < 8; ++i) {
            if (h[i] < 0 || h[i] >= nv) {
                ok = false;
                break;
            }
            p[i] = mesh.vertices[h[i]];
        }
        out.push_back(ok ? hexScaledJacobian(p) : 0.0);
    }
    return out;
}

std::vector<HexValidity> hexValidities(const HexMesh& mesh, int threads) {
    std::vector<HexValidity> out(mesh.hexes.size(), HexValidity::Invalid);
    const long nv = static_cast<long>(mesh.vertices.size());
    const int chunks = mesh.hexes.size() < 4096 ? 1 : resolveThreadCount(threads);
    parallelChunks(mesh.hexes.size(), chunks, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t h = b; h < e; ++h) {
            std::array<Vec3d, 8> p;
            bool ok = true;
            for (int i = 0; i < 8 && ok; ++i) {
                const int v = mesh.hexes[h][i];
                ok = v >= 0 && v < nv;
                if (ok) p[i] = mesh.vertices[v];
            }
            if (ok) out[h] = classifyHexValidity(p);
        }
    });
    return out;
}

QualityStats computeQuality(const HexMesh& mesh, int threads) {
    QualityStats s;
    const std::vector<double> sj = scaledJacobians(mesh);
    if (sj.empty()) return s;
    double sum = 0, mn = sj.front();
    for (const double x : sj) {
        sum += x;
        mn = std::min(mn, x);
        if (x <= 0) ++s.inverted_hexes;
    }
    s.min_scaled_jacobian = mn;
    s.mean_scaled_jacobian = sum / static_cast<double>(sj.size());
    const std::vector<HexValidity> validity = hexValidities(mesh, threads);
    for (std::size_t h = 0; h < validity.size(); ++h) {
        if (validity[h] == HexValidity::Invalid) {
            if (s.invalid_hexes == 0) s.first_invalid_hex = static_cast<long>(h);
            ++s.invalid_hexes;
        } else if (validity[h] == HexValidity::Undecided) {
            ++s.undecided_hexes;
        }
    }
    return s;
}

} // namespace HexEx
