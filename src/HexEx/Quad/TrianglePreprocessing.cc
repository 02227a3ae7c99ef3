#include "TrianglePreprocessing.hh"

#include "../Core/Error.hh"
#include "../Core/Parallel.hh"
#include "../Preprocessing/Sanitization.hh"
#include "PlanarOrientation.hh"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace HexEx {

PlanarTransform TriTransitions::at(std::size_t h) const {
    if (is_identity(h)) return PlanarTransform();
    const auto it = std::lower_bound(seam.begin(), seam.end(), static_cast<int>(h));
    return seam_transform[static_cast<std::size_t>(it - seam.begin())];
}

namespace {
/// Corner of triangle @p f at vertex @p v (-1 if none).
int cornerOf(const ParametrizedTriMesh& m, int f, int v) {
    const auto& t = m.triangles[static_cast<std::size_t>(f)];
    return t[0] == v ? 0 : t[1] == v ? 1 : t[2] == v ? 2 : -1;
}

/// Best planar rotation for edge vectors e (source chart) and g (target chart): the k
/// maximizing g . (R_k e). Sets @p ambiguous when e or g is (nearly) zero or two rotations
/// score (nearly) the same.
int fitQuarterTurns(const Vec2d& e, const Vec2d& g, bool& ambiguous) {
    // R_k e for k = 0..3: (x, y), (-y, x), (-x, -y), (y, -x).
    const double s[4] = {g[0] * e[0] + g[1] * e[1], -g[0] * e[1] + g[1] * e[0], -(g[0] * e[0] + g[1] * e[1]),
                         g[0] * e[1] - g[1] * e[0]};
    int best = 0;
    for (int k = 1; k < 4; ++k)
        if (s[k] > s[best]) best = k;
    double second = -1e300;
    for (int k = 0; k < 4; ++k)
        if (k != best) second = std::max(second, s[k]);
    const double scale = std::sqrt((e[0] * e[0] + e[1] * e[1]) * (g[0] * g[0] + g[1] * g[1]));
    ambiguous = !(scale > 1e-12) || s[best] - second <= 1e-9 * scale;
    return best;
}
/// Translation for rotation @p k between the two charts of an edge: the mean of the
/// corner differences w - R u, rounded (exact rounding).
PlanarTransform fitTranslation(int k, const Vec2d& u0, const Vec2d& u1, const Vec2d& w0, const Vec2d& w1) {
    PlanarTransform T;
    T.k = k;
    const Vec2d r0 = T.rotate(u0), r1 = T.rotate(u1);
    T.tu = static_cast<int>(std::lround(0.5 * ((w0[0] - r0[0]) + (w1[0] - r1[0]))));
    T.tv = static_cast<int>(std::lround(0.5 * ((w0[1] - r0[1]) + (w1[1] - r1[1]))));
    return T;
}

/// Transition with rotation @p k from the corners of edge halfedge @p h (exact rounding).
PlanarTransform fitTranslation(const ParametrizedTriMesh& m, const TriParams& params, std::size_t h, int o, int k) {
    const int f = static_cast<int>(h / 3), i = static_cast<int>(h % 3), g = o / 3;
    const int ka = (i + 1) % 3, kb = (i + 2) % 3;
    const int ja = cornerOf(m, g, m.triangles[static_cast<std::size_t>(f)][ka]);
    const int jb = cornerOf(m, g, m.triangles[static_cast<std::size_t>(f)][kb]);
    return fitTranslation(k, params[static_cast<std::size_t>(f)][ka], params[static_cast<std::size_t>(f)][kb],
                          params[static_cast<std::size_t>(g)][ja], params[static_cast<std::size_t>(g)][jb]);
}

/// Resolves the rotation of ambiguous edges (zero parametric length) by consistency:
/// around regular vertices the transitions compose to the identity, so the transition
/// across an ambiguous edge is the composition along any other path between its two
/// triangles that, together with the edge, encloses no cone. Such a path is searched
/// breadth first over known transitions, among at most kResolveReach triangles and never
/// through a triangle at a known cone (vertexHolonomy() over the known edges). Edges are
/// taken in halfedge order and each resolved edge helps the next; returns the number left
/// with their best fit. Works on @p full, the transitions of all halfedges (@p tr's kind
/// still describes the best fits, for the holonomy of the known edges).
long resolveByVertexConsistency(const ParametrizedTriMesh& m, const TriAdjacency& adj, const TriParams& params,
                                const TriTransitions& tr, std::vector<PlanarTransform>& full, std::vector<char>& ambiguous) {
    constexpr std::size_t kResolveReach = 256;
    std::vector<std::size_t> open;
    for (std::size_t h = 0; h < ambiguous.size(); ++h) {
        if (!ambiguous[h]) continue;
        ambiguous[static_cast<std::size_t>(adj.opposite[h])] = 1;  // both halfedges of the edge
        open.push_back(h);
    }
    const std::vector<int> hol = vertexHolonomy(m, adj, tr, &ambiguous);
    auto atCone = [&](int f) {
        for (int v : m.triangles[static_cast<std::size_t>(f)])
            if (hol[static_cast<std::size_t>(v)] > 0) return true;
        return false;
    };
    std::vector<int> seen(m.triangles.size(), -1), queue;
    long arbitrary = 0;
    std::vector<PlanarTransform> toChart(m.triangles.size());
    bool changed = true;
    while (changed && !open.empty()) {
        changed = false;
        for (std::size_t idx = 0; idx < open.size();) {
            const std::size_t h = open[idx];
            const int o = adj.opposite[h];
            const int f0 = static_cast<int>(h / 3), g0 = o / 3;
            // Breadth first from f0 over known transitions until g0 is reached.
            queue.assign(1, f0);
            seen[static_cast<std::size_t>(f0)] = static_cast<int>(h);
            toChart[static_cast<std::size_t>(f0)] = PlanarTransform();
            bool found = false;
            for (std::size_t q = 0; q < queue.size() && !found && queue.size() <= kResolveReach; ++q) {
                const int f = queue[q];
                for (int j = 0; j < 3 && !found; ++j) {
                    const std::size_t he = 3 * static_cast<std::size_t>(f) + static_cast<std::size_t>(j);
                    const int oe = adj.opposite[he];
                    if (oe < 0 || ambiguous[he]) continue;
                    const int g = oe / 3;
                    if (seen[static_cast<std::size_t>(g)] == static_cast<int>(h)) continue;
                    seen[static_cast<std::size_t>(g)] = static_cast<int>(h);
                    toChart[static_cast<std::size_t>(g)] = full[he] * toChart[static_cast<std::size_t>(f)];
                    if (g == g0) {
                        found = true;
                    } else if (!atCone(g)) {
                        queue.push_back(g);
                    }
                }
            }
            if (found) {
                full[h] = fitTranslation(m, params, h, o, toChart[static_cast<std::size_t>(g0)].k);
                full[static_cast<std::size_t>(o)] = full[h].inverse();
                ambiguous[h] = ambiguous[static_cast<std::size_t>(o)] = 0;
                open.erase(open.begin() + static_cast<std::ptrdiff_t>(idx));
                changed = true;
            } else {
                ++idx;
            }
        }
        if (!changed && !open.empty()) {
            // Stuck (e.g. a triangle collapsed to a point has no known edge): keep the best
            // fit of the first open edge as known, which fixes such a triangle's chart, and go on.
            const std::size_t h = open.front();
            ambiguous[h] = ambiguous[static_cast<std::size_t>(adj.opposite[h])] = 0;
            open.erase(open.begin());
            ++arbitrary;
            changed = true;
        }
    }
    return arbitrary;
}
} // namespace

TriTransitions computeTriTransitions(const ParametrizedTriMesh& m, const TriAdjacency& adj, const TriParams& params,
                                     const std::vector<int>* given, int threads) {
    const std::size_t nh = adj.opposite.size();
    TriTransitions tr;
    if (given && given->size() != nh)
        throw InputError("given rotations: " + std::to_string(given->size()) + " values for " + std::to_string(nh) +
                         " halfedges");
    // Every halfedge's kind is written exactly once below (boundary ones by themselves,
    // each edge by its smaller halfedge), so the array is not zeroed first.
    tr.kind.resize(nh);
    const int chunks = std::max(1, threads);
    std::vector<long> ambiguous(static_cast<std::size_t>(chunks), 0);
    std::vector<char> isAmbiguous(given ? 0 : nh, 0);
    std::vector<std::string> errors(static_cast<std::size_t>(chunks));
    // Per chunk, the halfedges with a transition other than the identity.
    std::vector<std::vector<std::pair<int, PlanarTransform>>> seams(static_cast<std::size_t>(chunks));
    auto kindOf = [](const PlanarTransform& T) {
        return static_cast<unsigned char>(T.k | (T.is_identity() ? 0 : TriTransitions::kNotIdentity));
    };
    parallelChunks(nh, chunks, [&](int chunk, std::size_t hb, std::size_t he) {
        auto& seam = seams[static_cast<std::size_t>(chunk)];
        for (std::size_t h = hb; h < he; ++h) {
            const int o = adj.opposite[h];
            if (o < 0) {
                tr.kind[h] = 0;
                continue;
            }
            if (o < static_cast<int>(h)) continue;  // each edge once, from its smaller halfedge
            const int f = static_cast<int>(h / 3), i = static_cast<int>(h % 3);
            const int g = o / 3;
            const int ka = (i + 1) % 3, kb = (i + 2) % 3;
            const int va = m.triangles[static_cast<std::size_t>(f)][ka], vb = m.triangles[static_cast<std::size_t>(f)][kb];
            const int ja = cornerOf(m, g, va), jb = cornerOf(m, g, vb);
            const Vec2d& u0 = params[static_cast<std::size_t>(f)][ka];
            const Vec2d& u1 = params[static_cast<std::size_t>(f)][kb];
            const Vec2d& w0 = params[static_cast<std::size_t>(g)][ja];
            const Vec2d& w1 = params[static_cast<std::size_t>(g)][jb];
            int k = 0;
            if (given) {
                const int a = (*given)[h], b = (*given)[static_cast<std::size_t>(o)];
                if (a < 0 || a > 3 || b < 0 || b > 3 || (a + b) % 4 != 0) {
                    errors[static_cast<std::size_t>(chunk)] = "given rotations: halfedges " + std::to_string(h) + " and " +
                                                              std::to_string(o) + " have quarter turns " + std::to_string(a) +
                                                              " and " + std::to_string(b) + " (must be 0..3 and inverse)";
                    return;
                }
                k = a;
            } else {
                bool amb = false;
                k = fitQuarterTurns(u1 - u0, w1 - w0, amb);
                if (amb) {
                    // The edge does not fix the rotation; the translation must still be an
                    // integer vector: keep the rotations for which it (nearly) is.
                    unsigned mask = 0;
                    for (int c = 0; c < 4; ++c) {
                        PlanarTransform R;
                        R.k = c;
                        const Vec2d d = w0 - R.rotate(u0);
                        if (std::fabs(d[0] - std::round(d[0])) <= 1e-6 && std::fabs(d[1] - std::round(d[1])) <= 1e-6)
                            mask |= 1u << c;
                    }
                    for (int c = 0; c < 4; ++c)
                        if (mask == (1u << c)) {
                            k = c;  // the only one: determined after all
                            amb = false;
                        }
                    if (amb) {
                        ++ambiguous[static_cast<std::size_t>(chunk)];
                        isAmbiguous[h] = 1;
                        for (int c = 3; c >= 0; --c)
                            if (mask & (1u << c)) k = c;  // the smallest candidate
                    }
                }
            }
            const PlanarTransform T = fitTranslation(k, u0, u1, w0, w1);
            const PlanarTransform Ti = T.inverse();
            tr.kind[h] = kindOf(T);
            tr.kind[static_cast<std::size_t>(o)] = kindOf(Ti);
            if (!T.is_identity()) {
                seam.emplace_back(static_cast<int>(h), T);
                seam.emplace_back(o, Ti);
            }
        }
    });
    for (const auto& e : errors)
        if (!e.empty()) throw InputError(e);
    for (long a : ambiguous) tr.ambiguous += a;
    std::vector<std::pair<int, PlanarTransform>> all;
    std::size_t total = 0;
    for (const auto& sm : seams) total += sm.size();
    all.reserve(total);
    for (auto& sm : seams) {
        all.insert(all.end(), sm.begin(), sm.end());
        std::vector<std::pair<int, PlanarTransform>>().swap(sm);
    }
    if (tr.ambiguous > 0) {
        // Resolution on the full array (rare: maps with edges of zero parametric length).
        std::vector<PlanarTransform> full(nh);
        for (const auto& e : all) full[static_cast<std::size_t>(e.first)] = e.second;
        tr.unresolved = resolveByVertexConsistency(m, adj, params, tr, full, isAmbiguous);
        all.clear();
        for (std::size_t h = 0; h < nh; ++h) {
            tr.kind[h] = kindOf(full[h]);
            if (!full[h].is_identity()) all.emplace_back(static_cast<int>(h), full[h]);
        }
    }
    std::sort(all.begin(), all.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    tr.seam.resize(all.size());
    tr.seam_transform.resize(all.size());
    for (std::size_t i = 0; i < all.size(); ++i) {
        tr.seam[i] = all[i].first;
        tr.seam_transform[i] = all[i].second;
    }
    return tr;
}

long sanitizeTriParams(const ParametrizedTriMesh& m, const TriAdjacency& adj, TriParams& params, const TriTransitions& tr,
                       double epsilon, int threads) {
    const std::size_t nv = m.points.size();
    const int chunks = std::max(1, threads);
    std::vector<int> snapped(static_cast<std::size_t>(chunks), 0);
    auto isIdentity = [&](std::size_t h) { return tr.is_identity(h); };
    // quantizeParameter() on the (u, v, 0) point (the third coordinate stays 0).
    auto quantize = [&](Vec2d& u, double bound, int& snap) {
        Vec3d x(u[0], u[1], 0);
        quantizeParameter(x, bound, epsilon, snap);
        u = Vec2d(x[0], x[1]);
    };
    parallelChunks(nv, chunks, [&](int chunk, std::size_t vb, std::size_t ve) {
        int& snap = snapped[static_cast<std::size_t>(chunk)];
        std::vector<int> star;
        std::vector<PlanarTransform> toChart;
        for (std::size_t vi = vb; vi < ve; ++vi) {
            const int v = static_cast<int>(vi);
            const int b = adj.vertex_offset[vi], e = adj.vertex_offset[vi + 1];
            if (b == e) continue;
            // Common case: identity transitions around v and one parameter everywhere.
            bool simple = true;
            const int f0 = adj.vertex_triangles[static_cast<std::size_t>(b)];
            const Vec2d first = params[static_cast<std::size_t>(f0)][cornerOf(m, f0, v)];
            for (int p = b; p < e && simple; ++p) {
                const int f = adj.vertex_triangles[static_cast<std::size_t>(p)];
                const int k = cornerOf(m, f, v);
                if (!(params[static_cast<std::size_t>(f)][k] == first)) simple = false;
                for (int j = 0; j < 3 && simple; ++j)
                    if (j != k && !isIdentity(3 * static_cast<std::size_t>(f) + static_cast<std::size_t>(j))) simple = false;
            }
            if (simple) {
                Vec2d u = first;
                quantize(u, std::max(std::fabs(u[0]), std::fabs(u[1])), snap);
                if (u == first) continue;
                for (int p = b; p < e; ++p) {
                    const int f = adj.vertex_triangles[static_cast<std::size_t>(p)];
                    params[static_cast<std::size_t>(f)][cornerOf(m, f, v)] = u;
                }
                continue;
            }
            // Breadth first over the edges around v, composing transitions from f0's chart.
            star.assign(1, f0);
            toChart.assign(1, PlanarTransform());
            for (std::size_t q = 0; q < star.size(); ++q) {
                const int f = star[q];
                const int k = cornerOf(m, f, v);
                for (int j = 0; j < 3; ++j) {
                    if (j == k) continue;  // the edge opposite v does not contain it
                    const std::size_t h = 3 * static_cast<std::size_t>(f) + static_cast<std::size_t>(j);
                    const int o = adj.opposite[h];
                    if (o < 0) continue;
                    const int g = o / 3;
                    if (std::find(star.begin(), star.end(), g) != star.end()) continue;
                    star.push_back(g);
                    toChart.push_back(tr.at(h) * toChart[q]);
                }
            }
            Vec2d u = first;
            double bound = 0;
            const double umax = std::max(std::fabs(u[0]), std::fabs(u[1]));
            for (std::size_t q = 0; q < star.size(); ++q) {
                const Vec2d& p = params[static_cast<std::size_t>(star[q])][cornerOf(m, star[q], v)];
                const PlanarTransform& t = toChart[q];
                bound = std::max({bound, std::fabs(p[0]), std::fabs(p[1]), umax + std::max(std::abs(t.tu), std::abs(t.tv))});
            }
            quantize(u, bound, snap);
            for (std::size_t q = 0; q < star.size(); ++q)
                params[static_cast<std::size_t>(star[q])][cornerOf(m, star[q], v)] = toChart[q].apply(u);
        }
    });
    long total = 0;
    for (int s : snapped) total += s;
    return total;
}

std::vector<signed char> classifyTriangles(const TriParams& params, int threads) {
    std::vector<signed char> s(params.size());
    parallelChunks(params.size(), std::max(1, threads), [&](int, std::size_t fb, std::size_t fe) {
        for (std::size_t f = fb; f < fe; ++f)
            s[f] = static_cast<signed char>(orient2dUV(params[f][0], params[f][1], params[f][2][0], params[f][2][1]));
    });
    return s;
}

std::vector<int> vertexHolonomy(const ParametrizedTriMesh& m, const TriAdjacency& adj, const TriTransitions& tr,
                                const std::vector<char>* unknown, int threads) {
    const std::size_t nv = m.points.size();
    std::vector<int> hol(nv, -1);
    parallelChunks(nv, std::max(1, threads), [&](int, std::size_t vb, std::size_t ve) {
    for (std::size_t vi = vb; vi < ve; ++vi) {
        if (adj.vertex_offset[vi] == adj.vertex_offset[vi + 1]) continue;
        const int v = static_cast<int>(vi);
        const int f0 = adj.vertex_triangles[static_cast<std::size_t>(adj.vertex_offset[vi])];
        // Around the fan: leave each triangle through the edge at v it was not entered by.
        // Planar rotations commute, so the quarter turns just add up.
        int turns = 0;
        int f = f0, entry = -1, steps = 0;
        const int limit = adj.vertex_offset[vi + 1] - adj.vertex_offset[vi] + 1;
        bool ok = true;
        do {
            const int k = cornerOf(m, f, v);
            const int e = entry == (k + 1) % 3 ? (k + 2) % 3 : (k + 1) % 3;
            const std::size_t he = 3 * static_cast<std::size_t>(f) + static_cast<std::size_t>(e);
            const int oe = adj.opposite[he];
            if (oe < 0 || (unknown && (*unknown)[he]) || ++steps > limit) {
                ok = false;
                break;
            }
            turns += tr.kind[he] & 3;
            f = oe / 3;
            entry = oe % 3;
        } while (f != f0);
        if (ok) hol[vi] = turns % 4;
    }
    });
    return hol;
}

} // namespace HexEx
