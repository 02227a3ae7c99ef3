/// @file OccurrenceRanks.cc
/// rankOccurrences(): marks per occurrence in parallel chunks, then the marks as bit sets
/// with prefix counts.

#include "OccurrenceRanks.hh"

#include "../Core/Parallel.hh"

#include <algorithm>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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
    // Per occurrence: bit 0 used, bit 1 joined (parallel marks; all writers of a pass
    // store the same bit).
    std::vector<char> mark(nOcc, 0);
    auto use = [&](int o) { __atomic_store_n(&mark[static_cast<std::size_t>(o)], char(1), __ATOMIC_RELAXED); };
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
        for (std::size_t i = b; i < e; ++i)
            for (int o : implicit.cells[i]) use(o);
    });
    parallelChunks(jo.size(), ufChunks, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i) {
            __atomic_fetch_or(&mark[static_cast<std::size_t>(jo[i].first)], char(2), __ATOMIC_RELAXED);
            __atomic_fetch_or(&mark[static_cast<std::size_t>(jo[i].second)], char(2), __ATOMIC_RELAXED);
        }
    });
    // The marks as two bit sets, 64 occurrences a word, with each word's first rank.
    const std::size_t nWords = (nOcc + 63) / 64;
    occ.word.resize(nWords);
    occ.used.resize(nWords);
    std::vector<long> inChunk(static_cast<std::size_t>(ufChunks) + 1, 0), usedInChunk(static_cast<std::size_t>(ufChunks), 0);
    parallelChunks(nWords, ufChunks, [&](int k, std::size_t w0, std::size_t w1) {
        long n = 0;
        for (std::size_t w = w0; w < w1; ++w) {
            std::uint64_t el = 0, us = 0;
            const std::size_t o0 = 64 * w, o1 = std::min(o0 + 64, nOcc);
#if defined(__SSE2__)
            if (o1 - o0 == 64) {
                for (int q = 0; q < 4; ++q) {
                    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(mark.data() + o0 + 16 * static_cast<std::size_t>(q)));
                    const auto nonzero = static_cast<unsigned>(~_mm_movemask_epi8(_mm_cmpeq_epi8(v, _mm_setzero_si128()))) & 0xffffu;
                    const auto bit0 = static_cast<unsigned>(_mm_movemask_epi8(_mm_slli_epi16(v, 7)));  // each byte's bit 0
                    el |= static_cast<std::uint64_t>(nonzero) << (16 * q);
                    us |= static_cast<std::uint64_t>(bit0) << (16 * q);
                }
            } else
#endif
                for (std::size_t o = o0; o < o1; ++o) {
                    el |= static_cast<std::uint64_t>(mark[o] != 0) << (o - o0);
                    us |= static_cast<std::uint64_t>(mark[o] & 1) << (o - o0);
                }
            occ.word[w] = {el, n};
            occ.used[w] = us;
            n += bitCount64(el);
            usedInChunk[static_cast<std::size_t>(k)] += bitCount64(us);
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
