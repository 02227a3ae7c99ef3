#pragma once
/// @file UntangleOutput.hh
/// The text report of an untangling run, shared by `hexex untangle` and `hexex extract --untangle`.

#include <HexEx/Untangling/Untangler.hh>

#include <iosfwd>
#include <string>

namespace HexExTool {

/// Writes the report of @p r as indented lines ("untangle: ...") to @p os.
void printUntangleReport(std::ostream& os, const HexEx::UntangleReport& r);

} // namespace HexExTool
