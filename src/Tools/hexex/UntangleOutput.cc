/// @file UntangleOutput.cc
/// Text report of an untangling run.

#include "UntangleOutput.hh"

#include <iomanip>
#include <ostream>

namespace HexExTool {

void printUntangleReport(std::ostream& os, const HexEx::UntangleReport& r) {
    const auto flags = os.flags();
    const auto prec = os.precision();
    os << std::setprecision(4);
    os << "untangle: invalid hexes " << r.invalid_before << " -> " << r.invalid_after << " of " << r.hexes
       << " (certified: J > 0 on the whole hex); undecided " << r.undecided_before << " -> " << r.undecided_after << "\n"
       << "untangle: inverted hexes " << r.inverted_before << " -> " << r.inverted_after << " of " << r.hexes
       << " (a corner Jacobian <= 0)\n"
       << "untangle: scaled Jacobian min " << r.min_scaled_jacobian_before << " -> " << r.min_scaled_jacobian_after
       << ", mean " << r.mean_scaled_jacobian_before << " -> " << r.mean_scaled_jacobian_after << "\n"
       << "untangle: vertices moved " << r.moved_vertices << " (free " << r.free_vertices << ", "
       << (r.rings < 0 ? std::string("whole mesh") : std::to_string(r.rings) + " rings") << "), displacement max "
       << r.max_displacement << ", mean " << r.mean_displacement << " of the bbox diagonal\n"
       << "untangle: iterations " << r.outer_iterations << " regularisation steps, " << r.lbfgs_iterations
       << " L-BFGS (+" << r.quality_iterations << " for quality), " << r.attempts << " neighbourhood(s); time " << std::setprecision(3) << r.seconds << " s\n";
    if (r.released_feature_vertices > 0)
        os << "untangle: " << r.released_feature_vertices
           << " vertices on feature curves/corners released onto the surface (their hexes stayed inverted with them kept)\n";
    if (!r.message.empty()) os << "untangle: " << r.message << "\n";
    os.flags(flags);
    os.precision(prec);
}

} // namespace HexExTool
