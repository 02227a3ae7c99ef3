/// @file HexMeshReaders.cc
/// Dispatch of the hex mesh readers by format, and the Medit reader.

#include "HexMeshReaders.hh"
#include "OvmModel.hh"
#include "ReaderSupport.hh"
#include "TextParsing.hh"
#include "VtkCells.hh"

namespace HexEx {

namespace {
using detail::failAt;
using detail::iequals;
using detail::quoteToken;

// ----------------------------------------------------------------------------------------
// Medit

HexMesh readMedit(std::string_view text, const std::string& name) {
    detail::Lexer lx(text, name, 1, '#');
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
        const detail::Token kw = lx.next("keyword");
        if (iequals(kw.text, "MeshVersionFormatted")) {
            lx.integer("mesh version", 1, 4);
            haveVersion = true;
        } else if (iequals(kw.text, "Dimension")) {
            const long long d = lx.integer("dimension", 2, 3);
            if (d != 3) lx.fail(kw.line, "only Dimension 3 is supported");
            haveDim = true;
        } else if (iequals(kw.text, "Vertices")) {
            if (haveVertices) lx.fail(kw.line, "second Vertices section");
            const long long n = lx.count("number of vertices", 8);
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
            const long long n = lx.count("number of elements", 2 * (k + 1));
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
            const long long n = lx.count("number of entries", 2 * per);
            for (long long i = 0; i < n * per; ++i) lx.next("value");
        }
    }
    if (!haveVersion) lx.fail(lx.eofLine(), "missing MeshVersionFormatted");
    if (!haveDim) lx.fail(lx.eofLine(), "missing Dimension");
    if (!haveVertices) lx.fail(lx.eofLine(), "missing Vertices section");
    detail::VtkCellAdder adder(mesh);
    for (std::size_t e = 0; e < elems.size(); ++e) {
        for (auto& id : elems[e].ids) {
            if (id < 1 || id > static_cast<long long>(mesh.vertices.size()))
                failAt(name, elems[e].line, "vertex index " + std::to_string(id) + " out of range [1, " +
                                                std::to_string(mesh.vertices.size()) + "]");
            id -= 1;  // 1-based
        }
        const std::string err = adder.add(static_cast<long long>(e), elems[e].type, elems[e].ids.data(), elems[e].ids.size());
        if (!err.empty()) failAt(name, elems[e].line, "element " + err.substr(5));
    }
    return mesh;
}

} // namespace

HexMesh readHexMeshBuffer(std::string_view text, HexMeshFormat format, const std::string& name) {
    switch (format) {
    case HexMeshFormat::Vtk: return detail::readLegacyVtk(text, name);
    case HexMeshFormat::Vtu: return detail::readVtu(text, name);
    case HexMeshFormat::Medit: return readMedit(text, name);
    case HexMeshFormat::Ovm:
    case HexMeshFormat::Ovmb: return hexMeshFromOvm(parseOvm(text, name));
    }
    failAt(name, 0, "unknown format");
}

HexMesh readHexMesh(const std::string& path) {
    const HexMeshFormat format = hexMeshFormatFromPath(path);
    return readHexMeshBuffer(detail::readWholeFile(path), format, path);
}

} // namespace HexEx
