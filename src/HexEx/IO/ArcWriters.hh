#pragma once
/// @file ArcWriters.hh
/// @ingroup io
/// Writers for the edge arcs and face patches of an extraction (HexArcs) as VTK XML
/// UnstructuredGrid (.vtu, ASCII): a small writer of its own, since these are polylines and
/// triangle soups rather than hex meshes.

#include "../Mesh/HexArcs.hh"

#include <string>

namespace HexEx {

/// Writes every formed edge arc as a VTK_POLY_LINE cell with the cell data `edge_id` (the
/// hex-mesh edge id), `vertex0` and `vertex1` (its hex-mesh vertices).
/// @throws InputError naming @p path if it cannot be written.
void writeEdgeArcsVtu(const std::string& path, const HexArcs& arcs);

/// Writes every triangle of every formed face patch as a VTK_TRIANGLE cell with the cell
/// data `face_id` (the hex-mesh face id).
/// @throws InputError naming @p path if it cannot be written.
void writeFacePatchesVtu(const std::string& path, const HexArcs& arcs);

} // namespace HexEx
