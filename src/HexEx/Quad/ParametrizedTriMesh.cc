#include "ParametrizedTriMesh.hh"

#include "../Core/Error.hh"
#include "../Core/Parallel.hh"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace HexEx {

TriAdjacency buildTriAdjacency(const ParametrizedTriMesh& m, int threads) {
    const std::size_t nf = m.triangles.size(), nv = m.points.size();
    if (m.params.size() != nf)
        throw InputError("triangle mesh: " + std::to_string(m.params.size()) + " parameter triples for " +
                         std::to_string(nf) + " triangles");
    if (nf > static_cast<std::size_t>(INT32_MAX / 3) || nv > static_cast<std::size_t>(INT32_MAX))
        throw InputError("triangle mesh: too many elements");
    const int chunks = std::max(1, threads);
    // Checks in parallel, each chunk keeping its first error: the lowest chunk's error is
    // the one a sequential scan would report first.
    auto firstError = [&](std::size_t n, auto&& check) {
        std::vector<std::string> errors(static_cast<std::size_t>(chunks));
        parallelChunks(n, chunks, [&](int c, std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e && errors[static_cast<std::size_t>(c)].empty(); ++i)
                check(i, errors[static_cast<std::size_t>(c)]);
        });
        for (const auto& e : errors)
            if (!e.empty()) throw InputError(e);
    };
    firstError(nv, [&](std::size_t v, std::string& err) {
        for (int k = 0; k < 3 && err.empty(); ++k)
            if (!std::isfinite(m.points[v][k])) err = "triangle mesh: vertex " + std::to_string(v) + ": position is not finite";
    });
    TriAdjacency adj;
    // Corners per vertex, counted per chunk of triangles (no shared counters): slot[c][v]
    // is chunk c's count for v, later the position of its next triangle of v.
    std::vector<std::vector<int, DefaultInitAllocator<int>>> slot(static_cast<std::size_t>(chunks));
    {
        std::vector<std::string> errors(static_cast<std::size_t>(chunks));
        parallelChunks(nf, chunks, [&](int c, std::size_t fb, std::size_t fe) {
            auto& cnt = slot[static_cast<std::size_t>(c)];
            cnt.assign(nv, 0);
            std::string& err = errors[static_cast<std::size_t>(c)];
            for (std::size_t f = fb; f < fe; ++f) {
                const auto& t = m.triangles[f];
                for (int k = 0; k < 3 && err.empty(); ++k) {
                    if (t[k] < 0 || static_cast<std::size_t>(t[k]) >= nv) {
                        err = "triangle mesh: triangle " + std::to_string(f) + ": vertex index " + std::to_string(t[k]) +
                              " out of range (" + std::to_string(nv) + " vertices)";
                    } else if (!std::isfinite(m.params[f][k][0]) || !std::isfinite(m.params[f][k][1])) {
                        err = "triangle mesh: triangle " + std::to_string(f) + ": parameter of corner " + std::to_string(k) +
                              " is not finite";
                    }
                }
                if (err.empty() && (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]))
                    err = "triangle mesh: triangle " + std::to_string(f) + ": repeated vertex";
                if (!err.empty()) return;
                for (int k = 0; k < 3; ++k) ++cnt[static_cast<std::size_t>(t[k])];
            }
        });
        for (const auto& e : errors)
            if (!e.empty()) throw InputError(e);
    }
    // Offsets per vertex and each chunk's first position per vertex, in parallel over
    // vertex ranges (per-range totals, then a prefix sum over the ranges).
    adj.vertex_offset.resize(nv + 1);
    std::vector<long> rangeFirst(static_cast<std::size_t>(chunks) + 1, 0);
    parallelChunks(nv, chunks, [&](int r, std::size_t vb, std::size_t ve) {
        long total = 0;
        for (const auto& cnt : slot)
            if (!cnt.empty())
                for (std::size_t v = vb; v < ve; ++v) total += cnt[v];
        rangeFirst[static_cast<std::size_t>(r) + 1] = total;
    });
    for (int r = 0; r < chunks; ++r) rangeFirst[static_cast<std::size_t>(r) + 1] += rangeFirst[static_cast<std::size_t>(r)];
    parallelChunks(nv, chunks, [&](int r, std::size_t vb, std::size_t ve) {
        int pos = static_cast<int>(rangeFirst[static_cast<std::size_t>(r)]);
        for (std::size_t v = vb; v < ve; ++v) {
            adj.vertex_offset[v] = pos;
            for (auto& cnt : slot)
                if (!cnt.empty()) {
                    const int k = cnt[v];
                    cnt[v] = pos;
                    pos += k;
                }
        }
    });
    adj.vertex_offset[nv] = static_cast<int>(3 * nf);
    // Triangles per vertex in ascending order: chunk c places its triangles (in order)
    // after those of the chunks before it.
    adj.vertex_triangles.resize(3 * nf);
    parallelChunks(nf, chunks, [&](int c, std::size_t fb, std::size_t fe) {
        auto& pos = slot[static_cast<std::size_t>(c)];
        for (std::size_t f = fb; f < fe; ++f)
            for (int k = 0; k < 3; ++k)
                adj.vertex_triangles[static_cast<std::size_t>(pos[static_cast<std::size_t>(m.triangles[f][k])]++)] = static_cast<int>(f);
    });
    slot.clear();
    // Halfedge 3f+i runs a -> b; its opposite runs b -> a in a triangle around b.
    // Fast path: the first such triangle in b's star, then a check that the pairing is
    // consistent (every match mutual, no boundary halfedge with a twin running the same
    // way). Any edge used other than once in each direction fails the check (all a -> b
    // halfedges match the same first b -> a one), and then the full scan below runs and
    // reports the first defect exactly as it always did.
    adj.opposite.resize(3 * nf);  // every entry is written by the pass below
    auto starOf = [&](int v, auto&& visit) {
        for (int p = adj.vertex_offset[static_cast<std::size_t>(v)]; p < adj.vertex_offset[static_cast<std::size_t>(v) + 1]; ++p)
            if (!visit(adj.vertex_triangles[static_cast<std::size_t>(p)])) return;
    };
    parallelChunks(nf, chunks, [&](int, std::size_t fb, std::size_t fe) {
        for (std::size_t f = fb; f < fe; ++f)
            for (int i = 0; i < 3; ++i) {
                const int a = m.triangles[f][(i + 1) % 3], b = m.triangles[f][(i + 2) % 3];
                int found = -1;
                starOf(b, [&](int g) {
                    if (g == static_cast<int>(f)) return true;
                    const auto& tg = m.triangles[static_cast<std::size_t>(g)];
                    const int pb = tg[0] == b ? 0 : tg[1] == b ? 1 : 2;
                    if (tg[(pb + 1) % 3] != a) return true;
                    found = 3 * g + (pb + 2) % 3;
                    return false;
                });
                adj.opposite[3 * f + static_cast<std::size_t>(i)] = found;
            }
    });
    std::vector<char> consistent(static_cast<std::size_t>(chunks), 1);
    parallelChunks(nf, chunks, [&](int chunk, std::size_t fb, std::size_t fe) {
        bool ok = true;
        for (std::size_t h = 3 * fb; h < 3 * fe && ok; ++h) {
            const int o = adj.opposite[h];
            if (o >= 0) {
                ok = adj.opposite[static_cast<std::size_t>(o)] == static_cast<int>(h);
                continue;
            }
            const std::size_t f = h / 3, i = h % 3;
            const int a = m.triangles[f][(i + 1) % 3], b = m.triangles[f][(i + 2) % 3];
            starOf(b, [&](int g) {  // a twin a -> b elsewhere?
                if (g == static_cast<int>(f)) return true;
                const auto& tg = m.triangles[static_cast<std::size_t>(g)];
                const int pb = tg[0] == b ? 0 : tg[1] == b ? 1 : 2;
                if (tg[(pb + 2) % 3] == a) ok = false;
                return ok;
            });
        }
        consistent[static_cast<std::size_t>(chunk)] = ok;
    });
    if (std::find(consistent.begin(), consistent.end(), 0) == consistent.end()) return adj;
    std::vector<std::string> errors(static_cast<std::size_t>(chunks));
    parallelChunks(nf, chunks, [&](int chunk, std::size_t fb, std::size_t fe) {
        for (std::size_t f = fb; f < fe && errors[static_cast<std::size_t>(chunk)].empty(); ++f)
            for (int i = 0; i < 3; ++i) {
                const int a = m.triangles[f][(i + 1) % 3], b = m.triangles[f][(i + 2) % 3];
                int found = -1, count = 0;
                for (int p = adj.vertex_offset[static_cast<std::size_t>(b)]; p < adj.vertex_offset[static_cast<std::size_t>(b) + 1]; ++p) {
                    const int g = adj.vertex_triangles[static_cast<std::size_t>(p)];
                    if (g == static_cast<int>(f)) continue;
                    const auto& tg = m.triangles[static_cast<std::size_t>(g)];
                    const int pb = tg[0] == b ? 0 : tg[1] == b ? 1 : 2;  // b's corner in g
                    if (tg[(pb + 1) % 3] == a) {  // g runs b -> a: halfedge opposite corner pb + 2
                        found = 3 * g + (pb + 2) % 3;
                        ++count;
                    } else if (tg[(pb + 2) % 3] == a) {
                        errors[static_cast<std::size_t>(chunk)] =
                            "triangle mesh: triangles " + std::to_string(f) + " and " + std::to_string(g) +
                            " use edge (" + std::to_string(a) + ", " + std::to_string(b) +
                            ") in the same direction (inconsistent orientation or non-manifold edge)";
                    }
                }
                if (count > 1 && errors[static_cast<std::size_t>(chunk)].empty())
                    errors[static_cast<std::size_t>(chunk)] = "triangle mesh: edge (" + std::to_string(a) + ", " +
                                                             std::to_string(b) + ") is shared by more than two triangles";
                adj.opposite[3 * f + static_cast<std::size_t>(i)] = found;
            }
    });
    for (const auto& e : errors)
        if (!e.empty()) throw InputError(e);
    return adj;
}

} // namespace HexEx
