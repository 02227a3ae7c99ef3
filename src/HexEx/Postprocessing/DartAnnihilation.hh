#pragma once
/// @file DartAnnihilation.hh
/// Dart annihilation (paper 4.4.1): a regular dart and an anti dart linked by any alpha_i
/// cancel; the darts around them are reconnected by
/// alpha_j(alpha_j(d)) = alpha_j(d'), alpha_j(alpha_j(d')) = alpha_j(d) for all j with alpha_j(d) != d'.

#include <array>
#include <functional>
#include <utility>
#include <vector>

namespace HexEx {

/// Result counters.
struct AnnihilationStats {
    long pairs = 0;           ///< annihilated regular/anti pairs
    long remaining_anti = 0;  ///< anti darts left at the fixed point
};

/// Annihilates pairs until no regular dart is linked to an anti dart. @p alpha holds the
/// links (a free link is the dart itself, -1 means unconnected and is left alone);
/// @p sign is +1/-1 per dart; @p alive is cleared for removed darts. Processing order is
/// by ascending dart index with a work list, so the result is deterministic.
///
/// If @p heirs is given, it receives (removed dart, surviving dart that inherits its
/// h-vertex) pairs in ascending order of the removed dart: at each removal the regular and the anti dart are joined (the paper's vertex
/// merging joins the h-vertices of an annihilated pair) and each with its alpha_1, alpha_2
/// and alpha_3 partners of that moment (darts at the same h-vertex), transitively; every
/// dart of such a group gets the group's smallest surviving dart. The positions of removed
/// darts are then candidates for their heir's vertex (VertexMerging.hh): those of regular
/// darts like the vertex's own, those of anti darts (in the flipped part) only as a last
/// resort. With @p same_place (true if two darts, the first the smaller, sit at the same
/// grid point of the same tet), an entry at the same place and with the same heir as the
/// entry before it is left out: it would add the same candidate again.
AnnihilationStats annihilateDarts(std::vector<std::array<int, 4>>& alpha, const std::vector<signed char>& sign,
                                  std::vector<char>& alive, std::vector<std::pair<int, int>>* heirs = nullptr,
                                  const std::function<bool(int, int)>& same_place = {});

} // namespace HexEx
