#pragma once
/// @file ReportJson.hh
/// @ingroup io
/// The extraction report as JSON (the `--report` file of `hexex extract`).
///
/// The document has this fixed structure (keys are never renamed; more keys may be added):
/// ```
/// {"input":   {"vertices", "tets", "boundary_faces", "flipped_tets", "degenerate_tets",
///              "singular_edges", "parametric_volume", ...},
///  "output":  {"vertices", "hexes", "non_hex_cells", "quads", "boundary_quads", "unconnected_darts"},
///  "darts":   {"extracted", "anti", "annihilated_pairs", ...},
///  "valid_all_hex": bool,
///  "quality": {"min_scaled_jacobian", "mean_scaled_jacobian", "inverted_hexes",
///              "invalid_hexes", "undecided_hexes", "certified_valid"},
///  "timings_s": {"read", "preprocess", "vertices", "darts", "connect", "postprocess",
///                "assemble", "write", "total"},
///  "threads": N, "version": "x.y.z", ...}
/// ```
/// Extra keys: "input" also has "singular_vertices", "ambiguous_transitions",
/// "unresolved_transitions", "snapped_coordinates", "inconsistent_transitions",
/// "repaired_corners" and, when corners were repaired, "repairs" (at most 32 entries
/// {"tet", "corner", "vertex", "original", "repaired"}); "darts" has "remaining_anti" and
/// "asymmetric_links"; top level has "validation" (the validator's counts, "valid" and
/// "summary") and "warnings" (array of strings). In "quality", "inverted_hexes" counts hexes
/// with a corner Jacobian <= 0 (the 8-corner test), "invalid_hexes" hexes whose Jacobian is
/// proved <= 0 somewhere inside (classifyHexValidity()), "undecided_hexes" those the exact
/// test could not decide; "certified_valid" is true when both are 0. Numbers are JSON numbers (doubles in
/// shortest round-trip form); non-finite numbers are written as null.

#include "../Extraction/ExtractionReport.hh"
#include "../Mesh/HexMeshQuality.hh"
#include "../Untangling/HexOptimizer.hh"
#include "../Untangling/Untangler.hh"

#include <string>
#include <vector>

namespace HexEx {

/// What the report needs beyond ExtractionReport: the stages outside the extractor.
struct ReportExtras {
    double read_s = 0;                  ///< seconds spent reading the input
    double write_s = 0;                 ///< seconds spent writing the output
    double total_s = 0;                 ///< wall-clock seconds of the whole run
    QualityStats quality;               ///< quality of the output hexes
    std::vector<std::string> warnings;  ///< more warnings (reader, writer), listed after the report's own
    const UntangleReport* untangle = nullptr;  ///< the untangling run, if any (key `untangle`, same names as Python's report)
    const OptimizeReport* optimize = nullptr;  ///< the optimisation run, if any (key `optimize`, optimizeReportToJson())
};

/// Renders @p report and @p extras as a JSON object (indented, ending with a newline).
std::string reportToJson(const ExtractionReport& report, const ReportExtras& extras);

/// A JSON string literal for @p s (quotes added; `"`, `\`, and control characters escaped;
/// other bytes passed through unchanged).
std::string jsonQuote(const std::string& s);

/// A JSON number for @p x in shortest round-trip form, or `null` if @p x is not finite.
std::string jsonNumber(double x);

} // namespace HexEx
