/// @file ObjWriter.cc
/// OBJ text in parallel pieces: each section (`v`, `vt`, `f`) is cut into one range of
/// elements per thread, each range formatted into its own buffer sized for the longest
/// possible line, and the buffers are written in order.

#include "ObjWriter.hh"

#include "../Core/Error.hh"
#include "../Core/Parallel.hh"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace HexEx {

namespace {

/// Below this many elements a section is formatted on one thread.
constexpr std::size_t kParallelElements = 20000;

/// Longest text of one double (shortest round-trip form, e.g. -2.2250738585072014e-308).
constexpr std::size_t kMaxReal = 25;
/// Longest text of one int.
constexpr std::size_t kMaxInt = 11;

/// Writes @p x (finite) as its shortest round-trip text.
inline char* putReal(char* p, double x) { return std::to_chars(p, p + kMaxReal, x).ptr; }
/// Writes @p x.
inline char* putInt(char* p, long long x) { return std::to_chars(p, p + 20, x).ptr; }

/// Formats @p n elements with @p line(i, p) -> end (at most @p maxLine bytes each), in
/// one piece per thread, appended to @p pieces in element order.
template <class Line>
void formatSection(std::vector<std::string>& pieces, std::size_t n, std::size_t maxLine, int threads, Line&& line) {
    if (n == 0) return;
    const int nt = n < kParallelElements ? 1 : std::max(1, threads);
    const std::size_t first = pieces.size();
    pieces.resize(first + static_cast<std::size_t>(nt));
    parallelChunks(n, nt, [&](int c, std::size_t b, std::size_t e) {
        std::string& s = pieces[first + static_cast<std::size_t>(c)];
        s.resize((e - b) * maxLine);
        char* const start = &s[0];
        char* p = start;
        for (std::size_t i = b; i < e; ++i) p = line(i, p);
        s.resize(static_cast<std::size_t>(p - start));
    });
}

/// Throws InputError if @p x is not finite.
inline void requireFinite(double x, const char* what, std::size_t i) {
    if (!std::isfinite(x)) throw InputError(std::string("cannot write OBJ: ") + what + " " + std::to_string(i) + " has a coordinate that is not finite");
}

/// The pieces of a triangle mesh's OBJ text.
std::vector<std::string> triPieces(const ParametrizedTriMesh& m, int threads) {
    const std::size_t nf = m.triangles.size();
    if (m.params.size() != nf) throw InputError("cannot write OBJ: " + std::to_string(nf) + " triangles but " +
                                                std::to_string(m.params.size()) + " parameter triples");
    std::vector<std::string> pieces;
    pieces.push_back("# " + std::to_string(m.points.size()) + " vertices, " + std::to_string(nf) +
                     " triangles, one vt per triangle corner\n");
    const int nt = std::max(1, resolveThreadCount(threads));
    formatSection(pieces, m.points.size(), 3 + 3 * (kMaxReal + 1), nt, [&](std::size_t i, char* p) {
        const Vec3d& x = m.points[i];
        for (int d = 0; d < 3; ++d) requireFinite(x[d], "vertex", i);
        *p++ = 'v';
        for (int d = 0; d < 3; ++d) {
            *p++ = ' ';
            p = putReal(p, x[d]);
        }
        *p++ = '\n';
        return p;
    });
    formatSection(pieces, 3 * nf, 4 + 2 * (kMaxReal + 1), nt, [&](std::size_t i, char* p) {
        const Vec2d& t = m.params[i / 3][i % 3];
        requireFinite(t[0], "parameter of triangle", i / 3);
        requireFinite(t[1], "parameter of triangle", i / 3);
        *p++ = 'v';
        *p++ = 't';
        *p++ = ' ';
        p = putReal(p, t[0]);
        *p++ = ' ';
        p = putReal(p, t[1]);
        *p++ = '\n';
        return p;
    });
    const long long nv = static_cast<long long>(m.points.size());
    formatSection(pieces, nf, 2 + 3 * (2 * kMaxInt + 2), nt, [&](std::size_t f, char* p) {
        *p++ = 'f';
        for (std::size_t k = 0; k < 3; ++k) {
            const int v = m.triangles[f][k];
            if (v < 0 || v >= nv) throw InputError("cannot write OBJ: triangle " + std::to_string(f) + " has vertex index out of range");
            *p++ = ' ';
            p = putInt(p, static_cast<long long>(v) + 1);
            *p++ = '/';
            p = putInt(p, static_cast<long long>(3 * f + k) + 1);
        }
        *p++ = '\n';
        return p;
    });
    return pieces;
}

/// The pieces of a quad mesh's OBJ text.
std::vector<std::string> quadPieces(const QuadMesh& qm, int threads) {
    std::vector<std::string> pieces;
    const int nt = std::max(1, resolveThreadCount(threads));
    formatSection(pieces, qm.vertices.size(), 3 + 3 * (kMaxReal + 1), nt, [&](std::size_t i, char* p) {
        const Vec3d& x = qm.vertices[i];
        for (int d = 0; d < 3; ++d) requireFinite(x[d], "vertex", i);
        *p++ = 'v';
        for (int d = 0; d < 3; ++d) {
            *p++ = ' ';
            p = putReal(p, x[d]);
        }
        *p++ = '\n';
        return p;
    });
    formatSection(pieces, qm.quads.size(), 2 + 4 * (kMaxInt + 1), nt, [&](std::size_t q, char* p) {
        *p++ = 'f';
        for (int v : qm.quads[q]) {
            *p++ = ' ';
            p = putInt(p, static_cast<long long>(v) + 1);
        }
        *p++ = '\n';
        return p;
    });
    std::string poly;
    for (const auto& loop : qm.polygons) {
        poly += 'f';
        for (int v : loop) poly += ' ' + std::to_string(static_cast<long long>(v) + 1);
        poly += '\n';
    }
    pieces.push_back(std::move(poly));
    return pieces;
}

/// Concatenation of @p pieces.
std::string join(const std::vector<std::string>& pieces) {
    std::size_t n = 0;
    for (const auto& s : pieces) n += s.size();
    std::string out;
    out.reserve(n);
    for (const auto& s : pieces) out += s;
    return out;
}

/// Writes @p pieces to @p path in order.
void writePieces(const std::string& path, const std::vector<std::string>& pieces) {
    std::FILE* fp = std::fopen(path.c_str(), "wb");
    if (!fp) throw InputError(path + ": cannot open for writing");
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> guard(fp, &std::fclose);
    for (const auto& s : pieces)
        if (!s.empty() && std::fwrite(s.data(), 1, s.size(), fp) != s.size()) throw InputError(path + ": write error");
    if (std::fclose(guard.release()) != 0) throw InputError(path + ": write error");
}

} // namespace

std::string formatTriObj(const ParametrizedTriMesh& m, int threads) { return join(triPieces(m, threads)); }

void writeTriObjFile(const std::string& path, const ParametrizedTriMesh& m, int threads) {
    std::vector<std::string> pieces;
    try {
        pieces = triPieces(m, threads);
    } catch (const InputError& e) {
        throw InputError(path + ": " + e.what());
    }
    writePieces(path, pieces);
}

std::string formatQuadObj(const QuadMesh& qm, int threads) { return join(quadPieces(qm, threads)); }

void writeQuadObjFile(const std::string& path, const QuadMesh& qm, int threads) {
    std::vector<std::string> pieces;
    try {
        pieces = quadPieces(qm, threads);
    } catch (const InputError& e) {
        throw InputError(path + ": " + e.what());
    }
    writePieces(path, pieces);
}

} // namespace HexEx
