#pragma once
/// @file DartAnnihilation.hh
/// @ingroup pipeline
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
    /// Broken hex cells next to changed darts after the first pass (with retries only): 0 if
    /// none; otherwise the exact count where a retry had to be compared with it, else 1 (the
    /// check stops at the first broken cell when a retry is kept without that comparison);
    /// 0 where phase by phase ran first and was kept (no ascending pass ran, phased_first).
    long broken_cells_before = 0;
    long broken_cells_after = 0;  ///< the same for the order kept
    long retry_runs = 0;          ///< runs in other orders
    bool repaired = false;        ///< AnnihilationRetry::repair left no broken cell after the first retry
    int reordered = 0;            ///< the order kept: 0 the first pass (ascending), 1 phase by phase, 2 descending, k > 2 hashed
    long merged_vertex_runs = 0;  ///< retries that left no broken cell but merged vertices (LocalVertexCheck.hh), ranked below every other
    bool alpha3_only_kept = false; ///< the order kept left broken cells that are hexes once alpha_3 is ignored (AnnihilationRetry::keep_alpha3_only)
    bool phased_beside = false;   ///< the phase-by-phase run ran beside the first pass and was taken over (AnnihilationRetry::threads)
    bool phased_first = false;    ///< phase by phase ran first and was kept; no ascending pass ran (AnnihilationRetry::phased_first_share)
};

/// Retries of the annihilation (annihilateDarts()) in other orders, for 3D hex maps.
///
/// Where fold layers overlap several regular layers or a singular edge, which regular dart
/// an anti dart cancels with depends on the processing order, and some orders leave broken
/// hex cells (measured on the shared hex meshes folded by 0.6-0.8 grid units: two cells
/// merged into one polyhedron, a cell glued to itself). After the first pass (ascending
/// order), the cells around every dart the pass re-linked are checked
/// (countDefectiveHexCells()). If one is broken, every touched dart is put back to its
/// original links and the whole annihilation runs again in other ways: first phase by
/// phase (only partners linked by alpha_0, then by alpha_0..1, alpha_0..2 and all four; each
/// phase over every anti dart in ascending order), then in descending order, then in orders
/// given by a fixed hash of the dart index, until one leaves no broken cell; otherwise the
/// one with the fewest is kept (ties: the earlier). Each retry costs time in proportion to the
/// darts the first pass touched, not to the whole map. Deterministic; maps whose first pass
/// leaves no broken cell are not affected.
struct AnnihilationRetry {
    bool enabled = false;     ///< check and retry at all
    int orders = 16;          ///< other orders tried at most
    int patience = 6;         ///< stop after this many orders in a row that leave no fewer broken cells than the best
    /// Keep the first retry whose broken cells are all hexes once their alpha_3 links are
    /// ignored (only quads crossed or partial: the face repair and relinking handle those)
    /// instead of trying further orders; not if one of those cells is glued to itself and
    /// linked to no other broken cell (the relinking would find no partner for its quads).
    bool keep_alpha3_only = true;
    /// Called once, after the first retry (phase by phase) if it leaves broken cells, with the
    /// darts of the broken cells (found among the cells of the darts the run changed): may re-link
    /// the darts of those cells (reconnectBrokenCells()) and returns true if no broken cell
    /// is left; then no further order is tried and that result is kept.
    std::function<bool(const std::vector<int>& changed)> repair;
    /// Count every broken cell the first pass leaves before the retries (as before issue 35's
    /// eighth round) instead of stopping at the first and counting them all only where a
    /// retry is compared with that count: the same result, more work (for the tests).
    bool exact_first_count = false;
    /// With 2 or more, a map whose anti darts are at least an eighth of its darts runs the
    /// first retry (phase by phase) on a second thread beside the first pass, on copies of
    /// the links and survivors, and takes it over if the first pass leaves a broken cell
    /// (else it is stopped and dropped): the same result as running it after the first pass
    /// (Documentation/algorithm.md, "The phase-by-phase run beside the first pass"), at the
    /// cost of a second copy of the links, survivors and flags while both run.
    int threads = 1;
    /// Heavy folds: on a map of at least @ref phased_first_min_darts darts whose anti darts are
    /// at least this share of them, phase by phase runs *first*, and is kept where the retries
    /// would keep it as their first variant (no broken cell and no merged vertex, broken cells
    /// only in alpha_3, or repaired by @ref repair); otherwise every dart is put back and the
    /// annihilation runs as without it (ascending first, then the retries). This skips the
    /// ascending pass, which such maps undo anyway (all 7 heavy cases of issue 35's run-time
    /// table keep phase by phase). It changes the result where the ascending pass would have
    /// left no broken cell (Documentation/algorithm.md, "Tenth round"). 0 turns it off.
    double phased_first_share = 0.35;
    /// Smaller maps keep the ascending pass first (see @ref phased_first_share): it costs
    /// little there, and their outputs stay as they were.
    long phased_first_min_darts = 1000000;
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
/// resort. @p retry turns on the retries in other orders where the first pass leaves broken
/// hex cells (AnnihilationRetry). With @p same_place (true if two darts, the first the smaller, sit at the same
/// grid point of the same tet), an entry at the same place and with the same heir as the
/// entry before it is left out: it would add the same candidate again.
///
/// @p mutual_links promises that every link is mutual: alpha_i(alpha_i(d)) = d wherever
/// alpha_i(d) is another dart (connectStage() cuts the one-sided ones). The result is the
/// same as without the promise; the work list then skips checks that cannot succeed
/// (algorithm.md, "Annihilation with mutual links"). A broken promise can change the result.
AnnihilationStats annihilateDarts(std::vector<std::array<int, 4>>& alpha, const std::vector<signed char>& sign,
                                  std::vector<char>& alive, std::vector<std::pair<int, int>>* heirs = nullptr,
                                  const std::function<bool(int, int)>& same_place = {},
                                  const AnnihilationRetry& retry = {}, bool mutual_links = false);

} // namespace HexEx
