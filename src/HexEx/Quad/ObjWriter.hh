#pragma once
/// @file ObjWriter.hh
/// Fast OBJ writers of the 2D pipeline: numbers formatted with std::to_chars (shortest
/// text that reads back to the same double) into large buffers, chunks of elements
/// formatted in parallel and written in order, so the text does not depend on the thread
/// count.

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

/// OBJ text of @p qm: one `v` per vertex, `f a b c d` per quad, then `f ...` per polygon.
std::string formatQuadObj(const QuadMesh& qm, int threads = 1);

/// Writes formatQuadObj() to @p path. Throws InputError naming the file on a write error.
void writeQuadObjFile(const std::string& path, const QuadMesh& qm, int threads = 1);

} // namespace HexEx
