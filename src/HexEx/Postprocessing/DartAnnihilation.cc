#include "DartAnnihilation.hh"

#include "../Core/UnionFind.hh"

#include <deque>

namespace HexEx {

AnnihilationStats annihilateDarts(std::vector<std::array<int, 4>>& alpha, const std::vector<signed char>& sign,
                                  std::vector<char>& alive, std::vector<int>* heir) {
    AnnihilationStats st;
    const long n = static_cast<long>(alpha.size());
    UnionFind sameVertex(heir ? alpha.size() : 0);
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
        if (heir) {
            // The pair's h-vertices merge (paper 4.4.2: a pair linked by alpha_0 joins the
            // vertices of its two darts), and each dart stays with the darts around its
            // h-vertex (alpha_1..alpha_3 partners).
            sameVertex.unite(static_cast<int>(reg), static_cast<int>(anti));
            for (int j = 1; j < 4; ++j)
                for (const long self : {reg, anti}) {
                    const long x = A(self)[j];
                    if (x >= 0 && x != reg && x != anti) sameVertex.unite(static_cast<int>(self), static_cast<int>(x));
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
    if (heir) {
        // Smallest surviving dart per group (darts ascending: the first one seen).
        heir->assign(alpha.size(), -1);
        std::vector<int> first(alpha.size(), -1);
        for (long d = 0; d < n; ++d) {
            if (!alive[static_cast<std::size_t>(d)]) continue;
            const auto r = static_cast<std::size_t>(sameVertex.find(static_cast<int>(d)));
            if (first[r] < 0) first[r] = static_cast<int>(d);
        }
        for (long d = 0; d < n; ++d)
            (*heir)[static_cast<std::size_t>(d)] = first[static_cast<std::size_t>(sameVertex.find(static_cast<int>(d)))];
    }
    return st;
}

} // namespace HexEx
