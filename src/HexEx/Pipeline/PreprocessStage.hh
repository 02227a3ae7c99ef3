#pragma once
/// @file PreprocessStage.hh
/// @ingroup pipeline
/// Pipeline stage "preprocess" (paper 4.1): refuses unusable parameters, computes the
/// halfface transitions, sanitizes the parameters and classifies the tets.

#include "../Extraction/ExtractionReport.hh"
#include "../Extraction/TetSoS.hh"
#include "../Mesh/ParametrizedTetMesh.hh"
#include "../Preprocessing/Transitions.hh"

#include <string>
#include <utility>
#include <vector>

namespace HexEx {

/// Input of preprocess().
struct PreprocessInput {
    const ParametrizedTetMesh* input = nullptr;         ///< the map (adjacency built)
    const std::vector<int>* given_rotations = nullptr;  ///< ExtractionOptions::given_rotations
    double epsilon = 1e-6;                              ///< sanitization tolerance
    double max_hexes = 4e7;                             ///< limit on the unsigned parametric volume
    int threads = 1;                                    ///< worker threads (resolved, >= 1)
    /// If set, the parameters taken (moved from) as the working copy instead of copying
    /// input->params; they must be input->params itself (a caller that owns the input).
    CornerParams* owned_params = nullptr;
};

/// What the memory estimate (estimateMemory()) needs from every tet, gathered by the
/// preprocessing passes that read the parameters anyway (no extra pass over the tets).
struct TetCostSummary {
    double points = 0;           ///< sum of the unsigned image volumes of non-degenerate tets (grid cells)
    double points_implicit = 0;  ///< the same with implicit cells: large proper tets count only a shell along their faces
    double dense_bytes = 0;      ///< bytes of the dense per-box-point indices of tets with large bounding boxes
    double large_proper = 0;     ///< unsigned image volume of the proper tets with a dense index (large bounding box)
    double large_flipped = 0;    ///< unsigned image volume of the flipped tets with a dense index
    double flipped_box_points = 0;  ///< bounding-box points of the flipped tets with a dense index, summed
    double flipped_union_box = 0;   ///< points of the one box around all flipped tets with a dense index
    /// Up to 5 tets with the largest unsigned image volume in the input parameters (before
    /// sanitization): (tet, volume in grid cells), largest first, ties by smaller tet.
    std::vector<std::pair<int, double>> largest_input;
};

/// Output of preprocess(). Move-only: @ref tets points into @ref params (a move keeps
/// the vector's storage, a copy would not).
struct PreprocessOutput {
    CornerParams params;                ///< sanitized corner parameters
    Transitions transitions;            ///< transition per halfface
    std::vector<TetSoS> tets;           ///< symbolic-perturbation data per tet (points into params)
    double abs_volume = 0;              ///< unsigned parametric volume (before sanitization)
    ExtractionReport::Input stats;      ///< the report's input statistics
    TetCostSummary cost;                ///< per-tet sizes for the memory estimate
    std::vector<std::string> warnings;  ///< warnings of this stage

    /// Empty output.
    PreprocessOutput() = default;
    /// Move (keeps the storage tets point into).
    PreprocessOutput(PreprocessOutput&&) = default;
    /// Move assignment (keeps the storage tets point into).
    PreprocessOutput& operator=(PreprocessOutput&&) = default;
    /// No copies: the copy's tets would point into the original's parameters.
    PreprocessOutput(const PreprocessOutput&) = delete;
    /// No copies (see the copy constructor).
    PreprocessOutput& operator=(const PreprocessOutput&) = delete;
};

/// Runs the stage. Throws InputError for unusable input: missing adjacency, wrong
/// parameter count, non-finite or out-of-range parameters, a parametric volume above
/// max_hexes, inconsistent given rotations. Deterministic for any thread count.
PreprocessOutput preprocess(const PreprocessInput& in);

} // namespace HexEx
