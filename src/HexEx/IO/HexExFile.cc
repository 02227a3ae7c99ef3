/// @file HexExFile.cc
/// Implementation of the `.hexex` reader (in-memory tokenizer with std::from_chars) and writer.

#include "HexExFile.hh"
#include "FileBytes.hh"
#include "ReaderSupport.hh"
#include "TextParsing.hh"

#include "../Core/Error.hh"
#include "../Core/Parallel.hh"
#include "../Predicates/ExactPredicates.hh"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cstdint>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <utility>

namespace HexEx {

namespace {

/// Largest vertex count accepted (vertex handles are ints).
constexpr long long kMaxVertices = INT_MAX;
/// Largest tet count accepted (halffaces 4*c and cell edges 6*c must fit an int).
constexpr long long kMaxTets = INT_MAX / 8;

using detail::quoteToken;
/// Whitespace as understood by the format.
inline bool isSpace(char ch) { return detail::isFormatSpace(ch); }
/// isSpace() with one comparison for the common bytes (every format space is <= ' ').
inline bool isSpaceFast(char ch) { return static_cast<unsigned char>(ch) <= ' ' && isSpace(ch); }

/// The tokenizer of the text readers with this format's messages for numbers and counts;
/// every failure becomes an InputError "<name>:<line>: <reason>".
class Parser : public detail::Lexer {
public:
    using Lexer::Lexer;

    /// Sets the note added to end-of-file messages (e.g. "file declares 5 vertices").
    void setNote(std::string note) { note_ = std::move(note); }

    /// Next token; @p what() describes the expected item for the end-of-file message.
    template <class What>
    std::string_view token(const What& what) {
        if (!more())
            fail(eofLine(), "unexpected end of file: expected " + what() + (note_.empty() ? "" : " (" + note_ + ")"));
        return next(std::string()).text;
    }

    /// Next token as a signed integer (no range check beyond long long).
    template <class What>
    long long integer(const What& what) {
        const std::string_view tok = token(what);
        long long value = 0;
        const detail::NumberParse r = detail::parseInteger(tok, value);
        if (r == detail::NumberParse::OutOfRange) fail(line(), "integer " + quoteToken(tok) + " out of range for " + what());
        if (r != detail::NumberParse::Ok) fail(line(), "expected an integer for " + what() + ", got " + quoteToken(tok));
        return value;
    }

    /// Next token as a finite double.
    template <class What>
    double real(const What& what) {
        const std::string_view tok = token(what);
        double value = 0;
        const detail::NumberParse r = detail::parseRealFast(tok, value);
        if (r == detail::NumberParse::OutOfRange)
            fail(line(), "number " + quoteToken(tok) + " out of double range for " + what());
        if (r != detail::NumberParse::Ok) fail(line(), "expected a number for " + what() + ", got " + quoteToken(tok));
        if (!std::isfinite(value)) fail(line(), "NaN or infinite value " + quoteToken(tok) + " for " + what());
        return value;
    }

    /// Next token as a count in [0, maxCount].
    long long count(const char* what, long long maxCount) {
        const long long n = integer([&] { return std::string(what); });
        if (n < 0) fail(line(), "negative " + std::string(what) + " " + std::to_string(n));
        if (n > maxCount)
            fail(line(), std::string(what) + " " + std::to_string(n) + " too large (at most " +
                             std::to_string(maxCount) + ")");
        return n;
    }

private:
    std::string note_;
};

const char* const kAxisName[3] = {"x", "y", "z"};
const char* const kParamName[3] = {"u", "v", "w"};

/// Tets of one orientation: how many, and the first five (all an error message names).
struct TetList {
    std::size_t count = 0;          ///< number of such tets
    std::vector<std::size_t> first;  ///< the first (at most five) of them
    /// Counts tet @p c.
    void add(std::size_t c) {
        if (count++ < 5) first.push_back(c);
    }
};

/// "tet K (line L), ..." for the first five tets of @p list, then "and N more".
std::string listTets(const TetList& list, const std::vector<int>& lines) {
    std::string s;
    for (std::size_t i = 0; i < list.first.size(); ++i) {
        if (i) s += ", ";
        s += "tet " + std::to_string(list.first[i]) + " (line " + std::to_string(lines[list.first[i]]) + ")";
    }
    if (list.count > list.first.size()) s += " and " + std::to_string(list.count - list.first.size()) + " more";
    return s;
}

/// Fast path for the vertex section: the 3 @p nv coordinates from the parser's place, in
/// one pass over the text (no per-token bookkeeping of the token-by-token parser), the parser
/// then moved past them. Returns false on anything unusual (a missing, malformed or
/// non-finite number), with @p positions and the parser as they were: the caller's
/// token-by-token loop then reports the exact error.
bool parseVerticesFast(std::string_view text, Parser& in, long long nv, std::vector<Vec3d>& positions) {
    const std::size_t n = text.size();
    std::size_t p = in.offset();
    long long breaks = 0;
    for (long long v = 0; v < nv; ++v) {
        Vec3d x;
        for (int k = 0; k < 3; ++k) {
            while (p < n && isSpaceFast(text[p])) {
                breaks += text[p] == '\n';
                ++p;
            }
            const std::size_t start = p;
            while (p < n && !isSpaceFast(text[p])) ++p;
            double value = 0;
            if (p == start || detail::parseRealFast(text.substr(start, p - start), value) != detail::NumberParse::Ok ||
                !std::isfinite(value)) {
                positions.clear();
                return false;
            }
            x[k] = value;
        }
        positions.push_back(x);
    }
    in.advance(p, breaks);
    return true;
}

/// Tokens per tet: 4 vertex indices and 12 parameters.
constexpr int kTetTokens = 16;

/// Fast path for the tet section of large files. The text from @p begin (line
/// @p firstLine) is cut into chunks at token boundaries; tokens and line breaks are counted
/// per chunk, then every chunk parses its tokens straight into place (token g is field
/// g % 16 of tet g / 16). Returns false on anything unusual (wrong token count, a malformed
/// or non-finite number, an index out of range, a repeated vertex): the caller then runs
/// the sequential parser, which reports the exact error.
bool parseTetsParallel(std::string_view text, std::size_t begin, int firstLine, long long nv, long long nc,
                       std::vector<std::array<VertexHandle, 4>>& cells, CornerParams& params, std::vector<int>& lines,
                       int threads) {
    const std::size_t n = text.size();
    const int k = 4 * threads;  // more chunks than threads: lines are not all equally long
    std::vector<std::size_t> cut(static_cast<std::size_t>(k) + 1, n);
    cut[0] = begin;
    for (int i = 1; i < k; ++i) {
        std::size_t p = std::max(begin + (n - begin) * static_cast<std::size_t>(i) / static_cast<std::size_t>(k),
                                 cut[static_cast<std::size_t>(i) - 1]);
        while (p < n && !isSpace(text[p])) ++p;  // a cut never splits a token
        cut[static_cast<std::size_t>(i)] = p;
    }
    std::vector<long long> tokens(static_cast<std::size_t>(k), 0), breaks(static_cast<std::size_t>(k), 0);
    parallelChunks(static_cast<std::size_t>(k), threads, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i) {
            // Branch-free count: a token starts at a byte > ' ' after a byte <= ' ' (every cut
            // is at a space, so the first byte of a chunk starts no token). Bytes below ' '
            // that are not format spaces (rare) make the chunk be counted exactly instead.
            long long nTokens = 0, nBreaks = 0, nOdd = 0;
            const auto* u = reinterpret_cast<const unsigned char*>(text.data());
            for (std::size_t p = cut[i] + 1; p < cut[i + 1]; ++p) {
                const unsigned ch = u[p];
                nTokens += (ch > ' ') & (u[p - 1] <= ' ');
                nBreaks += ch == '\n';
                nOdd += (ch < '\t') | (ch - 14u < 18u);  // below ' ' but not one of \t \n \v \f \r
            }
            if (cut[i] < cut[i + 1]) nBreaks += text[cut[i]] == '\n';
            if (nOdd > 0) {
                bool inToken = false;
                nTokens = nBreaks = 0;
                for (std::size_t p = cut[i]; p < cut[i + 1]; ++p) {
                    const bool sp = isSpace(text[p]);
                    nTokens += !sp && !inToken;
                    nBreaks += text[p] == '\n';
                    inToken = !sp;
                }
            }
            tokens[i] = nTokens;
            breaks[i] = nBreaks;
        }
    });
    std::vector<long long> firstToken(static_cast<std::size_t>(k) + 1, 0), lineAt(static_cast<std::size_t>(k) + 1, firstLine);
    for (std::size_t i = 0; i < static_cast<std::size_t>(k); ++i) {
        firstToken[i + 1] = firstToken[i] + tokens[i];
        lineAt[i + 1] = lineAt[i] + breaks[i];
    }
    if (firstToken.back() != kTetTokens * nc || lineAt.back() > INT_MAX) return false;
    cells.resize(static_cast<std::size_t>(nc));
    params.resize(static_cast<std::size_t>(nc));
    lines.resize(static_cast<std::size_t>(nc));
    std::vector<char> ok(static_cast<std::size_t>(k), 1);
    parallelChunks(static_cast<std::size_t>(k), threads, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e && ok[i]; ++i) {
            const long long g = firstToken[i];
            int line = static_cast<int>(lineAt[i]);
            std::size_t p = cut[i];
            const std::size_t end = cut[i + 1];
            auto c = static_cast<std::size_t>(g / kTetTokens);
            int f = static_cast<int>(g % kTetTokens);
            const std::size_t partial = f == 0 ? SIZE_MAX : c;  // tet begun by the previous chunk
            bool good = true;
            while (good) {
                while (p < end && isSpaceFast(text[p])) {
                    line += text[p] == '\n';
                    ++p;
                }
                if (p >= end) break;
                const std::size_t start = p;
                while (p < end && !isSpaceFast(text[p])) ++p;
                const std::string_view tok = text.substr(start, p - start);
                if (f < 4) {
                    long long idx = 0;
                    good = detail::parseIndex(tok, nv, idx);
                    auto& cv = cells[c];
                    cv[static_cast<std::size_t>(f)] = VertexHandle(static_cast<int>(idx));
                    if (f == 0) lines[c] = line;
                    // A repeated vertex (the sequential parser names it) once the tet's
                    // indices are complete; a tet cut by a chunk boundary is checked afterwards.
                    if (f == 3 && c != partial)
                        good = good && cv[0] != cv[1] && cv[0] != cv[2] && cv[0] != cv[3] && cv[1] != cv[2] &&
                               cv[1] != cv[3] && cv[2] != cv[3];
                } else {
                    double value = 0;
                    good = detail::parseRealFast(tok, value) == detail::NumberParse::Ok && std::isfinite(value);
                    params[c][static_cast<std::size_t>((f - 4) / 3)][(f - 4) % 3] = value;
                }
                if (++f == kTetTokens) {
                    f = 0;
                    ++c;
                }
            }
            ok[i] = good;
        }
    });
    if (std::find(ok.begin(), ok.end(), 0) != ok.end()) return false;
    // Tets whose indices straddle a chunk boundary were not checked for repeats above.
    for (std::size_t i = 1; i < static_cast<std::size_t>(k); ++i) {
        const auto c = static_cast<std::size_t>(firstToken[i] / kTetTokens);
        if (c >= cells.size()) continue;
        const auto& cv = cells[c];
        for (int a = 0; a < 4; ++a)
            for (int b = a + 1; b < 4; ++b)
                if (cv[static_cast<std::size_t>(a)] == cv[static_cast<std::size_t>(b)]) return false;
    }
    return true;
}

/// readHexExBuffer(); @p chunked: the vertex section goes through parseVerticesFast() and large tet
/// sections through parseTetsParallel() first.
ParametrizedTetMesh readBuffer(std::string_view text, const std::string& name, ReadReport* report, int threads,
                               bool chunked) {
    Parser in(text, name);

    // Vertices.
    const long long nv = in.count("vertex count", kMaxVertices);
    if (nv == 0) in.fail(in.line(), "mesh has no vertices (vertex count is 0)");
    std::vector<Vec3d> positions;
    // A vertex takes at least 6 bytes ("0 0 0\n"): never reserve more than the file can hold.
    in.setNote("file declares " + std::to_string(nv) + " vertices");
    positions.reserve(static_cast<std::size_t>(std::min<long long>(nv, in.remaining() / 5 + 1)));
    const bool parsedVertices = chunked && parseVerticesFast(text, in, nv, positions);
    for (long long v = parsedVertices ? nv : 0; v < nv; ++v) {
        Vec3d p;
        for (int k = 0; k < 3; ++k)
            p[k] = in.real([&] {
                return std::string(kAxisName[k]) + " coordinate of vertex " + std::to_string(v);
            });
        positions.push_back(p);
    }

    // Tets.
    in.setNote("");
    const long long nc = in.count("tet count", kMaxTets);
    if (nc == 0) in.fail(in.line(), "mesh has no tets (tet count is 0)");
    const std::size_t ncReserve = static_cast<std::size_t>(std::min<long long>(nc, in.remaining() / 31 + 1));
    std::vector<std::array<VertexHandle, 4>> cells;
    CornerParams params;
    std::vector<int> lines;  // line of each tet's first token
    in.setNote("file declares " + std::to_string(nc) + " tets");
    // Large files: the chunked parse (in parallel on several threads; on one it takes about
    // 2/3 of the CPU of the token-by-token parser); if it finds anything wrong, the
    // token-by-token parser below runs from the same place and reports the exact error.
    constexpr long long kParallelMinTets = 20000;
    const int nThreads = resolveThreadCount(threads);
    const bool parsed = chunked && nc >= kParallelMinTets &&
                        parseTetsParallel(text, in.offset(), static_cast<int>(in.line()), nv, nc, cells, params, lines, nThreads);
    if (!parsed) {
        cells.clear();
        params.clear();
        lines.clear();
    }
    cells.reserve(ncReserve);
    params.reserve(ncReserve);
    lines.reserve(ncReserve);
    for (long long c = parsed ? nc : 0; c < nc; ++c) {
        const auto tetDesc = [&] { return "tet " + std::to_string(c); };
        std::array<VertexHandle, 4> cv;
        for (int i = 0; i < 4; ++i) {
            const auto desc = [&] { return "vertex index " + std::to_string(i) + " of " + tetDesc(); };
            if (i == 0 && in.more()) lines.push_back(static_cast<int>(in.line()));
            const long long idx = in.integer(desc);
            if (idx < 0 || idx >= nv)
                in.fail(in.line(), "vertex index " + std::to_string(idx) + " of tet " + std::to_string(c) +
                                       " out of range [0, " + std::to_string(nv) + ")");
            cv[i] = VertexHandle(static_cast<int>(idx));
            for (int j = 0; j < i; ++j)
                if (cv[j] == cv[i])
                    in.fail(in.line(), "tet " + std::to_string(c) + " repeats vertex " + std::to_string(idx));
        }
        std::array<Vec3d, 4> cp;
        for (int i = 0; i < 4; ++i)
            for (int k = 0; k < 3; ++k)
                cp[i][k] = in.real([&] {
                    return "parameter " + std::string(kParamName[k]) + " of corner " + std::to_string(i) + " of " +
                           tetDesc();
                });
        cells.push_back(cv);
        params.push_back(cp);
    }
    if (!parsed && in.more()) in.fail(in.line(), "unexpected data after last tet");

    // 3D orientation (exact): all positive, or all negative (mirrored), nothing else.
    // Signs on all threads; the first degenerate tet and the lists are found in tet order.
    std::vector<signed char> sign(cells.size());
    parallelChunks(cells.size(), cells.size() >= static_cast<std::size_t>(kParallelMinTets) ? nThreads : 1,
                   [&](int, std::size_t b, std::size_t e) {
                       for (std::size_t c = b; c < e; ++c) {
                           const auto& cv = cells[c];
                           sign[c] = static_cast<signed char>(
                               orient3d(positions[cv[0].uidx()], positions[cv[1].uidx()], positions[cv[2].uidx()],
                                        positions[cv[3].uidx()]));
                       }
                   });
    TetList negative, positive;
    for (std::size_t c = 0; c < cells.size(); ++c) {
        if (sign[c] == 0) in.fail(lines[c], "tet " + std::to_string(c) + " is degenerate in 3D (zero volume)");
        (sign[c] < 0 ? negative : positive).add(c);
    }
    std::vector<std::string> warnings;
    bool reoriented = false;
    if (positive.count == 0) {
        for (std::size_t c = 0; c < cells.size(); ++c) {  // swap corners 2 and 3 (and their parameters)
            std::swap(cells[c][2], cells[c][3]);
            std::swap(params[c][2], params[c][3]);
        }
        reoriented = true;
        warnings.push_back(name + ": mesh is mirrored: all " + std::to_string(cells.size()) +
                           " tets were negatively oriented and have been reoriented");
    } else if (negative.count > 0) {
        const std::string total = std::to_string(cells.size());
        if (negative.count <= positive.count)
            in.fail(lines[negative.first.front()],
                    "inconsistent tet orientation: " + std::to_string(negative.count) + " of " + total +
                        " tets are inverted in 3D (negatively oriented): " + listTets(negative, lines));
        in.fail(lines[positive.first.front()],
                "inconsistent tet orientation: " + std::to_string(positive.count) + " of " + total +
                    " tets are positively oriented while the others are inverted in 3D: " +
                    listTets(positive, lines));
    }

    // Assemble the mesh (the parsed arrays become the mesh's own).
    std::vector<char> used(positions.size(), 0);
    for (const auto& cv : cells)
        for (const VertexHandle v : cv) used[v.uidx()] = 1;
    const auto nUnused = std::count(used.begin(), used.end(), 0);
    if (nUnused > 0)
        warnings.push_back(name + ": " + std::to_string(nUnused) + " of " + std::to_string(positions.size()) +
                           " vertices are not used by any tet");
    ParametrizedTetMesh pm;
    pm.mesh.assign(std::move(positions), std::move(cells));
    pm.params = std::move(params);

    detail::finishTetMesh(pm, name, nThreads);

    if (report) {
        report->reoriented = reoriented;
        report->warnings.insert(report->warnings.end(), warnings.begin(), warnings.end());
    }
    return pm;
}

} // namespace

ParametrizedTetMesh readHexExBuffer(std::string_view text, const std::string& name, ReadReport* report, int threads) {
    return readBuffer(text, name, report, threads, true);
}

ParametrizedTetMesh detail::readHexExBufferTokenByToken(std::string_view text, const std::string& name,
                                                        ReadReport* report, int threads) {
    return readBuffer(text, name, report, threads, false);
}

ParametrizedTetMesh readHexExStream(std::istream& in, const std::string& name, ReadReport* report) {
    return readHexExBuffer(detail::readWholeStream(in, name), name, report);
}

ParametrizedTetMesh readHexExFile(const std::string& path, ReadReport* report) {
    const detail::FileBytes bytes(path);
    return readHexExBuffer(bytes.view(), path, report);
}

void writeHexExStream(std::ostream& out, const ParametrizedTetMesh& pm) {
    const TetMesh& mesh = pm.mesh;
    if (pm.params.size() != mesh.n_cells())
        throw std::invalid_argument("writeHexExStream: " + std::to_string(pm.params.size()) +
                                    " parameter sets for " + std::to_string(mesh.n_cells()) + " tets");
    // Numbers in their shortest round-trip form, the text flushed to @p out in ~1 MiB chunks.
    std::string buf;
    const auto put = [&](auto x, char separator) {
        char tmp[64];
        buf.append(tmp, std::to_chars(tmp, tmp + sizeof tmp, x).ptr);
        buf += separator;
        if (buf.size() >= (1u << 20) && separator == '\n') {
            out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
            buf.clear();
        }
    };
    put(mesh.n_vertices(), '\n');
    for (std::size_t v = 0; v < mesh.n_vertices(); ++v) {
        const Vec3d& p = mesh.position(VertexHandle(static_cast<int>(v)));
        for (int k = 0; k < 3; ++k) put(p[k], k == 2 ? '\n' : ' ');
    }
    put(mesh.n_cells(), '\n');
    for (std::size_t c = 0; c < mesh.n_cells(); ++c) {
        for (const VertexHandle v : mesh.cell_vertices(CellHandle(static_cast<int>(c)))) put(v.idx(), ' ');
        for (int i = 0; i < 4; ++i)
            for (int k = 0; k < 3; ++k) put(pm.params[c][i][k], i == 3 && k == 2 ? '\n' : ' ');
    }
    out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
    out.flush();
}

void writeHexExFile(const std::string& path, const ParametrizedTetMesh& pm) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw std::runtime_error(path + ": cannot open file for writing: " + std::strerror(errno));
    writeHexExStream(out, pm);
    out.close();
    if (!out) throw std::runtime_error(path + ": write error");
}

} // namespace HexEx
