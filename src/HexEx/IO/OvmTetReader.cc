/// @file OvmTetReader.cc
/// Implementation of the OpenVolumeMesh ASCII tet mesh reader: a line reader with comment
/// stripping, strict number parsing with std::from_chars, then reconstruction of the tets
/// from their halffaces.

#include "OvmTetReader.hh"
#include "ReaderSupport.hh"
#include "TextParsing.hh"

#include "../Core/Error.hh"
#include "../Predicates/ExactPredicates.hh"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numeric>
#include <system_error>
#include <utility>
#include <vector>

namespace HexEx {

namespace {

constexpr long long kMaxVertices = INT_MAX;
constexpr long long kMaxEdges = INT_MAX / 2;  // halfedges 2e+1 fit an int
constexpr long long kMaxFaces = INT_MAX / 2;  // halffaces 2f+1 fit an int
constexpr long long kMaxCells = INT_MAX / 8;  // as the .hexex reader

/// Parametrization property names accepted (compared case-insensitively).
const char* const kParamNames[] = {"parametrization", "parameterization", "param", "params",
                                   "parameter",       "parameters",       "uvw",   "igm"};

inline bool isSpace(char ch) { return detail::isFormatSpace(ch); }
using detail::quoteToken;

std::string lower(std::string_view s) {
    std::string r(s);
    std::transform(r.begin(), r.end(), r.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return r;
}


/// Reads "clean" lines (comments stripped, trimmed, blank lines skipped) and parses their
/// tokens; every failure becomes an InputError "<name>:<line>: <reason>".
class LineReader {
public:
    LineReader(std::string_view text, const std::string& name) : text_(text), name_(name) {}

    [[noreturn]] void fail(int line, const std::string& reason) const {
        throw InputError(name_ + ":" + std::to_string(line) + ": " + reason);
    }

    /// Moves to the next non-blank line; false at the end of the text.
    bool next() {
        while (pos_ < text_.size()) {
            const std::size_t eol = std::min(text_.find('\n', pos_), text_.size());
            std::string_view raw = text_.substr(pos_, eol - pos_);
            pos_ = eol + 1;
            ++lineNo_;
            // Strip a comment that starts outside double quotes.
            bool inQuote = false;
            for (std::size_t i = 0; i < raw.size(); ++i) {
                if (raw[i] == '"') inQuote = !inQuote;
                else if (raw[i] == '#' && !inQuote) {
                    raw = raw.substr(0, i);
                    break;
                }
            }
            while (!raw.empty() && isSpace(raw.front())) raw.remove_prefix(1);
            while (!raw.empty() && isSpace(raw.back())) raw.remove_suffix(1);
            if (raw.empty()) continue;
            line_ = raw;
            split();
            return true;
        }
        line_ = {};
        tokens_.clear();
        return false;
    }

    /// Moves to the next line; at the end of the text fails with "expected @p what".
    template <class What>
    void require(const What& what) {
        if (!next()) fail(eofLine(), "unexpected end of file: expected " + what());
    }

    int line() const { return lineNo_; }
    /// Line number for end-of-file messages: the last line of the text.
    int eofLine() const {
        int n = static_cast<int>(std::count(text_.begin(), text_.end(), '\n'));
        if (text_.empty() || text_.back() != '\n') ++n;
        return std::max(n, 1);
    }
    std::string_view text() const { return line_; }
    std::size_t size() const { return tokens_.size(); }
    std::string_view token(std::size_t i) const { return tokens_[i]; }
    std::size_t remainingBytes() const { return pos_ < text_.size() ? text_.size() - pos_ : 0; }

    /// Fails unless the line has exactly @p n tokens.
    template <class What>
    void expectTokens(std::size_t n, const What& what) const {
        if (tokens_.size() != n)
            fail(lineNo_, "expected " + std::to_string(n) + (n == 1 ? " value" : " values") + " for " + what() +
                              ", got " + std::to_string(tokens_.size()) + " in " + quoteToken(line_));
    }

    /// Token @p i as an integer.
    template <class What>
    long long integer(std::size_t i, const What& what) const {
        const std::string_view tok = tokens_[i];
        long long value = 0;
        const detail::NumberParse r = detail::parseInteger(tok, value);
        if (r == detail::NumberParse::OutOfRange) fail(lineNo_, "integer " + quoteToken(tok) + " out of range for " + what());
        if (r != detail::NumberParse::Ok) fail(lineNo_, "expected an integer for " + what() + ", got " + quoteToken(tok));
        return value;
    }

    /// Token @p i as an index in [0, n).
    template <class What>
    int index(std::size_t i, long long n, const What& what) const {
        const long long v = integer(i, what);
        if (v < 0 || v >= n)
            fail(lineNo_, what() + " " + std::to_string(v) + " out of range [0, " + std::to_string(n) + ")");
        return static_cast<int>(v);
    }

    /// Token @p i as a double; NaN and infinity (also from overflow) are returned as such (callers decide).
    template <class What>
    double real(std::size_t i, const What& what) const {
        const std::string_view tok = tokens_[i];
        double value = 0;
        const detail::NumberParse r = detail::parseReal(tok, value);
        if (r == detail::NumberParse::Malformed)
            fail(lineNo_, "expected a number for " + what() + ", got " + quoteToken(tok));
        return value;  // OutOfRange: value is +-HUGE_VAL, rejected by finite()
    }

    /// Token @p i as a finite double.
    template <class What>
    double finite(std::size_t i, const What& what) const {
        const double v = real(i, what);
        if (!std::isfinite(v)) fail(lineNo_, "NaN or infinite value " + quoteToken(tokens_[i]) + " for " + what());
        return v;
    }

    /// Reads the section keyword line @p keyword and the count line after it.
    long long section(const char* keyword, long long maxCount) {
        require([&] { return std::string("section '") + keyword + "'"; });
        if (tokens_.size() != 1 || lower(tokens_[0]) != lower(keyword))
            fail(lineNo_, std::string("expected section '") + keyword + "', got " + quoteToken(line_));
        const std::string what = std::string(keyword) + " count";
        const auto desc = [&] { return lower(what); };
        require(desc);
        expectTokens(1, desc);
        const long long n = integer(0, desc);
        if (n < 0) fail(lineNo_, "negative " + desc() + " " + std::to_string(n));
        if (n > maxCount)
            fail(lineNo_, desc() + " " + std::to_string(n) + " too large (at most " + std::to_string(maxCount) + ")");
        return n;
    }

private:
    void split() {
        tokens_.clear();
        std::size_t i = 0;
        while (i < line_.size()) {
            while (i < line_.size() && isSpace(line_[i])) ++i;
            const std::size_t start = i;
            while (i < line_.size() && !isSpace(line_[i])) ++i;
            if (i > start) tokens_.push_back(line_.substr(start, i - start));
        }
    }

    std::string_view text_;
    const std::string& name_;
    std::size_t pos_ = 0;
    int lineNo_ = 0;
    std::string_view line_;
    std::vector<std::string_view> tokens_;
};

/// One property block header: entity, type and name.
struct PropHeader {
    std::string entity, type, name;
    int line = 0;
};

/// Union-find with path halving.
int findRoot(std::vector<int>& parent, int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
}

} // namespace

ParametrizedTetMesh readOvmTetBuffer(std::string_view text, const std::string& name, ReadReport* report) {
    LineReader in(text, name);
    std::vector<std::string> warnings;

    // Header.
    in.require([] { return std::string("header 'OVM ASCII'"); });
    if (in.size() == 2 && lower(in.token(0)) == "ovm" && lower(in.token(1)) == "binary")
        in.fail(in.line(), "binary OpenVolumeMesh files are not supported (expected 'OVM ASCII')");
    if (in.size() != 2 || lower(in.token(0)) != "ovm" || lower(in.token(1)) != "ascii")
        in.fail(in.line(), "not an OpenVolumeMesh ASCII file: expected header 'OVM ASCII', got " + quoteToken(in.text()));

    // Vertices.
    const long long nv = in.section("Vertices", kMaxVertices);
    if (nv == 0) in.fail(in.line(), "mesh has no vertices (vertex count is 0)");
    std::vector<Vec3d> positions;
    positions.reserve(static_cast<std::size_t>(std::min<long long>(nv, in.remainingBytes() / 6 + 1)));
    for (long long v = 0; v < nv; ++v) {
        const auto desc = [&] { return "vertex " + std::to_string(v) + " (file declares " + std::to_string(nv) + ")"; };
        in.require(desc);
        in.expectTokens(3, [&] { return "vertex " + std::to_string(v); });
        Vec3d p;
        for (int k = 0; k < 3; ++k)
            p[k] = in.finite(static_cast<std::size_t>(k), [&] {
                return std::string(1, "xyz"[k]) + " coordinate of vertex " + std::to_string(v);
            });
        positions.push_back(p);
    }

    // Edges.
    const long long ne = in.section("Edges", kMaxEdges);
    std::vector<std::array<int, 2>> edges;
    edges.reserve(static_cast<std::size_t>(std::min<long long>(ne, in.remainingBytes() / 4 + 1)));
    for (long long e = 0; e < ne; ++e) {
        const auto desc = [&] { return "edge " + std::to_string(e) + " (file declares " + std::to_string(ne) + ")"; };
        in.require(desc);
        in.expectTokens(2, [&] { return "edge " + std::to_string(e); });
        std::array<int, 2> ev;
        for (int k = 0; k < 2; ++k)
            ev[k] = in.index(static_cast<std::size_t>(k), nv, [&] {
                return "vertex index " + std::to_string(k) + " of edge " + std::to_string(e);
            });
        if (ev[0] == ev[1])
            in.fail(in.line(), "edge " + std::to_string(e) + " connects vertex " + std::to_string(ev[0]) + " to itself");
        edges.push_back(ev);
    }
    auto heSource = [&](int he) { return edges[static_cast<std::size_t>(he / 2)][he % 2]; };
    auto heTarget = [&](int he) { return edges[static_cast<std::size_t>(he / 2)][1 - he % 2]; };

    // Faces (triangles): vertex loops.
    const long long nf = in.section("Faces", kMaxFaces);
    std::vector<std::array<int, 3>> faceLoop;
    faceLoop.reserve(static_cast<std::size_t>(std::min<long long>(nf, in.remainingBytes() / 8 + 1)));
    for (long long f = 0; f < nf; ++f) {
        const auto fdesc = [&] { return "face " + std::to_string(f); };
        in.require([&] { return fdesc() + " (file declares " + std::to_string(nf) + ")"; });
        const long long valence = in.integer(0, [&] { return "valence of " + fdesc(); });
        if (valence != 3)
            in.fail(in.line(), fdesc() + " has valence " + std::to_string(valence) +
                                   ": only triangles are supported (tetrahedral meshes)");
        in.expectTokens(4, [&] { return fdesc() + " (valence and 3 halfedges)"; });
        std::array<int, 3> he;
        for (int k = 0; k < 3; ++k)
            he[k] = in.index(static_cast<std::size_t>(k + 1), 2 * ne, [&] {
                return "halfedge " + std::to_string(k) + " of " + fdesc();
            });
        std::array<int, 3> loop;
        for (int k = 0; k < 3; ++k) {
            if (heTarget(he[k]) != heSource(he[(k + 1) % 3]))
                in.fail(in.line(), fdesc() + ": halfedges " + std::to_string(he[k]) + " and " +
                                       std::to_string(he[(k + 1) % 3]) + " are not consecutive (the loop is not closed)");
            loop[k] = heSource(he[k]);
        }
        if (loop[0] == loop[1] || loop[1] == loop[2] || loop[0] == loop[2])
            in.fail(in.line(), fdesc() + " repeats a vertex");
        faceLoop.push_back(loop);
    }
    auto halffaceLoop = [&](int hf) {
        const auto& l = faceLoop[static_cast<std::size_t>(hf / 2)];
        return hf % 2 == 0 ? l : std::array<int, 3>{l[0], l[2], l[1]};
    };

    // Polyhedra (tets).
    const long long nc = in.section("Polyhedra", kMaxCells);
    if (nc == 0) in.fail(in.line(), "mesh has no tets (polyhedron count is 0)");
    const std::size_t ncReserve = static_cast<std::size_t>(std::min<long long>(nc, in.remainingBytes() / 10 + 1));
    std::vector<std::array<int, 4>> cellHf;
    std::vector<std::array<int, 4>> corners;
    std::vector<int> cellLine;
    cellHf.reserve(ncReserve);
    corners.reserve(ncReserve);
    cellLine.reserve(ncReserve);
    std::vector<int> halffaceCell(static_cast<std::size_t>(2 * nf), -1);
    for (long long c = 0; c < nc; ++c) {
        const auto cdesc = [&] { return "polyhedron " + std::to_string(c); };
        in.require([&] { return cdesc() + " (file declares " + std::to_string(nc) + ")"; });
        const long long valence = in.integer(0, [&] { return "valence of " + cdesc(); });
        if (valence != 4)
            in.fail(in.line(), cdesc() + " has " + std::to_string(valence) +
                                   " halffaces: only tetrahedra (4 triangular halffaces) are supported");
        in.expectTokens(5, [&] { return cdesc() + " (valence and 4 halffaces)"; });
        std::array<int, 4> hf;
        for (int k = 0; k < 4; ++k) {
            hf[k] = in.index(static_cast<std::size_t>(k + 1), 2 * nf, [&] {
                return "halfface " + std::to_string(k) + " of " + cdesc();
            });
            int& owner = halffaceCell[static_cast<std::size_t>(hf[k])];
            if (owner == static_cast<int>(c))
                in.fail(in.line(), cdesc() + " lists halfface " + std::to_string(hf[k]) + " twice");
            if (owner >= 0)
                in.fail(in.line(), "halfface " + std::to_string(hf[k]) + " is used by polyhedron " +
                                       std::to_string(owner) + " and " + cdesc());
            owner = static_cast<int>(c);
        }
        // The four halffaces must be the four triangles over four vertices, consistently oriented.
        std::array<std::array<int, 3>, 4> loops;
        for (int k = 0; k < 4; ++k) loops[k] = halffaceLoop(hf[k]);
        const auto l0 = loops[0];
        int fourth = -1;
        for (int k = 1; k < 4 && fourth < 0; ++k)
            for (const int v : loops[k])
                if (v != l0[0] && v != l0[1] && v != l0[2]) {
                    fourth = v;
                    break;
                }
        if (fourth < 0) in.fail(in.line(), cdesc() + " is not a tetrahedron: all its halffaces lie on three vertices");
        const std::array<int, 4> cv{l0[0], l0[1], l0[2], fourth};
        std::array<std::pair<int, int>, 12> directed;
        std::array<std::array<int, 3>, 4> sets;
        for (int k = 0; k < 4; ++k) {
            for (const int v : loops[k])
                if (std::find(cv.begin(), cv.end(), v) == cv.end())
                    in.fail(in.line(), cdesc() + " is not a tetrahedron: its halffaces span more than four vertices");
            for (int j = 0; j < 3; ++j) directed[3 * k + j] = {loops[k][j], loops[k][(j + 1) % 3]};
            sets[k] = loops[k];
            std::sort(sets[k].begin(), sets[k].end());
        }
        std::sort(sets.begin(), sets.end());
        if (std::adjacent_find(sets.begin(), sets.end()) != sets.end())
            in.fail(in.line(), cdesc() + " is not a tetrahedron: two of its halffaces lie on the same triangle");
        std::sort(directed.begin(), directed.end());
        if (std::adjacent_find(directed.begin(), directed.end()) != directed.end())
            in.fail(in.line(), cdesc() + ": halffaces are not consistently oriented (an edge is traversed twice "
                                         "in the same direction)");
        cellHf.push_back(hf);
        corners.push_back(cv);
        cellLine.push_back(in.line());
    }

    // Property blocks.
    const auto isParamName = [](const std::string& n) {
        const std::string l = lower(n);
        return std::find_if(std::begin(kParamNames), std::end(kParamNames),
                            [&](const char* k) { return l == k; }) != std::end(kParamNames);
    };
    CornerParams params;
    bool haveParams = false;
    std::string usedProp;
    std::vector<PropHeader> seen;
    while (in.next()) {
        PropHeader ph;
        ph.line = in.line();
        const std::string_view t = in.text();
        const std::size_t q1 = t.find('"');
        const std::size_t q2 = q1 == std::string_view::npos ? q1 : t.find('"', q1 + 1);
        if (in.size() < 3 || q1 == std::string_view::npos || q2 == std::string_view::npos ||
            t.find_first_not_of(" \t\r\v\f", q2 + 1) != std::string_view::npos)
            in.fail(in.line(), "expected a property block header 'ENTITY TYPE \"name\"', got " + quoteToken(t));
        ph.entity = std::string(in.token(0));
        std::string_view type = t.substr(ph.entity.size(), q1 - ph.entity.size());
        while (!type.empty() && isSpace(type.front())) type.remove_prefix(1);
        while (!type.empty() && isSpace(type.back())) type.remove_suffix(1);
        if (type.empty()) in.fail(in.line(), "property block header " + quoteToken(t) + " has no type");
        ph.type = std::string(type);
        ph.name = std::string(t.substr(q1 + 1, q2 - q1 - 1));
        const std::string ent = lower(ph.entity);
        long long n = 0;
        if (ent == "vprop") n = nv;
        else if (ent == "eprop") n = ne;
        else if (ent == "heprop") n = 2 * ne;
        else if (ent == "fprop") n = nf;
        else if (ent == "hfprop") n = 2 * nf;
        else if (ent == "cprop") n = nc;
        else if (ent == "mprop") n = 1;
        else
            in.fail(in.line(), "unknown property entity " + quoteToken(ph.entity) +
                                   " (expected VProp, EProp, HEProp, FProp, HFProp, CProp or MProp)");
        const std::string ltype = lower(ph.type);
        const bool hfParam = ent == "hfprop" && (ltype == "vec3d" || ltype == "vec3f") && isParamName(ph.name);
        const bool cParam = ent == "cprop" && ltype == "vec12d" && isParamName(ph.name);
        const std::string label = ph.entity + " " + ph.type + " \"" + ph.name + "\"";
        const auto valueDesc = [&](long long i) {
            return [&, i] {
                return "value " + std::to_string(i) + " of property " + label + " (" + std::to_string(n) + " values)";
            };
        };
        if ((hfParam || cParam) && haveParams) {
            warnings.push_back(name + ":" + std::to_string(ph.line) + ": ignoring parametrization property " + label +
                               " (using " + usedProp + ")");
        } else if (hfParam) {
            params.assign(corners.size(), {});
            for (long long i = 0; i < n; ++i) {
                in.require(valueDesc(i));
                in.expectTokens(3, valueDesc(i));
                const int c = halffaceCell[static_cast<std::size_t>(i)];
                if (c < 0) continue;  // halfface of no cell: value unused
                Vec3d u;
                for (int k = 0; k < 3; ++k)
                    u[k] = in.finite(static_cast<std::size_t>(k), [&] {
                        return std::string(1, "uvw"[k]) + " of halfface " + std::to_string(i) + " in property " + label;
                    });
                // The halfface's value belongs to the corner of its cell that it does not contain.
                const auto loop = halffaceLoop(static_cast<int>(i));
                const auto& cv = corners[static_cast<std::size_t>(c)];
                for (int j = 0; j < 4; ++j)
                    if (std::find(loop.begin(), loop.end(), cv[j]) == loop.end()) params[static_cast<std::size_t>(c)][j] = u;
            }
            haveParams = true;
            usedProp = label + " (line " + std::to_string(ph.line) + ")";
            continue;
        } else if (cParam) {
            params.assign(corners.size(), {});
            for (long long i = 0; i < n; ++i) {
                in.require(valueDesc(i));
                in.expectTokens(12, valueDesc(i));
                for (int j = 0; j < 4; ++j)
                    for (int k = 0; k < 3; ++k)
                        params[static_cast<std::size_t>(i)][j][k] = in.finite(static_cast<std::size_t>(3 * j + k), [&] {
                            return std::string(1, "uvw"[k]) + " of corner " + std::to_string(j) + " of polyhedron " +
                                   std::to_string(i) + " in property " + label;
                        });
            }
            haveParams = true;
            usedProp = label + " (line " + std::to_string(ph.line) + ")";
            continue;
        }
        seen.push_back(ph);
        for (long long i = 0; i < n; ++i) in.require(valueDesc(i));  // skip the values
    }
    if (!haveParams) {
        std::string found;
        for (std::size_t i = 0; i < seen.size() && i < 8; ++i)
            found += (i ? ", " : "") + seen[i].entity + " " + seen[i].type + " \"" + seen[i].name + "\" (line " +
                     std::to_string(seen[i].line) + ")";
        if (seen.size() > 8) found += " and " + std::to_string(seen.size() - 8) + " more";
        in.fail(in.eofLine(), "no parametrization property: expected a block 'HFProp vec3d \"NAME\"' or "
                              "'CProp vec12d \"NAME\"' with NAME one of Parametrization, Parameterization, param, "
                              "params, parameter, parameters, uvw, igm; found " +
                                  (found.empty() ? std::string("no property blocks") : found));
    }

    // Orientation: exact sign per cell in file corner order, uniform per connected component.
    std::vector<int> sign(corners.size());
    for (std::size_t c = 0; c < corners.size(); ++c) {
        const auto& cv = corners[c];
        sign[c] = orient3d(positions[static_cast<std::size_t>(cv[0])], positions[static_cast<std::size_t>(cv[1])],
                           positions[static_cast<std::size_t>(cv[2])], positions[static_cast<std::size_t>(cv[3])]);
        if (sign[c] == 0) in.fail(cellLine[c], "polyhedron " + std::to_string(c) + " is degenerate in 3D (zero volume)");
    }
    std::vector<int> parent(corners.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (long long f = 0; f < nf; ++f) {
        const int a = halffaceCell[static_cast<std::size_t>(2 * f)], b = halffaceCell[static_cast<std::size_t>(2 * f + 1)];
        if (a >= 0 && b >= 0) parent[static_cast<std::size_t>(findRoot(parent, a))] = findRoot(parent, b);
    }
    std::vector<int> npos(corners.size(), 0), nneg(corners.size(), 0), firstPos(corners.size(), -1),
        firstNeg(corners.size(), -1);
    for (std::size_t c = 0; c < corners.size(); ++c) {
        const auto r = static_cast<std::size_t>(findRoot(parent, static_cast<int>(c)));
        if (sign[c] > 0) {
            if (npos[r]++ == 0) firstPos[r] = static_cast<int>(c);
        } else if (nneg[r]++ == 0) {
            firstNeg[r] = static_cast<int>(c);
        }
    }
    for (std::size_t r = 0; r < corners.size(); ++r) {
        if (npos[r] == 0 || nneg[r] == 0) continue;
        const bool negMinor = nneg[r] <= npos[r];
        const int c = negMinor ? firstNeg[r] : firstPos[r];
        in.fail(cellLine[static_cast<std::size_t>(c)],
                "inconsistent orientation: polyhedron " + std::to_string(c) + " is inverted in 3D relative to its "
                "neighbours (" + std::to_string(negMinor ? nneg[r] : npos[r]) + " of " +
                    std::to_string(npos[r] + nneg[r]) + " cells of its connected component disagree with the others)");
    }
    for (std::size_t c = 0; c < corners.size(); ++c)
        if (sign[c] < 0) {
            std::swap(corners[c][1], corners[c][2]);
            std::swap(params[c][1], params[c][2]);
        }

    // Assemble.
    ParametrizedTetMesh pm;
    pm.mesh.reserve(positions.size(), corners.size());
    for (const auto& p : positions) pm.mesh.add_vertex(p);
    std::vector<char> used(positions.size(), 0);
    for (const auto& cv : corners) {
        pm.mesh.add_cell({VertexHandle(cv[0]), VertexHandle(cv[1]), VertexHandle(cv[2]), VertexHandle(cv[3])});
        for (const int v : cv) used[static_cast<std::size_t>(v)] = 1;
    }
    pm.params = std::move(params);
    const auto nUnused = std::count(used.begin(), used.end(), 0);
    if (nUnused > 0)
        warnings.push_back(name + ": " + std::to_string(nUnused) + " of " + std::to_string(positions.size()) +
                           " vertices are not used by any tet");
    detail::finishTetMesh(pm, name);

    if (report) report->warnings.insert(report->warnings.end(), warnings.begin(), warnings.end());
    return pm;
}

ParametrizedTetMesh readOvmTetStream(std::istream& in, const std::string& name, ReadReport* report) {
    return readOvmTetBuffer(detail::readWholeStream(in, name), name, report);
}

ParametrizedTetMesh readOvmTetMesh(const std::string& path, ReadReport* report) {
    std::ifstream in = detail::openInputFile(path);
    return readOvmTetStream(in, path, report);
}

} // namespace HexEx
