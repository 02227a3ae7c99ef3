#pragma once
/// @file OvmTetReader.hh
/// @ingroup io
/// Reader and writer of tetrahedral meshes with an integer-grid map in the OpenVolumeMesh
/// formats: ASCII (`.ovm`) and binary (`.ovmb`, recognised by its magic bytes; layout in
/// OvmBinary.cc). Both are parsed into an OvmModel (OvmModel.hh) and checked the same way.
///
/// ## Accepted ASCII layout
/// The file is read line by line. Text from `#` to the end of a line (outside a quoted
/// property name) is a comment; blank lines are skipped; keywords are case-insensitive.
/// ```
/// OVM ASCII
/// Vertices
/// n_v
/// x y z                       (n_v lines)
/// Edges
/// n_e
/// a b                         (n_e lines: vertex indices, halfedge 2e runs a->b, 2e+1 b->a)
/// Faces
/// n_f
/// 3 he0 he1 he2               (n_f lines: valence and halfedges forming a closed loop;
///                              halfface 2f is this loop, 2f+1 the reversed loop)
/// Polyhedra
/// n_c
/// 4 hf0 hf1 hf2 hf3           (n_c lines: valence and halffaces)
/// ENTITY TYPE "name"          (property blocks, as OpenVolumeMesh writes them: one value
/// value                        per line, one line per entity: n_v for VProp, n_e for EProp,
/// ...                          2 n_e for HEProp, n_f for FProp, 2 n_f for HFProp, n_c for
///                              CProp, 1 for MProp)
/// ```
/// The old `OVM BINARY` format is rejected. In `.ovmb` files, the map is a halfface property
/// of type `3d` (vec3d; `3f` is accepted too) with a name as below; chunks must give each
/// entity's values in order (the way OpenVolumeMesh writes them); compressed chunks are
/// rejected, unknown chunk types skipped with a warning. Every face must be a triangle and every polyhedron a
/// tetrahedron: four triangular halffaces over four distinct vertices, consistently
/// oriented (every directed edge used once), no halfface used by two cells.
///
/// ## The integer-grid map
/// It is read from the first property block (in file order) that matches one of:
/// - `HFProp vec3d "NAME"` (or `vec3f`): one parameter `u v w` per halfface. The value of a
///   halfface of cell c is the parameter, in c's chart, of the vertex of c OPPOSITE that
///   halfface. Values of halffaces that belong to no cell are ignored.
/// - `CProp vec12d "NAME"`: twelve numbers per cell, `u0 v0 w0 u1 v1 w1 u2 v2 w2 u3 v3 w3`,
///   the parameters of the cell's corners in the file corner order defined below.
///
/// NAME, after any `X::` prefix (as in `HexHex::Parametrization`, the convention of the
/// OpenVolumeMesh-based tools HexHex and AlgoHex), is compared case-insensitively with: `parametrization`, `parameterization`,
/// `param`, `params`, `parameter`, `parameters`, `uvw`, `igm`. Other property blocks are
/// skipped. No matching block is an error that lists the property blocks found.
///
/// ## Corner order and orientation
/// The *file corner order* of a cell is: the three vertices of its first halfface `hf0` in
/// that halfface's loop order (for halfface 2f: the sources of the face's halfedges in
/// order, starting at the source of the first; for 2f+1: the same loop reversed, starting at
/// the same vertex), followed by the remaining fourth vertex. CProp values are given in this
/// order. The reader then rotates the first three corners (an even permutation, with their
/// parameters) until corner 0 is the vertex opposite the cell's LAST halfface: a tet
/// `a b c d` written as OpenVolumeMesh-based tools and ovmFromTetMesh() write it (halffaces
/// `a b c`, `a c d`, `a d b`, `b d c`) reads back as `a b c d`, so `.hexex` -> `.ovmb` ->
/// extraction gives bit-identical output. The returned TetMesh must be
/// positively oriented in 3D, which depends on whether the file lists halffaces pointing
/// out of their cells or into them (OpenVolumeMesh's convention). The reader computes
/// the exact 3D orientation of every cell in this corner order; within each connected
/// component (cells joined by shared faces) all cells must agree:
/// - all positive: corners are kept;
/// - all negative (outward halffaces): corners 1 and 2 are swapped (with their parameters),
///   so that TetMesh halfface 3 of the cell lies on the file's hf0, with its orientation;
/// - mixed: InputError naming the first cell of the minority (the mesh is folded in 3D);
/// - a cell of zero volume: InputError.
///
/// ## Errors
/// Every problem throws InputError "<file>:<line>: <reason>" (for `.ovmb`:
/// "<file>: byte <offset>: <reason>"; bad header or section
/// keyword, bad or negative counts, indices out of range, faces that are not closed
/// triangles, cells that are not tetrahedra, NaN or infinite numbers, missing
/// parametrization, truncated files, orientation), or "<file>: <reason>" when no line
/// applies (missing file, non-manifold mesh). The returned mesh has its adjacency built.

#include "../Mesh/ParametrizedTetMesh.hh"
#include "HexExFile.hh"
#include "OvmModel.hh"

#include <string>
#include <string_view>

namespace HexEx {

/// Reads a tet mesh with its map from the OpenVolumeMesh ASCII file @p path (see the file
/// overview). Warnings (unused vertices, ignored extra parametrization blocks) are appended
/// to @p report; `report->reoriented` stays false (choosing the halfface orientation
/// convention is not a repair).
/// @throws InputError as described in the file overview.
ParametrizedTetMesh readOvmTetMesh(const std::string& path, ReadReport* report = nullptr);

/// Reads OpenVolumeMesh ASCII data held in memory; @p name is used in error messages.
/// @throws InputError as readOvmTetMesh().
ParametrizedTetMesh readOvmTetBuffer(std::string_view text, const std::string& name, ReadReport* report = nullptr);

/// The tet mesh with its map stored in @p model (see the file overview); warnings go to @p report.
/// @throws InputError at the face or cell at fault.
ParametrizedTetMesh tetMeshFromOvm(const OvmModel& model, ReadReport* report = nullptr);

/// The OpenVolumeMesh model of @p pm: tet `a b c d` becomes the cell of halffaces `a b c`,
/// `a c d`, `a d b`, `b d c` (pointing into the cell, as OpenVolumeMesh orients them; the
/// opposite corners are d, b, c, a), faces and edges numbered in order of first use, the
/// map as halfface parameters (halffaces of no cell get 0).
/// @throws std::invalid_argument if the parameter count does not match the cell count.
OvmModel ovmFromTetMesh(const ParametrizedTetMesh& pm);

/// Writes @p pm with its map to @p path as OpenVolumeMesh binary (@p binary) or ASCII.
/// @throws InputError naming the path if it cannot be written; std::invalid_argument as ovmFromTetMesh().
void writeOvmTetMesh(const std::string& path, const ParametrizedTetMesh& pm, bool binary);

} // namespace HexEx
