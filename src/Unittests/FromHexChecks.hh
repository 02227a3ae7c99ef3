#pragma once
// Checks for maps built by HexEx::mapFromHexMesh(): is the extracted mesh the expected one
// (isomorphic, vertices in place, every vertex on a preimage of its grid point, no new
// inverted hexes)?

#include <HexEx/Generators/MapFromHexMesh.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/Mesh/HexMesh.hh>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace HexExTest {

/// Outcome of checkFromHex().
struct FromHexCheck {
    bool valid_all_hex = false;      ///< the extraction report says valid all-hex
    bool isomorphic = false;         ///< same hexes under a vertex bijection
    std::string why;                 ///< first reason the mesh is not the expected one
    std::size_t vertices = 0;        ///< output vertices
    std::size_t off_position = 0;    ///< vertices farther than 1e-9 of the diagonal from their expected position
    std::size_t off_boundary = 0;    ///< of the off-position vertices, those on the boundary of the expected mesh
    std::size_t not_on_preimage = 0; ///< off-position vertices not at a preimage of their grid point
    std::size_t new_inverted = 0;    ///< inverted output hexes whose expected hex is not inverted
    std::size_t checked = 0;         ///< vertices whose position is checked (scale > 1: the source vertices only)
    bool inversions_apply = true;    ///< false for scale > 1 with perturbation (the map itself moves refined vertices)
    /// Everything the issue asks for.
    bool ok() const {
        return valid_all_hex && isomorphic && not_on_preimage == 0 && off_position * 100 <= checked &&
               (new_inverted == 0 || !inversions_apply);
    }
    /// One line for failure messages.
    std::string summary() const {
        std::ostringstream s;
        s << "valid=" << valid_all_hex << " iso=" << isomorphic << " (" << why << ") vertices=" << vertices
          << " off=" << off_position << " (boundary " << off_boundary << ")" << " not_on_preimage=" << not_on_preimage << " new_inverted=" << new_inverted;
        return s.str();
    }
};

namespace detail {

/// Smallest corner Jacobian determinant of a VTK hex (negative or zero: inverted).
inline double minCornerJacobian(const HexEx::HexMesh& m, const std::array<int, 8>& h) {
    static const int nb[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7}, {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
    double best = 1e300;
    for (int i = 0; i < 8; ++i) {
        const HexEx::Vec3d p = m.vertices[h[i]];
        const HexEx::Vec3d a = m.vertices[h[nb[i][0]]] - p, b = m.vertices[h[nb[i][1]]] - p,
                           c = m.vertices[h[nb[i][2]]] - p;
        best = std::min(best, (a % b) | c);
    }
    return best;
}

/// The 48 symmetries of the unit cube as permutations of the VTK corners.
inline std::vector<std::array<int, 8>> cubeSymmetries() {
    std::vector<std::array<int, 8>> out;
    const int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
    auto indexOf = [](const HexEx::Vec3i& l) {
        for (int i = 0; i < 8; ++i)
            if (HexEx::hexCornerLattice(i) == l) return i;
        return -1;
    };
    for (const auto& p : perms)
        for (int s = 0; s < 8; ++s) {
            std::array<int, 8> q{};
            for (int i = 0; i < 8; ++i) {
                const HexEx::Vec3i l = HexEx::hexCornerLattice(i);
                HexEx::Vec3i r;
                for (int k = 0; k < 3; ++k) r[k] = ((s >> k) & 1) ? 1 - l[p[k]] : l[p[k]];
                q[i] = indexOf(r);
            }
            out.push_back(q);
        }
    return out;
}

/// Barycentric coordinates of @p x in the tet @p c of @p m (unnormalized sign-safe).
inline bool baryIn(const HexEx::TetMesh& m, int c, const HexEx::Vec3d& x, double tol, double lam[4]) {
    const auto& cv = m.cell_vertices(HexEx::CellHandle(c));
    HexEx::Vec3d p[4];
    for (int k = 0; k < 4; ++k) p[k] = m.position(cv[k]);
    const double V = ((p[1] - p[0]) % (p[2] - p[0])) | (p[3] - p[0]);
    if (V == 0) return false;
    for (int j = 0; j < 4; ++j) {
        HexEx::Vec3d q[4] = {p[0], p[1], p[2], p[3]};
        q[j] = x;
        lam[j] = (((q[1] - q[0]) % (q[2] - q[0])) | (q[3] - q[0])) / V;
        if (lam[j] < -tol) return false;
    }
    return true;
}

/// Parameter of @p x in tet @p c (barycentric interpolation of the corner parameters).
inline HexEx::Vec3d paramAt(const HexEx::ParametrizedTetMesh& pm, int c, const double lam[4]) {
    HexEx::Vec3d u(0, 0, 0);
    for (int k = 0; k < 4; ++k) u += pm.params[static_cast<std::size_t>(c)][k] * lam[k];
    return u;
}

} // namespace detail

/// Compares the extraction @p out (with report @p rep) of the perturbed map @p gen against
/// the expected mesh @p expected. @p source is the hex mesh the map was built from and
/// @p exact the same map without perturbation (same seed and scale): they give each
/// expected vertex its grid point and the charts to carry it into neighbouring hexes.
inline FromHexCheck checkFromHex(const HexEx::HexMesh& source, const HexEx::MapFromHexResult& exact,
                                 const HexEx::MapFromHexResult& gen, const HexEx::HexMesh& expected,
                                 const HexEx::HexMesh& out, const HexEx::ExtractionReport& rep) {
    using HexEx::Vec3d;
    FromHexCheck r;
    r.valid_all_hex = rep.valid_all_hex;
    r.vertices = out.vertices.size();
    const std::size_t nv = expected.vertices.size();
    Vec3d lo = expected.vertices.empty() ? Vec3d(0, 0, 0) : expected.vertices[0], hi = lo;
    for (const auto& p : expected.vertices) {
        lo.minimize(p);
        hi.maximize(p);
    }
    const double diag = (hi - lo).norm();
    const double tol = 1e-9 * diag;

    // 1. Vertices at their expected position (sorted sweep over x).
    std::vector<int> match(out.vertices.size(), -1);
    {
        std::vector<int> order(nv);
        for (std::size_t i = 0; i < nv; ++i) order[i] = static_cast<int>(i);
        std::sort(order.begin(), order.end(), [&](int a, int b) { return expected.vertices[a][0] < expected.vertices[b][0]; });
        for (std::size_t v = 0; v < out.vertices.size(); ++v) {
            const Vec3d x = out.vertices[v];
            auto it = std::lower_bound(order.begin(), order.end(), x[0] - tol,
                                       [&](int a, double val) { return expected.vertices[a][0] < val; });
            for (; it != order.end() && expected.vertices[*it][0] <= x[0] + tol; ++it)
                if ((expected.vertices[*it] - x).norm() <= tol) {
                    match[v] = *it;
                    break;
                }
        }
    }
    // 2. The remaining vertices through the hexes: an output hex whose matched corners fit
    //    exactly one expected hex under one cube symmetry gets its other corners from it.
    std::vector<std::vector<int>> hexesOf(nv);
    for (std::size_t h = 0; h < expected.hexes.size(); ++h)
        for (int v : expected.hexes[h]) hexesOf[v].push_back(static_cast<int>(h));
    const auto syms = detail::cubeSymmetries();
    std::vector<int> hexMatch(out.hexes.size(), -1);
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t h = 0; h < out.hexes.size(); ++h) {
            if (hexMatch[h] >= 0) continue;
            const auto& oh = out.hexes[h];
            int anchor = -1;
            int matched = 0;
            for (int i = 0; i < 8; ++i)
                if (match[oh[i]] >= 0) {
                    ++matched;
                    if (anchor < 0) anchor = i;
                }
            if (matched < 4) continue;
            int found = -1;
            std::array<int, 8> img{};
            for (int eh : hexesOf[match[oh[anchor]]]) {
                for (const auto& s : syms) {
                    bool fits = true;
                    for (int i = 0; i < 8 && fits; ++i)
                        fits = match[oh[i]] < 0 || match[oh[i]] == expected.hexes[eh][s[i]];
                    if (!fits) continue;
                    if (found >= 0 && found != eh) {
                        found = -2;
                        break;
                    }
                    found = eh;
                    for (int i = 0; i < 8; ++i) img[i] = expected.hexes[eh][s[i]];
                }
                if (found == -2) break;
            }
            if (found < 0) continue;
            hexMatch[h] = found;
            for (int i = 0; i < 8; ++i)
                if (match[oh[i]] < 0) {
                    match[oh[i]] = img[i];
                    changed = true;
                }
        }
    }
    // 3. Bijection and equal hex sets.
    r.isomorphic = true;
    if (out.vertices.size() != nv || out.hexes.size() != expected.hexes.size() || !out.polyhedra.empty()) {
        r.isomorphic = false;
        r.why = "counts " + std::to_string(out.vertices.size()) + "/" + std::to_string(nv) + " vertices, " +
                std::to_string(out.hexes.size()) + "/" + std::to_string(expected.hexes.size()) + " hexes, " +
                std::to_string(out.polyhedra.size()) + " polyhedra";
    }
    std::vector<int> hit(nv, 0);
    for (std::size_t v = 0; v < out.vertices.size() && r.isomorphic; ++v) {
        if (match[v] < 0) {
            r.isomorphic = false;
            r.why = "vertex " + std::to_string(v) + " has no counterpart";
        } else if (hit[match[v]]++) {
            r.isomorphic = false;
            r.why = "two vertices map to expected vertex " + std::to_string(match[v]);
        }
    }
    if (r.isomorphic) {
        std::multiset<std::array<int, 8>> want, got;
        for (auto h : expected.hexes) {
            std::sort(h.begin(), h.end());
            want.insert(h);
        }
        for (const auto& oh : out.hexes) {
            std::array<int, 8> h{};
            for (int i = 0; i < 8; ++i) h[i] = match[oh[i]];
            std::sort(h.begin(), h.end());
            got.insert(h);
        }
        if (want != got) {
            r.isomorphic = false;
            r.why = "hexes differ";
        }
    }
    if (r.isomorphic) r.why = "ok";

    // 4. Inverted hexes where the expected hex is not inverted.
    if (r.isomorphic) {
        std::map<std::array<int, 8>, double> expectedJac;
        for (const auto& h : expected.hexes) {
            auto k = h;
            std::sort(k.begin(), k.end());
            expectedJac[k] = detail::minCornerJacobian(expected, h);
        }
        for (const auto& oh : out.hexes) {
            std::array<int, 8> k{};
            for (int i = 0; i < 8; ++i) k[i] = match[oh[i]];
            std::sort(k.begin(), k.end());
            if (detail::minCornerJacobian(out, oh) <= 0 && expectedJac[k] > 0) ++r.new_inverted;
        }
    }

    // 5. Off-position vertices: on a preimage of their grid point? The grid point comes from
    //    the unperturbed map (in the chart of the source hex around the expected position);
    //    it is carried into the charts of hexes up to three face steps away.
    const HexEx::TetMesh& tm = exact.map.mesh;
    const int nTets = static_cast<int>(tm.n_cells());
    const int K = static_cast<int>(std::lround(std::cbrt(static_cast<double>(expected.hexes.size()) /
                                                         std::max<std::size_t>(1, source.hexes.size()))));
    // Local lattice maps between face-adjacent source hexes.
    static const int kFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    std::map<std::array<int, 4>, std::vector<std::pair<int, int>>> faceHexes;
    for (std::size_t h = 0; h < source.hexes.size(); ++h)
        for (int j = 0; j < 6; ++j) {
            std::array<int, 4> k{};
            for (int q = 0; q < 4; ++q) k[q] = source.hexes[h][kFaces[j][q]];
            std::sort(k.begin(), k.end());
            faceHexes[k].emplace_back(static_cast<int>(h), j);
        }
    std::vector<std::vector<std::pair<int, HexEx::GridTransform>>> adj(source.hexes.size());  // chart A -> chart B
    for (const auto& [k, hs] : faceHexes) {
        if (hs.size() != 2) continue;
        for (int dir = 0; dir < 2; ++dir) {
            const int A = hs[dir].first, B = hs[1 - dir].first;
            const int* loop = kFaces[hs[dir].second];
            HexEx::Vec3i pa[3], pb[3];
            const int pick[3] = {0, 1, 3};
            for (int q = 0; q < 3; ++q) {
                const int v = source.hexes[A][loop[pick[q]]];
                int ib = 0;
                while (source.hexes[B][ib] != v) ++ib;
                pa[q] = exact.charts[A].apply(HexEx::hexCornerLattice(loop[pick[q]]) * K);
                pb[q] = exact.charts[B].apply(HexEx::hexCornerLattice(ib) * K);
            }
            for (int rr = 0; rr < HexEx::Rotation::kCount; ++rr) {
                const HexEx::Rotation rot(rr);
                if (rot.apply(pa[1] - pa[0]) == pb[1] - pb[0] && rot.apply(pa[2] - pa[0]) == pb[2] - pb[0]) {
                    adj[A].emplace_back(B, HexEx::GridTransform(rot, pb[0] - rot.apply(pa[0])));
                    break;
                }
            }
        }
    }
    std::vector<char> onBoundary(nv, 0);
    {
        std::map<std::array<int, 4>, int> quads;
        for (const auto& h : expected.hexes)
            for (const auto& f : kFaces) {
                std::array<int, 4> k{};
                for (int q = 0; q < 4; ++q) k[q] = h[f[q]];
                std::sort(k.begin(), k.end());
                ++quads[k];
            }
        for (const auto& [k, n] : quads)
            if (n == 1)
                for (int v : k) onBoundary[v] = 1;
    }
    // With scale K > 1 only the source vertices have a fixed expected position: the map
    // puts the refined grid points wherever the moved face and cell centres take them.
    std::vector<char> checkedPos(nv, K == 1 ? 1 : 0);
    if (K != 1) {
        std::vector<Vec3d> src = source.vertices;
        std::sort(src.begin(), src.end(), [](const Vec3d& a, const Vec3d& b) { return a[0] < b[0]; });
        for (std::size_t e = 0; e < nv; ++e) {
            const Vec3d x = expected.vertices[e];
            auto it = std::lower_bound(src.begin(), src.end(), x[0] - tol, [](const Vec3d& a, double val) { return a[0] < val; });
            for (; it != src.end() && (*it)[0] <= x[0] + tol; ++it)
                if ((*it - x).norm() <= tol) checkedPos[e] = 1;
        }
        r.inversions_apply = gen.map.params == exact.map.params;
    }
    for (std::size_t e = 0; e < nv; ++e) r.checked += checkedPos[e] ? 1 : 0;
    for (std::size_t v = 0; v < out.vertices.size(); ++v) {
        if (match[v] < 0) continue;
        const Vec3d want = expected.vertices[match[v]];
        if ((out.vertices[v] - want).norm() <= tol) continue;
        if (checkedPos[match[v]]) ++r.off_position;
        if (checkedPos[match[v]] && onBoundary[match[v]]) ++r.off_boundary;
        // Grid point of the expected vertex.
        int hs = -1;
        HexEx::Vec3i g;
        double lam[4];
        for (int c = 0; c < nTets && hs < 0; ++c)
            if (detail::baryIn(tm, c, want, 1e-9, lam)) {
                const Vec3d u = detail::paramAt(exact.map, c, lam);
                g = HexEx::Vec3i(static_cast<int>(std::lround(u[0])), static_cast<int>(std::lround(u[1])),
                                 static_cast<int>(std::lround(u[2])));
                hs = c / 24;
            }
        bool onPreimage = false;
        if (hs >= 0) {
            // The grid point in every chart up to three steps away.
            std::map<int, std::vector<HexEx::Vec3i>> inChart;
            std::vector<std::pair<int, HexEx::Vec3i>> frontier = {{hs, g}};
            inChart[hs].push_back(g);
            for (int step = 0; step < 3; ++step) {
                std::vector<std::pair<int, HexEx::Vec3i>> next;
                for (const auto& [h, z] : frontier)
                    for (const auto& [b, t] : adj[static_cast<std::size_t>(h)]) {
                        const HexEx::Vec3i zb = t.apply(z);
                        auto& list = inChart[b];
                        if (std::find(list.begin(), list.end(), zb) != list.end()) continue;
                        list.push_back(zb);
                        next.emplace_back(b, zb);
                    }
                frontier.swap(next);
            }
            const Vec3d x = out.vertices[v];
            for (int c = 0; c < nTets && !onPreimage; ++c) {
                if (!detail::baryIn(gen.map.mesh, c, x, 1e-9, lam)) continue;
                const auto it = inChart.find(c / 24);
                if (it == inChart.end()) continue;
                const Vec3d u = detail::paramAt(gen.map, c, lam);
                for (const auto& z : it->second)
                    if ((u - HexEx::toVec3d(z)).norm() <= 1e-6) onPreimage = true;
            }
        }
        if (!onPreimage) ++r.not_on_preimage;
    }
    return r;
}

} // namespace HexExTest
