#pragma once
/// @file Version.hh
/// @ingroup kernel
/// The library's version, for reports and bindings.

namespace HexEx {

/// Library version string (x.y.z): the `project(HexEx VERSION ...)` of the top-level CMakeLists.txt.
const char* version();

} // namespace HexEx
