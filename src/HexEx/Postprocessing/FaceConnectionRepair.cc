#include "FaceConnectionRepair.hh"

#include "../Core/Parallel.hh"

#include <algorithm>
#include <map>
#include <vector>

namespace HexEx {

long completePartialFaceConnections(GMap<3>& g, int threads) {
    long repaired = 0;
    const std::size_t n = g.n_darts();
    std::vector<char> done(n, 0);
    // Quick skip: a consistent face has the same alpha_3 freedom along alpha_0 and alpha_1.
    auto consistent = [&](DartHandle d0) {
        const bool f = g.is_free(d0, 3);
        return f == g.is_free(g.alpha(d0, 0), 3) && f == g.is_free(g.alpha(d0, 1), 3);
    };
    // The darts that fail the quick skip, found in parallel (read only). A repair only
    // links whole faces (a partial quad and the quad it is linked to), whose darts then
    // pass the test, so no other dart can start failing it: visiting only these darts, in
    // order and with the test repeated, does what a scan of all darts would.
    const int chunks = std::max(1, std::min(threads, static_cast<int>(n / 65536)));
    std::vector<std::vector<int>> candidates(static_cast<std::size_t>(chunks));
    parallelChunks(n, chunks, [&](int k, std::size_t b, std::size_t e) {
        for (std::size_t s = b; s < e; ++s) {
            const DartHandle d0(static_cast<int>(s));
            if (g.is_alive(d0) && !consistent(d0)) candidates[static_cast<std::size_t>(k)].push_back(d0.idx());
        }
    });
    std::vector<int> todo;
    for (const auto& c : candidates) todo.insert(todo.end(), c.begin(), c.end());
    for (const int s : todo) {
        const DartHandle d0(s);
        if (done[static_cast<std::size_t>(s)] || consistent(d0)) continue;
        const std::vector<DartHandle> face = g.orbit(d0, 0b0011);
        for (auto x : face) done[x.uidx()] = 1;
        // Partial: some darts linked by alpha_3, some free.
        DartHandle seed;
        bool anyFree = false;
        for (auto x : face) {
            if (g.is_free(x, 3)) anyFree = true;
            else if (!seed.is_valid()) seed = x;
        }
        if (!anyFree || !seed.is_valid() || face.size() != 8) continue;
        // Propagate the correspondence x -> phi(x) from the seed over alpha_0 and alpha_1.
        std::map<int, int> phi{{seed.idx(), g.alpha(seed, 3).idx()}};
        std::vector<DartHandle> stack{seed};
        bool ok = true;
        while (!stack.empty() && ok) {
            const DartHandle x = stack.back();
            stack.pop_back();
            const DartHandle y(phi[x.idx()]);
            for (int i = 0; i < 2; ++i) {
                const DartHandle xn = g.alpha(x, i), yn = g.alpha(y, i);
                auto it = phi.find(xn.idx());
                if (it == phi.end()) {
                    phi[xn.idx()] = yn.idx();
                    stack.push_back(xn);
                } else if (it->second != yn.idx()) {
                    ok = false;
                }
            }
        }
        if (!ok || phi.size() != 8) continue;
        // Every existing link must agree with phi and every missing one be free on both sides.
        for (const auto& [x, y] : phi) {
            const DartHandle X(x), Y(y);
            if (X == Y || !g.is_alive(Y)) { ok = false; break; }
            const bool xFree = g.is_free(X, 3), yFree = g.is_free(Y, 3);
            if (!xFree && g.alpha(X, 3) != Y) ok = false;
            if (!yFree && g.alpha(Y, 3) != X) ok = false;
        }
        if (!ok) continue;
        for (const auto& [x, y] : phi)
            if (g.is_free(DartHandle(x), 3)) g.sew(DartHandle(x), DartHandle(y), 3);
        ++repaired;
    }
    return repaired;
}

} // namespace HexEx
