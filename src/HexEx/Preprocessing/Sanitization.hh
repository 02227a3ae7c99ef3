#pragma once
/// @file Sanitization.hh
/// Sanitization of the parametrization (paper 4.1.2): after it, the parameters of every
/// vertex in all its tets are related exactly by the transitions, so every later predicate
/// is exact and consistent across charts.

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
    int snapped_coordinates = 0;  ///< coordinates moved onto an integer
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
SanitizeStats sanitizeParameters(const TetMesh& mesh, CornerParams& params, const Transitions& tr,
                                 const SanitizeOptions& opt = {});

/// Orientation sign of every tet's parameter image after sanitization: +1 proper,
/// -1 flipped, 0 degenerate (exact).
std::vector<signed char> classifyTets(const CornerParams& params);

} // namespace HexEx
