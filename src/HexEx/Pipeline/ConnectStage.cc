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
    // Plain pointers and a flag per dart: the loop reads only the link array (through the
    // vector's reference the compiler reloaded its start at every access).
    const DartLinks* links = alpha.data();
    parallelChunks(alpha.size(), in.threads, [&, links](int k, std::size_t b, std::size_t e) {
        std::vector<std::pair<std::size_t, int>>& mine = oneSided[static_cast<std::size_t>(k)];
        for (std::size_t d = b; d < e; ++d) {
            if (d + kAhead < e) {
                const DartLinks& ahead = links[d + kAhead];
                for (int i = 0; i < 4; ++i)
                    if (ahead[static_cast<std::size_t>(i)] >= 0)
                        __builtin_prefetch(&links[static_cast<std::size_t>(ahead[static_cast<std::size_t>(i)])][static_cast<std::size_t>(i)]);
            }
            const DartLinks& own = links[d];
            const int self = static_cast<int>(d);
            bool broken = false;
            for (int i = 0; i < 4; ++i) {
                const int p = own[static_cast<std::size_t>(i)];
                broken |= p >= 0 && p != self && links[static_cast<std::size_t>(p)][static_cast<std::size_t>(i)] != self;
            }
            if (!broken) continue;
            for (int i = 0; i < 4; ++i) {
                const int p = own[static_cast<std::size_t>(i)];
                if (p >= 0 && p != self && links[static_cast<std::size_t>(p)][static_cast<std::size_t>(i)] != self) mine.emplace_back(d, i);
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
