#include "QuadGMapValidator.hh"

#include "../Core/Parallel.hh"

#include <algorithm>
#include <array>
#include <sstream>

namespace HexEx {

namespace {
/// The links of a map and which darts are alive: a GMap<2>'s, or an extractor's links
/// array (no GMap: every dart alive).
struct LinkView {
    const std::array<int, 3>* L;  ///< links per dart
    std::size_t n;                ///< darts
    const GMap<2>* g;             ///< the map (null: every dart alive)
    /// True if @p d is a dart of the map and alive.
    bool alive(int d) const {
        return d >= 0 && static_cast<std::size_t>(d) < n && (!g || g->is_alive(DartHandle(d)));
    }
};

/// Labels the orbits of two links (bits a and b) by search, smallest dart first; works for
/// any map, involutive or not. @p first receives the smallest dart of each orbit.
QuadLabelVector labelPair(const LinkView& g, int a, int b, QuadLabelVector& size, QuadLabelVector& first) {
    const std::array<int, 3>* L = g.L;
    const std::size_t n = g.n;
    QuadLabelVector label(n, -1);
    std::vector<int> stack;
    size.clear();
    first.clear();
    for (std::size_t s = 0; s < n; ++s) {
        if (!g.alive(static_cast<int>(s)) || label[s] >= 0) continue;
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
                if (!g.alive(e) || label[static_cast<std::size_t>(e)] >= 0)
                    continue;
                label[static_cast<std::size_t>(e)] = l;
                stack.push_back(e);
            }
        }
    }
    return label;
}

/// Labels, sizes and smallest darts of the orbits of one pair of involutions.
struct PairLabels {
    QuadLabelVector label;          ///< orbit per dart
    QuadLabelVector size, first;    ///< per orbit: darts, smallest dart
};

/// The generator pairs of the face, vertex and edge orbits.
constexpr int kPairs[3][2] = {{0, 1}, {1, 2}, {0, 2}};

/// labelPair() for the three pairs at once, for a map whose links are involutions on the
/// alive darts (so an orbit is a cycle or a chain that alternates the two generators): in
/// parallel, the same labels. Pass 1 marks each orbit's smallest dart (a walk that stops
/// at the first smaller dart, started only where both neighbours are larger), then each
/// chunk numbers its marked darts in dart order from its offset, and pass 2 walks each
/// orbit once from its smallest dart and writes its label (orbits are disjoint, so the
/// writes are too). The label arrays are not zeroed: pass 1 writes -1 for erased darts,
/// pass 2 every alive dart's label.
void labelInvolutionOrbits(const LinkView& g, int threads, PairLabels out[3]) {
    const std::array<int, 3>* L = g.L;
    const std::size_t n = g.n;
    // Visits the orbit of d under pair q (d itself excluded), alternating the generators,
    // in both directions of a chain; stops early when visit() returns false.
    auto walk = [&](int q, int d, auto&& visit) {
        for (int start = 0; start < 2; ++start) {
            int x = d, k = start;
            for (;;) {
                const int y = L[static_cast<std::size_t>(x)][static_cast<std::size_t>(kPairs[q][k])];
                if (y == x) break;  // end of a chain: walk the other way from d
                if (y == d) return;  // cycle closed: everything seen
                if (!visit(y)) return;
                x = y;
                k ^= 1;
            }
        }
    };
    std::vector<unsigned char, DefaultInitAllocator<unsigned char>> roots(n);  // bit q: smallest dart of its pair-q orbit
    for (int q = 0; q < 3; ++q) out[q].label.resize(n);
    const int chunks = std::max(1, threads);
    std::vector<std::array<int, 3>> count(static_cast<std::size_t>(chunks), {0, 0, 0});
    parallelChunks(n, chunks, [&](int c, std::size_t bgn, std::size_t end) {
        auto& cnt = count[static_cast<std::size_t>(c)];
        for (std::size_t s = bgn; s < end; ++s) {
            const int d = static_cast<int>(s);
            if (!g.alive(d)) {
                roots[s] = 0;
                for (int q = 0; q < 3; ++q) out[q].label[s] = -1;
                continue;
            }
            unsigned char bits = 0;
            for (int q = 0; q < 3; ++q) {
                bool smallest = L[s][static_cast<std::size_t>(kPairs[q][0])] >= d && L[s][static_cast<std::size_t>(kPairs[q][1])] >= d;
                if (smallest) walk(q, d, [&](int y) { return (smallest = y > d); });
                if (smallest) {
                    bits = static_cast<unsigned char>(bits | (1u << q));
                    ++cnt[static_cast<std::size_t>(q)];
                }
            }
            roots[s] = bits;
        }
    });
    std::vector<std::array<int, 3>> base(static_cast<std::size_t>(chunks) + 1, {0, 0, 0});
    for (int c = 0; c < chunks; ++c)
        for (std::size_t q = 0; q < 3; ++q)
            base[static_cast<std::size_t>(c) + 1][q] = base[static_cast<std::size_t>(c)][q] + count[static_cast<std::size_t>(c)][q];
    for (std::size_t q = 0; q < 3; ++q) {
        const std::size_t orbits = static_cast<std::size_t>(base.back()[q]);
        out[q].size.resize(orbits);  // every orbit's entries are written in pass 2
        out[q].first.resize(orbits);
    }
    parallelChunks(n, chunks, [&](int c, std::size_t bgn, std::size_t end) {
        std::array<int, 3> l = base[static_cast<std::size_t>(c)];
        for (std::size_t s = bgn; s < end; ++s) {
            if (!roots[s]) continue;
            const int d = static_cast<int>(s);
            for (int q = 0; q < 3; ++q) {
                if (!(roots[s] & (1u << q))) continue;
                PairLabels& P = out[q];
                const int lq = l[static_cast<std::size_t>(q)]++;
                P.label[s] = lq;
                int sz = 1;
                walk(q, d, [&](int y) {
                    P.label[static_cast<std::size_t>(y)] = lq;
                    ++sz;
                    return true;
                });
                P.size[static_cast<std::size_t>(lq)] = sz;
                P.first[static_cast<std::size_t>(lq)] = d;
            }
        }
    });
}
} // namespace

std::string QuadGMapValidation::summary() const {
    std::ostringstream os;
    os << (valid() ? "valid" : "INVALID") << ": " << darts << " darts, " << not_involution << " non-involutive, "
       << open_links << " open, eq1 " << eq1_edge_connection << ", eq3 " << eq3_quad << ", " << boundary_darts
       << " boundary darts";
    return os.str();
}

namespace {
/// validateQuadGMap() and validateQuadLinks() on a LinkView.
QuadGMapValidation validateView(const LinkView& g, QuadOrbitLabels* labels, int threads) {
    const std::array<int, 3>* L = g.L;
    const std::size_t n = g.n;
    auto alive = [&](int d) { return g.alive(d); };
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
    PairLabels P[3];
    if (v.not_involution == 0) {
        labelInvolutionOrbits(g, threads, P);
    } else {
        for (int q = 0; q < 3; ++q) {
            if (q > 0 && !labels) break;  // only the faces are needed for the checks
            P[q].label = labelPair(g, kPairs[q][0], kPairs[q][1], P[q].size, P[q].first);
        }
    }
    const QuadLabelVector& face = P[0].label;
    const QuadLabelVector& fsize = P[0].size;
    std::vector<long> eq3(static_cast<std::size_t>(chunks), 0);
    parallelChunks(n, chunks, [&](int c, std::size_t bgn, std::size_t end) {
        for (std::size_t s = bgn; s < end; ++s)
            if (face[s] >= 0 && fsize[static_cast<std::size_t>(face[s])] != 8) ++eq3[static_cast<std::size_t>(c)];
    });
    for (long e : eq3) v.eq3_quad += e;
    if (labels) {
        labels->n_faces = static_cast<int>(P[0].size.size());
        labels->face = std::move(P[0].label);
        labels->face_first = std::move(P[0].first);
        labels->n_vertices = static_cast<int>(P[1].size.size());
        labels->vertex = std::move(P[1].label);
        labels->vertex_first = std::move(P[1].first);
        labels->n_edges = static_cast<int>(P[2].size.size());
        labels->edge = std::move(P[2].label);
        labels->edge_first = std::move(P[2].first);
    }
    return v;
}
} // namespace

QuadGMapValidation validateQuadGMap(const GMap<2>& g, QuadOrbitLabels* labels, int threads) {
    return validateView(LinkView{g.links().data(), g.links().size(), &g}, labels, threads);
}

QuadGMapValidation validateQuadLinks(const QuadLinks& links, QuadOrbitLabels* labels, int threads) {
    return validateView(LinkView{links.data(), links.size(), nullptr}, labels, threads);
}

} // namespace HexEx
