#pragma once
/// @file HexMeshWriters.hh
/// @ingroup io
/// Writers of the output hex mesh (HexMesh) in the formats the `hexex` tool supports,
/// chosen by file extension:
///
/// - `.vtu`  VTK XML UnstructuredGrid (opens in ParaView). Hexes are VTK_HEXAHEDRON (12);
///           polyhedra are VTK_POLYHEDRON (42) with `faces` / `faceoffsets` arrays. Encoding
///           (VtuEncoding): binary by default (raw appended data, UInt64 headers, Float64
///           points, Int32 indices), zlib-compressed, or ASCII.
/// - `.vtk`  legacy VTK (DataFile Version 3.0), ASCII UNSTRUCTURED_GRID. Hexes are
///           VTK_HEXAHEDRON (12). Legacy files have no portable polyhedron syntax, so every
///           face of a polyhedron is written as its own VTK_POLYGON (7) cell; when there are
///           polyhedra, the cell-data array `hexex_cell_id` (int) gives for every VTK cell
///           the index of the HexMesh cell it belongs to (hexes first, then polyhedra), and
///           readHexMesh() uses it to reassemble the polyhedra.
/// - `.ovm`, `.ovmb`  OpenVolumeMesh ASCII or binary (OvmModel.hh). Halfedge 2e+o runs from the edge's first vertex to its
///           second for o = 0; halfface 2f+o is the face's own vertex loop for o = 0 and the
///           reversed loop for o = 1. Convention of this writer: every cell lists its
///           halffaces oriented outward (counter-clockwise seen from outside the cell);
///           hexes list their six halffaces in the order of OpenVolumeMesh's hexahedral
///           kernel (`.ovmb` files of hexes only are marked hexahedral). A face shared by
///           two cells is stored once, with the orientation of its first occurrence.
/// - `.mesh` Medit (MeshVersionFormatted 2, Dimension 3) with `Vertices` and `Hexahedra`
///           (1-based, VTK vertex order, reference 0). Medit has no polyhedra: non-hex
///           cells are left out and the writer returns a warning saying how many.
///
/// Positions are written with 17 significant digits, so they read back bit-identically.

#include "../Mesh/HexFaceNeighbours.hh"
#include "../Mesh/HexMesh.hh"

#include <array>
#include <iosfwd>
#include <string>
#include <vector>

namespace HexEx {

/// File formats of hex meshes.
enum class HexMeshFormat {
    Vtu,    ///< VTK XML UnstructuredGrid (`.vtu`)
    Vtk,    ///< legacy VTK (`.vtk`)
    Ovm,    ///< OpenVolumeMesh ASCII (`.ovm`)
    Ovmb,   ///< OpenVolumeMesh binary (`.ovmb`)
    Medit,  ///< Medit / GMF ASCII (`.mesh`)
};

/// How `.vtu` data arrays are stored.
enum class VtuEncoding {
    Binary,      ///< raw appended data (compact and fast; the default)
    Compressed,  ///< raw appended data, zlib-compressed (vtkZLibDataCompressor)
    Ascii,       ///< text inside the DataArray elements (for reading by eye)
};

/// The encoding named @p name: "binary", "compressed" or "ascii".
/// @throws std::invalid_argument for any other name.
VtuEncoding vtuEncodingFromName(const std::string& name);

/// The format named by the extension of @p path (case-insensitive).
/// @throws InputError naming the path if the extension is none of .vtu, .vtk, .ovm, .ovmb, .mesh.
HexMeshFormat hexMeshFormatFromPath(const std::string& path);

/// Writes @p mesh in @p format to @p out (`.vtu` data arrays in @p encoding), in blocks of
/// about 1 MiB; text is formatted and `.ovm`/`.ovmb` faces are numbered on @p threads
/// threads (0 = all hardware threads); the bytes do not depend on the thread count.
/// With @p neighbours (the hexes' face neighbours from the extraction, extractHexMesh()) the
/// `.ovm`/`.ovmb` faces are numbered from that table if it is the one of @p mesh, instead of
/// matching the quads (the same bytes); it is used up (left empty) by those formats.
/// @return warnings (e.g. cells a format cannot store); empty if everything was written.
/// @throws std::invalid_argument if the mesh references a vertex out of range or has a
///         polyhedron face with fewer than three vertices.
std::vector<std::string> writeHexMeshStream(std::ostream& out, const HexMesh& mesh, HexMeshFormat format,
                                            VtuEncoding encoding = VtuEncoding::Binary, int threads = 0,
                                            HexFaceNeighbours* neighbours = nullptr);

/// Writes @p mesh to @p path in the format given by its extension (see the file overview),
/// on @p threads threads and with @p neighbours as writeHexMeshStream().
/// @return warnings, each starting with "<path>: "; empty if everything was written.
/// @throws InputError naming the path for an unknown extension or an unwritable path;
///         std::invalid_argument as writeHexMeshStream().
std::vector<std::string> writeHexMesh(const std::string& path, const HexMesh& mesh,
                                      VtuEncoding encoding = VtuEncoding::Binary, int threads = 0,
                                      HexFaceNeighbours* neighbours = nullptr);

/// Writes singular edges as legacy VTK POLYDATA: @p points, line @p segments (pairs of
/// point indices) and a cell-data scalar `valence` (one value per segment, @p valences).
/// @throws std::invalid_argument if a segment index is out of range or the sizes of
///         @p segments and @p valences differ; InputError naming the path if it cannot be written.
void writeSingularEdgesVtk(const std::string& path, const std::vector<Vec3d>& points,
                           const std::vector<std::array<int, 2>>& segments, const std::vector<int>& valences);

} // namespace HexEx
