#include "GMapValidator.hh"

#include "../Core/Parallel.hh"

#include <algorithm>
#include <sstream>

namespace HexEx {

namespace {

/// Labels orbits under a set of generator functions; returns orbit sizes per label.
template <class Next>
std::vector<int> labelBy(const GMap<3>& g, int n_gen, Next next, std::vector<int>& size) {
    const std::size_t n = g.n_darts();
    std::vector<int> label(n, -1);
    std::vector<int> stack;
    size.clear();
    for (std::size_t s = 0; s < n; ++s) {
        if (!g.is_alive(DartHandle(static_cast<int>(s))) || label[s] >= 0) continue;
        const int l = static_cast<int>(size.size());
        size.push_back(0);
        label[s] = l;
        stack.assign(1, static_cast<int>(s));
        while (!stack.empty()) {
            const int d = stack.back();
            stack.pop_back();
            ++size[static_cast<std::size_t>(l)];
            for (int k = 0; k < n_gen; ++k) {
                const int e = next(d, k);
                if (e < 0 || static_cast<std::size_t>(e) >= n || !g.is_alive(DartHandle(e))) continue;
                if (label[static_cast<std::size_t>(e)] < 0) {
                    label[static_cast<std::size_t>(e)] = l;
                    stack.push_back(e);
                }
            }
        }
    }
    return label;
}

/// Labels the orbits of two involutions a, b: each orbit is a path or a cycle that
/// alternates a and b, so it is walked once in each direction instead of searched.
/// Same labels as labelBy() whenever a and b are involutions.
template <class A, class B>
std::vector<int> labelAlternating(const GMap<3>& g, A fa, B fb, std::vector<int>& size) {
    const std::size_t n = g.n_darts();
    std::vector<int> label(n, -1);
    size.clear();
    auto usable = [&](int x) { return x >= 0 && static_cast<std::size_t>(x) < n && g.is_alive(DartHandle(x)); };
    for (std::size_t s = 0; s < n; ++s) {
        if (!g.is_alive(DartHandle(static_cast<int>(s))) || label[s] >= 0) continue;
        const int l = static_cast<int>(size.size());
        int count = 1;
        label[s] = l;
        for (int firstA = 1; firstA >= 0; --firstA) {  // forward starting with a, then backward with b
            int cur = static_cast<int>(s);
            bool useA = firstA != 0;
            while (true) {
                const int nx = useA ? fa(cur) : fb(cur);
                if (!usable(nx) || nx == cur || label[static_cast<std::size_t>(nx)] >= 0) break;
                label[static_cast<std::size_t>(nx)] = l;
                ++count;
                cur = nx;
                useA = !useA;
            }
        }
        size.push_back(count);
    }
    return label;
}

} // namespace

std::vector<int> labelOrbits(const GMap<3>& g, unsigned mask, int* n_labels) {
    const auto& L = g.links();
    int gens[4], ng = 0;
    for (int i = 0; i < 4; ++i)
        if (mask & (1u << i)) gens[ng++] = i;
    std::vector<int> size;
    auto label = labelBy(g, ng, [&](int d, int k) { return L[static_cast<std::size_t>(d)][gens[k]]; }, size);
    if (n_labels) *n_labels = static_cast<int>(size.size());
    return label;
}

GMapValidation validateHexGMap(const GMap<3>& g, HexOrbitLabels* labels, int threads) {
    GMapValidation v;
    const auto& L = g.links();
    const std::size_t n = g.n_darts();
    auto a = [&](int d, int i) { return L[static_cast<std::size_t>(d)][i]; };
    // Per-dart checks, in parallel chunks with per-chunk counters (deterministic sums).
    const int chunks = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(std::max(1, threads)), std::max<std::size_t>(1, n / 65536)));
    std::vector<GMapValidation> part(static_cast<std::size_t>(chunks));
    parallelChunks(n, chunks, [&](int k, std::size_t b, std::size_t e) {
        GMapValidation& w = part[static_cast<std::size_t>(k)];
        for (std::size_t s = b; s < e; ++s) {
            const int d = static_cast<int>(s);
            if (!g.is_alive(DartHandle(d))) continue;
            ++w.darts;
            bool bad = false;
            for (int i = 0; i < 4; ++i) {
                const int x = a(d, i);
                if (!g.is_alive(DartHandle(x)) || a(x, i) != d) bad = true;
            }
            if (bad) {
                ++w.not_involution;
                continue;
            }
            if (a(d, 0) == d || a(d, 1) == d || a(d, 2) == d) ++w.open_links;
            if (a(a(a(a(d, 0), 2), 0), 2) != d) ++w.eq1_edge_connection;
            if (a(d, 3) == d) {
                ++w.boundary_darts;
            } else if (a(a(a(a(d, 0), 3), 0), 3) != d || a(a(a(a(d, 1), 3), 1), 3) != d) {
                ++w.eq2_face_connection;
            }
        }
    });
    for (const auto& w : part) {
        v.darts += w.darts;
        v.not_involution += w.not_involution;
        v.open_links += w.open_links;
        v.eq1_edge_connection += w.eq1_edge_connection;
        v.boundary_darts += w.boundary_darts;
        v.eq2_face_connection += w.eq2_face_connection;
    }
    auto countBad = [&](std::vector<int>& label, std::vector<int>& size, int want) {
        long bad = 0;
        for (std::size_t s = 0; s < n; ++s)
            if (label[s] >= 0 && size[static_cast<std::size_t>(label[s])] != want) ++bad;
        return bad;
    };
    // The four orbit labelings are independent: run them side by side.
    std::vector<int> l01, l12, l0121, l012, s01, s12, s0121, size;
    parallelChunks(4, std::min(4, std::max(1, threads)), [&](int, std::size_t b, std::size_t e) {
        for (std::size_t job = b; job < e; ++job) {
            if (job == 0) l01 = labelAlternating(g, [&](int d) { return a(d, 0); }, [&](int d) { return a(d, 1); }, s01);
            if (job == 1) l12 = labelAlternating(g, [&](int d) { return a(d, 1); }, [&](int d) { return a(d, 2); }, s12);
            if (job == 2)
                l0121 = labelAlternating(g, [&](int d) { return a(d, 0); }, [&](int d) { return a(a(a(d, 1), 2), 1); }, s0121);
            if (job == 3) l012 = labelBy(g, 3, [&](int d, int k) { return a(d, k); }, size);
        }
    });
    v.eq3_quad = countBad(l01, s01, 8);
    v.eq4_corner = countBad(l12, s12, 6);
    v.eq5_strip = countBad(l0121, s0121, 8);
    v.eq6_hex = countBad(l012, size, 48);
    if (labels) {
        labels->cell = std::move(l012);
        labels->cell_size = std::move(size);
        labels->face = std::move(l01);
        labels->corner = std::move(l12);
        labels->face_size = std::move(s01);
        labels->corner_size = std::move(s12);
    }
    return v;
}

std::string GMapValidation::summary() const {
    std::ostringstream os;
    os << (valid() ? "valid" : "INVALID") << ": " << darts << " darts";
    if (not_involution) os << ", " << not_involution << " non-involutive";
    if (open_links) os << ", " << open_links << " open";
    if (eq1_edge_connection) os << ", eq1 " << eq1_edge_connection;
    if (eq2_face_connection) os << ", eq2 " << eq2_face_connection;
    if (eq3_quad) os << ", eq3 " << eq3_quad;
    if (eq4_corner) os << ", eq4 " << eq4_corner;
    if (eq5_strip) os << ", eq5 " << eq5_strip;
    if (eq6_hex) os << ", eq6 " << eq6_hex;
    return os.str();
}

} // namespace HexEx
