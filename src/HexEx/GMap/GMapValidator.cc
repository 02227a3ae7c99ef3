#include "GMapValidator.hh"

#include "../Core/Parallel.hh"
#include "../Core/UnionFind.hh"

#include <algorithm>
#include <functional>
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


/// Walks the orbit of @p s under two involutions a, b (a path or a cycle alternating them),
/// once from s starting with a, then starting with b; calls visit(x) on every dart not yet
/// seen (s is marked by the caller); seen(x) tells whether x was visited. Returns the orbit size.
template <class A, class B, class Seen, class Visit>
int walkAlternating(int s, A fa, B fb, Seen seen, Visit visit) {
    int count = 1;
    for (int firstA = 1; firstA >= 0; --firstA) {
        int cur = s;
        bool useA = firstA != 0;
        while (true) {
            const int nx = useA ? fa(cur) : fb(cur);
            if (nx == cur || seen(nx)) break;
            visit(nx);
            ++count;
            cur = nx;
            useA = !useA;
        }
    }
    return count;
}

/// Orbit labelling for maps whose darts are all alive and whose links are all involutions,
/// in one pass over the cells (<alpha_0, alpha_1, alpha_2> orbits): each cell is found by a
/// breadth-first search from its smallest dart (cells numbered in dart order, each cell's
/// darts in search order), and while its darts are in the cache its strip and face orbits
/// (they never leave the cell) are walked, faces numbered cell after cell (the corners are
/// labelled apart, labelCorners()). Terminates on any map whose links are dart indices (every walk stops at a marked
/// dart), so it may run before the involution checks are known; its labels are used only
/// if they find an involutive map with every dart alive.
struct CellLabels {
    GMapValidation counts;     ///< equation 3-6 counts
    std::vector<int> cell;     ///< per dart: its cell
    std::vector<int> size;     ///< per cell: number of darts
    std::vector<int> darts;    ///< the darts, cell after cell
    std::vector<int> off;      ///< cell c holds darts[off[c] .. off[c + 1])
    std::vector<int> face;     ///< per dart: its face orbit
    std::vector<int> fsize;    ///< per face orbit: number of darts
};

CellLabels labelCells(const GMap<3>& g) {
    const auto& L = g.links();
    const std::size_t n = L.size();
    CellLabels cs;
    cs.cell.assign(n, -1);
    cs.face.assign(n, -1);
    cs.darts.reserve(n);
    // Exact sizes for a hex map (48 darts per cell, 8 per face, 6 per corner): no growth
    // beyond them, which would keep up to twice the memory through the assembly.
    cs.size.reserve(n / 48 + 1);
    cs.off.reserve(n / 48 + 2);
    cs.fsize.reserve(n / 8 + 1);
    cs.off.push_back(0);
    auto a = [&](int d, int i) { return L[static_cast<std::size_t>(d)][i]; };
    auto a121 = [&](int d) { return a(a(a(d, 1), 2), 1); };
    std::vector<int>& face = cs.face;
    // face[] doubles as the visited mark of the strip walks (-2) before faces are labelled.
    constexpr int kStripSeen = -2;
    GMapValidation& v = cs.counts;
    for (std::size_t s = 0; s < n; ++s) {
        if (cs.cell[s] >= 0) continue;
        const int c = static_cast<int>(cs.size.size());
        const std::size_t first = cs.darts.size();
        cs.cell[s] = c;
        cs.darts.push_back(static_cast<int>(s));
        for (std::size_t q = first; q < cs.darts.size(); ++q) {
            const auto& r = L[static_cast<std::size_t>(cs.darts[q])];
            for (int i = 0; i < 3; ++i) {
                int& l = cs.cell[static_cast<std::size_t>(r[i])];
                if (l < 0) {
                    l = c;
                    __builtin_prefetch(&L[static_cast<std::size_t>(r[i])]);
                    cs.darts.push_back(r[i]);
                }
            }
        }
        const int size = static_cast<int>(cs.darts.size() - first);
        cs.size.push_back(size);
        cs.off.push_back(static_cast<int>(cs.darts.size()));
        const int* const begin = cs.darts.data() + first;
        const int* const end = cs.darts.data() + cs.darts.size();
        if (size != 48) v.eq6_hex += size;
        for (const int* x = begin; x != end; ++x) {
            if (face[static_cast<std::size_t>(*x)] != -1) continue;
            face[static_cast<std::size_t>(*x)] = kStripSeen;
            const int m = walkAlternating(
                *x, [&](int d) { return a(d, 0); }, a121, [&](int d) { return face[static_cast<std::size_t>(d)] == kStripSeen; },
                [&](int d) { face[static_cast<std::size_t>(d)] = kStripSeen; });
            if (m != 8) v.eq5_strip += m;
        }
        for (const int* x = begin; x != end; ++x) {
            if (face[static_cast<std::size_t>(*x)] >= 0) continue;
            const int f = static_cast<int>(cs.fsize.size());
            face[static_cast<std::size_t>(*x)] = f;
            const int m = walkAlternating(
                *x, [&](int d) { return a(d, 0); }, [&](int d) { return a(d, 1); },
                [&](int d) { return face[static_cast<std::size_t>(d)] >= 0; }, [&](int d) { face[static_cast<std::size_t>(d)] = f; });
            cs.fsize.push_back(m);
            if (m != 8) v.eq3_quad += m;
        }
    }
    return cs;
}

/// Corner orbits (<alpha_1, alpha_2>) of a map whose links are all involutions, numbered in
/// order of their smallest dart, with the equation 4 count.
struct CornerLabels {
    std::vector<int> corner;  ///< per dart: its corner orbit
    std::vector<int> size;    ///< per corner orbit: number of darts
    long eq4_corner = 0;      ///< darts of corner orbits without 6 darts
};

/// Labels the corners of @p g in one pass in dart order (the same labels as the per-dart
/// checks give in one chunk, validateHexGMap()).
CornerLabels labelCorners(const GMap<3>& g) {
    const auto& L = g.links();
    CornerLabels k;
    k.size.reserve(L.size() / 6 + 1);  // exact for a hex map: no growth beyond it
    k.corner = labelAlternating(
        g, [&](int d) { return L[static_cast<std::size_t>(d)][1]; }, [&](int d) { return L[static_cast<std::size_t>(d)][2]; }, k.size);
    for (const int m : k.size)
        if (m != 6) k.eq4_corner += m;
    return k;
}

/// Takes the labels of @p cs and @p ks into @p out (if given) and their equation 3-6 counts into @p v.
void useCellLabels(CellLabels&& cs, CornerLabels&& ks, GMapValidation& v, HexOrbitLabels* out) {
    v.eq3_quad += cs.counts.eq3_quad;
    v.eq4_corner += ks.eq4_corner;
    v.eq5_strip += cs.counts.eq5_strip;
    v.eq6_hex += cs.counts.eq6_hex;
    if (!out) return;
    out->cell = std::move(cs.cell);
    out->cell_size = std::move(cs.size);
    out->face = std::move(cs.face);
    out->face_size = std::move(cs.fsize);
    out->corner = std::move(ks.corner);
    out->corner_size = std::move(ks.size);
    out->cell_darts = std::move(cs.darts);
    out->cell_offset = std::move(cs.off);
}


/// Size of the orbit of @p s under the involutions @p gens (at most @p cap darts are visited).
template <class Gen>
int orbitSize(int s, const std::vector<Gen>& gens, int cap) {
    std::vector<int> seen{s}, stack{s};
    while (!stack.empty() && static_cast<int>(seen.size()) < cap) {
        const int d = stack.back();
        stack.pop_back();
        for (const auto& f : gens) {
            const int x = f(d);
            if (std::find(seen.begin(), seen.end(), x) == seen.end()) {
                seen.push_back(x);
                stack.push_back(x);
            }
        }
    }
    return static_cast<int>(seen.size());
}

/// Fills v.examples: the first darts (ascending) that fail each check counted in @p v.
void collectExamples(const GMap<3>& g, GMapValidation& v) {
    const auto& L = g.links();
    const std::size_t n = g.n_darts();
    auto a = [&](int d, int i) { return L[static_cast<std::size_t>(d)][i]; };
    using Gen = std::function<int(int)>;
    const std::vector<Gen> quad = {[&](int d) { return a(d, 0); }, [&](int d) { return a(d, 1); }};
    const std::vector<Gen> corner = {[&](int d) { return a(d, 1); }, [&](int d) { return a(d, 2); }};
    const std::vector<Gen> strip = {[&](int d) { return a(d, 0); }, [&](int d) { return a(a(a(d, 1), 2), 1); }};
    const std::vector<Gen> cell = {[&](int d) { return a(d, 0); }, [&](int d) { return a(d, 1); },
                                   [&](int d) { return a(d, 2); }};
    const char* names[8] = {"not_involution", "open_link", "eq1", "eq2", "eq3", "eq4", "eq5", "eq6"};
    const long counts[8] = {v.not_involution, v.open_links, v.eq1_edge_connection, v.eq2_face_connection,
                            v.eq3_quad, v.eq4_corner, v.eq5_strip, v.eq6_hex};
    std::vector<std::vector<int>> found(8);
    auto need = [&](int k) { return counts[k] > 0 && static_cast<int>(found[k].size()) < GMapValidation::kExamplesPerCheck; };
    for (std::size_t s = 0; s < n; ++s) {
        bool any = false;
        for (int k = 0; k < 8; ++k) any = any || need(k);
        if (!any) break;
        const int d = static_cast<int>(s);
        if (!g.is_alive(DartHandle(d))) continue;
        bool inv = true;
        for (int i = 0; i < 4; ++i) {
            const int x = a(d, i);
            if (!g.is_alive(DartHandle(x)) || a(x, i) != d) inv = false;
        }
        if (!inv) {
            if (need(0)) found[0].push_back(d);
            continue;  // the other checks assume involutions
        }
        if (need(1) && (a(d, 0) == d || a(d, 1) == d || a(d, 2) == d)) found[1].push_back(d);
        if (need(2) && a(a(a(a(d, 0), 2), 0), 2) != d) found[2].push_back(d);
        if (need(3) && a(d, 3) != d && (a(a(a(a(d, 0), 3), 0), 3) != d || a(a(a(a(d, 1), 3), 1), 3) != d))
            found[3].push_back(d);
        if (need(4) && orbitSize(d, quad, 64) != 8) found[4].push_back(d);
        if (need(5) && orbitSize(d, corner, 64) != 6) found[5].push_back(d);
        if (need(6) && orbitSize(d, strip, 64) != 8) found[6].push_back(d);
        if (need(7) && orbitSize(d, cell, 256) != 48) found[7].push_back(d);
    }
    v.examples.clear();
    for (int k = 0; k < 8; ++k)
        for (int d : found[k]) {
            GMapViolation e;
            e.check = names[k];
            e.dart = d;
            v.examples.push_back(e);
        }
}

} // namespace

std::vector<int> labelVertexOrbits(const GMap<3>& g, const HexOrbitLabels& labels, int* n_labels) {
    if (labels.cell_offset.empty()) return labelOrbits(g, 0b1110, n_labels);
    const auto& L = g.links();
    const std::size_t n = L.size();
    const std::vector<int>& corner = labels.corner;
    UnionFind uf(labels.corner_size.size());
    for (std::size_t d = 0; d < n; ++d) uf.unite(corner[d], corner[static_cast<std::size_t>(L[d][3])]);
    // Number the classes by first appearance in dart order: by their smallest dart.
    std::vector<int> rootLabel(labels.corner_size.size(), -1);
    std::vector<int> label(n);
    int nv = 0;
    for (std::size_t d = 0; d < n; ++d) {
        int& l = rootLabel[static_cast<std::size_t>(uf.find(corner[d]))];
        if (l < 0) l = nv++;
        label[d] = l;
    }
    if (n_labels) *n_labels = nv;
    return label;
}

long countQuadOrbits(const GMap<3>& g, const HexOrbitLabels& labels, long* boundary) {
    const auto& L = g.links();
    const std::size_t n = L.size();
    std::vector<int> qlabel;
    std::vector<char> bq;
    long nq = 0;
    if (labels.cell_offset.empty()) {
        int m = 0;
        qlabel = labelOrbits(g, 0b1011, &m);
        nq = m;
        bq.assign(static_cast<std::size_t>(m), 0);
        for (std::size_t d = 0; d < n; ++d)
            if (qlabel[d] >= 0 && L[d][3] == static_cast<int>(d)) bq[static_cast<std::size_t>(qlabel[d])] = 1;
    } else {
        const std::vector<int>& face = labels.face;
        const std::size_t nf = labels.face_size.size();
        UnionFind uf(nf);
        for (std::size_t d = 0; d < n; ++d) uf.unite(face[d], face[static_cast<std::size_t>(L[d][3])]);
        bq.assign(nf, 0);
        for (std::size_t d = 0; d < n; ++d)
            if (L[d][3] == static_cast<int>(d)) bq[static_cast<std::size_t>(uf.find(face[d]))] = 1;
        for (std::size_t f = 0; f < nf; ++f)
            if (uf.find(static_cast<int>(f)) == static_cast<int>(f)) ++nq;
    }
    if (boundary) *boundary = std::count(bq.begin(), bq.end(), 1);
    return nq;
}

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

GMapValidation validateHexGMap(const GMap<3>& g, HexOrbitLabels* labels, int threads, const std::function<void(int)>& beside) {
    GMapValidation v;
    const auto& L = g.links();
    const std::size_t n = g.n_darts();
    auto a = [&](int d, int i) { return L[static_cast<std::size_t>(d)][i]; };
    // Per-dart checks, in parallel chunks with per-chunk counters (deterministic sums).
    // With two or more threads the cell search and labelling (labelCells(), sequential)
    // runs on one of them while the others do the per-dart checks and then label the corners;
    // both are used only if the checks find an involutive map with every dart alive.
    const bool overlap = threads >= 2 && n >= 65536;
    CellLabels cells;
    CornerLabels corners;
    const int checkThreads = overlap ? threads - 1 : std::max(1, threads);
    const int chunks = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(checkThreads), std::max<std::size_t>(1, n / 65536)));
    std::vector<GMapValidation> part(static_cast<std::size_t>(chunks));
    // In one chunk the checks also label the corners, in dart order as labelCorners() (a
    // corner's darts are at one grid point and were just read by the involution test); the
    // labels are used only on an involutive map with every dart alive.
    const bool cornersInChecks = chunks == 1;
    if (cornersInChecks) {
        corners.corner.assign(n, -1);
        corners.size.reserve(n / 6 + 1);
    }
    auto checks = [&](int k, std::size_t b, std::size_t e) {
        GMapValidation& w = part[static_cast<std::size_t>(k)];
        std::vector<int>& corner = corners.corner;
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
            if (cornersInChecks && corner[s] < 0) {
                const int c = static_cast<int>(corners.size.size());
                corner[s] = c;
                const int m = walkAlternating(
                    d, [&](int x) { return a(x, 1); }, [&](int x) { return a(x, 2); },
                    [&](int x) { return corner[static_cast<std::size_t>(x)] >= 0; }, [&](int x) { corner[static_cast<std::size_t>(x)] = c; });
                corners.size.push_back(m);
                if (m != 6) corners.eq4_corner += m;
            }
        }
    };
    // Every dart alive and every link an involution: the per-cell labels are used.
    auto involutive = [&]() {
        long alive = 0, notInvolution = 0;
        for (const auto& w : part) {
            alive += w.darts;
            notInvolution += w.not_involution;
        }
        return notInvolution == 0 && alive == static_cast<long>(n);
    };
    if (overlap) {
        parallelChunks(2, 2, [&](int job, std::size_t, std::size_t) {
            if (job == 0) {
                cells = labelCells(g);
            } else {
                parallelChunks(n, chunks, checks);
                if (!cornersInChecks && involutive()) corners = labelCorners(g);
                if (beside) beside(checkThreads);
            }
        });
    } else {
        parallelChunks(n, chunks, checks);
    }
    // Without the overlap the work beside runs first, on every thread (its result does not
    // depend on the thread count), as if it were before the validation.
    if (!overlap && beside) beside(std::max(1, threads));
    for (const auto& w : part) {
        v.darts += w.darts;
        v.not_involution += w.not_involution;
        v.open_links += w.open_links;
        v.eq1_edge_connection += w.eq1_edge_connection;
        v.boundary_darts += w.boundary_darts;
        v.eq2_face_connection += w.eq2_face_connection;
    }
    if (v.not_involution == 0 && v.darts == static_cast<long>(n)) {
        if (!overlap) cells = labelCells(g);
        if (!overlap && !cornersInChecks) corners = labelCorners(g);
        useCellLabels(std::move(cells), std::move(corners), v, labels);
        if (!v.valid()) collectExamples(g, v);
        return v;
    }
    // Not used: freed before the general labelling.
    cells = CellLabels{};
    corners = CornerLabels{};
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
    if (!v.valid()) collectExamples(g, v);
    return v;
}

void describeViolations(const GMap<3>& g, const std::vector<int>& vertex_label, GMapValidation& v) {
    const auto& L = g.links();
    for (GMapViolation& e : v.examples) {
        e.face_vertices.clear();
        if (e.dart < 0 || static_cast<std::size_t>(e.dart) >= L.size()) continue;
        int d = e.dart;
        for (int step = 0; step < 16; ++step) {
            const int vl = static_cast<std::size_t>(d) < vertex_label.size() ? vertex_label[static_cast<std::size_t>(d)] : -1;
            if (step % 2 == 0 && (e.face_vertices.empty() || e.face_vertices.back() != vl)) e.face_vertices.push_back(vl);
            const int nx = L[static_cast<std::size_t>(d)][step % 2];
            if (nx < 0 || static_cast<std::size_t>(nx) >= L.size() || nx == d) break;
            d = nx;
            if (d == e.dart) break;
        }
        if (e.face_vertices.size() > 1 && e.face_vertices.front() == e.face_vertices.back()) e.face_vertices.pop_back();
    }
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
