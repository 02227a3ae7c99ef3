#include "DartAnnihilation.hh"

#include "../Core/UnionFind.hh"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <utility>

namespace HexEx {

AnnihilationStats annihilateDarts(std::vector<std::array<int, 4>>& alpha, const std::vector<signed char>& sign,
                                  std::vector<char>& alive, std::vector<std::pair<int, int>>* heirs,
                                  const std::function<bool(int, int)>& same_place) {
    AnnihilationStats st;
    const long n = static_cast<long>(alpha.size());
    // Per dart: kQueued (on the work list) and kTouched (joined some vertex group).
    constexpr std::uint8_t kQueued = 1, kTouched = 2;
    std::vector<std::uint8_t> flag(static_cast<std::size_t>(n), 0);
    // Union-find over all darts, allocated when the first pair annihilates (maps without
    // folds pay nothing). Dense ids cost 4 bytes per dart; a hash map of the touched darts
    // cost about 35 bytes per touched dart, and on fold-heavy maps nearly every dart is touched.
    UnionFind sameVertex(0);
    auto idOf = [&](long d) {
        if (sameVertex.parent.empty()) sameVertex = UnionFind(static_cast<std::size_t>(n));
        flag[static_cast<std::size_t>(d)] |= kTouched;
        return static_cast<int>(d);
    };
    // The work list is every anti dart in ascending order, followed by the darts queued
    // again on the way (first in, first out). The first part is a scan, not a stored list.
    for (long d = 0; d < n; ++d)
        if (alive[static_cast<std::size_t>(d)] && sign[static_cast<std::size_t>(d)] < 0) flag[static_cast<std::size_t>(d)] |= kQueued;
    std::deque<long> requeued;
    long scan = 0;
    auto next = [&]() -> long {
        for (; scan < n; ++scan)
            if (flag[static_cast<std::size_t>(scan)] & kQueued && sign[static_cast<std::size_t>(scan)] < 0) return scan++;
        if (requeued.empty()) return -1;
        const long d = requeued.front();
        requeued.pop_front();
        return d;
    };
    auto A = [&](long d) -> std::array<int, 4>& { return alpha[static_cast<std::size_t>(d)]; };
    for (long anti = next(); anti >= 0; anti = next()) {
        flag[static_cast<std::size_t>(anti)] &= static_cast<std::uint8_t>(~kQueued);
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
                        !(flag[static_cast<std::size_t>(cand)] & kQueued)) {
                        requeued.push_back(cand);
                        flag[static_cast<std::size_t>(cand)] |= kQueued;
                    }
                }
            }
    }
    for (long d = 0; d < n; ++d)
        if (alive[static_cast<std::size_t>(d)] && sign[static_cast<std::size_t>(d)] < 0) ++st.remaining_anti;
    if (heirs && !sameVertex.parent.empty()) {
        // Smallest surviving dart per group, kept in the union-find's own array: after full
        // compression every dart points at its root (the group's smallest dart, see
        // UnionFind::unite()), and a root with an heir holds -2 - heir.
        std::vector<int>& parent = sameVertex.parent;
        for (long d = 0; d < n; ++d) parent[static_cast<std::size_t>(d)] = sameVertex.find(static_cast<int>(d));
        auto rootOf = [&](std::size_t d) { return parent[d] < 0 ? d : static_cast<std::size_t>(parent[d]); };
        for (std::size_t d = 0; d < flag.size(); ++d) {
            if (!(flag[d] & kTouched) || !alive[d]) continue;
            const std::size_t r = rootOf(d);
            if (parent[r] >= 0) parent[r] = -2 - static_cast<int>(d);  // darts ascend: the first is the smallest
        }
        auto heirOf = [&](std::size_t d) {
            const int p = parent[rootOf(d)];
            return p < 0 ? -2 - p : -1;
        };
        // (removed dart, heir) in dart order; a dart at the same place as the previous
        // entry with the same heir adds no candidate and is left out.
        auto wanted = [&](std::size_t d, int h, int lastDart, int lastHeir) {
            return !(lastDart >= 0 && h == lastHeir && same_place && same_place(lastDart, static_cast<int>(d)));
        };
        std::size_t count = 0;
        for (int pass = 0; pass < 2; ++pass) {  // count, then fill (exact reserve)
            if (pass == 1) {
                heirs->clear();
                heirs->reserve(count);
            }
            int lastDart = -1, lastHeir = -1;
            for (std::size_t d = 0; d < flag.size(); ++d) {
                if (!(flag[d] & kTouched) || alive[d]) continue;
                const int h = heirOf(d);
                if (h < 0 || !wanted(d, h, lastDart, lastHeir)) continue;
                lastDart = static_cast<int>(d);
                lastHeir = h;
                if (pass == 0) ++count;
                else heirs->emplace_back(static_cast<int>(d), h);
            }
        }
    } else if (heirs) {
        heirs->clear();
    }
    return st;
}

} // namespace HexEx
