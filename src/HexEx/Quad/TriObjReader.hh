#pragma once
/// @file TriObjReader.hh
/// @ingroup quad
/// A fast reader for OBJ triangle meshes with per-corner texture coordinates (`v`, `vt`,
/// `f v/vt` or `f v/vt/vn`), the input format of the 2D pipeline. The text is cut into
/// chunks at line boundaries, counted, then parsed in place with std::from_chars, one
/// chunk per thread; the result does not depend on the thread count.

#include "ParametrizedTriMesh.hh"

#include <string>
#include <string_view>

namespace HexEx {

/// Parses the OBJ text @p text (named @p name in errors) into a ParametrizedTriMesh:
/// points in `v` order, triangles in `f` order with their corners in the order written,
/// the parameter of each corner taken from its `vt` (the first two components; a third
/// is ignored). Negative (relative) indices are resolved as in the OBJ specification;
/// `vn`, `o`, `g`, `s`, `usemtl`, `mtllib`, `l`, comments and other lines are ignored.
/// Throws InputError "<name>:<line>: <reason>" for a malformed number, a non-finite
/// coordinate, a face that is not a triangle, a corner without `vt` index, an index out of
/// range; "<name>: no faces" for a file without faces. Parsed on @p threads threads (0 =
/// all hardware threads; at most one per MB of text); the result does not depend on it.
ParametrizedTriMesh parseTriObj(std::string_view text, const std::string& name, int threads = 1);

/// Reads the file @p path (memory-mapped where POSIX mmap exists, else read whole) and
/// parses it with parseTriObj(). Throws InputError naming the file if it cannot be opened
/// or read.
ParametrizedTriMesh readTriObjFile(const std::string& path, int threads = 1);

} // namespace HexEx
