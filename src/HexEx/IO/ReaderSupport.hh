#pragma once
/// @file ReaderSupport.hh
/// @ingroup io
/// Steps shared by the readers and writers: reading a whole stream or file, opening an input
/// file with a clear error, writing a whole file, and finishing a tet mesh (adjacency and
/// manifoldness).

#include "../Core/Error.hh"
#include "../Mesh/ParametrizedTetMesh.hh"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>

namespace HexEx {
namespace detail {

/// The rest of @p in as a string; InputError "<name>: read error" on failure.
inline std::string readWholeStream(std::istream& in, const std::string& name) {
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw InputError(name + ": read error");
    return text;
}

/// Opens @p path for binary reading; InputError "<path>: cannot open file: <reason>".
inline std::ifstream openInputFile(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": cannot open file: is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open file: " + std::strerror(errno));
    return in;
}

/// The whole file @p path (read in one piece when its size is known); InputError
/// "<path>: cannot open file: <reason>" or "<path>: read error".
inline std::string readWholeFile(const std::string& path) {
    std::ifstream in = openInputFile(path);
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0) {  // not seekable (e.g. a pipe)
        in.clear();
        in.seekg(0, std::ios::beg);
        return readWholeStream(in, path);
    }
    std::string text(static_cast<std::size_t>(size), '\0');
    in.seekg(0, std::ios::beg);
    if (!in.read(text.data(), size)) throw InputError(path + ": read error");
    return text;
}

/// Writes @p bytes to @p path; InputError naming the path if it cannot be written.
inline void writeWholeFile(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path + ": cannot open file for writing");
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) throw InputError(path + ": error while writing the file");
}

/// Builds the adjacency of a freshly read mesh (on @p threads threads, 0 = all hardware
/// threads) and checks that it is a manifold; errors are prefixed with the file @p name.
inline void finishTetMesh(ParametrizedTetMesh& pm, const std::string& name, int threads = 0) {
    try {
        pm.mesh.build_adjacency(threads);
    } catch (const InputError& e) {
        throw InputError(name + ": " + e.what());
    }
    const std::string manifold = pm.mesh.check_manifold(threads);
    if (!manifold.empty()) throw InputError(name + ": " + manifold);
}

} // namespace detail
} // namespace HexEx
