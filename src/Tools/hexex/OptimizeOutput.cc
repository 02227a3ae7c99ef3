/// @file OptimizeOutput.cc
/// Text report of an optimisation run.

#include "OptimizeOutput.hh"

#include <iomanip>
#include <ostream>

namespace HexExTool {

void printOptimizeReport(std::ostream& os, const HexEx::OptimizeReport& r) {
    const auto flags = os.flags();
    const auto prec = os.precision();
    os << std::setprecision(4);
    os << "optimize: scaled Jacobian min " << r.min_scaled_jacobian_before << " -> " << r.min_scaled_jacobian_after
       << ", mean " << r.mean_scaled_jacobian_before << " -> " << r.mean_scaled_jacobian_after << " (" << r.hexes
       << " hexes)\n";
    if (r.trimmed_hexes > 0)
        os << "optimize: removed " << r.trimmed_hexes << " hexes outside the input surface (a fold of the map) "
           << "before the layer\n";
    if (r.pillowed_hexes > 0)
        os << "optimize: pillowed: " << r.pillowed_hexes << " hexes and " << r.pillow_vertices
           << " vertices added along the boundary (min " << r.min_scaled_jacobian_pillowed << " after, "
           << r.pillow_invalid << " hexes not certified valid before untangling)\n";
    if (r.min_scaled_jacobian_projected != r.min_scaled_jacobian_before)
        os << "optimize: min " << r.min_scaled_jacobian_projected << " after putting the boundary on the surface\n";
    os << "optimize: hexes not certified valid " << r.invalid_before << " -> " << r.invalid_after << "\n"
       << "optimize: vertices free " << r.free_vertices << " (on surface " << r.surface_vertices << ", on curves "
       << r.curve_vertices << "), at corners " << r.corner_vertices << ", fixed " << r.fixed_vertices;
    if (r.unprojected_vertices > 0) os << " (" << r.unprojected_vertices << " could not be put on the surface)";
    os << "; surface: " << r.feature_curves << " feature curves, " << r.feature_corners << " corners\n"
       << "optimize: distance to the surface max " << r.max_surface_distance / (r.diagonal > 0 ? r.diagonal : 1)
       << ", mean " << r.mean_surface_distance / (r.diagonal > 0 ? r.diagonal : 1) << "; feature vertices to their curve max "
       << r.max_feature_distance / (r.diagonal > 0 ? r.diagonal : 1) << " (of the bbox diagonal)\n"
       << "optimize: " << r.accepted_blocks << " of " << r.global_blocks << " L-BFGS blocks accepted ("
       << r.lbfgs_iterations << " iterations), " << r.local_moves << " vertex moves in " << r.local_passes
       << " passes; time " << std::setprecision(3) << r.seconds << " s\n";
    if (!r.message.empty()) os << "optimize: " << r.message << "\n";
    os.flags(flags);
    os.precision(prec);
}

} // namespace HexExTool
