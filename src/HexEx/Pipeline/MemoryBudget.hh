#pragma once
/// @file MemoryBudget.hh
/// @ingroup pipeline
/// Pipeline stage "budget": estimates the memory the extraction will need before any
/// per-grid-point or per-dart data is allocated, refuses maps that would exceed
/// ExtractionOptions::max_memory, and words the messages of every memory refusal
/// (estimate, dart cap, std::bad_alloc) the same way: cause, the tets with the largest
/// parametric images, what to do.

#include "../Mesh/TetMesh.hh"
#include "PreprocessStage.hh"

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace HexEx {

/// Bytes one dart costs at the peak of the pipeline, for the estimate and the dart cap
/// (measured 40-110 B on the benchmark inputs, see Documentation/performance.md).
constexpr double kBytesPerDart = 64;

/// Result of estimateMemory().
struct MemoryEstimate {
    double darts = 0;              ///< estimated number of darts
    double bytes = 0;              ///< estimated peak bytes of the extraction
    std::uint64_t budget = 0;      ///< the budget it is checked against (bytes; 0 = none)
    std::size_t max_darts = 0;     ///< darts the budget allows (cap for the dart extraction)
    /// The estimate assumed that the large flipped tets cancel against large proper ones
    /// (cheap folds); the dart cap then applies to the darts left after the cancellation.
    bool cheap_folds = false;
    /// Up to 5 tets with the largest parametric images in the input (before sanitization,
    /// which may carry a wrong parameter into the tets around its vertex): (tet, unsigned
    /// volume in grid cells), largest first. These are the tets to check.
    std::vector<std::pair<int, double>> largest_tets;
};

/// Estimates the darts and bytes of the extraction of @p pre from its TetCostSummary: 48
/// darts per grid cell of every tet's image (with @p implicit_cells, only a shell along the
/// faces of large proper tets, 0.5 grid points per unit of face area), dense per-box-point
/// indices of tets with large bounding boxes, a fixed cost per tet. With @p cheap_folds
/// (ExtractionOptions::cheap_folds, not with arcs) the image volume of the large flipped
/// tets and as much of the large proper tets' is taken to cancel, and the fold
/// cancellation's owner masks (17 B per point of the box around the large flipped tets) are
/// added instead. @p budget (bytes, 0 = no limit) is stored and turned into max_darts.
/// Constant time.
MemoryEstimate estimateMemory(const PreprocessOutput& pre, bool implicit_cells, std::uint64_t budget,
                              bool cheap_folds = false);

/// Throws ResourceError (memoryRefusal()) if the estimate exceeds its budget.
void checkMemoryBudget(const MemoryEstimate& est);

/// Bytes per dart of the annihilation's phase-by-phase run beside the first pass
/// (AnnihilateInput::phased_beside: its own links, survivors and flags; measured 29 B per
/// dart on pig 1.5 seed 21, 3.76M darts, peak 371 -> 480 MB at 2 threads).
constexpr double kBytesPerPhasedTwinDart = 32;

/// True if the estimate plus @p extra_bytes stays within its budget (always true without one).
/// Optional work that only saves time (e.g. the annihilation's run beside the first pass)
/// asks this before it allocates.
bool budgetAllows(const MemoryEstimate& est, double extra_bytes);

/// "tet 10 (1.38e+06 grid cells), tet 20 (7.3 grid cells), ...": the entries of
/// MemoryEstimate::largest_tets / TetCostSummary::largest_input for messages.
std::string largestImagesText(const std::vector<std::pair<int, double>>& largest);

/// The message of a refusal: @p cause, then the largest parametric images of @p est (if
/// known) and what to do.
std::string memoryRefusal(const std::string& cause, const MemoryEstimate* est);

} // namespace HexEx
