#pragma once
/// @file DartReconnection.hh
/// Reconnection of darts that the annihilation left in broken hex cells (the paper's
/// "split vertices", section 5.2, Figure 13): where the annihilation, in every order tried,
/// leaves cells that are not hexes although their darts are there, the darts are regrouped
/// into cubes by their own parameters and re-linked as hexes (Documentation/algorithm.md,
/// "Reconnecting the darts of broken cells").

#include "../Extraction/DartExtraction.hh"

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace HexEx {

/// What reconnectBrokenCells() did.
struct ReconnectionStats {
    long broken_cells = 0;        ///< broken hex cells found (<alpha_0, alpha_1, alpha_2> orbits that are not hexes even with their alpha_3 links ignored)
    long reconnected_cells = 0;   ///< hex cells the re-linked darts form (replacing broken ones)
    long unresolved_cells = 0;    ///< broken cells left as they were (no valid reconnection found)
    long alpha3_only_groups = 0;  ///< groups of broken cells that are hexes once alpha_3 is ignored (left to the face repair)
    /// Per group of broken cells left as they were: its smallest dart and why (at most 8 entries).
    std::vector<std::pair<int, std::string>> unresolved;
    /// For each entry of unresolved: the group's darts and its broken cells.
    std::vector<std::pair<long, long>> unresolved_size;
};

/// Finds the broken hex cells among the alive darts (countDefectiveHexCells() over all
/// alive darts) and tries to re-link the alpha_0..alpha_2 links of each connected group of
/// them (darts joined by any link) into hexes. Groups whose cells are hexes once their
/// alpha_3 links are ignored (partially connected or crossed quads) are left alone: the face
/// repair and relinking deal with those (FaceConnectionRepair.hh, FaceRelinking.hh).
///
/// Every dart knows its frame `(z, d1, d2, d3)` in the chart of its tet; darts of one tet
/// that span the same unit cube are parts of one cell, related exactly as their frames
/// are. Between tets, each link of the group that would be right if it were an `alpha_i`
/// link says how the two tets' charts are related (the rigid grid motion that maps the
/// partner's frame onto `alpha_i*` of the dart's frame). The tets are placed in one common
/// chart one at a time, each by the motion most links to the tets already placed agree on
/// (ties: smallest tet), so that links crossed by the annihilation, which disagree with
/// the others, are outvoted, and charts meeting around a singular edge are related through
/// the links that go around it the way the darts do. If the frames then fill whole cubes,
/// each frame once, the darts are re-linked cube by cube (`alpha_0*`, `alpha_1*`,
/// `alpha_2*` of each frame); the result is kept only if every re-linked cell and every
/// cell linked to it by alpha_3 passes the local hex check (countDefectiveHexCells()),
/// otherwise the links are put back and the group is counted as unresolved.
///
/// @p darts gives the frames (indices as in @p alpha); @p alive marks the survivors of the
/// annihilation. Deterministic (groups in order of their smallest dart). Cost: one pass of
/// the local hex check over all alive darts, plus time in proportion to the broken cells.
///
/// @p seeds, if given, limits the search for broken cells to the cells of these darts (the
/// annihilation passes the darts whose links it changed: no other cell can have broken).
/// @p undo, if given, receives (dart, links before) for every dart of every group re-linked,
/// in order, so that the caller can put them back (restore in reverse order).
ReconnectionStats reconnectBrokenCells(std::vector<std::array<int, 4>>& alpha, const std::vector<char>& alive, const DartVector& darts,
                                       const std::function<std::vector<int>()>& chart_components = {},
                                       const std::vector<int>* seeds = nullptr,
                                       std::vector<std::pair<int, std::array<int, 4>>>* undo = nullptr);

} // namespace HexEx
