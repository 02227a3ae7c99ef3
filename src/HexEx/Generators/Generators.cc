#include "Generators.hh"

#include "../Predicates/ExactPredicates.hh"
#include "RandomDraws.hh"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>

namespace HexEx {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Appends the six tets of one box. Box corners are numbered by bits (bit d set: high side
/// along axis d); @p v and @p p give each corner's vertex and parameter (in the box's chart).
/// The split runs around the main diagonal from corner r to corner 7^r, i.e. it is the Kuhn
/// split of the box mirrored along the axes set in @p reflect. Corners are ordered so that
/// every tet is positively oriented in parameter space.
void addBoxTets(ParametrizedTetMesh& pm, const VertexHandle v[8], const Vec3d p[8], unsigned reflect) {
    static const int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
    const int mirrored = ((reflect & 1) ? 1 : 0) + ((reflect & 2) ? 1 : 0) + ((reflect & 4) ? 1 : 0);
    for (int k = 0; k < 6; ++k) {
        const int* s = perms[k];
        int corner[4] = {0, 1 << s[0], (1 << s[0]) | (1 << s[1]), 7};
        for (int& c : corner) c ^= static_cast<int>(reflect);
        // Unmirrored, the path tet has the sign of the permutation; each mirror flips it.
        const bool odd = (k >= 3) != (mirrored % 2 == 1);
        if (odd) std::swap(corner[1], corner[2]);
        pm.mesh.add_cell({v[corner[0]], v[corner[1]], v[corner[2]], v[corner[3]]});
        pm.params.push_back({p[corner[0]], p[corner[1]], p[corner[2]], p[corner[3]]});
    }
}

/// Throws std::logic_error if some tet is not strictly positive in 3D or in its chart.
void verifyPositive(const ParametrizedTetMesh& pm, const char* what) {
    const TetMesh& m = pm.mesh;
    for (std::size_t c = 0; c < m.n_cells(); ++c) {
        const auto& cv = m.cell_vertices(CellHandle(static_cast<int>(c)));
        const auto& q = pm.params[c];
        if (orient3d(q[0], q[1], q[2], q[3]) <= 0)
            throw std::logic_error(std::string(what) + ": tet " + std::to_string(c) + " is not positive in parameter space");
        if (orient3d(m.position(cv[0]), m.position(cv[1]), m.position(cv[2]), m.position(cv[3])) <= 0)
            throw std::logic_error(std::string(what) + ": tet " + std::to_string(c) + " is not positive in 3D");
    }
}

/// True if all tets are strictly positive in 3D.
bool allPositive3d(const TetMesh& m) {
    for (std::size_t c = 0; c < m.n_cells(); ++c) {
        const auto& cv = m.cell_vertices(CellHandle(static_cast<int>(c)));
        if (orient3d(m.position(cv[0]), m.position(cv[1]), m.position(cv[2]), m.position(cv[3])) <= 0) return false;
    }
    return true;
}

/// The grid coordinate extent * i / n, correctly rounded (exact whenever n divides extent * i).
double gridCoord(int extent, int i, int n) {
    return static_cast<double>(static_cast<long long>(extent) * i) / static_cast<double>(n);
}

void requireAtLeast(int value, int minimum, const char* name, const char* fn) {
    if (value < minimum)
        throw std::invalid_argument(std::string(fn) + ": " + name + " must be at least " + std::to_string(minimum) +
                                    ", got " + std::to_string(value));
}

/// Builds a ring of nu x nv x nw boxes, periodic in u. @p twisted glues the seam by a quarter
/// turn (then nv == nw) and uses the reflected Kuhn split; @p radius is the ring's inner
/// radius for the untwisted and centre radius for the twisted variant.
ParametrizedTetMesh buildRing(int L, int W, int H, int nu, int nv, int nw, bool twisted, double radius) {
    ParametrizedTetMesh pm;
    const int sv = nv + 1, sw = nw + 1;
    pm.mesh.reserve(static_cast<std::size_t>(nu) * sv * sw, 6u * static_cast<std::size_t>(nu) * nv * nw);
    pm.params.reserve(6u * static_cast<std::size_t>(nu) * nv * nw);
    for (int iu = 0; iu < nu; ++iu)
        for (int iv = 0; iv <= nv; ++iv)
            for (int iw = 0; iw <= nw; ++iw) {
                const double u = gridCoord(L, iu, nu), v = gridCoord(W, iv, nv), w = gridCoord(H, iw, nw);
                const double theta = -2.0 * kPi * u / L;
                double rho, z;
                if (twisted) {
                    const double tau = 0.5 * kPi * u / L;
                    const double x = v - 0.5 * W, y = w - 0.5 * W;
                    rho = radius + x * std::cos(tau) - y * std::sin(tau);
                    z = x * std::sin(tau) + y * std::cos(tau);
                } else {
                    rho = radius + v;
                    z = w;
                }
                pm.mesh.add_vertex(Vec3d(rho * std::cos(theta), rho * std::sin(theta), z));
            }
    auto vid = [&](int iu, int iv, int iw) {
        if (iu == nu) {
            if (twisted) {
                const int jv = nw - iw, jw = iv;  // (v,w) -> (W-w, v)
                iv = jv;
                iw = jw;
            }
            iu = 0;
        }
        return VertexHandle((iu * sv + iv) * sw + iw);
    };
    for (int iu = 0; iu < nu; ++iu)
        for (int iv = 0; iv < nv; ++iv)
            for (int iw = 0; iw < nw; ++iw) {
                VertexHandle vh[8];
                Vec3d p[8];
                for (int c = 0; c < 8; ++c) {
                    const int ju = iu + (c & 1), jv = iv + ((c >> 1) & 1), jw = iw + ((c >> 2) & 1);
                    vh[c] = vid(ju, jv, jw);
                    p[c] = Vec3d(gridCoord(L, ju, nu), gridCoord(W, jv, nv), gridCoord(H, jw, nw));
                }
                const unsigned reflect = twisted ? ((iv & 1) ? 2u : 0u) | ((iw & 1) ? 4u : 0u) : 0u;
                addBoxTets(pm, vh, p, reflect);
            }
    return pm;
}

} // namespace

double tetVolume(const Vec3d& p0, const Vec3d& p1, const Vec3d& p2, const Vec3d& p3) {
    const Vec3d a = p1 - p0, b = p2 - p0, c = p3 - p0;
    const double det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                       a[2] * (b[0] * c[1] - b[1] * c[0]);
    return det / 6.0;
}

double totalParametricVolume(const ParametrizedTetMesh& pm) {
    double sum = 0.0;
    for (const auto& q : pm.params) sum += tetVolume(q[0], q[1], q[2], q[3]);
    return sum;
}

ParametrizedTetMesh generateCube(int n, int s) {
    requireAtLeast(n, 1, "n", "generateCube");
    requireAtLeast(s, 1, "s", "generateCube");
    ParametrizedTetMesh pm;
    const int sn = n + 1;
    pm.mesh.reserve(static_cast<std::size_t>(sn) * sn * sn, 6u * static_cast<std::size_t>(n) * n * n);
    pm.params.reserve(6u * static_cast<std::size_t>(n) * n * n);
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i)
                pm.mesh.add_vertex(Vec3d(gridCoord(1, i, n), gridCoord(1, j, n), gridCoord(1, k, n)));
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                VertexHandle vh[8];
                Vec3d p[8];
                for (int c = 0; c < 8; ++c) {
                    const int a = i + (c & 1), b = j + ((c >> 1) & 1), d = k + ((c >> 2) & 1);
                    vh[c] = VertexHandle((d * sn + b) * sn + a);
                    p[c] = Vec3d(gridCoord(s, a, n), gridCoord(s, b, n), gridCoord(s, d, n));
                }
                addBoxTets(pm, vh, p, 0);
            }
    verifyPositive(pm, "generateCube");
    return pm;
}

ParametrizedTetMesh generateCylinder(int k, int R, int H, int n, int m) {
    const char* fn = "generateCylinder";
    requireAtLeast(k, 3, "k", fn);
    requireAtLeast(R, 1, "R", fn);
    requireAtLeast(H, 1, "H", fn);
    requireAtLeast(n, 1, "n", fn);
    requireAtLeast(m, 1, "m", fn);
    ParametrizedTetMesh pm;
    const int sh = m + 1, sb = n + 1;
    // Vertex numbering: the m+1 axis vertices first, then per wedge the vertices with
    // a-index 1..n and b-index 0..n (a-index 0 belongs to the next wedge or the axis).
    const std::size_t nv = sh + static_cast<std::size_t>(k) * n * sb * sh;
    pm.mesh.reserve(nv, 6u * static_cast<std::size_t>(k) * n * n * m);
    pm.params.reserve(6u * static_cast<std::size_t>(k) * n * n * m);
    const double wedge = 2.0 * kPi / k;
    for (int ih = 0; ih <= m; ++ih) pm.mesh.add_vertex(Vec3d(0.0, 0.0, gridCoord(H, ih, m) / R));
    for (int w = 0; w < k; ++w)
        for (int ia = 1; ia <= n; ++ia)
            for (int ib = 0; ib <= n; ++ib)
                for (int ih = 0; ih <= m; ++ih) {
                    const double a = static_cast<double>(ia) / n, b = static_cast<double>(ib) / n;
                    const double phi = wedge * w + wedge * (std::atan2(b, a) / (0.5 * kPi));
                    const double rho = std::max(a, b);
                    pm.mesh.add_vertex(Vec3d(rho * std::cos(phi), rho * std::sin(phi), gridCoord(H, ih, m) / R));
                }
    auto vid = [&](int w, int ia, int ib, int ih) {
        if (ia == 0) {
            if (ib == 0) return VertexHandle(ih);
            // (0, b, h) of wedge w is (b, 0, h) of wedge w+1.
            w = (w + 1) % k;
            ia = ib;
            ib = 0;
        }
        return VertexHandle(sh + ((w * n + (ia - 1)) * sb + ib) * sh + ih);
    };
    for (int w = 0; w < k; ++w)
        for (int ia = 0; ia < n; ++ia)
            for (int ib = 0; ib < n; ++ib)
                for (int ih = 0; ih < m; ++ih) {
                    VertexHandle vh[8];
                    Vec3d p[8];
                    for (int c = 0; c < 8; ++c) {
                        const int ja = ia + (c & 1), jb = ib + ((c >> 1) & 1), jh = ih + ((c >> 2) & 1);
                        vh[c] = vid(w, ja, jb, jh);
                        p[c] = Vec3d(gridCoord(R, ja, n), gridCoord(R, jb, n), gridCoord(H, jh, m));
                    }
                    addBoxTets(pm, vh, p, 0);
                }
    verifyPositive(pm, fn);
    return pm;
}

ParametrizedTetMesh generateRing(int L, int W, int H, int nu, int nv, int nw) {
    const char* fn = "generateRing";
    requireAtLeast(L, 1, "L", fn);
    requireAtLeast(W, 1, "W", fn);
    requireAtLeast(H, 1, "H", fn);
    requireAtLeast(nu, 3, "nu", fn);
    requireAtLeast(nv, 1, "nv", fn);
    requireAtLeast(nw, 1, "nw", fn);
    ParametrizedTetMesh pm = buildRing(L, W, H, nu, nv, nw, false, static_cast<double>(W));
    verifyPositive(pm, fn);
    return pm;
}

ParametrizedTetMesh generateTwistedRing(int L, int W, int nu, int nv) {
    const char* fn = "generateTwistedRing";
    requireAtLeast(L, 1, "L", fn);
    requireAtLeast(W, 1, "W", fn);
    requireAtLeast(nu, 3, "nu", fn);
    requireAtLeast(nv, 2, "nv", fn);
    if (nv % 2 != 0) throw std::invalid_argument("generateTwistedRing: nv must be even, got " + std::to_string(nv));
    double radius = 2.0 * W;
    for (int attempt = 0; attempt < 40; ++attempt, radius *= 2.0) {
        ParametrizedTetMesh pm = buildRing(L, W, W, nu, nv, nv, true, radius);
        if (!allPositive3d(pm.mesh)) continue;
        verifyPositive(pm, fn);
        return pm;
    }
    throw std::logic_error("generateTwistedRing: no ring radius gives positive tets");
}

std::vector<GridTransform> applyRandomChartTransforms(ParametrizedTetMesh& pm, unsigned seed) {
    std::mt19937 gen(seed);
    std::vector<GridTransform> applied;
    applied.reserve(pm.params.size());
    for (auto& q : pm.params) {
        const Rotation r(static_cast<int>(uniformBelow(gen, Rotation::kCount)));
        Vec3i t;
        for (int d = 0; d < 3; ++d) t[d] = static_cast<int>(uniformBelow(gen, 11)) - 5;
        const GridTransform g(r, t);
        for (auto& x : q) x = g.apply(x);
        applied.push_back(g);
    }
    return applied;
}

void applyParameterNoise(ParametrizedTetMesh& pm, double a, unsigned seed) {
    TetMesh& m = pm.mesh;
    if (!m.has_adjacency()) m.build_adjacency();
    std::mt19937 gen(seed);
    for (std::size_t c = 0; c < m.n_cells(); ++c) {
        auto& q = pm.params[c];
        bool keep[4][3] = {};
        for (int j = 0; j < 4; ++j) {
            if (!m.is_boundary(TetMesh::halfface(CellHandle(static_cast<int>(c)), j))) continue;
            const int* f = TetMesh::kFaceCorners[j];
            for (int d = 0; d < 3; ++d)
                if (q[f[0]][d] == q[f[1]][d] && q[f[1]][d] == q[f[2]][d])
                    for (int k = 0; k < 3; ++k) keep[f[k]][d] = true;
        }
        for (int i = 0; i < 4; ++i)
            for (int d = 0; d < 3; ++d) {
                const double noise = a * (2.0 * uniform01(gen) - 1.0);  // drawn always: stream independent of geometry
                if (!keep[i][d]) q[i][d] += noise;
            }
    }
}

} // namespace HexEx
