#include "FaceRelinking.hh"

#include "../GMap/GMapValidator.hh"

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <vector>

namespace HexEx {

namespace {

/// The sorted four vertices of quad @p fd under @p label, or false if it has not four.
bool quadKey(const std::vector<int>& label, const std::vector<DartHandle>& fd, std::array<int, 4>& key) {
    int m = 0;
    for (const DartHandle x : fd) {
        const int v = label[x.uidx()];
        if (std::find(key.begin(), key.begin() + m, v) != key.begin() + m) continue;
        if (m == 4) return false;
        key[static_cast<std::size_t>(m++)] = v;
    }
    std::sort(key.begin(), key.end());
    return m == 4 && fd.size() == 8;
}

/// The keys (quadKey()) of the quads @p left of @p faceDarts under the vertex labels
/// @p vertex into @p keys, and their vertices marked in @p wanted (one entry per label, all
/// zero on entry); false if no quad of @p left has four vertices.
bool leftQuadKeys(const std::vector<int>& vertex, const std::vector<std::vector<DartHandle>>& faceDarts,
                  const std::vector<std::size_t>& left, std::set<std::array<int, 4>>& keys, std::vector<char>& wanted) {
    for (const std::size_t k : left) {
        std::array<int, 4> key{};
        if (!quadKey(vertex, faceDarts[k], key)) continue;
        keys.insert(key);
        for (const int v : key) wanted[static_cast<std::size_t>(v)] = 1;
    }
    return !keys.empty();
}

/// True if every alpha_i link (bit i of @p mask) of an alive dart is free or leads to an
/// alive dart that links back. Then what a search along those links reaches from a dart
/// (GMap::orbit(), or labelOrbits()'s search) is its whole orbit, the same from every dart
/// of the orbit, and labelOrbits(g, mask) gives two darts the same label exactly when a
/// search from one reaches the other. GMap::sew() and GMap::unsew(), the only changes of
/// the relinking, keep this true.
bool linksReturn(const GMap<3>& g, unsigned mask) {
    const auto& L = g.links();
    const std::size_t n = g.n_darts();
    for (std::size_t d = 0; d < n; ++d) {
        if (!g.is_alive(DartHandle(static_cast<int>(d)))) continue;
        for (int i = 0; i < 4; ++i) {
            if (!(mask >> i & 1)) continue;
            const int e = L[d][static_cast<std::size_t>(i)];
            if (e == static_cast<int>(d)) continue;
            if (e < 0 || static_cast<std::size_t>(e) >= n || !g.is_alive(DartHandle(e)) ||
                L[static_cast<std::size_t>(e)][static_cast<std::size_t>(i)] != static_cast<int>(d))
                return false;
        }
    }
    return true;
}

/// Vertex labels (<alpha_1, alpha_2, alpha_3> orbits) for the quads @p quads of @p faceDarts:
/// labelOrbits(g, 0b1110) unless @p returning (every link returns, linksReturn()); then only
/// the orbits of those quads' darts are searched (-1 for every other dart). The quads are
/// then paired by the same equalities of labels (a pairing uses nothing else of the values:
/// pairs of quads with equal keys are sewn independently of each other, in any order), at the
/// cost of the few vertices around the quads instead of a pass over the whole map.
std::vector<int> quadVertexLabels(const GMap<3>& g, const std::vector<std::vector<DartHandle>>& faceDarts,
                                  const std::vector<std::size_t>& quads, bool returning) {
    if (!returning) return labelOrbits(g, 0b1110);
    const auto& L = g.links();
    const std::size_t n = g.n_darts();
    std::vector<int> label(n, -1);
    std::vector<int> stack;
    int next = 0;
    for (const std::size_t k : quads)
        for (const DartHandle x : faceDarts[k]) {
            if (!g.is_alive(x) || label[x.uidx()] >= 0) continue;
            const int l = next++;
            label[x.uidx()] = l;
            stack.assign(1, x.idx());
            while (!stack.empty()) {
                const int d = stack.back();
                stack.pop_back();
                for (int i = 1; i < 4; ++i) {
                    const int e = L[static_cast<std::size_t>(d)][static_cast<std::size_t>(i)];
                    if (e < 0 || static_cast<std::size_t>(e) >= n || !g.is_alive(DartHandle(e)) || label[static_cast<std::size_t>(e)] >= 0) continue;
                    label[static_cast<std::size_t>(e)] = l;
                    stack.push_back(e);
                }
            }
        }
    return label;
}

/// In dart order, every alive dart d with an alpha_3 link that @p skip(d) lets through and
/// whose quad (<alpha_0, alpha_1> orbit) has one of @p keys under @p vertex (quadKey()):
/// calls @p take on d and on the dart it is linked to (the quad it was linked to).
template <class Skip, class Take>
void takeKeyedQuads(GMap<3>& g, const std::vector<int>& vertex, const std::set<std::array<int, 4>>& keys, const Skip& skip,
                    const Take& take) {
    const std::size_t n = g.n_darts();
    for (std::size_t d = 0; d < n; ++d) {
        const DartHandle x(static_cast<int>(d));
        if (!g.is_alive(x) || g.is_free(x, 3) || skip(d)) continue;
        std::array<int, 4> key{};
        const std::vector<DartHandle> fd = g.orbit(x, 0b0011);
        if (quadKey(vertex, fd, key) && keys.count(key)) {
            take(x);
            take(g.alpha(x, 3));
        }
    }
}

/// relinkMergedQuads() with the labels of the whole map: appends the sewn quads with the same
/// four vertices as a quad of @p left, and the quads they are linked to, to @p faceDarts;
/// false if there is none.
bool findMergedQuads(GMap<3>& g, std::vector<std::vector<DartHandle>>& faceDarts, const std::vector<std::size_t>& left) {
    int nVertices = 0, nFaces = 0;
    const std::vector<int> vertex = labelOrbits(g, 0b1110, &nVertices);
    std::set<std::array<int, 4>> keys;
    std::vector<char> wanted(static_cast<std::size_t>(nVertices), 0);
    if (!leftQuadKeys(vertex, faceDarts, left, keys, wanted)) return false;
    const std::vector<int> face = labelOrbits(g, 0b0011, &nFaces);
    std::vector<char> seen(static_cast<std::size_t>(nFaces), 0);
    for (const auto& fd : faceDarts) seen[static_cast<std::size_t>(face[fd[0].uidx()])] = 1;
    const std::size_t firstNew = faceDarts.size();
    auto take = [&](DartHandle d) {
        if (seen[static_cast<std::size_t>(face[d.uidx()])]) return;
        seen[static_cast<std::size_t>(face[d.uidx()])] = 1;
        faceDarts.push_back(g.orbit(d, 0b0011));
    };
    takeKeyedQuads(g, vertex, keys,
                   [&](std::size_t d) { return !wanted[static_cast<std::size_t>(vertex[d])] || seen[static_cast<std::size_t>(face[d])]; },
                   take);
    return faceDarts.size() > firstNew;
}

/// findMergedQuads() where every link returns (linksReturn()): the same quads in the same
/// order, with the orbits searched only around the quads of @p left. The vertices of their
/// keys are whole orbits found from their darts; a quad with a dart elsewhere has a vertex
/// that is in no key under either labelling, and a quad is "seen" by marks on its darts
/// (its <alpha_0, alpha_1> orbit) instead of a face label.
bool findMergedQuadsNear(GMap<3>& g, std::vector<std::vector<DartHandle>>& faceDarts, const std::vector<std::size_t>& left) {
    const std::vector<int> vertex = quadVertexLabels(g, faceDarts, left, true);
    std::set<std::array<int, 4>> keys;
    int nLabels = 0;
    for (const int v : vertex) nLabels = std::max(nLabels, v + 1);
    std::vector<char> wanted(static_cast<std::size_t>(nLabels), 0);
    if (!leftQuadKeys(vertex, faceDarts, left, keys, wanted)) return false;
    const std::size_t n = g.n_darts();
    std::vector<char> seen(n, 0);
    for (const auto& fd : faceDarts)
        for (const DartHandle x : g.orbit(fd[0], 0b0011)) seen[x.uidx()] = 1;
    const std::size_t firstNew = faceDarts.size();
    auto take = [&](DartHandle d) {
        if (seen[d.uidx()]) return;
        faceDarts.push_back(g.orbit(d, 0b0011));
        for (const DartHandle x : faceDarts.back()) seen[x.uidx()] = 1;
    };
    takeKeyedQuads(g, vertex, keys,
                   [&](std::size_t d) { return vertex[d] < 0 || !wanted[static_cast<std::size_t>(vertex[d])] || seen[d]; },
                   take);
    return faceDarts.size() > firstNew;
}

/// The end of relinkMergedQuads(): cuts the quads from @p firstNew on and pairs them with
/// those of @p left again; kept only if every one finds its partner, else every link is put back.
template <class SewByVertices>
void cutAndPairAgain(GMap<3>& g, std::vector<std::vector<DartHandle>>& faceDarts, const std::vector<std::size_t>& left,
                     std::size_t firstNew, bool returning, const SewByVertices& sewByVertices, FaceRelinkStats& st) {
    // Cut them, remembering the links.
    std::vector<std::pair<DartHandle, DartHandle>> saved;
    for (std::size_t k = firstNew; k < faceDarts.size(); ++k)
        for (const DartHandle x : faceDarts[k]) saved.emplace_back(x, g.alpha(x, 3));
    for (std::size_t k = firstNew; k < faceDarts.size(); ++k)
        for (const DartHandle x : faceDarts[k]) g.unsew(x, 3);
    std::vector<std::size_t> pool = left;
    for (std::size_t k = firstNew; k < faceDarts.size(); ++k) pool.push_back(k);
    const long relinkedBefore = st.relinked_faces;
    const std::vector<std::size_t> open = sewByVertices(quadVertexLabels(g, faceDarts, pool, returning), pool);
    if (open.empty()) {
        st.inconsistent_faces += static_cast<long>(faceDarts.size() - firstNew);
        return;
    }
    for (const std::size_t k : pool)
        for (const DartHandle x : faceDarts[k]) g.unsew(x, 3);
    for (const auto& [x, y] : saved)
        if (x != y) g.sew(x, y, 3);
    st.relinked_faces = relinkedBefore;
}

/// Last pass for the cut quads @p left that found no partner (pig folded by 1.5, seed 21: a
/// cell glued to itself by two of its own quads, whose four vertices stay one set because
/// two quads of other cells, linked to each other, cross the same way and pass equation 2):
/// the sewn quads with the same four vertices as a left quad are cut too, with the quads
/// they were linked to, and all of them are paired once more by the vertices of the map as
/// it is then. Kept only if every one of them finds its partner; otherwise every link is
/// put back. @p returning: every link returns (linksReturn()).
template <class SewByVertices>
void relinkMergedQuads(GMap<3>& g, std::vector<std::vector<DartHandle>>& faceDarts, const std::vector<std::size_t>& left,
                       bool returning, const SewByVertices& sewByVertices, FaceRelinkStats& st) {
    const std::size_t firstNew = faceDarts.size();
    if (!(returning ? findMergedQuadsNear(g, faceDarts, left) : findMergedQuads(g, faceDarts, left))) return;
    cutAndPairAgain(g, faceDarts, left, firstNew, returning, sewByVertices, st);
}

} // namespace

FaceRelinkStats relinkInconsistentFaces(GMap<3>& g) {
    FaceRelinkStats st;
    const std::size_t n = g.n_darts();
    const auto& L = g.links();
    auto a = [&](int d, int i) { return L[static_cast<std::size_t>(d)][i]; };
    auto alive = [&](int d) { return d >= 0 && static_cast<std::size_t>(d) < n && g.is_alive(DartHandle(d)); };
    int nCells = 0;
    const std::vector<int> cell = labelOrbits(g, 0b0111, &nCells);
    auto inconsistent = [&](int d) {
        const int e = a(d, 3);
        if (e == d) return false;
        if (!alive(e) || a(e, 3) != d || cell[static_cast<std::size_t>(e)] == cell[static_cast<std::size_t>(d)]) return true;
        for (int i = 0; i < 2; ++i) {
            const int x = a(d, i), y = a(e, i);
            if (!alive(x) || !alive(y) || a(x, 3) != y) return true;
        }
        return false;
    };
    // Quads to cut: those with an inconsistent dart, closed under "was linked to".
    std::vector<char> inCut(n, 0);
    std::vector<int> cutFaces;  // first dart of every cut quad
    std::vector<int> stack;
    auto addFace = [&](int d) {
        if (inCut[static_cast<std::size_t>(d)]) return;
        cutFaces.push_back(d);
        for (const DartHandle x : g.orbit(DartHandle(d), 0b0011)) {
            inCut[x.uidx()] = 1;
            stack.push_back(x.idx());
        }
    };
    for (std::size_t s = 0; s < n; ++s) {
        const int d = static_cast<int>(s);
        if (!g.is_alive(DartHandle(d)) || inCut[s] || !inconsistent(d)) continue;
        addFace(d);
        while (!stack.empty()) {
            const int x = stack.back();
            stack.pop_back();
            const int y = a(x, 3);
            if (y != x && alive(y)) addFace(y);
        }
    }
    if (cutFaces.empty()) return st;
    std::sort(cutFaces.begin(), cutFaces.end());
    st.inconsistent_faces = static_cast<long>(cutFaces.size());
    // The vertices are taken with the inconsistent links: they join darts at one vertex
    // (the links cross quads, not vertices), and without them a vertex can fall apart.
    // (The quads' <alpha_0, alpha_1> orbits do not depend on alpha_3: all are found first.)
    std::vector<std::vector<DartHandle>> faceDarts;
    faceDarts.reserve(cutFaces.size());
    for (const int f : cutFaces) faceDarts.push_back(g.orbit(DartHandle(f), 0b0011));
    std::vector<std::size_t> all(faceDarts.size());
    for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
    // Whether every link returns is checked once: only sew() and unsew() change links from here on.
    const bool returning = linksReturn(g, 0b1111);
    const std::vector<int> vertex = quadVertexLabels(g, faceDarts, all, returning);
    for (const auto& fd : faceDarts)
        for (const DartHandle x : fd) g.unsew(x, 3);
    // Quads by their four vertices (sorted); only quads of 8 darts with 4 distinct vertices.
    // Returns the quads left without a partner.
    auto sewByVertices = [&](const std::vector<int>& label, const std::vector<std::size_t>& quads) {
        std::map<std::array<int, 4>, std::vector<std::size_t>> byVertices;
        std::vector<char> sewn(faceDarts.size(), 0);
        for (const std::size_t k : quads) {
            const auto& fd = faceDarts[k];
            if (fd.size() != 8) continue;
            std::array<int, 4> key{};
            int m = 0;
            bool ok = true;
            for (const DartHandle x : fd) {
                const int v = label[x.uidx()];
                if (std::find(key.begin(), key.begin() + m, v) != key.begin() + m) continue;
                if (m == 4) { ok = false; break; }
                key[static_cast<std::size_t>(m++)] = v;
            }
            if (!ok || m != 4) continue;
            std::sort(key.begin(), key.end());
            byVertices[key].push_back(k);
        }
        for (const auto& [key, faces] : byVertices) {
            if (faces.size() != 2) continue;
            const auto& F = faceDarts[faces[0]];
            const auto& G = faceDarts[faces[1]];
            if (cell[F[0].uidx()] == cell[G[0].uidx()]) continue;
            // Dart x of F goes to the dart of G at the same vertex on the same edge.
            std::vector<std::pair<DartHandle, DartHandle>> pairs;
            for (const DartHandle x : F) {
                const int v = label[x.uidx()], w = label[static_cast<std::size_t>(a(x.idx(), 0))];
                for (const DartHandle y : G)
                    if (label[y.uidx()] == v && label[static_cast<std::size_t>(a(y.idx(), 0))] == w) pairs.emplace_back(x, y);
            }
            if (pairs.size() != 8) continue;
            for (const auto& [x, y] : pairs) g.sew(x, y, 3);
            sewn[faces[0]] = sewn[faces[1]] = 1;
            st.relinked_faces += 2;
        }
        std::vector<std::size_t> left;
        for (const std::size_t k : quads)
            if (!sewn[k]) left.push_back(k);
        return left;
    };
    const std::vector<std::size_t> left = sewByVertices(vertex, all);
    // Quads the crossed links left without a partner (their vertex labels, taken with those
    // links, merged two vertices, so several cut quads share one key): once more with the
    // vertices of the map as it is now (cut quads open, the others sewn), among those only.
    const std::vector<std::size_t> left2 = left.empty() ? left : sewByVertices(quadVertexLabels(g, faceDarts, left, returning), left);
    if (!left2.empty()) relinkMergedQuads(g, faceDarts, left2, returning, sewByVertices, st);
    return st;
}

} // namespace HexEx
