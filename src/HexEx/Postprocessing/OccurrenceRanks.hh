#pragma once
/// @file OccurrenceRanks.hh
/// The occurrences (grid points of the tets' boxes, ImplicitCells) that are elements of the
/// assembly's vertex union-find, numbered by rank. They depend on the darts' and implicit
/// cells' occurrences only, not on the validator's labels, so the assembly stage computes
/// them beside the validator's cell search (validateHexGMap()).

#include "HexMeshAssembly.hh"

#include "../Core/BitCount.hh"

#include <cstdint>
#include <vector>

namespace HexEx {

/// The occurrences that are elements of the vertex classes' union-find (used ones: corners
/// of implicit cells, or sat on or linked to by a dart; and those joined across a face), as
/// a bit set with the rank of each word's first element: element numbers in occurrence order.
struct OccurrenceRanks {
    /// 64 occurrences: bit o % 64 set if occurrence o is an element, and the number of
    /// elements before the word (together: one cache access per rank).
    struct Word {
        std::uint64_t element;  ///< the elements' bits
        std::int64_t first;     ///< elements before the word
    };
    std::vector<Word> word;            ///< per 64 occurrences
    std::vector<std::uint64_t> used;   ///< per word: the used (labelled) occurrences' bits
    long n = 0;                        ///< number of elements
    long n_used = 0;                   ///< number of used occurrences
    bool ready = false;                ///< filled by rankOccurrences()
    /// Element number of occurrence @p o (which must be an element).
    int rank(int o) const {
        const Word& w = word[static_cast<std::size_t>(o) >> 6];
        return static_cast<int>(w.first) + bitCount64(w.element & ((std::uint64_t(1) << (o & 63)) - 1));
    }
};

/// The OccurrenceRanks of the darts of @p g and the implicit cells @p implicit, on @p threads
/// threads (the result does not depend on it).
OccurrenceRanks rankOccurrences(const GMap<3>& g, const ImplicitCells& implicit, int threads);

} // namespace HexEx
