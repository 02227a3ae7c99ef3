/// @file OptimizeReportJson.cc
/// JSON rendering of the optimisation report.

#include "OptimizeReportJson.hh"

#include "ReportJson.hh"

#include <sstream>

namespace HexEx {

std::string optimizeReportToJson(const OptimizeReport& r, int indent) {
    std::ostringstream out;
    const std::string pad(static_cast<std::size_t>(indent + 2), ' ');
    bool first = true;
    auto key = [&](const char* k) {
        out << (first ? "{\n" : ",\n") << pad << jsonQuote(k) << ": ";
        first = false;
    };
    auto num = [&](const char* k, double v) { key(k), out << jsonNumber(v); };
    auto count = [&](const char* k, long v) { key(k), out << v; };
    auto hist = [&](const char* k, const std::vector<long>& h) {
        key(k);
        out << "[";
        for (std::size_t i = 0; i < h.size(); ++i) out << (i ? ", " : "") << h[i];
        out << "]";
    };
    count("hexes", r.hexes);
    num("min_scaled_jacobian_before", r.min_scaled_jacobian_before);
    num("mean_scaled_jacobian_before", r.mean_scaled_jacobian_before);
    num("min_scaled_jacobian_projected", r.min_scaled_jacobian_projected);
    num("min_scaled_jacobian_after", r.min_scaled_jacobian_after);
    num("mean_scaled_jacobian_after", r.mean_scaled_jacobian_after);
    count("invalid_before", r.invalid_before);
    count("invalid_after", r.invalid_after);
    hist("histogram_before", r.histogram_before);
    hist("histogram_after", r.histogram_after);
    count("free_vertices", r.free_vertices);
    count("surface_vertices", r.surface_vertices);
    count("curve_vertices", r.curve_vertices);
    count("corner_vertices", r.corner_vertices);
    count("fixed_vertices", r.fixed_vertices);
    count("unprojected_vertices", r.unprojected_vertices);
    count("feature_curves", r.feature_curves);
    count("feature_corners", r.feature_corners);
    num("diagonal", r.diagonal);
    num("max_surface_distance", r.max_surface_distance);
    num("mean_surface_distance", r.mean_surface_distance);
    num("max_feature_distance", r.max_feature_distance);
    num("mean_feature_distance", r.mean_feature_distance);
    count("global_blocks", r.global_blocks);
    count("accepted_blocks", r.accepted_blocks);
    count("lbfgs_iterations", r.lbfgs_iterations);
    count("local_passes", r.local_passes);
    count("local_moves", r.local_moves);
    num("seconds", r.seconds);
    count("pillowed_hexes", r.pillowed_hexes);
    count("pillow_vertices", r.pillow_vertices);
    count("trimmed_hexes", r.trimmed_hexes);
    num("min_scaled_jacobian_pillowed", r.min_scaled_jacobian_pillowed);
    count("pillow_invalid", r.pillow_invalid);
    key("reached_target"), out << (r.reached_target ? "true" : "false");
    key("success"), out << (r.success ? "true" : "false");
    key("message"), out << jsonQuote(r.message);
    out << "\n" << std::string(static_cast<std::size_t>(indent), ' ') << "}";
    return out.str();
}

} // namespace HexEx
