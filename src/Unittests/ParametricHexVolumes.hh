#pragma once
/// @file ParametricHexVolumes.hh
/// Test support: the 3D volume of the part of a tet mesh that an integer-grid map sends into
/// each unit cube, computed from the map alone (no darts, no tracing), so that the
/// extraction's hexes and face patches can be measured against it.
///
/// Every tet's parametric image is clipped against each unit cube of its own chart it
/// overlaps; the clipped parametric volume is pulled back with the tet's affine map
/// (vol3D = vol_param * |vol3D(tet) / vol_param(tet)|). Pieces (tet, cube) are joined across
/// a tet face when that face meets the cube in positive area and the neighbour's piece (the
/// cube carried over by the transition, computed here from the shared corners' parameters)
/// has positive volume: in a valid map each connected group is the preimage of one open
/// unit cube, i.e. one hex. A group names its hex by the hex-mesh vertices found at the cube
/// corners that lie in its tets (valid maps only: there the vertex positions are distinct).

#include <HexEx/HexEx.hh>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <vector>

namespace HexExTest {

/// A preimage of one unit cube: its 3D volume and the hex-mesh vertices at its corners.
struct CubePreimage {
    double volume = 0;          ///< 3D volume of the tets' parts mapped into the cube
    std::set<int> corners;      ///< hex-mesh vertices found at the cube's corners
    int missing_corners = 0;    ///< cube corners inside a tet with no hex vertex at their position
    int pieces = 0;             ///< (tet, cube) pieces in the group
};

namespace pvdetail {

using Tet = std::array<HexEx::Vec3d, 4>;

inline double tetVolume(const Tet& t) {
    return std::abs(((t[1] - t[0]) % (t[2] - t[0])) | (t[3] - t[0])) / 6;
}

/// Splits the prism with triangles (a0, a1, a2) and (b0, b1, b2) (edges ai-bi) into 3 tets.
inline void pushPrism(std::vector<Tet>& out, const HexEx::Vec3d& a0, const HexEx::Vec3d& a1, const HexEx::Vec3d& a2,
                      const HexEx::Vec3d& b0, const HexEx::Vec3d& b1, const HexEx::Vec3d& b2) {
    out.push_back({a0, a1, a2, b0});
    out.push_back({a1, a2, b0, b1});
    out.push_back({a2, b0, b1, b2});
}

/// Keeps the parts of @p tets with sign * (x[axis] - bound) <= 0, as tets again.
inline std::vector<Tet> clipTets(const std::vector<Tet>& tets, int axis, double bound, double sign) {
    std::vector<Tet> out;
    for (const Tet& T : tets) {
        double h[4];
        int in[4], ou[4], ni = 0, no = 0;
        for (int j = 0; j < 4; ++j) {
            h[j] = sign * (T[static_cast<std::size_t>(j)][axis] - bound);
            if (h[j] <= 0) in[ni++] = j;
            else ou[no++] = j;
        }
        if (no == 0) {
            out.push_back(T);
            continue;
        }
        if (ni == 0) continue;
        auto cut = [&](int i, int o) {
            const double s = h[i] / (h[i] - h[o]);
            HexEx::Vec3d x = T[static_cast<std::size_t>(i)] + (T[static_cast<std::size_t>(o)] - T[static_cast<std::size_t>(i)]) * s;
            x[axis] = bound;
            return x;
        };
        auto P = [&](int j) { return T[static_cast<std::size_t>(j)]; };
        if (ni == 1) {
            out.push_back({P(in[0]), cut(in[0], ou[0]), cut(in[0], ou[1]), cut(in[0], ou[2])});
        } else if (ni == 3) {
            // The tet without the corner at ou[0]: a prism between the kept face and the cut.
            pushPrism(out, P(in[0]), P(in[1]), P(in[2]), cut(in[0], ou[0]), cut(in[1], ou[0]), cut(in[2], ou[0]));
        } else {
            // Two corners kept: a prism between the triangles at in[0] and at in[1].
            pushPrism(out, P(in[0]), cut(in[0], ou[0]), cut(in[0], ou[1]), P(in[1]), cut(in[1], ou[0]), cut(in[1], ou[1]));
        }
    }
    return out;
}

/// Parametric volume of tet @p T (parameters) inside the cube [lo, lo + 1].
inline double volumeInCube(const Tet& T, const HexEx::Vec3i& lo) {
    std::vector<Tet> parts{T};
    for (int a = 0; a < 3 && !parts.empty(); ++a) {
        parts = clipTets(parts, a, lo[a], -1);
        parts = clipTets(parts, a, lo[a] + 1, 1);
    }
    double v = 0;
    for (const Tet& t : parts) v += tetVolume(t);
    return v;
}

/// Area of the triangle @p tri (parameters) inside the closed cube [lo, lo + 1].
inline double areaInCube(const std::array<HexEx::Vec3d, 3>& tri, const HexEx::Vec3i& lo) {
    std::vector<HexEx::Vec3d> poly(tri.begin(), tri.end());
    for (int a = 0; a < 3; ++a)
        for (int side = 0; side < 2; ++side) {
            const double bound = lo[a] + side, sign = side == 0 ? -1 : 1;
            std::vector<HexEx::Vec3d> next;
            for (std::size_t k = 0; k < poly.size(); ++k) {
                const HexEx::Vec3d &c = poly[k], &n = poly[(k + 1) % poly.size()];
                const double hc = sign * (c[a] - bound), hn = sign * (n[a] - bound);
                if (hc <= 0) next.push_back(c);
                if ((hc <= 0) != (hn <= 0)) {
                    HexEx::Vec3d x = c + (n - c) * (hc / (hc - hn));
                    x[a] = bound;
                    next.push_back(x);
                }
            }
            poly.swap(next);
        }
    HexEx::Vec3d twice(0, 0, 0);
    for (std::size_t k = 1; k + 1 < poly.size(); ++k) twice += (poly[k] - poly[0]) % (poly[k + 1] - poly[0]);
    return 0.5 * twice.norm();
}

/// Integer affine map u -> R u + t between two charts (R a rotation of the grid).
struct ChartMap {
    int R[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    HexEx::Vec3d t{0, 0, 0};
    HexEx::Vec3d apply(const HexEx::Vec3d& u) const {
        HexEx::Vec3d r = t;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) r[i] += R[i][j] * u[j];
        return r;
    }
};

/// The grid rotation and translation taking @p p (3 corners in one chart) to @p q (the same
/// corners in the neighbour's chart): the rotation that best maps the two edge vectors.
inline ChartMap chartMap(const std::array<HexEx::Vec3d, 3>& p, const std::array<HexEx::Vec3d, 3>& q) {
    ChartMap best;
    double bestErr = 1e300;
    std::array<int, 3> perm{0, 1, 2};
    do {
        for (int s = 0; s < 8; ++s) {
            ChartMap m;
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) m.R[i][j] = perm[static_cast<std::size_t>(i)] == j ? ((s >> i) & 1 ? -1 : 1) : 0;
            const int det = m.R[0][0] * (m.R[1][1] * m.R[2][2] - m.R[1][2] * m.R[2][1]) -
                            m.R[0][1] * (m.R[1][0] * m.R[2][2] - m.R[1][2] * m.R[2][0]) +
                            m.R[0][2] * (m.R[1][0] * m.R[2][1] - m.R[1][1] * m.R[2][0]);
            if (det != 1) continue;
            double err = 0;
            for (int k = 1; k < 3; ++k) err += (m.apply(p[static_cast<std::size_t>(k)] - p[0]) - (q[static_cast<std::size_t>(k)] - q[0])).norm();
            if (err < bestErr) {
                bestErr = err;
                best = m;
            }
        }
    } while (std::next_permutation(perm.begin(), perm.end()));
    const HexEx::Vec3d r = best.apply(p[0]);
    for (int i = 0; i < 3; ++i) best.t[i] = std::round(q[0][i] - r[i]);
    return best;
}

inline int findRoot(std::vector<int>& parent, int x) {
    while (parent[static_cast<std::size_t>(x)] != x) x = parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
    return x;
}

} // namespace pvdetail

/// The preimages of all unit cubes that the map of @p pm covers with positive volume (valid,
/// non-degenerate maps), each named by the vertices of @p hm at its corners; a corner
/// position counts as a hex vertex within @p tol (3D distance).
inline std::vector<CubePreimage> cubePreimages(HexEx::ParametrizedTetMesh pm, const HexEx::HexMesh& hm, double tol) {
    using namespace HexEx;
    using pvdetail::Tet;
    pm.mesh.build_adjacency();
    const std::size_t nt = pm.mesh.n_cells();
    // Pieces (tet, lowest cube corner) with positive volume, by key.
    std::map<std::pair<int, std::array<int, 3>>, int> pieceId;
    std::vector<std::pair<int, Vec3i>> pieces;
    std::vector<double> pieceVolume;
    constexpr double kMinParamVolume = 1e-14;  // slivers below this are numerical noise
    for (std::size_t t = 0; t < nt; ++t) {
        const Tet P{pm.params[t][0], pm.params[t][1], pm.params[t][2], pm.params[t][3]};
        const auto& cv = pm.mesh.cell_vertices(CellHandle(static_cast<int>(t)));
        const Tet X{pm.mesh.position(cv[0]), pm.mesh.position(cv[1]), pm.mesh.position(cv[2]), pm.mesh.position(cv[3])};
        const double scale = pvdetail::tetVolume(X) / pvdetail::tetVolume(P);  // |det J^-1|
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            double mn = 1e300, mx = -1e300;
            for (const Vec3d& p : P) {
                mn = std::min(mn, p[a]);
                mx = std::max(mx, p[a]);
            }
            lo[a] = static_cast<int>(std::floor(mn));
            hi[a] = static_cast<int>(std::ceil(mx));
        }
        for (int i = lo[0]; i < hi[0]; ++i)
            for (int j = lo[1]; j < hi[1]; ++j)
                for (int k = lo[2]; k < hi[2]; ++k) {
                    const double v = pvdetail::volumeInCube(P, Vec3i(i, j, k));
                    if (v <= kMinParamVolume) continue;
                    pieceId[{static_cast<int>(t), {i, j, k}}] = static_cast<int>(pieces.size());
                    pieces.emplace_back(static_cast<int>(t), Vec3i(i, j, k));
                    pieceVolume.push_back(v * scale);
                }
    }
    // Join pieces across tet faces that meet the cube in positive area.
    std::vector<int> parent(pieces.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (std::size_t q = 0; q < pieces.size(); ++q) {
        const int t = pieces[q].first;
        const Vec3i lo = pieces[q].second;
        const auto& cv = pm.mesh.cell_vertices(CellHandle(t));
        for (int f = 0; f < 4; ++f) {
            const HalfFaceHandle opp = pm.mesh.opposite_halfface(TetMesh::halfface(CellHandle(t), f));
            if (!opp.is_valid()) continue;
            const int u = TetMesh::cell(opp).idx();
            std::array<Vec3d, 3> p, r;
            for (int k = 0; k < 3; ++k) {
                const int c = TetMesh::kFaceCorners[f][k];
                p[static_cast<std::size_t>(k)] = pm.params[static_cast<std::size_t>(t)][static_cast<std::size_t>(c)];
                const auto& cu = pm.mesh.cell_vertices(CellHandle(u));
                const int cu_k = static_cast<int>(std::find(cu.begin(), cu.end(), cv[static_cast<std::size_t>(c)]) - cu.begin());
                r[static_cast<std::size_t>(k)] = pm.params[static_cast<std::size_t>(u)][static_cast<std::size_t>(cu_k)];
            }
            if (pvdetail::areaInCube(p, lo) <= kMinParamVolume) continue;
            const pvdetail::ChartMap g = pvdetail::chartMap(p, r);
            std::array<int, 3> ulo{1 << 30, 1 << 30, 1 << 30};
            for (int c = 0; c < 8; ++c) {
                const Vec3d x = g.apply(Vec3d(lo[0] + (c & 1), lo[1] + ((c >> 1) & 1), lo[2] + ((c >> 2) & 1)));
                for (int a = 0; a < 3; ++a) ulo[static_cast<std::size_t>(a)] = std::min(ulo[static_cast<std::size_t>(a)], static_cast<int>(std::lround(x[a])));
            }
            const auto it = pieceId.find({u, ulo});
            if (it == pieceId.end()) continue;  // the neighbour's side of the face is outside the cube
            parent[static_cast<std::size_t>(pvdetail::findRoot(parent, static_cast<int>(q)))] = pvdetail::findRoot(parent, it->second);
        }
    }
    // Groups: volume and the hex vertices at the cube corners that lie in their tets.
    std::map<int, int> groupOf;
    std::vector<CubePreimage> out;
    for (std::size_t q = 0; q < pieces.size(); ++q) {
        const int root = pvdetail::findRoot(parent, static_cast<int>(q));
        auto [it, inserted] = groupOf.emplace(root, static_cast<int>(out.size()));
        if (inserted) out.emplace_back();
        CubePreimage& G = out[static_cast<std::size_t>(it->second)];
        G.volume += pieceVolume[q];
        ++G.pieces;
        const int t = pieces[q].first;
        const auto& P = pm.params[static_cast<std::size_t>(t)];
        const auto& cv = pm.mesh.cell_vertices(CellHandle(t));
        const double V = ((P[1] - P[0]) % (P[2] - P[0])) | (P[3] - P[0]);
        for (int c = 0; c < 8; ++c) {
            const Vec3d z(pieces[q].second[0] + (c & 1), pieces[q].second[1] + ((c >> 1) & 1), pieces[q].second[2] + ((c >> 2) & 1));
            double lam[4];
            bool inside = true;
            for (int j = 0; j < 4; ++j) {
                std::array<Vec3d, 4> Q = P;
                Q[static_cast<std::size_t>(j)] = z;
                lam[j] = (((Q[1] - Q[0]) % (Q[2] - Q[0])) | (Q[3] - Q[0])) / V;
                inside = inside && lam[j] >= -1e-12;
            }
            if (!inside) continue;
            Vec3d x(0, 0, 0);
            for (int j = 0; j < 4; ++j) x += pm.mesh.position(cv[static_cast<std::size_t>(j)]) * lam[j];
            int found = -1;
            for (std::size_t v = 0; v < hm.vertices.size() && found < 0; ++v)
                if ((hm.vertices[v] - x).norm() <= tol) found = static_cast<int>(v);
            if (found < 0) ++G.missing_corners;
            else G.corners.insert(found);
        }
    }
    return out;
}

} // namespace HexExTest
