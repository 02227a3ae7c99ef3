/// @file TextMeshWriters.cc
/// OBJ, OFF and PLY text in parallel blocks: each section (`v`, `vt`, `f`) is formatted in rounds, every
/// thread formatting a contiguous block of elements into its own reused buffer sized for
/// the longest possible lines, and the buffers are written in order.

#include "TextMeshWriters.hh"

#include "../Core/Error.hh"
#include "../Core/Parallel.hh"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <functional>
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

/// Receives the text in order.
using Sink = std::function<void(const char*, std::size_t)>;

/// Bytes of text per thread and round (buffers reused across rounds, so large outputs do
/// not allocate, and fault in, one buffer as large as the file).
constexpr std::size_t kBlockBytes = std::size_t(1) << 20;

/// Formats @p n elements with @p line(i, p) -> end (at most @p maxLine bytes each) and
/// passes the text to @p sink in element order: in rounds, each of the threads formatting
/// a contiguous block into its own buffer.
template <class Line>
void formatSection(const Sink& sink, std::size_t n, std::size_t maxLine, int threads, Line&& line) {
    if (n == 0) return;
    const int nt = n < kParallelElements ? 1 : std::max(1, threads);
    const std::size_t block = std::max<std::size_t>(1, kBlockBytes / maxLine);  // elements per thread and round
    std::vector<std::unique_ptr<char[]>> bufs(static_cast<std::size_t>(nt));
    std::vector<std::size_t> used(static_cast<std::size_t>(nt), 0);
    for (auto& b : bufs) b.reset(new char[block * maxLine]);
    for (std::size_t start = 0; start < n; start += block * static_cast<std::size_t>(nt)) {
        const std::size_t stop = std::min(n, start + block * static_cast<std::size_t>(nt));
        parallelChunks(stop - start, nt, [&](int c, std::size_t b, std::size_t e) {
            char* const begin = bufs[static_cast<std::size_t>(c)].get();
            char* p = begin;
            for (std::size_t i = start + b; i < start + e; ++i) p = line(i, p);
            used[static_cast<std::size_t>(c)] = static_cast<std::size_t>(p - begin);
        });
        for (int c = 0; c < nt; ++c) {
            sink(bufs[static_cast<std::size_t>(c)].get(), used[static_cast<std::size_t>(c)]);
            used[static_cast<std::size_t>(c)] = 0;
        }
    }
}

/// Throws InputError if @p x is not finite.
inline void requireFinite(double x, const char* what, std::size_t i) {
    if (!std::isfinite(x)) throw InputError(std::string("cannot write OBJ: ") + what + " " + std::to_string(i) + " has a coordinate that is not finite");
}

/// Passes the OBJ text of a triangle mesh to @p sink.
void writeTri(const Sink& sink, const ParametrizedTriMesh& m, int threads) {
    const std::size_t nf = m.triangles.size();
    if (m.params.size() != nf) throw InputError("cannot write OBJ: " + std::to_string(nf) + " triangles but " +
                                                std::to_string(m.params.size()) + " parameter triples");
    const std::string head = "# " + std::to_string(m.points.size()) + " vertices, " + std::to_string(nf) +
                             " triangles, one vt per triangle corner\n";
    sink(head.data(), head.size());
    const int nt = std::max(1, resolveThreadCount(threads));
    formatSection(sink, m.points.size(), 3 + 3 * (kMaxReal + 1), nt, [&](std::size_t i, char* p) {
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
    formatSection(sink, 3 * nf, 4 + 2 * (kMaxReal + 1), nt, [&](std::size_t i, char* p) {
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
    formatSection(sink, nf, 2 + 3 * (2 * kMaxInt + 2), nt, [&](std::size_t f, char* p) {
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
}

/// Passes the text of a quad mesh in @p format to @p sink.
void writeQuad(const Sink& sink, const QuadMesh& qm, QuadFileFormat format, int threads) {
    const int nt = std::max(1, resolveThreadCount(threads));
    const bool obj = format == QuadFileFormat::Obj;
    const std::size_t nf = qm.quads.size() + qm.polygons.size();
    std::size_t longest = 4;
    for (const auto& loop : qm.polygons) longest = std::max(longest, loop.size());
    std::string head;
    if (format == QuadFileFormat::Off) {
        head = "OFF\n" + std::to_string(qm.vertices.size()) + " " + std::to_string(nf) + " 0\n";
    } else if (format == QuadFileFormat::Ply) {
        head = "ply\nformat ascii 1.0\ncomment written by HexEx\nelement vertex " + std::to_string(qm.vertices.size()) +
               "\nproperty double x\nproperty double y\nproperty double z\nelement face " + std::to_string(nf) +
               "\nproperty list " + (longest > 255 ? "int" : "uchar") + " int vertex_indices\nend_header\n";
    }
    sink(head.data(), head.size());
    formatSection(sink, qm.vertices.size(), 3 + 3 * (kMaxReal + 1), nt, [&](std::size_t i, char* p) {
        const Vec3d& x = qm.vertices[i];
        for (int d = 0; d < 3; ++d) requireFinite(x[d], "vertex", i);
        if (obj) {
            *p++ = 'v';
            *p++ = ' ';
        }
        p = putReal(p, x[0]);
        for (int d = 1; d < 3; ++d) {
            *p++ = ' ';
            p = putReal(p, x[d]);
        }
        *p++ = '\n';
        return p;
    });
    // OBJ: "f" and 1-based indices; OFF and PLY: the corner count and 0-based indices.
    const long long base = obj ? 1 : 0;
    formatSection(sink, qm.quads.size(), 2 + 4 * (kMaxInt + 1), nt, [&](std::size_t q, char* p) {
        *p++ = obj ? 'f' : '4';
        for (int v : qm.quads[q]) {
            *p++ = ' ';
            p = putInt(p, static_cast<long long>(v) + base);
        }
        *p++ = '\n';
        return p;
    });
    std::string poly;
    for (const auto& loop : qm.polygons) {
        poly += obj ? std::string("f") : std::to_string(loop.size());
        for (int v : loop) poly += ' ' + std::to_string(static_cast<long long>(v) + base);
        poly += '\n';
    }
    sink(poly.data(), poly.size());
}

/// Writes the text @p produce passes to its sink to @p path; errors (InputError) of
/// @p produce are prefixed with the path.
void writeFile(const std::string& path, const std::function<void(const Sink&)>& produce) {
    std::FILE* fp = std::fopen(path.c_str(), "wb");
    if (!fp) throw InputError(path + ": cannot open for writing");
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> guard(fp, &std::fclose);
    bool ok = true;
    try {
        produce([&](const char* p, std::size_t n) { ok = ok && (n == 0 || std::fwrite(p, 1, n, fp) == n); });
    } catch (const InputError& e) {
        throw InputError(path + ": " + e.what());
    }
    if (!ok) throw InputError(path + ": write error");
    if (std::fclose(guard.release()) != 0) throw InputError(path + ": write error");
}

/// The text @p produce passes to its sink.
std::string collect(const std::function<void(const Sink&)>& produce) {
    std::string out;
    produce([&](const char* p, std::size_t n) { out.append(p, n); });
    return out;
}

} // namespace

std::string formatTriObj(const ParametrizedTriMesh& m, int threads) {
    return collect([&](const Sink& s) { writeTri(s, m, threads); });
}

void writeTriObjFile(const std::string& path, const ParametrizedTriMesh& m, int threads) {
    writeFile(path, [&](const Sink& s) { writeTri(s, m, threads); });
}

std::string formatQuadMesh(const QuadMesh& qm, QuadFileFormat format, int threads) {
    return collect([&](const Sink& s) { writeQuad(s, qm, format, threads); });
}

void writeQuadMeshFile(const std::string& path, const QuadMesh& qm, QuadFileFormat format, int threads) {
    writeFile(path, [&](const Sink& s) { writeQuad(s, qm, format, threads); });
}

} // namespace HexEx
