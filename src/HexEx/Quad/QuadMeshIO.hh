#pragma once
/// @file QuadMeshIO.hh
/// @ingroup quad
/// Files of the 2D pipeline: triangle meshes with per-corner parameters as OBJ with `vt`
/// texture coordinates (read and written by TriObjReader.hh / TextMeshWriters.hh, parameters as
/// doubles, exact round trip), quad meshes as OBJ, OFF or PLY (TextMeshWriters.hh) or VTU
/// (a small writer here, VTK_QUAD / VTK_POLYGON cells).

#include "ParametrizedTriMesh.hh"
#include "QuadMesh.hh"

#include <string>

namespace HexEx {

/// Reads a triangle mesh with per-corner texture coordinates (`vt`, `f v/vt`) from an OBJ
/// file (parseTriObj()). Throws InputError naming the file (and the line) if it is not
/// .obj, cannot be read, is malformed or has no faces. Whether the surface is a manifold
/// is checked by the extraction (buildTriAdjacency()). Parsed on @p threads threads (0 =
/// all hardware threads); the result does not depend on it.
ParametrizedTriMesh readParametrizedTriMesh(const std::string& path, int threads = 1);

/// Writes @p m as OBJ with one `vt` per triangle corner (formatTriObj(): shortest
/// round-trip doubles, read back exactly by readParametrizedTriMesh(), and readable by
/// OpenMesh's OBJ reader). Throws InputError naming the file for a non-finite coordinate
/// or a write error.
void writeParametrizedTriMesh(const std::string& path, const ParametrizedTriMesh& m, int threads = 1);

/// Writes @p qm by extension: .obj, .off, .ply (ASCII) with writeQuadMeshFile(), .vtu as
/// VTK XML unstructured grid (ASCII). Throws
/// InputError for an unknown extension or a write error.
void writeQuadMesh(const std::string& path, const QuadMesh& qm, int threads = 1);

} // namespace HexEx
