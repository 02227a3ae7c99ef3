#pragma once
/// @file LocalHexCheck.hh
/// @ingroup pipeline
/// Checks the hex cells around given darts of an uncompacted link array (during the
/// annihilation, before the generalized map is built): the per-cell part of the
/// validator's equations 1-6 (GMapValidator.hh), plus "no alpha_3 link inside one cell".

#include <array>
#include <cstdint>
#include <vector>

namespace HexEx {

/// Counts the defective hex cells among the cells of the alive darts in @p seeds.
///
/// A cell is the <alpha_0, alpha_1, alpha_2> orbit of a seed over alive darts. It is
/// defective if it has a free, dangling or non-involutive alpha_0..alpha_2 link, does not
/// have 48 darts, or one of its darts breaks equation 1 ((alpha_0 alpha_2)^2 = id), 3
/// (<alpha_0, alpha_1> orbits of 8), 4 (<alpha_1, alpha_2> orbits of 6), 5
/// (<alpha_0, alpha_1 alpha_2 alpha_1> orbits of 8), or has an alpha_3 link (not free) that is
/// not an involution, breaks equation 2, or joins the cell to itself. Each cell is counted
/// once. @p mark is scratch space, one byte per dart, whose bits @p in_cell and @p done must
/// be clear on entry; they are clear again on return. If @p bad_darts is given, the darts of
/// every defective cell are appended to it. With @p stop_after > 0 the count stops as soon
/// as it reaches @p stop_after (the cells are visited in the order of @p seeds, so the result
/// is min(count, stop_after)).
long countDefectiveHexCells(const std::vector<std::array<int, 4>>& alpha, const std::vector<char>& alive,
                            const std::vector<int>& seeds, std::vector<std::uint8_t>& mark, std::uint8_t in_cell,
                            std::uint8_t done, std::vector<int>* bad_darts = nullptr, long stop_after = 0);

} // namespace HexEx
