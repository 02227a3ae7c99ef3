#pragma once
/// @file FoldCancellation.hh
/// @ingroup pipeline
/// Cheap folds: grid points whose darts all cancel are found before any dart is stored,
/// and get no darts at all.
///
/// Every regular/anti pair that annihilation removes sits at one grid point with one frame
/// (Documentation/performance.md, "Cheap folds"). At a grid point where every one of the 48
/// frames has exactly one regular and one anti owner among the tets of one chart (one fold
/// layer over one proper layer), a complete annihilation removes all its darts, leaves no
/// survivor there and so no heir (vertex groups never leave their grid point).
/// Such a point is *cancelled*: its darts are not stored, and the alpha_0 tracing walks
/// through it to the next point along the line (ConnectionTracing.cc), which is the
/// partner the annihilation's re-linking would have produced. Only points inside large
/// tets (with a dense index) are considered, and only tets of the same chart component
/// (tets joined by identity transitions) are counted as covering.

#include "../Mesh/TetMesh.hh"
#include "../Preprocessing/Transitions.hh"
#include "DartExtraction.hh"

#include <cstddef>
#include <vector>

namespace HexEx {

/// Per tet, the id of its chart component: tets joined across faces with the identity
/// transition share one (the smallest tet index of the component).
std::vector<int> identityChartComponents(const TetMesh& mesh, const Transitions& transitions);

/// Whether cancelFoldPoints() can find anything: some flipped tet gets a dense index (its grid
/// box has at least kDenseIndexMinPoints points). Tets with non-finite or absurd parameters
/// count as yes (the extraction reports them). Without, the chart components are not needed.
bool mayCancelFoldPoints(const std::vector<TetSoS>& tets);

/// Finds the cancelled points (see the file comment) among the dense indices @p dense
/// (their offsets counted, one per box point), marks them in DenseIndex::cancelled of
/// every tet with darts there, sets those darts to none in the offsets and in @p count
/// (darts per tet). Degenerate tets own no darts and are not counted; any other tet
/// without a dense index whose integer box meets a point makes it not cancelled
/// (conservative).
/// Does nothing with more than @p max_flipped flipped dense tets (the check is pairwise).
/// Returns the number of (tet, point) occurrences cancelled.
long cancelFoldPoints(const std::vector<TetSoS>& tets, const std::vector<int>& component,
                      const std::vector<DartSet::DenseIndex*>& dense, std::vector<std::size_t>& count,
                      std::size_t max_flipped = 64);

} // namespace HexEx
