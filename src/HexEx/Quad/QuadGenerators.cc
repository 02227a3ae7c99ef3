#include "QuadGenerators.hh"

#include "../Grid/PlanarRotation.hh"
#include "TrianglePreprocessing.hh"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace HexEx {

namespace {
/// Uniform double in [-a, a] from one 32-bit draw (platform independent).
double uniformIn(std::mt19937& rng, double a) { return a * (2.0 * (static_cast<double>(rng()) / 4294967295.0) - 1.0); }

/// Adds the two triangles of a box with corners (vertex ids) c00, c10, c11, c01 and
/// parameters p00, p10, p11, p01 (counter-clockwise).
void addBox(ParametrizedTriMesh& m, int c00, int c10, int c11, int c01, const Vec2d& p00, const Vec2d& p10,
            const Vec2d& p11, const Vec2d& p01) {
    m.triangles.push_back({c00, c10, c11});
    m.params.push_back({p00, p10, p11});
    m.triangles.push_back({c00, c11, c01});
    m.params.push_back({p00, p11, p01});
}
} // namespace

ParametrizedTriMesh generateSquare(int n, int s) {
    if (n < 1 || s < 1) throw std::invalid_argument("generateSquare: n and s must be >= 1");
    ParametrizedTriMesh m;
    auto id = [&](int i, int j) { return j * (n + 1) + i; };
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) m.points.push_back(Vec3d(double(i) / n, double(j) / n, 0));
    auto par = [&](int i, int j) { return Vec2d(double(s) * i / n, double(s) * j / n); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            addBox(m, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), par(i, j), par(i + 1, j), par(i + 1, j + 1),
                   par(i, j + 1));
    return m;
}

ParametrizedTriMesh generateConeDisk(int k, int R, int n) {
    if (k < 2 || R < 1 || n < 1) throw std::invalid_argument("generateConeDisk: k must be >= 2 and R, n >= 1");
    ParametrizedTriMesh m;
    const double pi = 4.0 * std::atan(1.0);
    // Vertex 0 is the centre; wedge i owns its points with p >= 1 (q = 0..n).
    auto id = [&](int i, int p, int q) -> int {
        if (p == 0 && q == 0) return 0;
        if (p == 0) return 1 + (((i + 1) % k) * n + (q - 1)) * (n + 1);  // side a = 0 is the next wedge's side b = 0
        return 1 + ((i * n) + (p - 1)) * (n + 1) + q;
    };
    m.points.assign(static_cast<std::size_t>(1 + k * n * (n + 1)), Vec3d(0, 0, 0));
    for (int i = 0; i < k; ++i)
        for (int p = 1; p <= n; ++p)
            for (int q = 0; q <= n; ++q) {
                const double a = double(p) / n, b = double(q) / n;
                const double ang = 2.0 * pi * (i + std::atan2(b, a) / (pi / 2)) / k;
                const double r = std::max(a, b);
                m.points[static_cast<std::size_t>(id(i, p, q))] = Vec3d(r * std::cos(ang), r * std::sin(ang), 0);
            }
    auto par = [&](int p, int q) { return Vec2d(double(R) * p / n, double(R) * q / n); };
    for (int i = 0; i < k; ++i)
        for (int q = 0; q < n; ++q)
            for (int p = 0; p < n; ++p)
                addBox(m, id(i, p, q), id(i, p + 1, q), id(i, p + 1, q + 1), id(i, p, q + 1), par(p, q), par(p + 1, q),
                       par(p + 1, q + 1), par(p, q + 1));
    return m;
}

ParametrizedTriMesh generateTorus(int L, int W, int nu, int nv) {
    if (nu < 3 || nv < 3 || L < 1 || W < 1)
        throw std::invalid_argument("generateTorus: nu, nv must be >= 3 and L, W >= 1");
    ParametrizedTriMesh m;
    const double pi = 4.0 * std::atan(1.0);
    auto id = [&](int i, int j) { return (j % nv) * nu + (i % nu); };
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            const double phi = 2 * pi * i / nu, psi = 2 * pi * j / nv;
            const double r = 2.0 + std::cos(psi);
            m.points.push_back(Vec3d(r * std::cos(phi), r * std::sin(phi), std::sin(psi)));
        }
    auto par = [&](int i, int j) { return Vec2d(double(L) * i / nu, double(W) * j / nv); };
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i)
            addBox(m, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), par(i, j), par(i + 1, j), par(i + 1, j + 1),
                   par(i, j + 1));
    return m;
}

ParametrizedTriMesh generateQuarterTurnSeam(int W, int n) {
    if (n < 2 || W < 1) throw std::invalid_argument("generateQuarterTurnSeam: n must be >= 2 and W >= 1");
    ParametrizedTriMesh m = generateSquare(n, W);
    for (std::size_t f = 0; f < m.triangles.size(); ++f) {
        const int box = static_cast<int>(f / 2), column = box % n;
        if (column < n / 2) continue;
        for (auto& p : m.params[f]) p = Vec2d(-p[1] + 3, p[0] - 2);
    }
    return m;
}

void applyRandomTriCharts(ParametrizedTriMesh& m, unsigned seed) {
    std::mt19937 rng(seed);
    for (auto& tri : m.params) {
        const Rotation R = planarRotation(static_cast<int>(rng() % 4));
        const int tx = static_cast<int>(rng() % 11) - 5, ty = static_cast<int>(rng() % 11) - 5;
        for (auto& p : tri) {
            const Vec3d r = R.apply(Vec3d(p[0], p[1], 0));
            p = Vec2d(r[0] + tx, r[1] + ty);
        }
    }
}

void applyTriParameterNoise(ParametrizedTriMesh& m, double a, unsigned seed) {
    const TriAdjacency adj = buildTriAdjacency(m);
    std::vector<std::array<std::array<char, 2>, 3>> keep(m.triangles.size());
    for (std::size_t f = 0; f < m.triangles.size(); ++f)
        for (int i = 0; i < 3; ++i) {
            if (adj.opposite[3 * f + static_cast<std::size_t>(i)] >= 0) continue;
            const int ka = (i + 1) % 3, kb = (i + 2) % 3;
            for (int c = 0; c < 2; ++c)
                if (m.params[f][ka][c] == m.params[f][kb][c]) keep[f][ka][c] = keep[f][kb][c] = 1;
        }
    std::mt19937 rng(seed);
    for (std::size_t f = 0; f < m.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 2; ++c) {
                const double d = uniformIn(rng, a);
                if (!keep[f][k][c]) m.params[f][k][c] += d;
            }
}

void perturbTriParameters(ParametrizedTriMesh& m, double a, unsigned seed, TriPerturbStats* stats) {
    if (!(a >= 0) || !std::isfinite(a)) throw std::invalid_argument("perturbation amplitude must be finite and >= 0");
    const TriAdjacency adj = buildTriAdjacency(m);
    TriParams params(m.params.begin(), m.params.end());
    const TriTransitions tr = computeTriTransitions(m, adj, params, nullptr, 1);
    const std::vector<int> holonomy = vertexHolonomy(m, adj, tr);
    TriPerturbStats st;
    std::mt19937 rng(seed);
    std::vector<int> star;
    std::vector<PlanarTransform> toChart;
    auto cornerOf = [&](int f, int v) {
        const auto& t = m.triangles[static_cast<std::size_t>(f)];
        return t[0] == v ? 0 : t[1] == v ? 1 : 2;
    };
    for (std::size_t vi = 0; vi < m.points.size(); ++vi) {
        const double dx = uniformIn(rng, a), dy = uniformIn(rng, a);
        const int v = static_cast<int>(vi);
        if (adj.vertex_offset[vi] == adj.vertex_offset[vi + 1]) continue;
        ++st.vertices;
        star.assign(1, adj.vertex_triangles[static_cast<std::size_t>(adj.vertex_offset[vi])]);
        toChart.assign(1, PlanarTransform());
        bool free[2] = {true, true}, boundary = false;
        for (std::size_t q = 0; q < star.size(); ++q) {
            const int f = star[q];
            const int k = cornerOf(f, v);
            for (int j = 0; j < 3; ++j) {
                if (j == k) continue;
                const std::size_t h = 3 * static_cast<std::size_t>(f) + static_cast<std::size_t>(j);
                const int o = adj.opposite[h];
                if (o < 0) {
                    // Boundary edge at v: an axis in which both ends agree on an integer stays fixed.
                    boundary = true;
                    const Vec2d& pa = params[static_cast<std::size_t>(f)][(j + 1) % 3];
                    const Vec2d& pb = params[static_cast<std::size_t>(f)][(j + 2) % 3];
                    for (int c = 0; c < 2; ++c)
                        if (pa[c] == pb[c] && pa[c] == std::round(pa[c])) {
                            // Axis c of this chart is axis R^-1(c) of the reference chart.
                            const AxisDir ref = toChart[q].inverse().applyDir(makeDir(c, 1));
                            free[dirAxis(ref)] = false;
                        }
                    continue;
                }
                const int g = o / 3;
                if (std::find(star.begin(), star.end(), g) != star.end()) continue;
                star.push_back(g);
                toChart.push_back(tr.at(h) * toChart[q]);
            }
        }
        if (boundary) ++st.boundary_vertices;
        if (!boundary && holonomy[vi] > 0) free[0] = free[1] = false;  // cone
        const Vec2d d(free[0] ? dx : 0.0, free[1] ? dy : 0.0);
        if (!free[0] && !free[1]) ++st.fixed_vertices;
        if (d[0] != 0 || d[1] != 0) ++st.moved_vertices;
        for (std::size_t q = 0; q < star.size(); ++q) {
            const Vec2d r = toChart[q].rotate(d);
            Vec2d& p = m.params[static_cast<std::size_t>(star[q])][cornerOf(star[q], v)];
            p = Vec2d(p[0] + r[0], p[1] + r[1]);
        }
    }
    if (stats) *stats = st;
}

double totalParametricArea(const ParametrizedTriMesh& m) {
    double s = 0;
    for (const auto& p : m.params)
        s += 0.5 * ((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]));
    return s;
}

} // namespace HexEx
