/// @file HexMeshReaders.cc
/// Implementation of the hex mesh readers: a line-tracking tokenizer shared by the text
/// formats, a minimal XML parser for `.vtu`, and cell reconstruction helpers.

#include "HexMeshReaders.hh"
#include "TextParsing.hh"

#include "../Core/Error.hh"
#include "../Mesh/HexMeshCheck.hh"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

namespace HexEx {

namespace {
using detail::quoteToken;

/// Case-insensitive comparison of a token with a keyword.
bool iequals(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}


/// Throws InputError "<name>:<line>: <reason>" (or without line if line <= 0).
[[noreturn]] void failAt(const std::string& name, int line, const std::string& reason) {
    if (line > 0) throw InputError(name + ":" + std::to_string(line) + ": " + reason);
    throw InputError(name + ": " + reason);
}

/// A token and the line it is on.
struct Token {
    std::string_view text;  ///< the characters
    int line = 0;           ///< 1-based line
};

/// Whitespace-separated tokens of a text, with line numbers and optional comments.
class Lexer {
public:
    /// Tokens of @p text, whose first character is on line @p firstLine.
    Lexer(std::string_view text, const std::string& name, int firstLine = 1, char comment = '\0')
        : text_(text), name_(name), line_(firstLine), comment_(comment) {}

    /// Throws InputError at @p line.
    [[noreturn]] void fail(int line, const std::string& reason) const { failAt(name_, line, reason); }

    /// Skips whitespace and comments; true if a token follows.
    bool more() {
        while (pos_ < text_.size()) {
            const char ch = text_[pos_];
            if (ch == '\n') {
                ++line_;
                ++pos_;
            } else if (ch == ' ' || ch == '\t' || ch == '\r' || ch == '\v' || ch == '\f') {
                ++pos_;
            } else if (comment_ && ch == comment_) {
                while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
            } else {
                return true;
            }
        }
        return false;
    }

    /// Line of the last token read, or of the end of the text.
    int line() const { return line_; }

    /// Line to report for an unexpected end of the text.
    int eofLine() const {
        return (!text_.empty() && text_.back() == '\n' && line_ > 1) ? line_ - 1 : line_;
    }

    /// Bytes left.
    std::size_t remaining() const { return text_.size() - pos_; }

    /// The next token; fails at the end of the text, naming @p what was expected.
    Token next(const std::string& what) {
        if (!more()) fail(eofLine(), "unexpected end of file, expected " + what);
        const std::size_t b = pos_;
        while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_])) &&
               !(comment_ && text_[pos_] == comment_))
            ++pos_;
        return {text_.substr(b, pos_ - b), line_};
    }

    /// Peeks at the next token without consuming it (empty at the end).
    std::string_view peek() {
        if (!more()) return {};
        std::size_t e = pos_;
        while (e < text_.size() && !std::isspace(static_cast<unsigned char>(text_[e]))) ++e;
        return text_.substr(pos_, e - pos_);
    }

    /// Reads an integer in [lo, hi].
    long long integer(const std::string& what, long long lo = LLONG_MIN, long long hi = LLONG_MAX) {
        const Token t = next(what);
        long long v = 0;
        const char* first = t.text.data();
        const char* last = first + t.text.size();
        if (first != last && *first == '+') ++first;
        const auto res = std::from_chars(first, last, v);
        if (res.ec != std::errc() || res.ptr != last) fail(t.line, "expected " + what + ", got " + quoteToken(t.text));
        if (v < lo || v > hi)
            fail(t.line, what + " " + std::to_string(v) + " out of range [" + std::to_string(lo) + ", " +
                             std::to_string(hi) + "]");
        return v;
    }

    /// Reads an int in [lo, hi].
    int int32(const std::string& what, long long lo, long long hi) {
        return static_cast<int>(integer(what, std::max<long long>(lo, INT_MIN), std::min<long long>(hi, INT_MAX)));
    }

    /// Reads a count, bounded by what the rest of the text can hold (@p perItem tokens each).
    long long count(const std::string& what, long long perItem = 1) {
        const long long maxCount = static_cast<long long>(remaining() / 2 / std::max<long long>(perItem, 1)) + 1;
        const Token t = next(what);
        long long v = 0;
        const auto res = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
        if (res.ec != std::errc() || res.ptr != t.text.data() + t.text.size())
            fail(t.line, "expected " + what + ", got " + quoteToken(t.text));
        if (v < 0) fail(t.line, what + " is negative (" + std::to_string(v) + ")");
        if (v > maxCount || v > INT_MAX)
            fail(t.line, what + " " + std::to_string(v) + " is larger than the file can hold");
        return v;
    }

    /// Reads a finite real number.
    double real(const std::string& what) {
        const Token t = next(what);
        double v = 0;
        const char* first = t.text.data();
        const char* last = first + t.text.size();
        if (first != last && *first == '+') ++first;
        const auto res = std::from_chars(first, last, v, std::chars_format::general);
        if (res.ec != std::errc() || res.ptr != last) fail(t.line, "expected " + what + ", got " + quoteToken(t.text));
        if (!std::isfinite(v)) fail(t.line, what + " is not finite");
        return v;
    }

    /// Reads the keyword @p kw (case-insensitive).
    void keyword(std::string_view kw) {
        const Token t = next("'" + std::string(kw) + "'");
        if (!iequals(t.text, kw)) fail(t.line, "expected '" + std::string(kw) + "', got " + quoteToken(t.text));
    }

private:
    std::string_view text_;
    const std::string& name_;
    std::size_t pos_ = 0;
    int line_ = 1;
    char comment_ = '\0';
};

// ----------------------------------------------------------------------------------------
// Cell reconstruction

/// Signed volume (times 6) of a closed polyhedron given by face loops.
double signedVolume6(const std::vector<Vec3d>& pts, const std::vector<std::vector<int>>& faces) {
    if (faces.empty() || faces[0].empty()) return 0;
    const Vec3d c = pts[faces[0][0]];
    double v = 0;
    for (const auto& f : faces)
        for (std::size_t i = 1; i + 1 < f.size(); ++i)
            v += ((pts[f[0]] - c) % (pts[f[i]] - c)) | (pts[f[i + 1]] - c);
    return v;
}

/// True if loop @p f equals @p g up to a cyclic shift.
bool cyclicEqual(const std::vector<int>& f, const std::array<int, 4>& g) {
    if (f.size() != 4) return false;
    for (int s = 0; s < 4; ++s) {
        bool eq = true;
        for (int i = 0; i < 4 && eq; ++i) eq = f[(s + i) % 4] == g[i];
        if (eq) return true;
    }
    return false;
}

/// The VTK-ordered hex bounded by six outward quads, if they form one.
std::optional<std::array<int, 8>> hexFromFaces(const std::vector<std::vector<int>>& faces) {
    if (faces.size() != 6) return std::nullopt;
    for (const auto& f : faces)
        if (f.size() != 4) return std::nullopt;
    std::array<int, 8> v{};
    const auto& b = faces[0];  // bottom, outward loop is 0 3 2 1
    v[0] = b[0];
    v[3] = b[1];
    v[2] = b[2];
    v[1] = b[3];
    // The side face with the directed edge a->b is (a, b, x, y): returns (x, y).
    auto side = [&](int a, int c) -> std::optional<std::pair<int, int>> {
        for (std::size_t k = 1; k < 6; ++k) {
            const auto& f = faces[k];
            for (int i = 0; i < 4; ++i)
                if (f[i] == a && f[(i + 1) % 4] == c) return std::make_pair(f[(i + 2) % 4], f[(i + 3) % 4]);
        }
        return std::nullopt;
    };
    const auto front = side(v[0], v[1]);
    const auto back = side(v[2], v[3]);
    if (!front || !back) return std::nullopt;
    v[5] = front->first;
    v[4] = front->second;
    v[7] = back->first;
    v[6] = back->second;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < i; ++j)
            if (v[i] == v[j]) return std::nullopt;
    std::array<bool, 6> used{};
    for (const auto& lf : kHexFaces) {
        const std::array<int, 4> g{{v[lf[0]], v[lf[1]], v[lf[2]], v[lf[3]]}};
        bool found = false;
        for (std::size_t k = 0; k < 6 && !found; ++k)
            if (!used[k] && cyclicEqual(faces[k], g)) used[k] = found = true;
        if (!found) return std::nullopt;
    }
    return v;
}

/// Polyhedron of a standard cell type given by its vertex ids (faces consistently
/// oriented, then made outward by the sign of the volume).
Polyhedron templatePolyhedron(int vtkType, const std::vector<int>& ids, const std::vector<Vec3d>& pts) {
    Polyhedron p;
    const auto& v = ids;
    if (vtkType == 10) {  // tetra
        p.faces = {{v[0], v[2], v[1]}, {v[0], v[1], v[3]}, {v[1], v[2], v[3]}, {v[2], v[0], v[3]}};
    } else if (vtkType == 13) {  // wedge / prism
        p.faces = {{v[0], v[2], v[1]}, {v[3], v[4], v[5]}, {v[0], v[1], v[4], v[3]}, {v[1], v[2], v[5], v[4]},
                   {v[2], v[0], v[3], v[5]}};
    } else if (vtkType == 14) {  // pyramid
        p.faces = {{v[0], v[3], v[2], v[1]}, {v[0], v[1], v[4]}, {v[1], v[2], v[4]}, {v[2], v[3], v[4]},
                   {v[3], v[0], v[4]}};
    } else {  // single polygon
        p.faces = {ids};
        return p;
    }
    if (signedVolume6(pts, p.faces) < 0)
        for (auto& f : p.faces) std::reverse(f.begin(), f.end());
    return p;
}

/// Number of vertices of a fixed-size VTK cell type, 0 for variable size, -1 if unsupported.
int vtkCellSize(long long type) {
    switch (type) {
    case 5: return 3;
    case 9: return 4;
    case 10: return 4;
    case 11: return 8;
    case 12: return 8;
    case 13: return 6;
    case 14: return 5;
    case 7: return 0;
    case 42: return 0;
    default: return -1;
    }
}

/// Collects cells read from VTK data and turns them into the HexMesh.
class VtkCellBuilder {
public:
    /// Builder for @p mesh (vertices already read); errors go to @p name.
    VtkCellBuilder(HexMesh& mesh, const std::string& name) : mesh_(mesh), name_(name) {}

    /// Adds cell of @p type with point ids @p ids (and, for type 42, the face stream
    /// [nFaces, n0, ids..., n1, ...] in @p faceStream). @p group >= 0 groups polygons into
    /// one polyhedron. @p line is used in errors.
    void add(long long type, const std::vector<long long>& ids, const long long* faceStream, std::size_t streamLen,
             long long group, int line, long long cellIndex) {
        const std::string where = "cell " + std::to_string(cellIndex);
        const int expected = vtkCellSize(type);
        if (expected < 0)
            failAt(name_, line, where + ": unsupported VTK cell type " + std::to_string(type));
        if (expected > 0 && static_cast<int>(ids.size()) != expected)
            failAt(name_, line, where + ": cell type " + std::to_string(type) + " needs " + std::to_string(expected) +
                                    " points, got " + std::to_string(ids.size()));
        const long long nv = static_cast<long long>(mesh_.vertices.size());
        std::vector<int> v;
        v.reserve(ids.size());
        for (const long long id : ids) {
            if (id < 0 || id >= nv)
                failAt(name_, line, where + ": point index " + std::to_string(id) + " out of range [0, " +
                                        std::to_string(nv) + ")");
            v.push_back(static_cast<int>(id));
        }
        if (type == 12 || type == 11) {
            std::array<int, 8> h{};
            for (int i = 0; i < 8; ++i) h[i] = v[i];
            if (type == 11) {  // voxel: x fastest, then y, then z
                std::swap(h[2], h[3]);
                std::swap(h[6], h[7]);
            }
            mesh_.hexes.push_back(h);
            return;
        }
        if (type == 42) {
            if (!faceStream || streamLen == 0) failAt(name_, line, where + ": polyhedron without faces");
            std::size_t k = 0;
            const long long nf = faceStream[k++];
            if (nf < 1 || static_cast<std::size_t>(nf) > streamLen)
                failAt(name_, line, where + ": invalid polyhedron face count " + std::to_string(nf));
            Polyhedron p;
            for (long long f = 0; f < nf; ++f) {
                if (k >= streamLen) failAt(name_, line, where + ": polyhedron face stream ends early");
                const long long n = faceStream[k++];
                if (n < 3 || static_cast<std::size_t>(n) > streamLen - k)
                    failAt(name_, line, where + ": invalid polyhedron face size " + std::to_string(n));
                std::vector<int> face;
                for (long long i = 0; i < n; ++i) {
                    const long long id = faceStream[k++];
                    if (id < 0 || id >= nv)
                        failAt(name_, line, where + ": polyhedron face point index " + std::to_string(id) +
                                                " out of range [0, " + std::to_string(nv) + ")");
                    face.push_back(static_cast<int>(id));
                }
                p.faces.push_back(std::move(face));
            }
            if (k != streamLen)
                failAt(name_, line, where + ": polyhedron face stream has " + std::to_string(streamLen - k) +
                                        " extra values");
            mesh_.polyhedra.push_back(std::move(p));
            return;
        }
        if (type == 5 || type == 7 || type == 9) {
            if (v.size() < 3) failAt(name_, line, where + ": polygon with fewer than 3 points");
            if (group >= 0) {
                auto it = groups_.find(group);
                if (it == groups_.end()) {
                    it = groups_.emplace(group, mesh_.polyhedra.size()).first;
                    mesh_.polyhedra.emplace_back();
                }
                mesh_.polyhedra[it->second].faces.push_back(v);
            } else {
                mesh_.polyhedra.push_back(templatePolyhedron(7, v, mesh_.vertices));
            }
            return;
        }
        mesh_.polyhedra.push_back(templatePolyhedron(static_cast<int>(type), v, mesh_.vertices));
    }

private:
    HexMesh& mesh_;
    const std::string& name_;
    std::map<long long, std::size_t> groups_;
};

// ----------------------------------------------------------------------------------------
// Legacy VTK

/// Skips @p n value tokens.
void skipValues(Lexer& lx, long long n, const std::string& what) {
    for (long long i = 0; i < n; ++i) lx.next(what);
}

HexMesh readVtk(std::string_view text, const std::string& name) {
    // Line 1: header, line 2: title.
    const std::size_t e1 = text.find('\n');
    const std::string_view l1 = text.substr(0, e1);
    if (l1.rfind("# vtk DataFile Version", 0) != 0)
        failAt(name, 1, "not a legacy VTK file (expected '# vtk DataFile Version x.y')");
    if (e1 == std::string_view::npos) failAt(name, 1, "unexpected end of file after the header");
    const std::size_t e2 = text.find('\n', e1 + 1);
    if (e2 == std::string_view::npos) failAt(name, 2, "unexpected end of file after the title");
    Lexer lx(text.substr(e2 + 1), name, 3);

    const Token fmt = lx.next("'ASCII'");
    if (iequals(fmt.text, "BINARY")) lx.fail(fmt.line, "binary legacy VTK files are not supported");
    if (!iequals(fmt.text, "ASCII")) lx.fail(fmt.line, "expected 'ASCII', got " + quoteToken(fmt.text));
    lx.keyword("DATASET");
    const Token ds = lx.next("dataset type");
    if (!iequals(ds.text, "UNSTRUCTURED_GRID"))
        lx.fail(ds.line, "dataset type " + quoteToken(ds.text) + " is not supported (expected UNSTRUCTURED_GRID)");

    HexMesh mesh;
    bool havePoints = false, haveCells = false, haveTypes = false;
    int cellsLine = 0;
    std::vector<long long> offsets;  // ncells + 1 entries into conn
    std::vector<long long> conn;
    std::vector<int> cellLines;
    std::vector<long long> types;
    std::vector<long long> groupIds;
    long long attrCount = -1;  // tuples of the current CELL_DATA / POINT_DATA block
    bool inCellData = false;

    auto skipField = [&](long long) {
        lx.next("field name");
        const long long arrays = lx.count("number of field arrays");
        for (long long a = 0; a < arrays; ++a) {
            const Token an = lx.next("field array name");
            (void)an;
            const long long comps = lx.count("number of components");
            const long long tuples = lx.count("number of tuples");
            lx.next("data type");
            if (comps > 0 && tuples > LLONG_MAX / comps) lx.fail(lx.line(), "field array too large");
            skipValues(lx, comps * tuples, "field array value");
        }
    };

    while (lx.more()) {
        const Token kw = lx.next("keyword");
        if (iequals(kw.text, "POINTS")) {
            if (havePoints) lx.fail(kw.line, "second POINTS section");
            const long long n = lx.count("number of points", 3);
            lx.next("point data type");
            mesh.vertices.resize(static_cast<std::size_t>(n));
            for (auto& p : mesh.vertices)
                for (int d = 0; d < 3; ++d) p[d] = lx.real("point coordinate");
            havePoints = true;
        } else if (iequals(kw.text, "CELLS")) {
            if (haveCells) lx.fail(kw.line, "second CELLS section");
            cellsLine = kw.line;
            const long long n = lx.count("number of cells");
            const long long size = lx.count("cell list size");
            if (iequals(lx.peek(), "OFFSETS")) {  // version 5.x
                lx.next("OFFSETS");
                lx.next("offset data type");
                if (n < 1) lx.fail(kw.line, "CELLS needs at least one offset in version 5 files");
                offsets.resize(static_cast<std::size_t>(n));
                cellLines.resize(static_cast<std::size_t>(n - 1));
                for (long long i = 0; i < n; ++i) {
                    offsets[i] = lx.integer("offset", 0, size);
                    if (i > 0) cellLines[i - 1] = lx.line();
                    if (i > 0 && offsets[i] < offsets[i - 1]) lx.fail(lx.line(), "offsets decrease");
                }
                if (offsets.front() != 0) lx.fail(kw.line, "first offset is not 0");
                if (offsets.back() != size) lx.fail(lx.line(), "last offset differs from the connectivity size");
                lx.keyword("CONNECTIVITY");
                lx.next("connectivity data type");
                conn.resize(static_cast<std::size_t>(size));
                for (auto& c : conn) c = lx.integer("point index");
            } else {
                offsets.assign(1, 0);
                long long read = 0;
                for (long long i = 0; i < n; ++i) {
                    const long long k = lx.integer("cell size", 0, size - read - 1);
                    cellLines.push_back(lx.line());
                    read += 1 + k;
                    for (long long j = 0; j < k; ++j) conn.push_back(lx.integer("point index"));
                    offsets.push_back(static_cast<long long>(conn.size()));
                }
                if (read != size)
                    lx.fail(lx.line(), "CELLS declares list size " + std::to_string(size) + " but the cells use " +
                                           std::to_string(read));
            }
            haveCells = true;
        } else if (iequals(kw.text, "CELL_TYPES")) {
            if (haveTypes) lx.fail(kw.line, "second CELL_TYPES section");
            const long long n = lx.count("number of cell types");
            types.resize(static_cast<std::size_t>(n));
            for (auto& t : types) t = lx.integer("cell type", 0, 255);
            haveTypes = true;
        } else if (iequals(kw.text, "CELL_DATA") || iequals(kw.text, "POINT_DATA")) {
            attrCount = lx.count("number of tuples");
            inCellData = iequals(kw.text, "CELL_DATA");
        } else if (iequals(kw.text, "SCALARS")) {
            if (attrCount < 0) lx.fail(kw.line, "SCALARS outside CELL_DATA / POINT_DATA");
            const Token sn = lx.next("scalar name");
            lx.next("scalar data type");
            long long comps = 1;
            const std::string_view nx = lx.peek();
            if (!nx.empty() && std::isdigit(static_cast<unsigned char>(nx[0])))
                comps = lx.integer("number of components", 1, 4);
            if (iequals(lx.peek(), "LOOKUP_TABLE")) {
                lx.next("LOOKUP_TABLE");
                lx.next("lookup table name");
            }
            if (inCellData && sn.text == "hexex_cell_id" && comps == 1) {
                groupIds.resize(static_cast<std::size_t>(attrCount));
                for (auto& g : groupIds) g = lx.integer("hexex_cell_id value", 0, LLONG_MAX);
            } else {
                skipValues(lx, attrCount * comps, "scalar value");
            }
        } else if (iequals(kw.text, "VECTORS") || iequals(kw.text, "NORMALS")) {
            if (attrCount < 0) lx.fail(kw.line, quoteToken(kw.text) + " outside CELL_DATA / POINT_DATA");
            lx.next("name");
            lx.next("data type");
            skipValues(lx, 3 * attrCount, "vector value");
        } else if (iequals(kw.text, "TENSORS")) {
            if (attrCount < 0) lx.fail(kw.line, "TENSORS outside CELL_DATA / POINT_DATA");
            lx.next("name");
            lx.next("data type");
            skipValues(lx, 9 * attrCount, "tensor value");
        } else if (iequals(kw.text, "TEXTURE_COORDINATES")) {
            if (attrCount < 0) lx.fail(kw.line, "TEXTURE_COORDINATES outside CELL_DATA / POINT_DATA");
            lx.next("name");
            const long long dim = lx.integer("dimension", 1, 3);
            lx.next("data type");
            skipValues(lx, dim * attrCount, "texture coordinate");
        } else if (iequals(kw.text, "COLOR_SCALARS")) {
            if (attrCount < 0) lx.fail(kw.line, "COLOR_SCALARS outside CELL_DATA / POINT_DATA");
            lx.next("name");
            const long long m = lx.integer("number of values", 1, 4);
            skipValues(lx, m * attrCount, "color value");
        } else if (iequals(kw.text, "LOOKUP_TABLE")) {
            lx.next("lookup table name");
            const long long m = lx.count("lookup table size", 4);
            skipValues(lx, 4 * m, "lookup table value");
        } else if (iequals(kw.text, "FIELD")) {
            skipField(0);
        } else if (iequals(kw.text, "METADATA")) {
            // Skip until the next section keyword.
            static const char* const kSections[] = {"POINTS", "CELLS", "CELL_TYPES", "CELL_DATA", "POINT_DATA",
                                                    "SCALARS", "VECTORS", "NORMALS", "FIELD", "TENSORS"};
            while (lx.more()) {
                const std::string_view p = lx.peek();
                bool stop = false;
                for (const char* s : kSections) stop = stop || iequals(p, s);
                if (stop) break;
                lx.next("metadata");
            }
        } else {
            lx.fail(kw.line, "unexpected keyword " + quoteToken(kw.text));
        }
    }
    if (!havePoints) failAt(name, 0, "no POINTS section");
    if (!haveCells) failAt(name, 0, "no CELLS section");
    if (!haveTypes) failAt(name, 0, "no CELL_TYPES section");
    const long long ncells = static_cast<long long>(offsets.size()) - 1;
    if (static_cast<long long>(types.size()) != ncells)
        failAt(name, cellsLine, "CELLS has " + std::to_string(ncells) + " cells but CELL_TYPES has " +
                                    std::to_string(types.size()));
    if (!groupIds.empty() && static_cast<long long>(groupIds.size()) != ncells)
        failAt(name, 0, "hexex_cell_id has " + std::to_string(groupIds.size()) + " values for " +
                            std::to_string(ncells) + " cells");

    VtkCellBuilder builder(mesh, name);
    std::vector<long long> ids;
    for (long long c = 0; c < ncells; ++c) {
        const long long b = offsets[c], e = offsets[c + 1];
        const int line = c < static_cast<long long>(cellLines.size()) ? cellLines[c] : cellsLine;
        if (types[c] == 42) {
            // Legacy face stream: [nFaces, n0, ids..., n1, ids...]; point ids are the faces'.
            builder.add(42, {}, conn.data() + b, static_cast<std::size_t>(e - b), -1, line, c);
            continue;
        }
        ids.assign(conn.begin() + b, conn.begin() + e);
        builder.add(types[c], ids, nullptr, 0, groupIds.empty() ? -1 : groupIds[c], line, c);
    }
    return mesh;
}

// ----------------------------------------------------------------------------------------
// Minimal XML for .vtu

/// A range of character data inside an element.
struct TextRange {
    std::size_t begin = 0, end = 0;  ///< byte range
    int line = 1;                    ///< line of begin
};

/// An element of the XML tree.
struct XmlNode {
    std::string name;                                        ///< tag name
    std::vector<std::pair<std::string, std::string>> attrs;  ///< attributes, entities decoded
    int line = 1;                                            ///< line of the start tag
    int parent = -1;                                         ///< parent index, -1 for the root
    std::vector<int> children;                               ///< child element indices
    std::vector<TextRange> text;                             ///< character data

    /// The attribute @p key, or nullptr.
    const std::string* attr(const std::string& key) const {
        for (const auto& a : attrs)
            if (a.first == key) return &a.second;
        return nullptr;
    }
};

/// Parses the subset of XML that VTK files use (no DTDs); fails on malformed structure.
std::vector<XmlNode> parseXml(std::string_view t, const std::string& name) {
    std::vector<XmlNode> nodes;
    std::vector<int> stack;
    std::size_t pos = 0;
    int line = 1;
    auto advanceTo = [&](std::size_t to) {
        for (; pos < to && pos < t.size(); ++pos)
            if (t[pos] == '\n') ++line;
    };
    auto skipPast = [&](std::string_view end, const char* what) {
        const std::size_t e = t.find(end, pos);
        if (e == std::string_view::npos) failAt(name, line, std::string("unterminated ") + what);
        advanceTo(e + end.size());
    };
    auto isNameChar = [](char ch) {
        return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-' || ch == '.' || ch == ':';
    };
    auto skipWs = [&] {
        while (pos < t.size() && std::isspace(static_cast<unsigned char>(t[pos]))) advanceTo(pos + 1);
    };
    auto decode = [](std::string_view s) {
        std::string out;
        for (std::size_t i = 0; i < s.size(); ++i) {
            if (s[i] == '&') {
                static const std::pair<const char*, char> ents[] = {
                    {"&lt;", '<'}, {"&gt;", '>'}, {"&amp;", '&'}, {"&quot;", '"'}, {"&apos;", '\''}};
                bool done = false;
                for (const auto& en : ents)
                    if (s.substr(i).rfind(en.first, 0) == 0) {
                        out += en.second;
                        i += std::string_view(en.first).size() - 1;
                        done = true;
                        break;
                    }
                if (done) continue;
            }
            out += s[i];
        }
        return out;
    };
    bool rootClosed = false;
    while (pos < t.size()) {
        if (t[pos] != '<') {
            const std::size_t e = std::min(t.find('<', pos), t.size());
            const TextRange r{pos, e, line};
            bool blank = true;
            for (std::size_t i = pos; i < e && blank; ++i) blank = std::isspace(static_cast<unsigned char>(t[i]));
            if (!stack.empty())
                nodes[stack.back()].text.push_back(r);
            else if (!blank)
                failAt(name, line, "text outside the root element");
            advanceTo(e);
            continue;
        }
        const std::string_view rest = t.substr(pos);
        if (rest.rfind("<?", 0) == 0) {
            skipPast("?>", "processing instruction");
        } else if (rest.rfind("<!--", 0) == 0) {
            skipPast("-->", "comment");
        } else if (rest.rfind("<![CDATA[", 0) == 0) {
            const std::size_t e = t.find("]]>", pos);
            if (e == std::string_view::npos) failAt(name, line, "unterminated CDATA section");
            if (stack.empty()) failAt(name, line, "CDATA outside the root element");
            advanceTo(pos + 9);
            nodes[stack.back()].text.push_back({pos, e, line});
            advanceTo(e + 3);
        } else if (rest.rfind("<!", 0) == 0) {
            skipPast(">", "declaration");
        } else if (rest.rfind("</", 0) == 0) {
            const int l = line;
            advanceTo(pos + 2);
            const std::size_t b = pos;
            while (pos < t.size() && isNameChar(t[pos])) ++pos;
            const std::string_view nm = t.substr(b, pos - b);
            skipWs();
            if (pos >= t.size() || t[pos] != '>') failAt(name, l, "malformed end tag");
            advanceTo(pos + 1);
            if (stack.empty() || nodes[stack.back()].name != nm)
                failAt(name, l, "end tag </" + std::string(nm) + "> does not match " +
                                    (stack.empty() ? std::string("any open element")
                                                   : "<" + nodes[stack.back()].name + "> (line " +
                                                         std::to_string(nodes[stack.back()].line) + ")"));
            stack.pop_back();
            if (stack.empty()) rootClosed = true;
        } else {
            XmlNode node;
            node.line = line;
            advanceTo(pos + 1);
            const std::size_t b = pos;
            while (pos < t.size() && isNameChar(t[pos])) ++pos;
            node.name = std::string(t.substr(b, pos - b));
            if (node.name.empty()) failAt(name, node.line, "malformed start tag");
            bool selfClosing = false;
            for (;;) {
                skipWs();
                if (pos >= t.size()) failAt(name, node.line, "unterminated start tag <" + node.name + ">");
                if (t[pos] == '>') {
                    advanceTo(pos + 1);
                    break;
                }
                if (t[pos] == '/') {
                    if (pos + 1 >= t.size() || t[pos + 1] != '>') failAt(name, line, "malformed start tag");
                    advanceTo(pos + 2);
                    selfClosing = true;
                    break;
                }
                const std::size_t ab = pos;
                while (pos < t.size() && isNameChar(t[pos])) ++pos;
                if (pos == ab) failAt(name, line, "malformed attribute in <" + node.name + ">");
                std::string key(t.substr(ab, pos - ab));
                skipWs();
                if (pos >= t.size() || t[pos] != '=') failAt(name, line, "attribute '" + key + "' without value");
                advanceTo(pos + 1);
                skipWs();
                if (pos >= t.size() || (t[pos] != '"' && t[pos] != '\''))
                    failAt(name, line, "attribute '" + key + "' value not quoted");
                const char q = t[pos];
                advanceTo(pos + 1);
                const std::size_t ve = t.find(q, pos);
                if (ve == std::string_view::npos) failAt(name, line, "unterminated attribute value");
                node.attrs.emplace_back(std::move(key), decode(t.substr(pos, ve - pos)));
                advanceTo(ve + 1);
            }
            if (rootClosed || (stack.empty() && !nodes.empty()))
                failAt(name, node.line, "more than one root element");
            const int idx = static_cast<int>(nodes.size());
            node.parent = stack.empty() ? -1 : stack.back();
            nodes.push_back(std::move(node));
            if (nodes[idx].parent >= 0) nodes[nodes[idx].parent].children.push_back(idx);
            if (!selfClosing)
                stack.push_back(idx);
            else if (stack.empty())
                rootClosed = true;
        }
    }
    if (!stack.empty())
        failAt(name, line, "element <" + nodes[stack.back()].name + "> (line " +
                               std::to_string(nodes[stack.back()].line) + ") is not closed");
    if (nodes.empty()) failAt(name, line, "no XML element found");
    return nodes;
}

/// Children of @p parent named @p tag.
std::vector<int> childrenNamed(const std::vector<XmlNode>& nodes, int parent, const std::string& tag) {
    std::vector<int> out;
    for (const int c : nodes[parent].children)
        if (nodes[c].name == tag) out.push_back(c);
    return out;
}

/// Reads all numbers of an ASCII DataArray.
template <class T>
std::vector<T> readDataArray(std::string_view text, const std::vector<XmlNode>& nodes, int idx,
                             const std::string& name, const std::string& what) {
    const XmlNode& n = nodes[idx];
    const std::string* format = n.attr("format");
    if (format && *format != "ascii")
        failAt(name, n.line, "DataArray " + what + " has format '" + *format + "'; only ascii is supported");
    std::vector<T> out;
    for (const TextRange& r : n.text) {
        Lexer lx(text.substr(r.begin, r.end - r.begin), name, r.line);
        while (lx.more()) {
            if constexpr (std::is_same_v<T, double>)
                out.push_back(lx.real(what + " value"));
            else
                out.push_back(lx.integer(what + " value"));
        }
    }
    return out;
}

/// Parses a non-negative integer attribute.
long long intAttr(const XmlNode& n, const std::string& key, const std::string& name) {
    const std::string* s = n.attr(key);
    if (!s) failAt(name, n.line, "<" + n.name + "> has no attribute " + key);
    long long v = 0;
    const auto res = std::from_chars(s->data(), s->data() + s->size(), v);
    if (res.ec != std::errc() || res.ptr != s->data() + s->size() || v < 0 || v > INT_MAX)
        failAt(name, n.line, "attribute " + key + "=" + quoteToken(*s) + " is not a valid count");
    return v;
}

HexMesh readVtu(std::string_view text, const std::string& name) {
    const std::vector<XmlNode> nodes = parseXml(text, name);
    const XmlNode& root = nodes[0];
    if (root.name != "VTKFile") failAt(name, root.line, "root element is <" + root.name + ">, expected <VTKFile>");
    const std::string* type = root.attr("type");
    if (!type || *type != "UnstructuredGrid")
        failAt(name, root.line, "VTKFile type is " + (type ? quoteToken(*type) : std::string("missing")) +
                                    ", expected 'UnstructuredGrid'");
    const auto grids = childrenNamed(nodes, 0, "UnstructuredGrid");
    if (grids.size() != 1) failAt(name, root.line, "expected one <UnstructuredGrid> element");
    if (!childrenNamed(nodes, 0, "AppendedData").empty())
        failAt(name, root.line, "appended data is not supported (only ascii DataArrays)");
    const auto pieces = childrenNamed(nodes, grids[0], "Piece");
    if (pieces.empty()) failAt(name, nodes[grids[0]].line, "no <Piece> element");

    HexMesh mesh;
    for (const int pi : pieces) {
        const XmlNode& piece = nodes[pi];
        const long long np = intAttr(piece, "NumberOfPoints", name);
        const long long nc = intAttr(piece, "NumberOfCells", name);
        const std::size_t base = mesh.vertices.size();
        HexMesh part;
        // Points.
        const auto pts = childrenNamed(nodes, pi, "Points");
        if (pts.size() != 1) failAt(name, piece.line, "<Piece> needs exactly one <Points> element");
        const auto parr = childrenNamed(nodes, pts[0], "DataArray");
        if (parr.size() != 1) failAt(name, nodes[pts[0]].line, "<Points> needs exactly one <DataArray>");
        const std::string* comps = nodes[parr[0]].attr("NumberOfComponents");
        if (!comps || *comps != "3") failAt(name, nodes[parr[0]].line, "points need NumberOfComponents=\"3\"");
        const auto coords = readDataArray<double>(text, nodes, parr[0], name, "point coordinate");
        if (static_cast<long long>(coords.size()) != 3 * np)
            failAt(name, nodes[parr[0]].line, "points array has " + std::to_string(coords.size()) +
                                                  " values, expected " + std::to_string(3 * np));
        part.vertices.resize(static_cast<std::size_t>(np));
        for (long long i = 0; i < np; ++i) part.vertices[i] = Vec3d(coords[3 * i], coords[3 * i + 1], coords[3 * i + 2]);
        // Cells.
        const auto cells = childrenNamed(nodes, pi, "Cells");
        if (cells.size() != 1) failAt(name, piece.line, "<Piece> needs exactly one <Cells> element");
        std::map<std::string, int> arrays;
        for (const int a : childrenNamed(nodes, cells[0], "DataArray")) {
            const std::string* an = nodes[a].attr("Name");
            if (an) arrays[*an] = a;
        }
        auto need = [&](const std::string& an) {
            const auto it = arrays.find(an);
            if (it == arrays.end()) failAt(name, nodes[cells[0]].line, "<Cells> has no DataArray '" + an + "'");
            return it->second;
        };
        const auto conn = readDataArray<long long>(text, nodes, need("connectivity"), name, "connectivity");
        const auto offs = readDataArray<long long>(text, nodes, need("offsets"), name, "offsets");
        const auto types = readDataArray<long long>(text, nodes, need("types"), name, "types");
        std::vector<long long> faces, faceoffs;
        if (arrays.count("faces")) faces = readDataArray<long long>(text, nodes, arrays["faces"], name, "faces");
        if (arrays.count("faceoffsets"))
            faceoffs = readDataArray<long long>(text, nodes, arrays["faceoffsets"], name, "faceoffsets");
        const int offLine = nodes[need("offsets")].line;
        if (static_cast<long long>(offs.size()) != nc)
            failAt(name, offLine, "offsets has " + std::to_string(offs.size()) + " values for " + std::to_string(nc) +
                                      " cells");
        if (static_cast<long long>(types.size()) != nc)
            failAt(name, nodes[need("types")].line, "types has " + std::to_string(types.size()) + " values for " +
                                                        std::to_string(nc) + " cells");
        VtkCellBuilder builder(part, name);
        long long prev = 0, prevFace = 0;
        std::vector<long long> ids;
        for (long long c = 0; c < nc; ++c) {
            const long long e = offs[c];
            if (e < prev || e > static_cast<long long>(conn.size()))
                failAt(name, offLine, "cell " + std::to_string(c) + ": offset " + std::to_string(e) +
                                          " out of range [" + std::to_string(prev) + ", " +
                                          std::to_string(conn.size()) + "]");
            ids.assign(conn.begin() + prev, conn.begin() + e);
            prev = e;
            if (types[c] == 42) {
                const int fl = arrays.count("faceoffsets") ? nodes[arrays["faceoffsets"]].line : piece.line;
                if (static_cast<long long>(faceoffs.size()) != nc)
                    failAt(name, fl, "polyhedron cell " + std::to_string(c) + " but faceoffsets has " +
                                         std::to_string(faceoffs.size()) + " values for " + std::to_string(nc) +
                                         " cells");
                const long long fe = faceoffs[c];
                if (fe <= prevFace || fe > static_cast<long long>(faces.size()))
                    failAt(name, fl, "cell " + std::to_string(c) + ": face offset " + std::to_string(fe) +
                                         " out of range (" + std::to_string(prevFace) + ", " +
                                         std::to_string(faces.size()) + "]");
                const long long fb = prevFace;
                prevFace = fe;
                builder.add(42, ids, faces.data() + fb, static_cast<std::size_t>(fe - fb), -1, fl, c);
                // The cell's point list must be the faces' points.
                const Polyhedron& p = part.polyhedra.back();
                for (const auto& f : p.faces)
                    for (const int v : f)
                        if (std::find(ids.begin(), ids.end(), v) == ids.end())
                            failAt(name, offLine, "cell " + std::to_string(c) + ": face point " + std::to_string(v) +
                                                      " is not in the cell's connectivity");
            } else {
                builder.add(types[c], ids, nullptr, 0, -1, offLine, c);
            }
        }
        // Append the piece with shifted vertex ids.
        const int shift = static_cast<int>(base);
        mesh.vertices.insert(mesh.vertices.end(), part.vertices.begin(), part.vertices.end());
        for (auto h : part.hexes) {
            for (int& v : h) v += shift;
            mesh.hexes.push_back(h);
        }
        for (auto p : part.polyhedra) {
            for (auto& f : p.faces)
                for (int& v : f) v += shift;
            mesh.polyhedra.push_back(std::move(p));
        }
        if (mesh.vertices.size() > static_cast<std::size_t>(INT_MAX)) failAt(name, piece.line, "too many points");
    }
    return mesh;
}

// ----------------------------------------------------------------------------------------
// Medit

HexMesh readMedit(std::string_view text, const std::string& name) {
    Lexer lx(text, name, 1, '#');
    HexMesh mesh;
    struct Elem {
        int type;                   // VTK type
        std::vector<long long> ids;  // 1-based
        int line;
    };
    std::vector<Elem> elems;
    bool haveVertices = false, haveDim = false, haveVersion = false;
    // Sections that are skipped: keyword and values per entry.
    static const std::pair<const char*, int> kSkip[] = {
        {"Edges", 3},          {"Triangles", 4},        {"Quadrilaterals", 5},     {"Corners", 1},
        {"Ridges", 1},         {"RequiredVertices", 1}, {"RequiredEdges", 1},      {"RequiredTriangles", 1},
        {"RequiredQuadrilaterals", 1}, {"Normals", 3},  {"Tangents", 3},           {"NormalAtVertices", 2},
        {"TangentAtVertices", 2}, {"Identifier", 0}};
    while (lx.more()) {
        const Token kw = lx.next("keyword");
        if (iequals(kw.text, "MeshVersionFormatted")) {
            lx.integer("mesh version", 1, 4);
            haveVersion = true;
        } else if (iequals(kw.text, "Dimension")) {
            const long long d = lx.integer("dimension", 2, 3);
            if (d != 3) lx.fail(kw.line, "only Dimension 3 is supported");
            haveDim = true;
        } else if (iequals(kw.text, "Vertices")) {
            if (haveVertices) lx.fail(kw.line, "second Vertices section");
            const long long n = lx.count("number of vertices", 4);
            mesh.vertices.resize(static_cast<std::size_t>(n));
            for (auto& p : mesh.vertices) {
                for (int d = 0; d < 3; ++d) p[d] = lx.real("vertex coordinate");
                lx.integer("vertex reference");
            }
            haveVertices = true;
        } else if (iequals(kw.text, "Hexahedra") || iequals(kw.text, "Tetrahedra") || iequals(kw.text, "Prisms") ||
                   iequals(kw.text, "Pyramids")) {
            const bool hex = iequals(kw.text, "Hexahedra"), tet = iequals(kw.text, "Tetrahedra"),
                       prism = iequals(kw.text, "Prisms");
            const int k = hex ? 8 : tet ? 4 : prism ? 6 : 5;
            const int type = hex ? 12 : tet ? 10 : prism ? 13 : 14;
            const long long n = lx.count("number of elements", k + 1);
            for (long long i = 0; i < n; ++i) {
                Elem el{type, {}, 0};
                for (int j = 0; j < k; ++j) {
                    el.ids.push_back(lx.integer("vertex index"));
                    if (j == 0) el.line = lx.line();
                }
                lx.integer("element reference");
                elems.push_back(std::move(el));
            }
        } else if (iequals(kw.text, "End")) {
            break;
        } else {
            int per = -1;
            for (const auto& s : kSkip)
                if (iequals(kw.text, s.first)) per = s.second;
            if (per < 0) lx.fail(kw.line, "unknown or unsupported keyword " + quoteToken(kw.text));
            if (per == 0) {  // Identifier "..." : skip one token
                lx.next("identifier");
                continue;
            }
            const long long n = lx.count("number of entries", per);
            skipValues(lx, n * per, "value");
        }
    }
    if (!haveVersion) failAt(name, 0, "missing MeshVersionFormatted");
    if (!haveDim) failAt(name, 0, "missing Dimension");
    if (!haveVertices) failAt(name, 0, "missing Vertices section");
    const long long nv = static_cast<long long>(mesh.vertices.size());
    for (std::size_t e = 0; e < elems.size(); ++e) {
        std::vector<int> v;
        for (const long long id : elems[e].ids) {
            if (id < 1 || id > nv)
                failAt(name, elems[e].line, "vertex index " + std::to_string(id) + " out of range [1, " +
                                                std::to_string(nv) + "]");
            v.push_back(static_cast<int>(id - 1));
        }
        if (elems[e].type == 12) {
            std::array<int, 8> h{};
            std::copy(v.begin(), v.end(), h.begin());
            mesh.hexes.push_back(h);
        } else {
            mesh.polyhedra.push_back(templatePolyhedron(elems[e].type, v, mesh.vertices));
        }
    }
    return mesh;
}

// ----------------------------------------------------------------------------------------
// OpenVolumeMesh

HexMesh readOvm(std::string_view text, const std::string& name) {
    Lexer lx(text, name, 1, '#');
    lx.keyword("OVM");
    const Token enc = lx.next("'ASCII'");
    if (iequals(enc.text, "BINARY")) lx.fail(enc.line, "binary OVM files are not supported");
    if (!iequals(enc.text, "ASCII")) lx.fail(enc.line, "expected 'ASCII', got " + quoteToken(enc.text));
    HexMesh mesh;
    lx.keyword("Vertices");
    const long long nv = lx.count("number of vertices", 3);
    mesh.vertices.resize(static_cast<std::size_t>(nv));
    for (auto& p : mesh.vertices)
        for (int d = 0; d < 3; ++d) p[d] = lx.real("vertex coordinate");
    lx.keyword("Edges");
    const long long ne = lx.count("number of edges", 2);
    std::vector<std::array<int, 2>> edges(static_cast<std::size_t>(ne));
    for (auto& e : edges) {
        e[0] = lx.int32("edge vertex index", 0, nv - 1);
        e[1] = lx.int32("edge vertex index", 0, nv - 1);
        if (e[0] == e[1]) lx.fail(lx.line(), "edge with equal end points " + std::to_string(e[0]));
    }
    lx.keyword("Faces");
    const long long nf = lx.count("number of faces", 4);
    std::vector<std::vector<int>> faces(static_cast<std::size_t>(nf));
    for (auto& f : faces) {
        const int d = lx.int32("face valence", 3, INT_MAX);
        const int line = lx.line();
        if (static_cast<std::size_t>(d) > lx.remaining() / 2 + 1) lx.fail(line, "face valence larger than the file");
        std::vector<int> hes(static_cast<std::size_t>(d));
        for (auto& he : hes) he = lx.int32("halfedge index", 0, 2 * ne - 1);
        for (int i = 0; i < d; ++i) {
            const int he = hes[i], nx = hes[(i + 1) % d];
            const int to = edges[he / 2][1 - he % 2];
            const int from = edges[nx / 2][nx % 2];
            if (to != from)
                lx.fail(line, "halfedges " + std::to_string(he) + " and " + std::to_string(nx) +
                                  " of the face are not connected");
            f.push_back(edges[he / 2][he % 2]);
        }
    }
    lx.keyword("Polyhedra");
    const long long nc = lx.count("number of polyhedra", 2);
    std::vector<std::vector<std::vector<int>>> cells(static_cast<std::size_t>(nc));
    std::vector<int> cellLines(static_cast<std::size_t>(nc));
    double volume = 0;
    for (long long c = 0; c < nc; ++c) {
        const int d = lx.int32("number of halffaces", 1, INT_MAX);
        cellLines[c] = lx.line();
        if (static_cast<std::size_t>(d) > lx.remaining() / 2 + 1)
            lx.fail(cellLines[c], "halfface count larger than the file");
        for (int i = 0; i < d; ++i) {
            const int hf = lx.int32("halfface index", 0, 2 * nf - 1);
            std::vector<int> loop = faces[hf / 2];
            if (hf % 2) std::reverse(loop.begin(), loop.end());
            cells[c].push_back(std::move(loop));
        }
        volume += signedVolume6(mesh.vertices, cells[c]);
    }
    // Properties may follow; they are ignored.
    const bool reverse = volume < 0;
    for (auto& cell : cells) {
        if (reverse)
            for (auto& f : cell) std::reverse(f.begin(), f.end());
        if (auto h = hexFromFaces(cell)) {
            mesh.hexes.push_back(*h);
        } else {
            Polyhedron p;
            p.faces = std::move(cell);
            mesh.polyhedra.push_back(std::move(p));
        }
    }
    return mesh;
}

} // namespace

HexMesh readHexMeshBuffer(std::string_view text, HexMeshFormat format, const std::string& name) {
    switch (format) {
    case HexMeshFormat::Vtk: return readVtk(text, name);
    case HexMeshFormat::Vtu: return readVtu(text, name);
    case HexMeshFormat::Medit: return readMedit(text, name);
    case HexMeshFormat::Ovm: return readOvm(text, name);
    }
    failAt(name, 0, "unknown format");
}

HexMesh readHexMesh(const std::string& path) {
    const HexMeshFormat format = hexMeshFormatFromPath(path);
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": is a directory, not a mesh file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open file for reading");
    std::string text;
    try {
        text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    } catch (const std::exception& e) {  // libstdc++ reports read errors (EISDIR, EIO) by throwing
        throw InputError(path + ": error while reading the file (" + e.what() + ")");
    }
    if (in.bad()) throw InputError(path + ": error while reading the file");
    return readHexMeshBuffer(text, format, path);
}

} // namespace HexEx
