#pragma once
/// @file BoundarySurface.hh
/// @ingroup quality
/// The boundary surface of an output hex mesh as an OpenMesh polygonal surface mesh, and a
/// writer for it (.obj, .off, .ply, .stl through OpenMesh's IO).
///
/// A face of the HexMesh is a boundary face if exactly one cell uses it (faces are
/// identified by their vertex sets, so orientation and starting vertex do not matter; faces
/// of hexes and of polyhedra are pooled, as in checkHexMesh()). Hex faces come from the VTK
/// vertex order (kHexFaces) and are oriented outward; polyhedron faces keep the loop given
/// in the Polyhedron (outward by the HexMesh convention).
///
/// There is deliberately no HexMeshOutputTraits adapter that produces a surface directly:
/// the output concept (MeshTraits.hh) has no "done" call after the last cell, and the
/// boundary is only known once every cell has been seen. Extract into a HexMesh and call
/// boundarySurface() on it.
///
/// Example:
/// ```
/// HexEx::HexMesh hm;
/// HexEx::extractHexMesh(input, hm);
/// HexEx::SurfaceMesh surface = HexEx::boundarySurface(hm);   // OpenMesh PolyMesh
/// HexEx::writeBoundarySurface("boundary.obj", hm);
/// ```

#include "HexMesh.hh"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <cstddef>
#include <string>
#include <vector>

namespace HexEx {

/// The surface mesh type of boundarySurface(): OpenMesh's array-kernel polygonal mesh with
/// double-precision points (`OpenMesh::DefaultTraitsDouble`, points are Vec3d), so positions
/// are copied without rounding.
using SurfaceMesh = OpenMesh::PolyMesh_ArrayKernelT<OpenMesh::DefaultTraitsDouble>;

/// What boundarySurface() did besides copying boundary faces.
struct BoundarySurfaceReport {
    std::size_t boundary_faces = 0;  ///< faces used by exactly one cell (quads and others)
    std::size_t boundary_quads = 0;  ///< boundary faces with four vertices
    std::size_t split_faces = 0;     ///< boundary faces that would make the surface non-manifold; added with their own copies of their vertices
    std::size_t skipped_faces = 0;   ///< boundary faces with fewer than three distinct vertices (left out)
};

/// The boundary faces of @p mesh as a polygonal surface (see the file overview).
///
/// Only vertices referenced by boundary faces are copied, compacted in ascending order of
/// their HexMesh index (so surface vertex k is the k-th referenced HexMesh vertex). Faces
/// appear in cell order: hexes first (faces in kHexFaces order), then polyhedra. A face
/// that OpenMesh cannot attach without making the surface non-manifold (possible for
/// defective extractions) is added with private copies of its vertices and counted in
/// @p report; faces with fewer than three distinct vertices are left out and counted.
///
/// @throws std::invalid_argument if a cell references a vertex index out of range.
SurfaceMesh boundarySurface(const HexMesh& mesh, BoundarySurfaceReport* report = nullptr);

/// True if @p path has one of the extensions writeSurfaceMesh() understands
/// (.obj, .off, .ply, .stl; case-insensitive).
bool isSurfaceMeshPath(const std::string& path);

/// Writes @p surface to @p path through `OpenMesh::IO::write_mesh`, format by extension:
/// `.obj`, `.off`, `.ply` or `.stl`, all ASCII. OpenMesh's writers store positions in
/// single precision (written with 9 significant digits, enough to identify each float). For `.stl` the faces of a copy are triangulated first, since STL stores
/// triangles only. OpenMesh's informational log (`omlog`) is muted during the write, so
/// nothing is printed on success.
/// @throws InputError "<path>: <reason>" for an unknown extension or if the file cannot be
///         written.
void writeSurfaceMesh(const std::string& path, const SurfaceMesh& surface);

/// Computes boundarySurface() of @p mesh and writes it with writeSurfaceMesh().
/// @return warnings, each starting with "<path>: " (faces split or skipped, see
///         BoundarySurfaceReport); empty if the surface was written as is.
/// @throws InputError as writeSurfaceMesh(); std::invalid_argument as boundarySurface().
std::vector<std::string> writeBoundarySurface(const std::string& path, const HexMesh& mesh);

} // namespace HexEx
