#pragma once
/// @file TetMeshInput.hh
/// @ingroup io
/// Reading a parametrized tet mesh in any supported input format, chosen by extension.

#include "HexExFile.hh"

#include <string>

namespace HexEx {

/// Reads @p path as OpenVolumeMesh if it ends in `.ovm` or `.ovmb` (any case), as `.hexex`
/// otherwise; `-` reads `.hexex` from standard input. Throws InputError like the readers.
ParametrizedTetMesh readParametrizedTetMesh(const std::string& path, ReadReport* report = nullptr);

} // namespace HexEx
