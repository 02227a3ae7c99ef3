#pragma once
/// @file UntangleReportDict.hh
/// HexEx::UntangleReport as a Python dict, shared by hexex._core.untangle and
/// hexex._core.untangle_with_repair.

#include <HexEx/Untangling/Untangler.hh>

#include <nanobind/nanobind.h>

namespace HexExPython {

/// The report as a dict with the field names of HexEx::UntangleReport (UntangleFunctions.cc).
nanobind::dict untangleReportToDict(const HexEx::UntangleReport& r);

} // namespace HexExPython
