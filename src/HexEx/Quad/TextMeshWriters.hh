#pragma once
/// @file TextMeshWriters.hh
/// @ingroup quad
/// Fast text writers of the 2D pipeline (triangle maps as OBJ; quad meshes as OBJ, OFF,
/// PLY): numbers formatted with std::to_chars (the shortest text that reads back to the
/// same double) into large buffers, blocks of elements formatted in parallel and written
/// in order, so the text does not depend on the thread count.

#include "ParametrizedTriMesh.hh"
#include "QuadMesh.hh"

#include <string>

namespace HexEx {

/// OBJ text of @p m: one `v` per point, one `vt` per triangle corner (3 f + k + 1 is the
/// `vt` of corner k of triangle f, so every `vt` is finite and used exactly once) and
/// `f v/vt v/vt v/vt` per triangle, formatted on @p threads threads (0 = all hardware
/// threads; small meshes use one). Throws InputError if a coordinate is not finite.
std::string formatTriObj(const ParametrizedTriMesh& m, int threads = 1);

/// Writes formatTriObj() to @p path. Throws InputError naming the file on a write error.
void writeTriObjFile(const std::string& path, const ParametrizedTriMesh& m, int threads = 1);

/// Text formats of quad meshes.
enum class QuadFileFormat {
    Obj,  ///< `v x y z`, `f a b c d` (1-based)
    Off,  ///< `OFF`, counts, `x y z`, `4 a b c d` (0-based)
    Ply   ///< ASCII PLY 1.0: double x, y, z; faces as a list of int vertex indices
};

/// Text of @p qm in @p format: the vertices, the quads, then the polygons (faces that are
/// not quads), formatted on @p threads threads (0 = all hardware threads; small meshes
/// use one). Throws InputError if a vertex coordinate is not finite.
std::string formatQuadMesh(const QuadMesh& qm, QuadFileFormat format, int threads = 1);

/// Writes formatQuadMesh() to @p path. Throws InputError naming the file on a write error.
void writeQuadMeshFile(const std::string& path, const QuadMesh& qm, QuadFileFormat format, int threads = 1);

} // namespace HexEx
