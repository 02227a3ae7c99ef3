/// @file OvmAscii.cc
/// OpenVolumeMesh ASCII (`.ovm`) into and out of an OvmModel: a line reader on top of the
/// shared tokenizer, strict number parsing, and a writer with 17 significant digits.

#include "OvmModel.hh"
#include "TextParsing.hh"

#include "../Core/Error.hh"

#include <algorithm>
#include <climits>
#include <cmath>
#include <exception>
#include <thread>

namespace HexEx {

namespace {

using detail::quoteToken;

std::string lower(std::string_view s) {
    std::string r(s);
    for (auto& c : r) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return r;
}

/// Reads the file line by line (blank lines and `#` comments skipped) and parses the tokens
/// of the current line; every failure becomes an InputError "<name>:<line>: <reason>".
class LineReader {
public:
    LineReader(std::string_view text, const std::string& name) : lx_(text, name, 1, '#') {}

    [[noreturn]] void fail(long long line, const std::string& reason) const { lx_.fail(line, reason); }
    /// Moves to the next non-blank line; false at the end of the text.
    bool next() {
        tokens_ = lx_.lineTokens();
        return !tokens_.empty();
    }
    /// Moves to the next line; at the end of the text fails with "expected <what>".
    void require(const std::string& what) {
        if (!next()) fail(eofLine(), "unexpected end of file: expected " + what);
    }
    long long line() const { return tokens_.empty() ? eofLine() : tokens_[0].line; }
    long long eofLine() const { return lx_.eofLine(); }
    /// The current line from its first to its last token.
    std::string_view text() const {
        if (tokens_.empty()) return {};
        const char* b = tokens_.front().text.data();
        return {b, static_cast<std::size_t>(tokens_.back().text.data() + tokens_.back().text.size() - b)};
    }
    std::size_t size() const { return tokens_.size(); }
    std::string_view token(std::size_t i) const { return tokens_[i].text; }
    std::size_t remainingBytes() const { return lx_.remaining(); }

    /// Fails unless the line has exactly @p n tokens.
    void expectTokens(std::size_t n, const std::string& what) const {
        if (tokens_.size() != n)
            fail(line(), "expected " + std::to_string(n) + (n == 1 ? " value" : " values") + " for " + what + ", got " +
                             std::to_string(tokens_.size()) + " in " + quoteToken(text()));
    }
    /// Token @p i as an integer.
    long long integer(std::size_t i, const std::string& what) const {
        long long value = 0;
        const detail::NumberParse r = detail::parseInteger(token(i), value);
        if (r == detail::NumberParse::OutOfRange) fail(line(), "integer " + quoteToken(token(i)) + " out of range for " + what);
        if (r != detail::NumberParse::Ok) fail(line(), "expected an integer for " + what + ", got " + quoteToken(token(i)));
        return value;
    }
    /// Token @p i as an index in [0, n).
    int index(std::size_t i, long long n, const std::string& what) const {
        const long long v = integer(i, what);
        if (v < 0 || v >= n) fail(line(), what + " " + std::to_string(v) + " out of range [0, " + std::to_string(n) + ")");
        return static_cast<int>(v);
    }
    /// Token @p i as a finite double.
    double finite(std::size_t i, const std::string& what) const {
        double value = 0;
        if (detail::parseReal(token(i), value) == detail::NumberParse::Malformed)
            fail(line(), "expected a number for " + what + ", got " + quoteToken(token(i)));
        if (!std::isfinite(value)) fail(line(), "NaN or infinite value " + quoteToken(token(i)) + " for " + what);
        return value;
    }
    /// Reads the section keyword line @p keyword and the count line after it; the count must
    /// fit the rest of the file with at least @p minBytes bytes per entity.
    long long section(const char* keyword, long long maxCount, std::size_t minBytes) {
        require(std::string("section '") + keyword + "'");
        if (size() != 1 || lower(token(0)) != lower(keyword))
            fail(line(), std::string("expected section '") + keyword + "', got " + quoteToken(text()));
        const std::string what = lower(std::string(keyword) + " count");
        require(what);
        expectTokens(1, what);
        const long long n = integer(0, what);
        if (n < 0) fail(line(), "negative " + what + " " + std::to_string(n));
        if (n > maxCount || n > static_cast<long long>(remainingBytes() / minBytes) + 1)
            fail(line(), what + " " + std::to_string(n) + " too large for the file");
        return n;
    }

private:
    detail::Lexer lx_;
    std::vector<detail::Token> tokens_;
};

/// Reads the property blocks after the Polyhedra section.
void readProperties(LineReader& in, OvmModel& m) {
    const long long nv = static_cast<long long>(m.vertices.size()), ne = static_cast<long long>(m.edges.size()),
                    nf = static_cast<long long>(m.faces.size()), nc = static_cast<long long>(m.cells.size());
    while (in.next()) {
        const long long line = in.line();
        const std::string_view t = in.text();
        const std::size_t q1 = t.find('"');
        const std::size_t q2 = q1 == std::string_view::npos ? q1 : t.find('"', q1 + 1);
        if (in.size() < 3 || q1 == std::string_view::npos || q2 == std::string_view::npos ||
            t.find_first_not_of(" \t\r\v\f", q2 + 1) != std::string_view::npos)
            in.fail(line, "expected a property block header 'ENTITY TYPE \"name\"', got " + quoteToken(t));
        const std::string entity(in.token(0));
        std::string_view type = t.substr(entity.size(), q1 - entity.size());
        while (!type.empty() && detail::isFormatSpace(type.front())) type.remove_prefix(1);
        while (!type.empty() && detail::isFormatSpace(type.back())) type.remove_suffix(1);
        if (type.empty()) in.fail(line, "property block header " + quoteToken(t) + " has no type");
        const std::string pname(t.substr(q1 + 1, q2 - q1 - 1));
        const std::string ent = lower(entity), ltype = lower(type);
        static const std::pair<const char*, int> kEntities[] = {{"vprop", 0}, {"eprop", 1}, {"heprop", 2},
                                                                 {"fprop", 3}, {"hfprop", 4}, {"cprop", 5},
                                                                 {"mprop", 6}};
        int kind = -1;
        for (const auto& e : kEntities)
            if (ent == e.first) kind = e.second;
        if (kind < 0)
            in.fail(line, "unknown property entity " + quoteToken(entity) +
                              " (expected VProp, EProp, HEProp, FProp, HFProp, CProp or MProp)");
        const long long n = std::array<long long, 7>{nv, ne, 2 * ne, nf, 2 * nf, nc, 1}[kind];
        const bool hfParam = kind == 4 && (ltype == "vec3d" || ltype == "vec3f") && isParametrizationName(pname);
        const bool cParam = kind == 5 && ltype == "vec12d" && isParametrizationName(pname);
        const std::string label = entity + " " + std::string(type) + " \"" + pname + "\"";
        const auto valueDesc = [&](long long i) {
            return "value " + std::to_string(i) + " of property " + label + " (" + std::to_string(n) + " values)";
        };
        if ((hfParam || cParam) && !m.paramLabel.empty()) {
            m.warnings.push_back(m.name + ":" + std::to_string(line) + ": ignoring parametrization property " + label +
                                 " (using " + m.paramLabel + ")");
        } else if (hfParam || cParam) {
            const int k = hfParam ? 3 : 12;
            std::vector<double> values;
            for (long long i = 0; i < n; ++i) {
                in.require(valueDesc(i));
                in.expectTokens(static_cast<std::size_t>(k), valueDesc(i));
                for (int j = 0; j < k; ++j)
                    values.push_back(in.finite(static_cast<std::size_t>(j), std::string(1, "uvw"[j % 3]) +
                                                   (hfParam ? " of halfface " : " of corner " + std::to_string(j / 3) +
                                                                                    " of polyhedron ") +
                                                   std::to_string(i) + " in property " + label));
            }
            if (hfParam)
                for (long long i = 0; i < n; ++i) m.halffaceParams.emplace_back(&values[3 * i]);
            else
                for (long long i = 0; i < n; ++i) std::copy_n(&values[12 * i], 12, m.cellParams.emplace_back().begin());
            m.paramLabel = label + " (line " + std::to_string(line) + ")";
            continue;
        }
        if (!hfParam && !cParam) m.skipped.push_back(label + " (line " + std::to_string(line) + ")");
        for (long long i = 0; i < n; ++i) in.require(valueDesc(i));
    }
}

} // namespace

OvmModel parseOvmAscii(std::string_view text, const std::string& name) {
    LineReader in(text, name);
    OvmModel m;
    m.name = name;
    in.require("header 'OVM ASCII'");
    if (in.size() == 2 && lower(in.token(0)) == "ovm" && lower(in.token(1)) == "binary")
        in.fail(in.line(), "the old 'OVM BINARY' format is not supported (binary files must be .ovmb)");
    if (in.size() != 2 || lower(in.token(0)) != "ovm" || lower(in.token(1)) != "ascii")
        in.fail(in.line(), "not an OpenVolumeMesh ASCII file: expected header 'OVM ASCII', got " + quoteToken(in.text()));

    const long long nv = in.section("Vertices", INT_MAX, 6);
    if (nv == 0) in.fail(in.line(), "mesh has no vertices (vertex count is 0)");
    m.vertices.resize(static_cast<std::size_t>(nv));
    for (long long v = 0; v < nv; ++v) {
        in.require("vertex " + std::to_string(v) + " (file declares " + std::to_string(nv) + ")");
        in.expectTokens(3, "vertex " + std::to_string(v));
        for (int k = 0; k < 3; ++k)
            m.vertices[v][k] = in.finite(static_cast<std::size_t>(k),
                                         std::string(1, "xyz"[k]) + " coordinate of vertex " + std::to_string(v));
    }

    const long long ne = in.section("Edges", INT_MAX / 2, 4);
    m.edges.resize(static_cast<std::size_t>(ne));
    for (long long e = 0; e < ne; ++e) {
        in.require("edge " + std::to_string(e) + " (file declares " + std::to_string(ne) + ")");
        in.expectTokens(2, "edge " + std::to_string(e));
        for (int k = 0; k < 2; ++k)
            m.edges[e][k] = in.index(static_cast<std::size_t>(k), nv,
                                     "vertex index " + std::to_string(k) + " of edge " + std::to_string(e));
        if (m.edges[e][0] == m.edges[e][1])
            in.fail(in.line(), "edge " + std::to_string(e) + " connects vertex " + std::to_string(m.edges[e][0]) +
                                   " to itself");
    }

    // Faces (closed loops of >= 3 halfedges) and polyhedra (>= 1 halfface): valence, then items.
    const auto readLists = [&in](const std::string& what, long long n, long long minValence, const std::string& item,
                                 long long nItems, std::vector<std::vector<int>>& lists, std::vector<long long>& pos) {
        lists.resize(static_cast<std::size_t>(n));
        pos.resize(static_cast<std::size_t>(n));
        for (long long i = 0; i < n; ++i) {
            const std::string desc = what + " " + std::to_string(i);
            in.require(desc + " (file declares " + std::to_string(n) + ")");
            const long long valence = in.integer(0, "valence of " + desc);
            if (valence < minValence || valence + 1 != static_cast<long long>(in.size()))
                in.expectTokens(static_cast<std::size_t>(std::max(valence, minValence) + 1),
                                desc + " (valence and " + std::to_string(valence) + " " + item + "s)");
            for (long long k = 0; k < valence; ++k)
                lists[i].push_back(in.index(static_cast<std::size_t>(k + 1), nItems,
                                            item + " " + std::to_string(k) + " of " + desc));
            pos[i] = in.line();
        }
    };
    const long long nf = in.section("Faces", INT_MAX / 2, 8);
    readLists("face", nf, 3, "halfedge", 2 * ne, m.faces, m.facePos);
    const long long nc = in.section("Polyhedra", INT_MAX / 8, 4);
    if (nc == 0) in.fail(in.line(), "polyhedron count is 0: the mesh has no tets or other cells");
    readLists("polyhedron", nc, 1, "halfface", 2 * nf, m.cells, m.cellPos);
    readProperties(in, m);
    m.endPos = in.eofLine();
    return m;
}

namespace {

/// The header and the Vertices section of an ASCII file of @p vertices.
void writeOvmAsciiVertices(detail::BlockOutput& o, const std::vector<Vec3d>& vertices, int threads) {
    o << "OVM ASCII\nVertices\n" << vertices.size() << '\n';
    detail::formatItems(o, vertices.size(), threads,
                        [&](detail::BlockOutput& t, std::size_t i) { t.vec17(vertices[i].data()) << '\n'; });
}

/// Everything after the Vertices section: edges, faces, polyhedra and the map.
void writeOvmAsciiTopology(detail::BlockOutput& o, const OvmFlatMesh& m, int threads) {
    o << "Edges\n" << m.edges.size() << '\n';
    detail::formatItems(o, m.edges.size(), threads, [&](detail::BlockOutput& t, std::size_t i) {
        t.intPair(m.edges[i][0], m.edges[i][1]);
    });
    const auto lists = [&](const char* section, const IntLists& items) {
        o << section << '\n' << items.size() << '\n';
        detail::formatItems(o, items.size(), threads,
                            [&](detail::BlockOutput& t, std::size_t i) { t.intLine(items.begin(i), items.end(i)); });
    };
    lists("Faces", m.faces);
    lists("Polyhedra", m.cells);
    if (m.halffaceParams && !m.halffaceParams->empty()) {
        const std::vector<Vec3d>& u = *m.halffaceParams;
        o << "HFProp vec3d \"HexHex::Parametrization\"\n";
        detail::formatItems(o, u.size(), threads,
                            [&](detail::BlockOutput& t, std::size_t i) { t.vec17(u[i].data()) << '\n'; });
    }
}

} // namespace

void writeOvmAscii(detail::BlockOutput& o, const OvmFlatMesh& m, int threads) {
    writeOvmAsciiVertices(o, *m.vertices, threads);
    writeOvmAsciiTopology(o, m, threads);
}

void writeOvmAscii(detail::BlockOutput& o, const HexMesh& mesh, int threads, HexFaceNeighbours* neighbours) {
    if (threads <= 1) {
        writeOvmAscii(o, ovmFlatFromHexMesh(mesh, 1, neighbours), 1);
        return;
    }
    // The vertices do not depend on the face numbering: they are formatted and handed to the
    // output on a thread of their own while the faces and edges are numbered on this one and
    // its helpers (which allocate, as before, from this thread's heap).
    std::exception_ptr error;
    std::thread vertices([&] {
        try {
            writeOvmAsciiVertices(o, mesh.vertices, 1);
        } catch (...) {
            error = std::current_exception();
        }
    });
    OvmFlatMesh flat;
    try {
        flat = ovmFlatFromHexMesh(mesh, threads, neighbours);
    } catch (...) {
        vertices.join();
        throw;
    }
    vertices.join();
    if (error) std::rethrow_exception(error);
    writeOvmAsciiTopology(o, flat, threads);
}

std::string writeOvmAscii(const OvmModel& m) {
    detail::BlockOutput o;
    writeOvmAscii(o, flatOvm(m));
    return o.take();
}

} // namespace HexEx
