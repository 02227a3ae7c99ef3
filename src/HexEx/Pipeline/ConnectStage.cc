#include "ConnectStage.hh"

#include "../Core/Parallel.hh"

#include <utility>

namespace HexEx {

ConnectOutput connectStage(const ConnectInput& in) {
    ConnectOutput out;
    out.alpha = traceConnections(*in.mesh, *in.transitions, *in.tets, *in.darts, in.threads, out.trace, in.progress);
    // Keep only mutual links: found first, then cut (a cut while others still read could
    // hide an asymmetry from the partner's side).
    auto& alpha = out.alpha;
    std::vector<std::vector<std::pair<std::size_t, int>>> oneSided(static_cast<std::size_t>(in.threads));
    // The partners' entries are read at random: they are prefetched kAhead darts early.
    constexpr std::size_t kAhead = 8;
    parallelChunks(alpha.size(), in.threads, [&](int k, std::size_t b, std::size_t e) {
        for (std::size_t d = b; d < e; ++d) {
            if (d + kAhead < e)
                for (int i = 0; i < 4; ++i) {
                    const int q = alpha[d + kAhead][i];
                    if (q >= 0) __builtin_prefetch(&alpha[static_cast<std::size_t>(q)][i]);
                }
            for (int i = 0; i < 4; ++i) {
                const int p = alpha[d][i];
                if (p < 0 || p == static_cast<int>(d)) continue;
                if (alpha[static_cast<std::size_t>(p)][i] != static_cast<int>(d)) oneSided[static_cast<std::size_t>(k)].emplace_back(d, i);
            }
        }
    });
    for (const auto& part : oneSided)
        for (const auto& [d, i] : part) {
            ++out.asymmetric_links;
            alpha[d][i] = kUnconnected;
        }
    return out;
}

} // namespace HexEx
