/// @file OccurrenceRanks.cc
/// rankOccurrences(): the occurrences' marks as bit sets (in parallel chunks), then prefix
/// counts per word.

#include "OccurrenceRanks.hh"

#include "../Core/Parallel.hh"

#include <algorithm>
#include <array>
#include <cstdint>

namespace HexEx {

OccurrenceRanks rankOccurrences(const GMap<3>& g, const ImplicitCells& implicit, int threads) {
    OccurrenceRanks occ;
    const std::size_t nd = g.n_darts();
    const long nocc = implicit.n_occurrences;
    const DefaultInitVector<int>& dartOccs = implicit.dart_occurrence;
    auto dartOcc = [&](std::size_t d) { return dartOccs.empty() ? -1 : dartOccs[d]; };
    const DefaultInitVector<int>& a3Occ = implicit.alpha3_occurrence;
    const auto& jo = implicit.joined_occurrences;
    const auto nOcc = static_cast<std::size_t>(nocc);
    const int ufChunks = nd + nOcc >= 16384 ? std::max(1, threads) : 1;
    // The marks go straight into the two bit sets (no byte per occurrence): plain ORs when
    // one chunk writes, else an atomic OR where a plain test finds the bit clear.
    const std::size_t nWords = (nOcc + 63) / 64;
    occ.word.assign(nWords, OccurrenceRanks::Word{0, 0});
    occ.used.assign(nWords, 0);
    const bool shared = ufChunks > 1;
    auto set = [shared](std::uint64_t& bits, int o) {
        const std::uint64_t b = std::uint64_t(1) << (o & 63);
        if (!shared) {
            bits |= b;
        } else if (!(__atomic_load_n(&bits, __ATOMIC_RELAXED) & b)) {
            __atomic_fetch_or(&bits, b, __ATOMIC_RELAXED);
        }
    };
    // A used occurrence is an element too: the used bits join the element bits with the
    // prefix counts below (one OR per mark here).
    auto join = [&](int o) { set(occ.word[static_cast<std::size_t>(o) >> 6].element, o); };
    auto use = [&](int o) { set(occ.used[static_cast<std::size_t>(o) >> 6], o); };
    parallelChunks(nd, ufChunks, [&](int, std::size_t d0, std::size_t d1) {
        int lastOcc = -1;  // the darts of one grid point of a tet are consecutive
        for (std::size_t d = d0; d < d1; ++d) {
            if (!g.is_alive(DartHandle(static_cast<int>(d)))) continue;
            const int o = dartOcc(d);
            if (o >= 0 && o != lastOcc) {
                lastOcc = o;
                use(o);
            }
            if (nocc > 0 && a3Occ[d] >= 0) use(a3Occ[d]);
        }
    });
    parallelChunks(implicit.cells.size(), ufChunks, [&](int, std::size_t b, std::size_t e) {
        const std::array<int, 8>* prev = nullptr;  // a cell's bottom is often the previous top
        for (std::size_t i = b; i < e; ++i) {
            const std::array<int, 8>& c = implicit.cells[i];
            const bool onTop = prev && c[0] == (*prev)[4] && c[1] == (*prev)[5] && c[2] == (*prev)[6] && c[3] == (*prev)[7];
            for (std::size_t k = onTop ? 4 : 0; k < 8; ++k) use(c[k]);
            prev = &c;
        }
    });
    parallelChunks(jo.size(), ufChunks, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i) {
            join(jo[i].first);
            join(jo[i].second);
        }
    });
    // Each word's first rank: counts per chunk of words, then the chunks' offsets.
    std::vector<long> inChunk(static_cast<std::size_t>(ufChunks) + 1, 0), usedInChunk(static_cast<std::size_t>(ufChunks), 0);
    parallelChunks(nWords, ufChunks, [&](int k, std::size_t w0, std::size_t w1) {
        long n = 0;
        for (std::size_t w = w0; w < w1; ++w) {
            occ.word[w].element |= occ.used[w];
            occ.word[w].first = n;
            n += bitCount64(occ.word[w].element);
            usedInChunk[static_cast<std::size_t>(k)] += bitCount64(occ.used[w]);
        }
        inChunk[static_cast<std::size_t>(k) + 1] = n;
    });
    for (std::size_t k = 0; k < static_cast<std::size_t>(ufChunks); ++k) inChunk[k + 1] += inChunk[k];
    parallelChunks(nWords, ufChunks, [&](int k, std::size_t w0, std::size_t w1) {
        for (std::size_t w = w0; w < w1; ++w) occ.word[w].first += inChunk[static_cast<std::size_t>(k)];
    });
    occ.n = inChunk.back();
    for (const long u : usedInChunk) occ.n_used += u;
    occ.ready = true;
    return occ;
}

} // namespace HexEx
