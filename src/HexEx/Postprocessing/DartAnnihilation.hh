#pragma once
/// @file DartAnnihilation.hh
/// Dart annihilation (paper 4.4.1): a regular dart and an anti dart linked by any alpha_i
/// cancel; the darts around them are reconnected by
/// alpha_j(alpha_j(d)) = alpha_j(d'), alpha_j(alpha_j(d')) = alpha_j(d) for all j with alpha_j(d) != d'.

#include <array>
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
/// If @p heir is given, it receives per dart the surviving dart that inherits its h-vertex,
/// or -1: a removed regular dart is joined with its alpha_1, alpha_2 and alpha_3 partners
/// at the time of removal (darts at the same h-vertex), transitively; every surviving or
/// removed regular dart of such a group gets the group's smallest surviving dart. Removed
/// regular darts are then still preimages of their heir's vertex (vertex placement uses
/// their positions as candidates). Anti darts (in the flipped part) get -1.
AnnihilationStats annihilateDarts(std::vector<std::array<int, 4>>& alpha, const std::vector<signed char>& sign,
                                  std::vector<char>& alive, std::vector<int>* heir = nullptr);

} // namespace HexEx
