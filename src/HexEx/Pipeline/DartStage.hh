#pragma once
/// @file DartStage.hh
/// @ingroup pipeline
/// Pipeline stage "darts" (paper 4.3.1): the darts of every tet (the h-vertices are the
/// grid points they sit on), with the implicit-cell fast path where it applies.

#include "../Extraction/DartExtraction.hh"
#include "../Preprocessing/Transitions.hh"
#include "../Mesh/TetMesh.hh"
#include "MemoryBudget.hh"

#include <vector>

namespace HexEx {

/// Input of extractDartStage().
struct DartStageInput {
    const TetMesh* mesh = nullptr;             ///< the tet mesh (adjacency built)
    const std::vector<TetSoS>* tets = nullptr; ///< per-tet predicates (PreprocessOutput::tets)
    double abs_volume = 0;                     ///< unsigned parametric volume (sizes buffers)
    bool implicit_cells = false;               ///< use the implicit-cell fast path (useImplicitCells())
    int threads = 1;                           ///< worker threads (resolved, >= 1)
    const MemoryEstimate* budget = nullptr;    ///< memory estimate and budget (null: no cap)
    /// Transitions per halfface; with @p cheap_folds, fold points whose darts all cancel get
    /// no darts (FoldCancellation.hh; only with flipped tets).
    const Transitions* transitions = nullptr;
    bool cheap_folds = false;                  ///< see @p transitions (ExtractionOptions::cheap_folds)
};

/// Output of extractDartStage().
struct DartStageOutput {
    DartSet darts;                   ///< the darts, grouped by tet
    std::vector<signed char> sign;   ///< per dart: +1 regular, -1 anti
    long anti = 0;                   ///< number of anti darts
    bool implicit_cells = false;     ///< the fast path was used (copied from the input)
};

/// Runs the stage. Throws InputError if a tet's image is absurdly large or the implicit
/// grid points exceed 32-bit indices, ResourceError (memoryRefusal()) as soon as the darts
/// exceed the budget's max_darts. Deterministic for any thread count.
DartStageOutput extractDartStage(const DartStageInput& in);

} // namespace HexEx
