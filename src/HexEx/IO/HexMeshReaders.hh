#pragma once
/// @file HexMeshReaders.hh
/// @ingroup io
/// Readers of hex mesh files (for `hexex validate` and round-trip tests): the formats of
/// HexMeshWriters.hh, also as written by other tools where the format allows.
///
/// - `.vtk` legacy ASCII UNSTRUCTURED_GRID (versions 2.0 to 4.2 with CELLS count lists and
///   version 5.1 with OFFSETS / CONNECTIVITY). Hexahedra (12) and voxels (11) become hexes;
///   tetrahedra (10), wedges (13), pyramids (14) and polyhedra (42, version <= 4.2 face
///   streams) become polyhedra; polygons (5, 7, 9) are grouped into polyhedra by the
///   cell-data array `hexex_cell_id` when present (see writeHexMesh()), otherwise each one is
///   a one-face polyhedron (a non-hex cell).
/// - `.vtu` VTK XML UnstructuredGrid with ASCII data arrays (one or more pieces); cell
///   types as for `.vtk`, polyhedra from the `faces` / `faceoffsets` arrays.
/// - `.mesh` Medit ASCII: `Vertices`, `Hexahedra` (VTK order), `Tetrahedra`, `Prisms`,
///   `Pyramids` (as polyhedra); surface and feature sections are skipped; `#` comments.
/// - `.ovm` OpenVolumeMesh ASCII. Cells of six quads that close up like a hex become hexes
///   (VTK order derived from the faces); all other cells become polyhedra. Halfface
///   orientation is taken from the file: outward as written by writeHexMesh(); if the total
///   signed volume of the cells is negative the file is taken to use inward halffaces and
///   every face loop is reversed. Anything after the `Polyhedra` section (properties) is ignored.
///
/// Every index is bounds-checked; malformed input never crashes or hangs.

#include "../Mesh/HexMesh.hh"
#include "HexMeshWriters.hh"

#include <string>
#include <string_view>

namespace HexEx {

/// Reads the hex mesh file @p path; the format is chosen by the extension as for writeHexMesh().
/// @throws InputError with a message "<file>:<line>: <reason>" for malformed input, or
///         "<file>: <reason>" when no line applies (unknown extension, unreadable file,
///         missing section).
HexMesh readHexMesh(const std::string& path);

/// Reads hex mesh data in @p format held in memory; @p name is used in error messages.
/// @throws InputError as readHexMesh().
HexMesh readHexMeshBuffer(std::string_view text, HexMeshFormat format, const std::string& name);

namespace detail {
/// Reads a legacy VTK file held in memory (LegacyVtkReader.cc); errors as readHexMesh().
HexMesh readLegacyVtk(std::string_view text, const std::string& name);
/// Reads a VTK XML UnstructuredGrid file held in memory (VtuReader.cc); errors as readHexMesh().
HexMesh readVtu(std::string_view text, const std::string& name);
} // namespace detail

} // namespace HexEx
