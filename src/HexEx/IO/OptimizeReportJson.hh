#pragma once
/// @file OptimizeReportJson.hh
/// @ingroup io
/// An OptimizeReport as a JSON object (`hexex optimize --json`, the key `optimize` of the
/// extraction report). Keys are the field names of HexEx::OptimizeReport; the histograms
/// are arrays of 20 counts over [-1, 1] (bin i covers [-1 + 0.1 i, -0.9 + 0.1 i)).

#include "../Untangling/HexOptimizer.hh"

#include <string>

namespace HexEx {

/// Renders @p report as a JSON object whose closing brace is indented by @p indent spaces
/// (no trailing newline).
std::string optimizeReportToJson(const OptimizeReport& report, int indent = 0);

} // namespace HexEx
