#pragma once
/// @file Sanitization.hh
/// @ingroup pipeline
/// Sanitization of the parametrization (paper 4.1.2): after it, the parameters of every
/// vertex in all its tets are related exactly by the transitions, so every later predicate
/// is exact and consistent across charts.

#include "CornerRepair.hh"
#include "Transitions.hh"

namespace HexEx {

/// Options of the sanitization.
struct SanitizeOptions {
    /// Parameter coordinates within this distance of an integer are snapped to it
    /// (default 1e-6: well above double rounding noise, well below any real feature).
    double epsilon = 1e-6;
    /// Worker threads (vertices are independent; the result does not depend on this).
    int threads = 1;
};

/// What the sanitization changed.
struct SanitizeStats {
    /// At most this many repairs are listed in @ref repairs.
    static constexpr std::size_t kMaxListed = 32;
    int snapped_coordinates = 0;      ///< coordinates moved onto an integer
    long repaired_corners = 0;        ///< corner parameters outvoted by the other tets at their vertex
    std::vector<CornerRepair> repairs;  ///< the first kMaxListed of them, by vertex
};

/// Rounds every coordinate of @p u to a multiple of the quantum for magnitude @p bound
/// (2^(e-52) with bound + 1 < 2^e, so that adding integers up to @p bound stays exact), then
/// snaps coordinates within @p epsilon of an integer, counting them in @p snapped. Shared by
/// the tet (sanitizeParameters()) and the triangle (2D) sanitization.
void quantizeParameter(Vec3d& u, double bound, double epsilon, int& snapped);

/// Per vertex: takes its parameter in its lowest-index incident tet, truncates it to the
/// precision that survives every chart of the vertex (the largest exponent over all its
/// charts), snaps coordinates within epsilon of an integer, and propagates it through the
/// transitions (breadth first over faces around the vertex) into every incident tet.
///
/// Majority vote: if the vertex's values (mapped into one chart) do not all agree, the
/// value shared by a strict majority of its tets is taken instead of the first tet's
/// (ties: the first tet's, as without the vote). "Agree" means equal up to epsilon per
/// coordinate, relative once the magnitude is above 1. Corners that disagree with the
/// majority value are counted and listed as repairs: one corrupted number (a
/// typo) is overwritten instead of spreading to the whole star as a fold.
SanitizeStats sanitizeParameters(const TetMesh& mesh, CornerParams& params, const Transitions& tr,
                                 const SanitizeOptions& opt = {});

/// Orientation sign of every tet's parameter image after sanitization: +1 proper,
/// -1 flipped, 0 degenerate (exact).
std::vector<signed char> classifyTets(const CornerParams& params);

} // namespace HexEx
