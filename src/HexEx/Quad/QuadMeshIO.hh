#pragma once
/// @file QuadMeshIO.hh
/// Files of the 2D pipeline, through OpenMesh's IO: triangle meshes with per-corner
/// parameters as OBJ with `vt` texture coordinates (read and written), quad meshes as
/// OBJ, OFF or PLY (OpenMesh) or VTU (a small writer here, VTK_QUAD / VTK_POLYGON cells).
///
/// OpenMesh's IO passes texture coordinates as single-precision floats, so parameters are
/// read and written with a 24-bit mantissa: integers and short dyadic fractions are exact,
/// other values are rounded by about 1e-7 relative (sanitization makes the map consistent
/// again; grid-aligned boundaries and cones stay exact).

#include "ParametrizedTriMesh.hh"
#include "QuadMesh.hh"

#include <string>

namespace HexEx {

/// Reads a triangle mesh with per-corner texture coordinates (`vt`, `f v/vt`) from an OBJ
/// file through OpenMesh. Throws InputError naming the file if it cannot be read, has no
/// faces, has no texture coordinates or OpenMesh dropped faces it could not add
/// (non-manifold or inconsistently oriented).
ParametrizedTriMesh readParametrizedTriMesh(const std::string& path);

/// Writes @p m as OBJ with one `vt` per corner parameter through OpenMesh (17 significant
/// digits, parameters as floats; see the file comment). Throws InputError if the mesh cannot be
/// converted (e.g. non-manifold) or the file cannot be written.
void writeParametrizedTriMesh(const std::string& path, const ParametrizedTriMesh& m);

/// Writes @p qm by extension: .obj, .off, .ply through OpenMesh's PolyMesh, .vtu as VTK XML
/// unstructured grid (ASCII). Throws InputError for an unknown extension or a write error.
void writeQuadMesh(const std::string& path, const QuadMesh& qm);

} // namespace HexEx
