#include "QuadGMapValidator.hh"

#include "../Core/Parallel.hh"

#include <algorithm>
#include <sstream>

namespace HexEx {

namespace {
/// Labels the orbits of two links (bits a and b) by search, smallest dart first; works for
/// any map, involutive or not. @p first receives the smallest dart of each orbit.
std::vector<int> labelPair(const GMap<2>& g, int a, int b, std::vector<int>& size, std::vector<int>& first) {
    const auto& L = g.links();
    const std::size_t n = L.size();
    std::vector<int> label(n, -1), stack;
    size.clear();
    first.clear();
    for (std::size_t s = 0; s < n; ++s) {
        if (!g.is_alive(DartHandle(static_cast<int>(s))) || label[s] >= 0) continue;
        const int l = static_cast<int>(size.size());
        size.push_back(0);
        first.push_back(static_cast<int>(s));
        label[s] = l;
        stack.assign(1, static_cast<int>(s));
        while (!stack.empty()) {
            const int d = stack.back();
            stack.pop_back();
            ++size[static_cast<std::size_t>(l)];
            for (int i : {a, b}) {
                const int e = L[static_cast<std::size_t>(d)][static_cast<std::size_t>(i)];
                if (e < 0 || static_cast<std::size_t>(e) >= n || !g.is_alive(DartHandle(e)) || label[static_cast<std::size_t>(e)] >= 0)
                    continue;
                label[static_cast<std::size_t>(e)] = l;
                stack.push_back(e);
            }
        }
    }
    return label;
}

/// labelPair() for a map whose links a and b are involutions on the alive darts (so an
/// orbit is a cycle or a chain that alternates a and b): in parallel, the same labels.
/// Pass 1 marks each orbit's smallest dart (a walk that stops at the first smaller dart),
/// pass 2 numbers the marked darts in dart order, pass 3 walks each orbit once from its
/// smallest dart and writes its label (orbits are disjoint, so the writes are too).
std::vector<int> labelInvolutionPair(const GMap<2>& g, int a, int b, std::vector<int>& size, std::vector<int>& first,
                                     int threads) {
    const auto& L = g.links();
    const std::size_t n = L.size();
    const int gens[2] = {a, b};
    // Visits the orbit of d (d itself excluded), alternating the generators, in both
    // directions of a chain; stops early when visit() returns false.
    auto walk = [&](int d, auto&& visit) {
        for (int start = 0; start < 2; ++start) {
            int x = d, k = start;
            for (;;) {
                const int y = L[static_cast<std::size_t>(x)][static_cast<std::size_t>(gens[k])];
                if (y == x) break;  // end of a chain: walk the other way from d
                if (y == d) return;  // cycle closed: everything seen
                if (!visit(y)) return;
                x = y;
                k ^= 1;
            }
        }
    };
    std::vector<char> isFirst(n, 0);
    const int chunks = std::max(1, threads);
    std::vector<int> count(static_cast<std::size_t>(chunks), 0);
    parallelChunks(n, chunks, [&](int c, std::size_t bgn, std::size_t end) {
        int cnt = 0;
        for (std::size_t s = bgn; s < end; ++s) {
            const int d = static_cast<int>(s);
            if (!g.is_alive(DartHandle(d))) continue;
            // Both neighbours first: most darts are not a local minimum of their orbit,
            // and a walk in one direction could otherwise run around most of a cycle.
            bool smallest = L[s][static_cast<std::size_t>(a)] >= d && L[s][static_cast<std::size_t>(b)] >= d;
            if (smallest) walk(d, [&](int y) { return (smallest = y > d); });
            isFirst[s] = smallest;
            cnt += smallest;
        }
        count[static_cast<std::size_t>(c)] = cnt;
    });
    std::vector<int> base(static_cast<std::size_t>(chunks) + 1, 0);
    for (int c = 0; c < chunks; ++c) base[static_cast<std::size_t>(c) + 1] = base[static_cast<std::size_t>(c)] + count[static_cast<std::size_t>(c)];
    const std::size_t orbits = static_cast<std::size_t>(base.back());
    size.assign(orbits, 0);
    first.assign(orbits, 0);
    std::vector<int> label(n, -1);
    parallelChunks(n, chunks, [&](int c, std::size_t bgn, std::size_t end) {
        int l = base[static_cast<std::size_t>(c)];
        for (std::size_t s = bgn; s < end; ++s) {
            if (!isFirst[s]) continue;
            const int d = static_cast<int>(s);
            label[s] = l;
            int sz = 1;
            walk(d, [&](int y) {
                label[static_cast<std::size_t>(y)] = l;
                ++sz;
                return true;
            });
            size[static_cast<std::size_t>(l)] = sz;
            first[static_cast<std::size_t>(l)] = d;
            ++l;
        }
    });
    return label;
}
} // namespace

std::string QuadGMapValidation::summary() const {
    std::ostringstream os;
    os << (valid() ? "valid" : "INVALID") << ": " << darts << " darts, " << not_involution << " non-involutive, "
       << open_links << " open, eq1 " << eq1_edge_connection << ", eq3 " << eq3_quad << ", " << boundary_darts
       << " boundary darts";
    return os.str();
}

QuadGMapValidation validateQuadGMap(const GMap<2>& g, QuadOrbitLabels* labels, int threads) {
    const auto& L = g.links();
    const std::size_t n = L.size();
    auto alive = [&](int d) { return d >= 0 && static_cast<std::size_t>(d) < n && g.is_alive(DartHandle(d)); };
    const int chunks = std::max(1, threads);
    std::vector<QuadGMapValidation> parts(static_cast<std::size_t>(chunks));
    parallelChunks(n, chunks, [&](int c, std::size_t bgn, std::size_t end) {
        QuadGMapValidation& v = parts[static_cast<std::size_t>(c)];
        for (std::size_t s = bgn; s < end; ++s) {
            const int d = static_cast<int>(s);
            if (!alive(d)) continue;
            ++v.darts;
            bool inv = true;
            for (int i = 0; i < 3; ++i) {
                const int p = L[s][static_cast<std::size_t>(i)];
                if (!alive(p) || L[static_cast<std::size_t>(p)][static_cast<std::size_t>(i)] != d) inv = false;
            }
            if (!inv) {
                ++v.not_involution;
                continue;
            }
            if (L[s][0] == d || L[s][1] == d) ++v.open_links;
            if (L[s][2] == d) {
                ++v.boundary_darts;
            } else {
                // (alpha_0 alpha_2)^2 = id: alpha_0 and alpha_2 commute.
                const int x = L[static_cast<std::size_t>(L[s][0])][2];
                const int y = L[static_cast<std::size_t>(L[s][2])][0];
                if (x != y) ++v.eq1_edge_connection;
            }
        }
    });
    QuadGMapValidation v;
    for (const QuadGMapValidation& p : parts) {
        v.darts += p.darts;
        v.not_involution += p.not_involution;
        v.open_links += p.open_links;
        v.eq1_edge_connection += p.eq1_edge_connection;
        v.boundary_darts += p.boundary_darts;
    }
    // Every alive dart's links are alive involutions: orbits are alternating cycles/chains.
    const bool involutive = v.not_involution == 0;
    auto label = [&](int a, int b, std::vector<int>& size, std::vector<int>& first) {
        return involutive ? labelInvolutionPair(g, a, b, size, first, threads) : labelPair(g, a, b, size, first);
    };
    std::vector<int> fsize, vsize, esize, ffirst, vfirst, efirst;
    std::vector<int> face = label(0, 1, fsize, ffirst);
    std::vector<long> eq3(static_cast<std::size_t>(chunks), 0);
    parallelChunks(n, chunks, [&](int c, std::size_t bgn, std::size_t end) {
        for (std::size_t s = bgn; s < end; ++s)
            if (face[s] >= 0 && fsize[static_cast<std::size_t>(face[s])] != 8) ++eq3[static_cast<std::size_t>(c)];
    });
    for (long e : eq3) v.eq3_quad += e;
    if (labels) {
        labels->face = std::move(face);
        labels->face_first = std::move(ffirst);
        labels->n_faces = static_cast<int>(fsize.size());
        labels->vertex = label(1, 2, vsize, vfirst);
        labels->vertex_first = std::move(vfirst);
        labels->n_vertices = static_cast<int>(vsize.size());
        labels->edge = label(0, 2, esize, efirst);
        labels->edge_first = std::move(efirst);
        labels->n_edges = static_cast<int>(esize.size());
    }
    return v;
}

} // namespace HexEx
