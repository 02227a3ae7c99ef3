#include "DartAnnihilation.hh"

#include "../Core/UnionFind.hh"

#include <algorithm>
#include <deque>
#include <utility>

namespace HexEx {

AnnihilationStats annihilateDarts(std::vector<std::array<int, 4>>& alpha, const std::vector<signed char>& sign,
                                  std::vector<char>& alive, std::vector<std::pair<int, int>>* heirs) {
    AnnihilationStats st;
    const long n = static_cast<long>(alpha.size());
    // Union-find over all darts, allocated when the first pair annihilates (maps without
    // folds pay nothing). Dense ids cost 5 bytes per dart; a hash map of the touched darts
    // cost about 35 bytes per touched dart, and on fold-heavy maps nearly every dart is touched.
    UnionFind sameVertex(0);
    std::vector<char> touched;  // per dart: joined some group
    auto idOf = [&](long d) {
        if (sameVertex.parent.empty()) {
            sameVertex = UnionFind(static_cast<std::size_t>(n));
            touched.assign(static_cast<std::size_t>(n), 0);
        }
        touched[static_cast<std::size_t>(d)] = 1;
        return static_cast<int>(d);
    };
    std::deque<long> work;
    std::vector<char> queued(static_cast<std::size_t>(n), 0);
    for (long d = 0; d < n; ++d)
        if (alive[static_cast<std::size_t>(d)] && sign[static_cast<std::size_t>(d)] < 0) {
            work.push_back(d);
            queued[static_cast<std::size_t>(d)] = 1;
        }
    auto A = [&](long d) -> std::array<int, 4>& { return alpha[static_cast<std::size_t>(d)]; };
    while (!work.empty()) {
        const long anti = work.front();
        work.pop_front();
        queued[static_cast<std::size_t>(anti)] = 0;
        if (!alive[static_cast<std::size_t>(anti)]) continue;
        long reg = -1;
        for (int i = 0; i < 4 && reg < 0; ++i) {
            const long r = A(anti)[i];
            if (r >= 0 && r != anti && alive[static_cast<std::size_t>(r)] && sign[static_cast<std::size_t>(r)] > 0) reg = r;
        }
        if (reg < 0) continue;
        if (heirs) {
            // The pair's h-vertices merge (paper 4.4.2: a pair linked by alpha_0 joins the
            // vertices of its two darts), and each dart stays with the darts around its
            // h-vertex (alpha_1..alpha_3 partners).
            sameVertex.unite(idOf(reg), idOf(anti));
            for (int j = 1; j < 4; ++j)
                for (const long self : {reg, anti}) {
                    const long x = A(self)[j];
                    if (x >= 0 && x != reg && x != anti) sameVertex.unite(idOf(self), idOf(x));
                }
        }
        for (int j = 0; j < 4; ++j) {
            const long x = A(reg)[j], y = A(anti)[j];
            if (x == anti) continue;
            // x takes y as partner and vice versa; a partner that is one of the removed pair
            // (a free link) turns into a free link of the survivor.
            const bool xs = x >= 0 && x != reg, ys = y >= 0 && y != anti;
            if (xs) A(x)[j] = static_cast<int>(ys ? y : (y < 0 ? -1 : x));
            if (ys) A(y)[j] = static_cast<int>(xs ? x : (x < 0 ? -1 : y));
        }
        alive[static_cast<std::size_t>(reg)] = alive[static_cast<std::size_t>(anti)] = 0;
        ++st.pairs;
        // The neighbours may now be regular/anti pairs themselves.
        for (int j = 0; j < 4; ++j)
            for (long nb : {A(reg)[j], A(anti)[j]}) {
                if (nb < 0 || !alive[static_cast<std::size_t>(nb)]) continue;
                for (int k = 0; k < 4; ++k) {
                    const long m = A(nb)[k];
                    const long cand = sign[static_cast<std::size_t>(nb)] < 0 ? nb : m;
                    if (cand >= 0 && alive[static_cast<std::size_t>(cand)] && sign[static_cast<std::size_t>(cand)] < 0 &&
                        !queued[static_cast<std::size_t>(cand)]) {
                        work.push_back(cand);
                        queued[static_cast<std::size_t>(cand)] = 1;
                    }
                }
            }
    }
    for (long d = 0; d < n; ++d)
        if (alive[static_cast<std::size_t>(d)] && sign[static_cast<std::size_t>(d)] < 0) ++st.remaining_anti;
    if (heirs) {
        // Smallest surviving dart per group, then (removed dart, heir) in dart order.
        heirs->clear();
        std::vector<int> heirOf(touched.size(), -1);  // per root
        for (std::size_t d = 0; d < touched.size(); ++d) {
            if (!touched[d] || !alive[d]) continue;
            int& h = heirOf[static_cast<std::size_t>(sameVertex.find(static_cast<int>(d)))];
            if (h < 0) h = static_cast<int>(d);  // darts ascend: the first is the smallest
        }
        std::size_t removed = 0;
        for (std::size_t d = 0; d < touched.size(); ++d) removed += (touched[d] && !alive[d]) ? 1 : 0;
        heirs->reserve(removed);  // exact: a grown vector may hold twice what it needs
        for (std::size_t d = 0; d < touched.size(); ++d) {
            if (!touched[d] || alive[d]) continue;
            const int h = heirOf[static_cast<std::size_t>(sameVertex.find(static_cast<int>(d)))];
            if (h >= 0) heirs->emplace_back(static_cast<int>(d), h);
        }
        std::sort(heirs->begin(), heirs->end());
    }
    return st;
}

} // namespace HexEx
