/// @file TriObjReader.cc
/// Chunked two-pass OBJ parsing: pass 1 counts the `v`, `vt` and `f` lines and the line
/// breaks of every chunk (so every line knows its number and every element its final
/// index), pass 2 parses each chunk into the final arrays, a last pass looks the corner
/// parameters up. Errors are collected per chunk; the first one in file order is thrown.

#include "TriObjReader.hh"

#include "../Core/Error.hh"
#include "../Core/Parallel.hh"

#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace HexEx {

namespace {

/// What a line declares.
enum class LineKind { Vertex, TexCoord, Face, Other };

/// At most one thread per this many bytes (thread start-up costs more than it saves on less).
constexpr std::size_t kParallelBytes = std::size_t(1) << 20;

inline bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

/// Kind of the line [p, e) by its first token.
inline LineKind classify(const char* p, const char* e) {
    while (p < e && isBlank(*p)) ++p;
    if (p == e) return LineKind::Other;
    const auto endsAt = [&](const char* q) { return q == e || isBlank(*q); };
    if (p[0] == 'v') {
        if (endsAt(p + 1)) return LineKind::Vertex;
        if (p + 1 < e && p[1] == 't' && endsAt(p + 2)) return LineKind::TexCoord;
        return LineKind::Other;
    }
    if (p[0] == 'f' && endsAt(p + 1)) return LineKind::Face;
    return LineKind::Other;
}

/// Per chunk: counts of pass 1 and the first error of pass 2.
struct ChunkInfo {
    const char* begin = nullptr;  ///< first byte
    const char* end = nullptr;    ///< one past the last byte
    std::size_t lines = 0;        ///< line breaks in the chunk
    std::size_t v = 0, vt = 0, f = 0;  ///< lines of each kind
    long long errorLine = 0;      ///< 1-based line of the first error (0: none)
    std::string error;            ///< its reason
};

/// A failure inside a chunk's parse (caught per chunk, never escapes).
struct ParseFailure {
    std::string reason;  ///< what is wrong with the line
};

/// A token quoted for a message: at most 30 characters, unprintable bytes as '?'.
std::string quoted(const char* b, const char* e) {
    std::string s = "'";
    for (const char* q = b; q < e && q < b + 30; ++q) {
        const unsigned char c = static_cast<unsigned char>(*q);
        s += (c >= 0x20 && c < 0x7f) ? static_cast<char>(c) : '?';
    }
    if (e - b > 30) s += "...";
    return s + "'";
}

/// Cursor over one line.
struct LineCursor {
    const char* p;  ///< next character
    const char* e;  ///< end of the line

    /// Skips blanks; true if a token follows.
    bool more() {
        while (p < e && isBlank(*p)) ++p;
        return p < e;
    }
    /// End of the token starting at p.
    const char* tokenEnd() const {
        const char* q = p;
        while (q < e && !isBlank(*q)) ++q;
        return q;
    }
    /// Reads a finite real number; @p what names it in errors.
    double real(const char* what) {
        if (!more()) throw ParseFailure{std::string("expected ") + what + ", the line ends"};
        const char* first = p;
        if (*first == '+' && e - first > 1 && first[1] != '-') ++first;
        double x = 0;
        const auto r = std::from_chars(first, e, x, std::chars_format::general);
        if (r.ec != std::errc() || (r.ptr < e && !isBlank(*r.ptr))) {
            const char* te = tokenEnd();
            if (r.ec == std::errc::result_out_of_range && r.ptr == te)
                throw ParseFailure{std::string(what) + " " + quoted(p, te) + " is out of range"};
            throw ParseFailure{std::string("expected ") + what + ", got " + quoted(p, te)};
        }
        if (!std::isfinite(x)) throw ParseFailure{std::string(what) + " " + quoted(p, r.ptr) + " is not finite"};
        p = r.ptr;
        return x;
    }
    /// Reads an integer (optional sign, at least one digit) ending at a '/', a blank or
    /// the end of the line.
    long long integer(const char* what) {
        const char* q = p;
        const bool negative = q < e && *q == '-';
        if (q < e && (*q == '-' || *q == '+')) ++q;
        const char* digits = q;
        unsigned long long x = 0;
        while (q < e && static_cast<unsigned>(*q - '0') < 10u) x = 10 * x + static_cast<unsigned>(*q++ - '0');
        if (q == digits || (q < e && !isBlank(*q) && *q != '/'))
            throw ParseFailure{std::string("expected ") + what + ", got " + quoted(p, tokenEnd())};
        if (q - digits > 18) throw ParseFailure{std::string(what) + " " + quoted(p, q) + " is out of range"};
        p = q;
        return negative ? -static_cast<long long>(x) : static_cast<long long>(x);
    }
};

/// Resolves an OBJ index @p raw (1-based, or negative relative to @p before elements
/// defined so far) against @p total elements (@p what, @p plural in messages); throws
/// for 0 and out-of-range indices.
inline int resolveIndex(long long raw, std::size_t before, std::size_t total, const char* what, const char* plural) {
    long long i;
    if (raw > 0) i = raw - 1;
    else if (raw < 0) i = static_cast<long long>(before) + raw;
    else throw ParseFailure{std::string(what) + " index 0 (OBJ indices start at 1)"};
    if (i < 0 || i >= static_cast<long long>(total))
        throw ParseFailure{std::string(what) + " index " + std::to_string(raw) + " out of range (" + std::to_string(total) + " " +
                           plural + (raw < 0 ? " defined before this line)" : " in the file)")};
    return static_cast<int>(i);
}

/// Cuts [b, e) into @p n chunks starting at line beginnings.
std::vector<ChunkInfo> cutChunks(const char* b, const char* e, int n) {
    std::vector<ChunkInfo> chunks;
    const char* start = b;
    const std::size_t size = static_cast<std::size_t>(e - b);
    for (int k = 1; k <= n && start < e; ++k) {
        const char* stop = k == n ? e : b + size * static_cast<std::size_t>(k) / static_cast<std::size_t>(n);
        if (stop < start) stop = start;
        if (stop < e) {
            const void* nl = std::memchr(stop, '\n', static_cast<std::size_t>(e - stop));
            stop = nl ? static_cast<const char*>(nl) + 1 : e;
        }
        ChunkInfo c;
        c.begin = start;
        c.end = stop;
        chunks.push_back(c);
        start = stop;
    }
    if (chunks.empty()) {
        ChunkInfo c;
        c.begin = c.end = b;
        chunks.push_back(c);
    }
    return chunks;
}

/// End of the line starting at @p p (the '\n' or @p e).
inline const char* lineEnd(const char* p, const char* e) {
    const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(e - p));
    return nl ? static_cast<const char*>(nl) : e;
}

} // namespace

ParametrizedTriMesh parseTriObj(std::string_view text, const std::string& name, int threads) {
    const char* tb = text.data();
    const char* te = tb + text.size();
    const int nt = static_cast<int>(std::max<std::size_t>(
        1, std::min<std::size_t>(static_cast<std::size_t>(resolveThreadCount(threads)), text.size() / kParallelBytes)));
    std::vector<ChunkInfo> chunks = cutChunks(tb, te, nt);
    const int nc = static_cast<int>(chunks.size());

    // Pass 1: counts.
    parallelChunks(chunks.size(), nc, [&](int, std::size_t cb, std::size_t ce) {
        for (std::size_t k = cb; k < ce; ++k) {
            ChunkInfo& c = chunks[k];
            for (const char* p = c.begin; p < c.end;) {
                const char* le = lineEnd(p, c.end);
                switch (classify(p, le)) {
                case LineKind::Vertex: ++c.v; break;
                case LineKind::TexCoord: ++c.vt; break;
                case LineKind::Face: ++c.f; break;
                case LineKind::Other: break;
                }
                if (le < c.end) ++c.lines;
                p = le + 1;
            }
        }
    });
    std::vector<std::size_t> v0(chunks.size() + 1, 0), vt0(chunks.size() + 1, 0), f0(chunks.size() + 1, 0);
    std::vector<long long> line0(chunks.size() + 1, 1);
    for (std::size_t k = 0; k < chunks.size(); ++k) {
        v0[k + 1] = v0[k] + chunks[k].v;
        vt0[k + 1] = vt0[k] + chunks[k].vt;
        f0[k + 1] = f0[k] + chunks[k].f;
        line0[k + 1] = line0[k] + static_cast<long long>(chunks[k].lines);
    }
    const std::size_t nv = v0.back(), nvt = vt0.back(), nf = f0.back();
    if (nv > static_cast<std::size_t>(INT_MAX) || nvt > static_cast<std::size_t>(INT_MAX) || nf > static_cast<std::size_t>(INT_MAX))
        throw InputError(name + ": more than 2^31 - 1 vertices, texture coordinates or faces");

    // Pass 2: parse in place.
    ParametrizedTriMesh m;
    m.points.resize(nv);
    m.triangles.resize(nf);
    std::vector<Vec2d> vt(nvt);
    std::vector<std::array<int, 3>> cornerVt(nf);
    parallelChunks(chunks.size(), nc, [&](int, std::size_t cb, std::size_t ce) {
        for (std::size_t k = cb; k < ce; ++k) {
            ChunkInfo& c = chunks[k];
            std::size_t iv = v0[k], ivt = vt0[k], jf = f0[k];
            long long line = line0[k];
            try {
                for (const char* p = c.begin; p < c.end; ++line) {
                    const char* le = lineEnd(p, c.end);
                    const LineKind kind = classify(p, le);
                    if (kind != LineKind::Other) {
                        LineCursor cur{p, le};
                        cur.more();
                        cur.p += kind == LineKind::TexCoord ? 2 : 1;  // the keyword
                        if (kind == LineKind::Vertex) {
                            Vec3d& x = m.points[iv++];
                            x[0] = cur.real("x coordinate");
                            x[1] = cur.real("y coordinate");
                            x[2] = cur.real("z coordinate");
                        } else if (kind == LineKind::TexCoord) {
                            Vec2d& t = vt[ivt++];
                            t[0] = cur.real("u coordinate");
                            t[1] = cur.real("v coordinate");
                            if (cur.more()) cur.real("w coordinate");
                            if (cur.more()) throw ParseFailure{"unexpected " + quoted(cur.p, cur.tokenEnd()) + " after the texture coordinate"};
                        } else {
                            std::array<int, 3>& tri = m.triangles[jf];
                            std::array<int, 3>& tv = cornerVt[jf];
                            ++jf;
                            int corners = 0;
                            while (cur.more()) {
                                if (corners == 3) throw ParseFailure{"face with more than 3 corners (only triangles are supported)"};
                                const char* tok = cur.p;
                                const long long a = cur.integer("vertex index");
                                if (cur.p == le || *cur.p != '/' || cur.p + 1 == le || cur.p[1] == '/' || isBlank(cur.p[1]))
                                    throw ParseFailure{"no per-corner texture coordinates: face corner " + quoted(tok, cur.tokenEnd()) +
                                                       " has no vt index (faces need 'f v/vt v/vt v/vt')"};
                                ++cur.p;
                                const long long b = cur.integer("texture coordinate index");
                                if (cur.p < le && *cur.p == '/') {  // normal index: checked for form only
                                    ++cur.p;
                                    cur.integer("normal index");
                                }
                                if (cur.p < le && !isBlank(*cur.p)) throw ParseFailure{"malformed face corner " + quoted(tok, cur.tokenEnd())};
                                tri[static_cast<std::size_t>(corners)] = resolveIndex(a, iv, nv, "vertex", "vertices");
                                tv[static_cast<std::size_t>(corners)] = resolveIndex(b, ivt, nvt, "texture coordinate", "texture coordinates");
                                ++corners;
                            }
                            if (corners < 3)
                                throw ParseFailure{"face with " + std::to_string(corners) + " corners (only triangles are supported)"};
                        }
                        if (kind == LineKind::Vertex && cur.more()) {  // w or a colour: numbers
                            while (cur.more()) cur.real("vertex coordinate");
                        }
                    }
                    p = le + 1;
                }
            } catch (const ParseFailure& f) {
                c.errorLine = line;
                c.error = f.reason;
            }
        }
    });
    for (const ChunkInfo& c : chunks)
        if (c.errorLine > 0) throw InputError(name + ":" + std::to_string(c.errorLine) + ": " + c.error);
    if (nf == 0) throw InputError(name + ": no faces");

    // Corner parameters.
    m.params.resize(nf);
    parallelChunks(nf, nt, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t f = b; f < e; ++f)
            for (std::size_t k = 0; k < 3; ++k) m.params[f][k] = vt[static_cast<std::size_t>(cornerVt[f][k])];
    });
    return m;
}

ParametrizedTriMesh readTriObjFile(const std::string& path, int threads) {
#if defined(__unix__) || defined(__APPLE__)
    // Mapped, not copied: the parse reads the page cache directly.
    const int fd = ::open(path.c_str(), O_RDONLY);
    if (fd < 0) throw InputError(path + ": cannot open file");
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        throw InputError(path + ": cannot read file (not a regular file)");
    }
    const std::size_t size = static_cast<std::size_t>(st.st_size);
    if (size == 0) {
        ::close(fd);
        return parseTriObj(std::string_view(), path, threads);
    }
    void* map = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE
#ifdef MAP_POPULATE
                                                     | MAP_POPULATE
#endif
                       ,
                       fd, 0);
    ::close(fd);
    if (map == MAP_FAILED) throw InputError(path + ": cannot read file");
    struct Unmap {
        void* p;
        std::size_t n;
        ~Unmap() { ::munmap(p, n); }
    } guard{map, size};
    return parseTriObj(std::string_view(static_cast<const char*>(map), size), path, threads);
#else
    std::FILE* fp = std::fopen(path.c_str(), "rb");
    if (!fp) throw InputError(path + ": cannot open file");
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> guard(fp, &std::fclose);
    if (std::fseek(fp, 0, SEEK_END) != 0) throw InputError(path + ": cannot read file");
    const long size = std::ftell(fp);
    if (size < 0 || std::fseek(fp, 0, SEEK_SET) != 0) throw InputError(path + ": cannot read file");
    std::unique_ptr<char[]> buf(new char[static_cast<std::size_t>(size) + 1]);
    if (size > 0 && std::fread(buf.get(), 1, static_cast<std::size_t>(size), fp) != static_cast<std::size_t>(size))
        throw InputError(path + ": cannot read file");
    return parseTriObj(std::string_view(buf.get(), static_cast<std::size_t>(size)), path, threads);
#endif
}

} // namespace HexEx
