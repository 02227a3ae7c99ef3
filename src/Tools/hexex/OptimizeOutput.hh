#pragma once
/// @file OptimizeOutput.hh
/// The text report of an optimisation run, shared by `hexex optimize` and `hexex extract --optimize`.

#include <HexEx/Untangling/HexOptimizer.hh>

#include <iosfwd>

namespace HexExTool {

/// Writes the report of @p r as indented lines ("optimize: ...") to @p os.
void printOptimizeReport(std::ostream& os, const HexEx::OptimizeReport& r);

} // namespace HexExTool
