#include "QuadReportJson.hh"

#include "../Core/Version.hh"
#include "../IO/ReportJson.hh"

#include <sstream>

namespace HexEx {

std::string quadReportToJson(const QuadExtractionReport& r, const QuadReportExtras& x) {
    std::ostringstream o;
    auto n = [](double v) { return jsonNumber(v); };
    o << "{\n  \"input\": {\"vertices\": " << r.input.vertices << ", \"triangles\": " << r.input.triangles
      << ", \"boundary_edges\": " << r.input.boundary_edges << ", \"flipped_triangles\": " << r.input.flipped_triangles
      << ", \"degenerate_triangles\": " << r.input.degenerate_triangles << ", \"cones\": " << r.input.cones
      << ", \"parametric_area\": " << n(r.input.parametric_area)
      << ", \"ambiguous_transitions\": " << r.input.ambiguous_transitions
      << ", \"unresolved_transitions\": " << r.input.unresolved_transitions
      << ", \"snapped_coordinates\": " << r.input.snapped_coordinates << "},\n";
    o << "  \"output\": {\"vertices\": " << r.output.vertices << ", \"quads\": " << r.output.quads
      << ", \"non_quad_faces\": " << r.output.non_quad_faces << ", \"edges\": " << r.output.edges
      << ", \"boundary_edges\": " << r.output.boundary_edges << ", \"unconnected_darts\": " << r.output.unconnected_darts
      << ", \"dropped_faces\": " << r.output.dropped_faces << "},\n";
    o << "  \"darts\": {\"extracted\": " << r.darts.extracted << ", \"anti\": " << r.darts.anti
      << ", \"annihilated_pairs\": " << r.darts.annihilated_pairs << ", \"remaining_anti\": " << r.darts.remaining_anti
      << ", \"asymmetric_links\": " << r.darts.asymmetric_links << "},\n";
    o << "  \"valid_all_quad\": " << (r.valid_all_quad ? "true" : "false") << ",\n";
    const QuadGMapValidation& v = r.validation;
    o << "  \"validation\": {\"darts\": " << v.darts << ", \"not_involution\": " << v.not_involution
      << ", \"open_links\": " << v.open_links << ", \"eq1_edge_connection\": " << v.eq1_edge_connection
      << ", \"eq3_quad\": " << v.eq3_quad << ", \"boundary_darts\": " << v.boundary_darts
      << ", \"valid\": " << (v.valid() ? "true" : "false") << ", \"summary\": " << jsonQuote(v.summary()) << "},\n";
    o << "  \"timings_s\": {\"read\": " << n(x.read_s) << ", \"preprocess\": " << n(r.timings_s.preprocess)
      << ", \"darts\": " << n(r.timings_s.darts) << ", \"connect\": " << n(r.timings_s.connect)
      << ", \"postprocess\": " << n(r.timings_s.postprocess) << ", \"assemble\": " << n(r.timings_s.assemble)
      << ", \"write\": " << n(x.write_s) << ", \"total\": " << n(x.total_s) << "},\n";
    o << "  \"threads\": " << r.threads << ",\n  \"version\": " << jsonQuote(version()) << ",\n  \"warnings\": [";
    for (std::size_t i = 0; i < r.warnings.size(); ++i) o << (i ? ", " : "") << jsonQuote(r.warnings[i]);
    o << "]\n}\n";
    return o.str();
}

} // namespace HexEx
