/// @file VertexPreimageChoice.cc
/// Choice among several preimages of a vertex's grid point (see VertexPreimageChoice.hh).

#include "VertexPreimageChoice.hh"

#include "../Core/UnionFind.hh"

#include <algorithm>
#include <cmath>

namespace HexEx {

namespace {
/// Clusters with at most this many candidate combinations are searched exhaustively.
constexpr double kMaxCombinations = 65536;

/// In @p q[1..], sorted ascending and holding @p old, replaces one entry equal to @p old by
/// @p now and keeps the list sorted; adjusts @p q[0], minus the number of entries <= 0.
/// The list is then the sorted list of the new values (up to the order of -0.0 and 0.0,
/// which compare equal; no NaN may be involved).
void replaceSorted(std::vector<double>& q, double old, double now) {
    if (old <= 0) q[0] += 1.0;
    if (now <= 0) q[0] -= 1.0;
    const auto b = q.begin() + 1, e = q.end();
    const auto it = std::lower_bound(b, e, old);
    if (now > old) {
        const auto j = std::upper_bound(it + 1, e, now);
        std::move(it + 1, j, it);
        *(j - 1) = now;
    } else if (now < old) {
        const auto j = std::upper_bound(b, it, now);
        std::move_backward(j, it, it + 1);
        *j = now;
    } else {
        *it = now;
    }
}
} // namespace

double minScaledJacobian(const HexMesh& mesh, const std::array<int, 8>& h) {
    // The three neighbours of each VTK corner, in right-handed order.
    static const int nb[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7}, {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
    double best = 1.0;
    for (int i = 0; i < 8; ++i) {
        const Vec3d p = mesh.vertices[static_cast<std::size_t>(h[static_cast<std::size_t>(i)])];
        const Vec3d a = mesh.vertices[static_cast<std::size_t>(h[static_cast<std::size_t>(nb[i][0])])] - p;
        const Vec3d b = mesh.vertices[static_cast<std::size_t>(h[static_cast<std::size_t>(nb[i][1])])] - p;
        const Vec3d c = mesh.vertices[static_cast<std::size_t>(h[static_cast<std::size_t>(nb[i][2])])] - p;
        const double len = a.norm() * b.norm() * c.norm();
        if (!(len > 0)) return -2.0;
        best = std::min(best, ((a % b) | c) / len);
    }
    return best;
}

long chooseVertexPreimages(HexMesh& mesh, const VertexCandidates& candidates) {
    const std::size_t nc = candidates.vertex.size();
    if (nc == 0) return 0;
    // Incident hexes of the listed vertices only.
    std::vector<int> slot(mesh.vertices.size(), -1);
    for (std::size_t k = 0; k < nc; ++k) slot[static_cast<std::size_t>(candidates.vertex[k])] = static_cast<int>(k);
    std::vector<int> off(nc + 1, 0);
    for (const auto& h : mesh.hexes)
        for (int v : h)
            if (slot[static_cast<std::size_t>(v)] >= 0) ++off[static_cast<std::size_t>(slot[static_cast<std::size_t>(v)]) + 1];
    for (std::size_t k = 0; k < nc; ++k) off[k + 1] += off[k];
    std::vector<int> inc(static_cast<std::size_t>(off.back()));
    // Clusters: listed vertices that share a hex are chosen together.
    UnionFind uf(nc);
    {
        std::vector<int> fill(off.begin(), off.end() - 1);
        for (std::size_t c = 0; c < mesh.hexes.size(); ++c) {
            int first = -1;
            for (int v : mesh.hexes[c]) {
                const int s = slot[static_cast<std::size_t>(v)];
                if (s < 0) continue;
                inc[static_cast<std::size_t>(fill[static_cast<std::size_t>(s)]++)] = static_cast<int>(c);
                if (first < 0) first = s;
                else uf.unite(first, s);
            }
        }
    }
    std::vector<std::vector<int>> clusters;  // listed indices, ascending; clusters by smallest member
    {
        std::vector<int> clusterOf(nc, -1);
        for (std::size_t k = 0; k < nc; ++k) {
            const auto r = static_cast<std::size_t>(uf.find(static_cast<int>(k)));
            if (clusterOf[r] < 0) {
                clusterOf[r] = static_cast<int>(clusters.size());
                clusters.emplace_back();
            }
            clusters[static_cast<std::size_t>(clusterOf[r])].push_back(static_cast<int>(k));
        }
    }
    auto setPos = [&](int k, int c) {
        mesh.vertices[static_cast<std::size_t>(candidates.vertex[static_cast<std::size_t>(k)])] =
            candidates.position[static_cast<std::size_t>(candidates.offset[static_cast<std::size_t>(k)] + c)];
    };
    std::vector<int> hexes;
    for (const auto& cl : clusters) {
        hexes.clear();
        for (int k : cl)
            for (int j = off[static_cast<std::size_t>(k)]; j < off[static_cast<std::size_t>(k) + 1]; ++j)
                hexes.push_back(inc[static_cast<std::size_t>(j)]);
        std::sort(hexes.begin(), hexes.end());
        hexes.erase(std::unique(hexes.begin(), hexes.end()), hexes.end());
        // Quality of a set of hexes: their minScaledJacobian() values sorted ascending,
        // compared lexicographically (the worst hex first, then the next worst, ...).
        // The first entry is minus the number of inverted hexes (value <= 0), so fewer
        // inverted hexes always win.
        auto quality = [&](const int* hb, const int* he) {
            std::vector<double> q(1, 0.0);
            for (const int* h = hb; h != he; ++h) {
                q.push_back(minScaledJacobian(mesh, mesh.hexes[static_cast<std::size_t>(*h)]));
                if (q.back() <= 0) q[0] -= 1.0;
            }
            std::sort(q.begin() + 1, q.end());
            return q;
        };
        // Candidates per member: the preferred ones first; all of them if those invert a hex.
        for (int pass = 0; pass < 2; ++pass) {
            std::vector<int> count(cl.size());
            double combos = 1;
            for (std::size_t m = 0; m < cl.size(); ++m) {
                const auto k = static_cast<std::size_t>(cl[m]);
                count[m] = pass == 0 ? candidates.preferred[k] : candidates.offset[k + 1] - candidates.offset[k];
                combos *= count[m];
            }
            double worst = -10;  // smallest minScaledJacobian() of the chosen combination
            if (combos <= kMaxCombinations) {
                // Every combination, in lexicographic order (the first best one wins). The
                // per-hex values are kept and only the hexes of members that changed are
                // evaluated again.
                std::vector<int> pick(cl.size(), 0), best(cl.size(), 0);
                std::vector<std::vector<int>> memberHexes(cl.size());  // positions in hexes
                for (std::size_t m = 0; m < cl.size(); ++m) {
                    const auto k = static_cast<std::size_t>(cl[m]);
                    for (int j = off[k]; j < off[k + 1]; ++j)
                        memberHexes[m].push_back(static_cast<int>(
                            std::lower_bound(hexes.begin(), hexes.end(), inc[static_cast<std::size_t>(j)]) - hexes.begin()));
                    setPos(cl[m], 0);
                }
                std::vector<double> value(hexes.size());
                for (std::size_t h = 0; h < hexes.size(); ++h) value[h] = minScaledJacobian(mesh, mesh.hexes[static_cast<std::size_t>(hexes[h])]);
                // The sorted list of a combination is kept up to date from the previous
                // one: the values of the hexes of the members that changed replace their
                // old values in it (the same list as sorting all values again, up to the
                // order of -0.0 and 0.0, which no comparison tells apart). With a NaN among
                // the values, each combination's list is sorted anew, as before.
                std::vector<double> bestQ, q(hexes.size() + 1);
                bool noNaN = true;
                auto sortAll = [&]() {
                    q[0] = 0;
                    for (std::size_t h = 0; h < hexes.size(); ++h) {
                        q[h + 1] = value[h];
                        if (value[h] <= 0) q[0] -= 1.0;
                    }
                    std::sort(q.begin() + 1, q.end());
                };
                for (double v : value) noNaN = noNaN && !std::isnan(v);
                sortAll();
                // Members with one candidate wrap back to it at every step: their positions
                // and hex values do not change, so the counter skips them.
                std::vector<std::size_t> varying;
                for (std::size_t m = 0; m < cl.size(); ++m)
                    if (count[m] > 1) varying.push_back(m);
                for (bool more = true; more;) {
                    if (!noNaN) sortAll();
                    if (bestQ.empty() || q > bestQ) {
                        bestQ = q;
                        best = pick;
                    }
                    more = false;
                    for (std::size_t v = varying.size(); v-- > 0;) {
                        const std::size_t m = varying[v];
                        const bool wrapped = ++pick[m] >= count[m];
                        if (wrapped) pick[m] = 0;
                        setPos(cl[m], pick[m]);
                        for (int h : memberHexes[m]) {
                            double& val = value[static_cast<std::size_t>(h)];
                            const double now = minScaledJacobian(mesh, mesh.hexes[static_cast<std::size_t>(hexes[static_cast<std::size_t>(h)])]);
                            if (std::isnan(now)) noNaN = false;
                            if (noNaN) replaceSorted(q, val, now);
                            val = now;
                        }
                        if (!wrapped) {
                            more = true;
                            break;
                        }
                    }
                }
                for (std::size_t m = 0; m < cl.size(); ++m) setPos(cl[m], best[m]);
                worst = bestQ.size() < 2 ? 1.0 : bestQ[1];
            } else {
                // Large clusters: one member at a time (its own hexes), sweeps in ascending
                // order until nothing changes (at most eight).
                for (std::size_t m = 0; m < cl.size(); ++m) setPos(cl[m], 0);
                std::vector<int> chosen(cl.size(), 0);
                bool moved = true;
                for (int sweep = 0; sweep < 8 && moved; ++sweep) {
                    moved = false;
                    for (std::size_t m = 0; m < cl.size(); ++m) {
                        const auto k = static_cast<std::size_t>(cl[m]);
                        const int* hb = inc.data() + off[k];
                        const int* he = inc.data() + off[k + 1];
                        int best = 0;
                        std::vector<double> q0;
                        for (int c = 0; c < count[m]; ++c) {
                            setPos(cl[m], c);
                            std::vector<double> q = quality(hb, he);
                            if (q0.empty() || q > q0) {
                                q0.swap(q);
                                best = c;
                            }
                        }
                        setPos(cl[m], best);
                        if (best != chosen[m]) moved = true;
                        chosen[m] = best;
                    }
                }
                const std::vector<double> all = quality(hexes.data(), hexes.data() + hexes.size());
                worst = all.size() < 2 ? 1.0 : all[1];
            }
            if (worst > 0) break;
        }
    }
    long changed = 0;
    for (std::size_t k = 0; k < nc; ++k)
        if (mesh.vertices[static_cast<std::size_t>(candidates.vertex[k])] !=
            candidates.position[static_cast<std::size_t>(candidates.offset[k])])
            ++changed;
    return changed;
}

} // namespace HexEx
