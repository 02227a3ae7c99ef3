/// @file LegacyVtkReader.cc
/// Reader of legacy VTK UNSTRUCTURED_GRID files, ASCII and BINARY (big-endian values after
/// each section header line), file versions 2.0 to 5.1.

#include "HexMeshReaders.hh"
#include "TextParsing.hh"
#include "VtkCells.hh"
#include "VtkDataBlocks.hh"


namespace HexEx {

namespace {

using detail::iequals;
using detail::quoteToken;

/// Byte size of a legacy VTK data type in binary files, 0 if unknown.
int binarySize(std::string_view type) {
    static const std::pair<const char*, int> kTypes[] = {
        {"bit", 0},  {"unsigned_char", 1}, {"char", 1},          {"short", 2},         {"unsigned_short", 2},
        {"int", 4},  {"unsigned_int", 4},  {"vtkidtype", 4},     {"long", 8},          {"unsigned_long", 8},
        {"float", 4}, {"double", 8},       {"vtktypeint64", 8},  {"vtktypeuint64", 8}, {"vtktypeint32", 4}};
    for (const auto& t : kTypes)
        if (iequals(type, t.first)) return t.second;
    return 0;
}

/// Reads @p n values of legacy data type @p type (ASCII tokens or big-endian binary).
template <class T>
std::vector<T> readValues(detail::Lexer& lx, bool binary, std::string_view type, long long n, const std::string& what) {
    std::vector<T> out;
    if (!binary) {
        out.reserve(static_cast<std::size_t>(std::min<long long>(n, static_cast<long long>(lx.remaining()))));
        for (long long i = 0; i < n; ++i) {
            if constexpr (std::is_same_v<T, double>) out.push_back(lx.real(what));
            else out.push_back(lx.integer(what));
        }
        return out;
    }
    const int size = binarySize(type);
    if (size == 0) lx.fail(lx.line(), "unsupported binary data type " + quoteToken(type) + " for " + what);
    if (static_cast<unsigned long long>(n) > lx.remaining() / static_cast<unsigned>(size))
        lx.fail(lx.line(), what + ": " + std::to_string(n) + " values do not fit in the rest of the file");
    const long long line = lx.line();
    const std::string_view b = lx.bytes(static_cast<std::size_t>(n) * static_cast<std::size_t>(size), what);
    try {
        out = detail::decodeNumbers<T>(b, size, iequals(type, "float") || iequals(type, "double"),
                                       !(type.rfind("unsigned", 0) == 0 || iequals(type, "vtktypeuint64")), true);
    } catch (const detail::BlockError& e) {
        lx.fail(line, what + ": " + e.what());
    }
    return out;
}

} // namespace

HexMesh detail::readLegacyVtk(std::string_view text, const std::string& name) {
    const std::size_t e1 = text.find('\n');
    if (text.substr(0, e1).rfind("# vtk DataFile Version", 0) != 0)
        detail::failAt(name, 1, "not a legacy VTK file (expected '# vtk DataFile Version x.y')");
    if (e1 == std::string_view::npos) detail::failAt(name, 1, "unexpected end of file after the header");
    const std::size_t e2 = text.find('\n', e1 + 1);
    if (e2 == std::string_view::npos) detail::failAt(name, 2, "unexpected end of file after the title");
    detail::Lexer lx(text.substr(e2 + 1), name, 3);

    const detail::Token fmt = lx.next("'ASCII' or 'BINARY'");
    const bool binary = iequals(fmt.text, "BINARY");
    if (!binary && !iequals(fmt.text, "ASCII")) lx.fail(fmt.line, "expected 'ASCII' or 'BINARY', got " + quoteToken(fmt.text));
    lx.keyword("DATASET");
    const detail::Token ds = lx.next("dataset type");
    if (!iequals(ds.text, "UNSTRUCTURED_GRID"))
        lx.fail(ds.line, "dataset type " + quoteToken(ds.text) + " is not supported (expected UNSTRUCTURED_GRID)");

    HexMesh mesh;
    long long cellsLine = 0, attrCount = -1;  // tuples of the current CELL_DATA / POINT_DATA block
    bool inCellData = false, havePoints = false;
    std::vector<long long> offsets, conn, types, groupIds;
    const auto skip = [&](const std::string& type, long long n, const char* what) {
        readValues<double>(lx, binary, type.empty() ? std::string_view("unsigned_char") : type, n, what);
    };
    while (lx.more()) {
        const detail::Token kw = lx.next("keyword");
        const auto needAttr = [&] {
            if (attrCount < 0) lx.fail(kw.line, quoteToken(kw.text) + " outside CELL_DATA / POINT_DATA");
        };
        if (iequals(kw.text, "POINTS")) {
            if (havePoints) lx.fail(kw.line, "second POINTS section");
            const long long n = lx.count("number of points", 6);
            const std::string type(lx.next("point data type").text);
            const auto xyz = readValues<double>(lx, binary, type, 3 * n, "point coordinate");
            for (long long i = 0; i < n; ++i) mesh.vertices.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
            havePoints = true;
        } else if (iequals(kw.text, "CELLS")) {
            if (cellsLine) lx.fail(kw.line, "second CELLS section");
            cellsLine = kw.line;
            const long long n = lx.count("number of cells", 1), size = lx.count("cell list size", 1);
            if (iequals(lx.peek(), "OFFSETS")) {  // version 5.x
                lx.next("OFFSETS");
                const std::string otype(lx.next("offset data type").text);
                if (n < 1) lx.fail(kw.line, "CELLS needs at least one offset in version 5 files");
                offsets = readValues<long long>(lx, binary, otype, n, "offset");
                lx.keyword("CONNECTIVITY");
                const std::string ctype(lx.next("connectivity data type").text);
                conn = readValues<long long>(lx, binary, ctype, size, "point index");
                if (offsets.front() != 0) lx.fail(kw.line, "first offset is not 0");
                for (long long i = 1; i < n; ++i)
                    if (offsets[i] < offsets[i - 1]) lx.fail(kw.line, "offsets decrease at offset " + std::to_string(i));
                if (offsets.back() != size) lx.fail(kw.line, "last offset differs from the connectivity size");
            } else {  // counted lists: n, ids..., n, ids...
                const auto list = readValues<long long>(lx, binary, "int", size, "cell list value");
                offsets.assign(1, 0);
                for (std::size_t k = 0; k < list.size();) {
                    if (list[k] < 0 || static_cast<std::size_t>(list[k]) >= list.size() - k)
                        lx.fail(kw.line, "cell " + std::to_string(offsets.size() - 1) + ": size " +
                                             std::to_string(list[k]) + " exceeds the cell list");
                    conn.insert(conn.end(), list.begin() + static_cast<long>(k) + 1,
                                list.begin() + static_cast<long>(k) + 1 + list[k]);
                    k += static_cast<std::size_t>(list[k]) + 1;
                    offsets.push_back(static_cast<long long>(conn.size()));
                }
                if (static_cast<long long>(offsets.size()) - 1 != n)
                    lx.fail(kw.line, "CELLS declares " + std::to_string(n) + " cells but the list holds " +
                                         std::to_string(offsets.size() - 1));
            }
        } else if (iequals(kw.text, "CELL_TYPES")) {
            if (!types.empty()) lx.fail(kw.line, "second CELL_TYPES section");
            types = readValues<long long>(lx, binary, "int", lx.count("number of cell types", 1), "cell type");
        } else if (iequals(kw.text, "CELL_DATA") || iequals(kw.text, "POINT_DATA")) {
            attrCount = lx.count("number of tuples", 1);
            inCellData = iequals(kw.text, "CELL_DATA");
        } else if (iequals(kw.text, "SCALARS")) {
            needAttr();
            const detail::Token sn = lx.next("scalar name");
            const std::string type(lx.next("scalar data type").text);
            long long comps = 1;
            if (!lx.peek().empty() && std::isdigit(static_cast<unsigned char>(lx.peek()[0])))
                comps = lx.integer("number of components", 1, 4);
            if (iequals(lx.peek(), "LOOKUP_TABLE")) {
                lx.next("LOOKUP_TABLE");
                lx.next("lookup table name");
            }
            if (inCellData && sn.text == "hexex_cell_id" && comps == 1)
                groupIds = readValues<long long>(lx, binary, type, attrCount, "hexex_cell_id value");
            else
                skip(type, attrCount * comps, "scalar value");
        } else if (iequals(kw.text, "VECTORS") || iequals(kw.text, "NORMALS") || iequals(kw.text, "TENSORS")) {
            needAttr();
            lx.next("name");
            skip(std::string(lx.next("data type").text), (iequals(kw.text, "TENSORS") ? 9 : 3) * attrCount, "value");
        } else if (iequals(kw.text, "TEXTURE_COORDINATES")) {
            needAttr();
            lx.next("name");
            const long long dim = lx.integer("dimension", 1, 3);
            skip(std::string(lx.next("data type").text), dim * attrCount, "texture coordinate");
        } else if (iequals(kw.text, "COLOR_SCALARS")) {
            needAttr();
            lx.next("name");
            const long long m = lx.integer("number of values", 1, 4);
            skip(binary ? "unsigned_char" : "float", m * attrCount, "color value");
        } else if (iequals(kw.text, "LOOKUP_TABLE")) {
            lx.next("lookup table name");
            skip(binary ? "unsigned_char" : "float", 4 * lx.count("lookup table size", 4), "lookup table value");
        } else if (iequals(kw.text, "FIELD")) {
            lx.next("field name");
            const long long arrays = lx.count("number of field arrays");
            for (long long a = 0; a < arrays; ++a) {
                lx.next("field array name");
                const long long comps = lx.count("number of components", 1), tuples = lx.count("number of tuples", 1);
                const std::string type(lx.next("data type").text);
                if (comps > 0 && tuples > LLONG_MAX / comps) lx.fail(lx.line(), "field array too large");
                skip(type, comps * tuples, "field array value");
            }
        } else if (iequals(kw.text, "METADATA")) {  // text up to the next section keyword
            static const char* const kSections[] = {"POINTS", "CELLS", "CELL_TYPES", "CELL_DATA", "POINT_DATA",
                                                    "SCALARS", "VECTORS", "NORMALS", "FIELD", "TENSORS"};
            while (lx.more() && std::none_of(std::begin(kSections), std::end(kSections),
                                             [&](const char* s) { return iequals(lx.peek(), s); }))
                lx.next("metadata");
        } else {
            lx.fail(kw.line, "unexpected keyword " + quoteToken(kw.text));
        }
    }
    if (!havePoints) lx.fail(lx.eofLine(), "no POINTS section");
    if (!cellsLine) lx.fail(lx.eofLine(), "no CELLS section");
    const long long ncells = static_cast<long long>(offsets.size()) - 1;
    if (static_cast<long long>(types.size()) != ncells)
        detail::failAt(name, cellsLine, "CELLS has " + std::to_string(ncells) + " cells but CELL_TYPES has " +
                                            std::to_string(types.size()));
    if (!groupIds.empty() && static_cast<long long>(groupIds.size()) != ncells)
        detail::failAt(name, cellsLine, "hexex_cell_id has " + std::to_string(groupIds.size()) + " values for " +
                                    std::to_string(ncells) + " cells");
    detail::VtkCellAdder adder(mesh);
    for (long long c = 0; c < ncells; ++c) {
        const long long* ids = conn.data() + offsets[c];
        const auto n = static_cast<std::size_t>(offsets[c + 1] - offsets[c]);
        const std::string err = types[c] == 42 ? adder.add(c, 42, nullptr, 0, ids, n)  // legacy face stream
                                               : adder.add(c, types[c], ids, n, nullptr, 0, groupIds.empty() ? -1 : groupIds[c]);
        if (!err.empty()) detail::failAt(name, cellsLine, err);
    }
    return mesh;
}

} // namespace HexEx
