/// @file VtuReader.cc
/// Reader of VTK XML UnstructuredGrid files (`.vtu`) with pugixml: DataArrays in ascii,
/// inline binary (base64) or appended (raw or base64) format, UInt32 or UInt64 headers,
/// optionally zlib-compressed, little- or big-endian; several pieces; any mix of the cell
/// types of VtkCells.hh.

#include "HexMeshReaders.hh"
#include "TextParsing.hh"
#include "VtkCells.hh"
#include "VtkDataBlocks.hh"

#include <pugixml.hpp>


namespace HexEx {

namespace {

/// The parsed document and what is needed to decode its arrays.
struct VtuFile {
    std::string_view text;      ///< the whole file
    const std::string& name;    ///< file name for messages
    std::string_view appended;  ///< bytes after the '_' of <AppendedData>, or empty
    bool appendedBase64 = false;
    int headerBytes = 4;
    bool compressed = false, bigEndian = false;

    /// Line of byte offset @p offset.
    long long lineOf(std::ptrdiff_t offset) const {
        const auto end = text.begin() + std::clamp<std::ptrdiff_t>(offset, 0, static_cast<std::ptrdiff_t>(text.size()));
        return 1 + std::count(text.begin(), end, '\n');
    }
    /// Throws InputError at the line of @p node.
    [[noreturn]] void fail(const pugi::xml_node& node, const std::string& reason) const {
        detail::failAt(name, lineOf(node.offset_debug()), reason);
    }
    /// The only child @p tag of @p parent, or fails.
    pugi::xml_node only(const pugi::xml_node& parent, const char* tag) const {
        const pugi::xml_node c = parent.child(tag);
        if (!c || c.next_sibling(tag)) fail(parent, "<" + std::string(parent.name()) + "> needs exactly one <" + tag + ">");
        return c;
    }
};

/// Size in bytes of a VTK XML data type, 0 if unknown.
int typeSize(std::string_view type) {
    static const std::pair<const char*, int> kTypes[] = {{"Int8", 1},   {"UInt8", 1},   {"Int16", 2}, {"UInt16", 2},
                                                         {"Int32", 4},  {"UInt32", 4},  {"Int64", 8}, {"UInt64", 8},
                                                         {"Float32", 4}, {"Float64", 8}};
    for (const auto& t : kTypes)
        if (type == t.first) return t.second;
    return 0;
}

/// All values of a DataArray as T (double or long long).
template <class T>
std::vector<T> readArray(const VtuFile& f, const pugi::xml_node& a, const std::string& what) {
    const std::string type = a.attribute("type").value(), format = a.attribute("format").value();
    const int size = typeSize(type);
    std::vector<T> out;
    if (format == "ascii" || (format.empty() && !a.attribute("offset"))) {
        const pugi::xml_text t = a.text();
        const std::string_view body = t.get();
        detail::Lexer lx(body, f.name, f.lineOf(a.offset_debug()));
        while (lx.more()) {
            if constexpr (std::is_same_v<T, double>) out.push_back(lx.real(what + " value"));
            else out.push_back(lx.integer(what + " value"));
        }
        return out;
    }
    if (!size) f.fail(a, "DataArray " + what + " has unsupported type '" + type + "'");
    std::string bytes;
    try {
        if (format == "binary") {
            detail::BlockSource src(a.text().get(), true);
            bytes = detail::readVtkBlock(src, f.headerBytes, f.compressed, f.bigEndian);
        } else if (format == "appended") {
            const pugi::xml_attribute off = a.attribute("offset");
            long long o = -1;
            if (!off || detail::parseInteger(off.value(), o) != detail::NumberParse::Ok || o < 0 ||
                static_cast<std::size_t>(o) > f.appended.size())
                f.fail(a, "DataArray " + what + ": appended offset '" + off.value() + "' is missing or outside the " +
                              std::to_string(f.appended.size()) + " bytes of appended data");
            detail::BlockSource src(f.appended.substr(static_cast<std::size_t>(o)), f.appendedBase64);
            bytes = detail::readVtkBlock(src, f.headerBytes, f.compressed, f.bigEndian);
        } else {
            f.fail(a, "DataArray " + what + " has unknown format '" + format + "'");
        }
    } catch (const detail::BlockError& e) {
        f.fail(a, "DataArray " + what + " (" + format + (format == "appended" ? std::string(" at offset ") + a.attribute("offset").value() : "") + "): " + e.what());
    }
    try {
        return detail::decodeNumbers<T>(bytes, size, type[0] == 'F', type[0] == 'I', f.bigEndian);
    } catch (const detail::BlockError& e) {
        f.fail(a, "DataArray " + what + ": " + e.what());
    }
}

/// Reads one <Piece>.
HexMesh readPiece(const VtuFile& f, const pugi::xml_node& piece) {
    HexMesh mesh;
    long long np = -1, nc = -1;
    for (auto [key, value] : {std::pair<const char*, long long*>{"NumberOfPoints", &np}, {"NumberOfCells", &nc}})
        if (detail::parseInteger(piece.attribute(key).value(), *value) != detail::NumberParse::Ok || *value < 0 ||
            *value > INT_MAX)
            f.fail(piece, std::string("attribute ") + key + "='" + piece.attribute(key).value() + "' is not a valid count");
    const pugi::xml_node parr = f.only(f.only(piece, "Points"), "DataArray");
    if (std::string(parr.attribute("NumberOfComponents").value()) != "3")
        f.fail(parr, "points need NumberOfComponents=\"3\"");
    const auto xyz = readArray<double>(f, parr, "point coordinate");
    if (static_cast<long long>(xyz.size()) != 3 * np)
        f.fail(parr, "points array has " + std::to_string(xyz.size()) + " values, expected " + std::to_string(3 * np));
    for (long long i = 0; i < np; ++i) mesh.vertices.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);

    const pugi::xml_node cells = f.only(piece, "Cells");
    const auto array = [&](const char* an, bool required) {
        const pugi::xml_node a = cells.find_child_by_attribute("DataArray", "Name", an);
        if (!a && required) f.fail(cells, std::string("<Cells> has no DataArray '") + an + "'");
        return a;
    };
    const auto conn = readArray<long long>(f, array("connectivity", true), "connectivity");
    const auto offs = readArray<long long>(f, array("offsets", true), "offsets");
    const auto types = readArray<long long>(f, array("types", true), "types");
    const pugi::xml_node facesNode = array("faces", false), faceOffsNode = array("faceoffsets", false);
    const auto faces = facesNode ? readArray<long long>(f, facesNode, "faces") : std::vector<long long>();
    const auto faceoffs = faceOffsNode ? readArray<long long>(f, faceOffsNode, "faceoffsets") : std::vector<long long>();
    if (static_cast<long long>(offs.size()) != nc || static_cast<long long>(types.size()) != nc)
        f.fail(cells, "offsets and types have " + std::to_string(offs.size()) + " and " + std::to_string(types.size()) +
                          " values for " + std::to_string(nc) + " cells");
    long long prev = 0, prevFace = 0;
    detail::VtkCellAdder adder(mesh);
    for (long long c = 0; c < nc; ++c) {
        if (offs[c] < prev || offs[c] > static_cast<long long>(conn.size()))
            f.fail(cells, "cell " + std::to_string(c) + ": offset " + std::to_string(offs[c]) + " out of range [" +
                              std::to_string(prev) + ", " + std::to_string(conn.size()) + "]");
        const long long* ids = conn.data() + prev;
        const auto n = static_cast<std::size_t>(offs[c] - prev);
        prev = offs[c];
        std::string err;
        if (types[c] == 42) {
            if (static_cast<long long>(faceoffs.size()) != nc)
                f.fail(cells, "polyhedron cell " + std::to_string(c) + " but faceoffsets has " +
                                  std::to_string(faceoffs.size()) + " values for " + std::to_string(nc) + " cells");
            if (faceoffs[c] <= prevFace || faceoffs[c] > static_cast<long long>(faces.size()))
                f.fail(cells, "cell " + std::to_string(c) + ": face offset " + std::to_string(faceoffs[c]) +
                                  " out of range (" + std::to_string(prevFace) + ", " + std::to_string(faces.size()) + "]");
            const long long* stream = faces.data() + prevFace;
            err = adder.add(c, 42, ids, n, stream, static_cast<std::size_t>(faceoffs[c] - prevFace));
            prevFace = faceoffs[c];
        } else {
            err = adder.add(c, types[c], ids, n);
        }
        if (!err.empty()) f.fail(array("offsets", true), err);
    }
    return mesh;
}

} // namespace

HexMesh detail::readVtu(std::string_view text, const std::string& name) {
    VtuFile f{text, name, {}};
    // Raw appended data is not XML: parse the document up to its '_' marker and close it.
    std::string xml(text);
    const std::size_t ad = text.find("<AppendedData");
    if (ad != std::string_view::npos) {
        const std::size_t gt = text.find('>', ad), us = gt == std::string_view::npos ? gt : text.find('_', gt);
        if (us == std::string_view::npos) detail::failAt(name, f.lineOf(static_cast<std::ptrdiff_t>(ad)), "<AppendedData> without the '_' marker");
        f.appended = text.substr(us + 1);
        xml = std::string(text.substr(0, us)) + "</AppendedData></VTKFile>";
    }
    pugi::xml_document doc;
    const pugi::xml_parse_result res = doc.load_buffer(xml.data(), xml.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!res) detail::failAt(name, f.lineOf(res.offset), std::string("malformed XML: ") + res.description());
    const pugi::xml_node root = doc.document_element();
    if (std::string(root.name()) != "VTKFile") f.fail(root, "root element is <" + std::string(root.name()) + ">, expected <VTKFile>");
    if (std::string(root.attribute("type").value()) != "UnstructuredGrid")
        f.fail(root, "VTKFile type is '" + std::string(root.attribute("type").value()) + "', expected 'UnstructuredGrid'");
    const std::string header = root.attribute("header_type").as_string("UInt32"), order = root.attribute("byte_order").as_string("LittleEndian"),
                      compressor = root.attribute("compressor").value();
    if (header != "UInt32" && header != "UInt64") f.fail(root, "unsupported header_type '" + header + "'");
    if (order != "LittleEndian" && order != "BigEndian") f.fail(root, "unknown byte_order '" + order + "'");
    if (!compressor.empty() && compressor != "vtkZLibDataCompressor")
        f.fail(root, "unsupported compressor '" + compressor + "' (only vtkZLibDataCompressor)");
    f.headerBytes = header == "UInt64" ? 8 : 4;
    f.bigEndian = order == "BigEndian";
    f.compressed = !compressor.empty();
    if (const pugi::xml_node app = root.child("AppendedData")) {
        const std::string enc = app.attribute("encoding").as_string("raw");
        if (enc != "raw" && enc != "base64") f.fail(app, "unknown AppendedData encoding '" + enc + "'");
        f.appendedBase64 = enc == "base64";
    }
    const pugi::xml_node grid = f.only(root, "UnstructuredGrid");
    if (!grid.child("Piece")) f.fail(grid, "no <Piece> element");
    HexMesh mesh;
    for (const pugi::xml_node piece : grid.children("Piece")) {
        HexMesh part = readPiece(f, piece);
        const int shift = static_cast<int>(mesh.vertices.size());
        if (part.vertices.size() > static_cast<std::size_t>(INT_MAX - shift)) f.fail(piece, "too many points");
        mesh.vertices.insert(mesh.vertices.end(), part.vertices.begin(), part.vertices.end());
        for (auto& h : part.hexes) {
            for (int& v : h) v += shift;
            mesh.hexes.push_back(h);
        }
        for (auto& p : part.polyhedra) {
            for (auto& fc : p.faces)
                for (int& v : fc) v += shift;
            mesh.polyhedra.push_back(std::move(p));
        }
    }
    return mesh;
}

} // namespace HexEx
