#pragma once
/// @file TriangleSurfaceReader.hh
/// @ingroup quality
/// Reading a triangle surface (the surface an optimised hex mesh's boundary must stay on)
/// from .obj, .off, .ply or .stl files through OpenMesh's readers.

#include "TriangleSurface.hh"

#include <string>

namespace HexEx {

/// Reads the surface mesh @p path (.obj, .off, .ply or .stl, by extension, case-insensitive)
/// with OpenMesh's readers; polygons are split into triangle fans. Vertices are kept in file
/// order (STL files are welded by OpenMesh's reader).
/// @throws InputError "<path>: <reason>" for an unknown extension, a file that cannot be
///         read, or a surface without faces.
TriangleSurface readTriangleSurface(const std::string& path);

} // namespace HexEx
