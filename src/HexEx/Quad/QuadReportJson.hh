#pragma once
/// @file QuadReportJson.hh
/// @ingroup quad
/// The 2D extraction report as JSON (the `--report` file of `hexex quad`), with the keys of
/// the 3D report where they apply (ReportJson.hh): "input" {"vertices", "triangles",
/// "boundary_edges", "flipped_triangles", "degenerate_triangles", "cones",
/// "parametric_area", "ambiguous_transitions", "unresolved_transitions", "snapped_coordinates"}, "output" {"vertices",
/// "quads", "non_quad_faces", "edges", "boundary_edges", "unconnected_darts",
/// "dropped_faces"}, "darts" {"extracted", "anti", "annihilated_pairs", "remaining_anti",
/// "asymmetric_links"}, "valid_all_quad", "validation" (counts, "valid", "summary"),
/// "timings_s" {"read", "preprocess", "darts", "connect", "postprocess", "assemble",
/// "write", "total"}, "threads", "version", "warnings".

#include "QuadExtraction.hh"

#include <string>

namespace HexEx {

/// Stages outside the extractor.
struct QuadReportExtras {
    double read_s = 0;   ///< seconds spent reading the input
    double write_s = 0;  ///< seconds spent writing the output
    double total_s = 0;  ///< wall-clock seconds of the whole run
};

/// Renders @p r and @p extras as a JSON object (indented, ending with a newline).
std::string quadReportToJson(const QuadExtractionReport& r, const QuadReportExtras& extras);

} // namespace HexEx
