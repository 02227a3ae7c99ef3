#pragma once
/// @file HexExFile.hh
/// @ingroup io
/// Reader and writer of the `.hexex` format: a tet mesh with its integer-grid map given
/// per tet corner.
///
/// The format is plain text, whitespace-separated (line breaks carry no meaning, but the
/// reader tracks them for its error messages):
/// ```
/// n_vertices
/// x y z                      (n_vertices times)
/// n_tets
/// a b c d  u0 v0 w0  u1 v1 w1  u2 v2 w2  u3 v3 w3     (n_tets times)
/// ```
/// `a b c d` are 0-based vertex indices; `(ui vi wi)` is the parameter of corner i in that
/// tet's own chart.

#include "../Mesh/ParametrizedTetMesh.hh"

#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace HexEx {

/// What the reader noticed and fixed without failing.
struct ReadReport {
    std::vector<std::string> warnings;  ///< human-readable warnings, "<file>: <text>"
    bool reoriented = false;            ///< true if every tet was inverted and has been reoriented
};

/// Reads a `.hexex` file.
///
/// Validates everything: counts, numbers (no NaN/Inf), vertex indices, repeated corners,
/// empty meshes, trailing data, 3D orientation (exact), manifoldness. A mesh whose tets are
/// all negatively oriented is taken as mirrored: corners 2 and 3 of every tet (and of its
/// parameters) are swapped and a warning is added to @p report. The returned mesh has its
/// adjacency built.
///
/// @throws InputError with a message "<file>:<line>: <reason>" on any malformed input
///         (and "<file>: <reason>" when no line applies, e.g. a missing file).
ParametrizedTetMesh readHexExFile(const std::string& path, ReadReport* report = nullptr);

/// Reads `.hexex` data from a stream; @p name is used in error messages.
/// @throws InputError as readHexExFile().
ParametrizedTetMesh readHexExStream(std::istream& in, const std::string& name, ReadReport* report = nullptr);

/// Reads `.hexex` data held in memory; @p name is used in error messages. Large tet
/// sections are parsed in chunks, in place, and the adjacency built on @p threads threads
/// (0 = all hardware threads); the result, and every error message, do not depend on it.
/// @throws InputError as readHexExFile().
ParametrizedTetMesh readHexExBuffer(std::string_view text, const std::string& name,
                                    ReadReport* report = nullptr, int threads = 0);

namespace detail {
/// readHexExBuffer() with every tet section read token by token: the parser that words
/// the error messages (readHexExBuffer() falls back to it on anything unusual) and the
/// reference that the chunked parse is tested against.
ParametrizedTetMesh readHexExBufferTokenByToken(std::string_view text, const std::string& name,
                                                ReadReport* report = nullptr, int threads = 0);
} // namespace detail

/// Writes @p pm in `.hexex` format to a stream. Doubles are written in the shortest form
/// that reads back bit-identically.
/// @throws std::invalid_argument if the parameter count does not match the cell count.
void writeHexExStream(std::ostream& out, const ParametrizedTetMesh& pm);

/// Writes @p pm to the file @p path (see writeHexExStream()).
/// @throws std::runtime_error if the file cannot be written.
void writeHexExFile(const std::string& path, const ParametrizedTetMesh& pm);

} // namespace HexEx
