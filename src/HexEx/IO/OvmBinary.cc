/// @file OvmBinary.cc
/// OpenVolumeMesh binary (`.ovmb`) into and out of an OvmModel. Layout (little-endian), from
/// OpenVolumeMesh's published Kaitai description of the format: a 48-byte header (magic
/// "OVMB\n\r\n\xff", file and header version, vertex dimension, topology type, 4 reserved
/// bytes, u64 counts of vertices, edges, faces, cells), then chunks of a 16-byte header
/// (4-char type, version, padding bytes, compression, flags, u64 length including padding)
/// and a body: DIRP (property directory), VERT (coordinates), TOPO (edges, faces, cells as
/// handles), PROP (property values), EOF.

#include "OvmModel.hh"

#include "../Core/Error.hh"
#include "../Core/Parallel.hh"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace HexEx {

namespace {

constexpr char kMagic[8] = {'O', 'V', 'M', 'B', '\n', '\r', '\n', '\xff'};

/// Bounds-checked little-endian reads; every failure names the byte offset.
class ByteReader {
public:
    ByteReader(std::string_view data, const OvmModel& m) : d_(data), m_(m) {}
    std::size_t pos = 0;  ///< current offset

    /// Fails unless @p n more bytes exist before @p end.
    void need(std::size_t n, std::size_t end, const char* what) const {
        if (n > end - std::min(pos, end))
            m_.fail(static_cast<long long>(pos), std::string("unexpected end of ") + what + " (needs " +
                                                     std::to_string(n) + " bytes, " + std::to_string(end - pos) +
                                                     " left)");
    }
    /// An unsigned integer of @p bytes bytes (1, 2, 4 or 8).
    std::uint64_t uint(int bytes, std::size_t end, const char* what) {
        need(static_cast<std::size_t>(bytes), end, what);
        std::uint64_t v = 0;
        for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(d_[pos + i]);
        pos += static_cast<std::size_t>(bytes);
        return v;
    }
    /// A finite IEEE double (8 bytes) or float (4 bytes).
    double real(int bytes, std::size_t end, const char* what) {
        const std::uint64_t bits = uint(bytes, end, what);
        double v = 0;
        if (bytes == 8) {
            std::memcpy(&v, &bits, 8);
        } else {
            const auto b32 = static_cast<std::uint32_t>(bits);
            float f = 0;
            std::memcpy(&f, &b32, 4);
            v = f;
        }
        if (!std::isfinite(v)) m_.fail(static_cast<long long>(pos - bytes), std::string("NaN or infinite ") + what);
        return v;
    }
    /// A string with a u32 length prefix.
    std::string string4(std::size_t end, const char* what) {
        const std::uint64_t n = uint(4, end, what);
        need(static_cast<std::size_t>(n), end, what);
        std::string s(d_.substr(pos, static_cast<std::size_t>(n)));
        pos += static_cast<std::size_t>(n);
        return s;
    }

private:
    std::string_view d_;
    const OvmModel& m_;
};

/// A property of the directory and how far its values have been read.
struct DirEntry {
    int entity = 0;
    std::string name, type;
    std::uint64_t filled = 0;
    bool param = false;
};

const char* const kEntityNames[] = {"vertex", "edge", "face", "cell", "halfedge", "halfface", "mesh"};

/// Number of bytes of an integer encoding (0 none, 1 u8, 2 u16, 4 u32), or fails.
int intEncoding(std::uint64_t code, const OvmModel& m, long long at, const char* what) {
    if (code != 1 && code != 2 && code != 4)
        m.fail(at, std::string("invalid ") + what + " encoding " + std::to_string(code) + " (expected 1, 2 or 4)");
    return static_cast<int>(code);
}

/// Reads a TOPO chunk body [r.pos, end) into the model.
void readTopo(ByteReader& r, std::size_t end, OvmModel& m, std::array<std::uint64_t, 4>& filled) {
    const long long at = static_cast<long long>(r.pos);
    const std::uint64_t base = r.uint(8, end, "TOPO chunk"), count = r.uint(4, end, "TOPO chunk");
    const int entity = static_cast<int>(r.uint(1, end, "TOPO chunk"));
    const auto valence = r.uint(1, end, "TOPO chunk");
    const auto valenceEnc = r.uint(1, end, "TOPO chunk"), handleEnc = r.uint(1, end, "TOPO chunk");
    const std::uint64_t offset = r.uint(8, end, "TOPO chunk");
    if (entity < 1 || entity > 3) m.fail(at + 12, "invalid TOPO entity " + std::to_string(entity) + " (expected 1, 2 or 3)");
    const std::uint64_t n[4] = {0, m.edges.size(), m.faces.size(), m.cells.size()};
    const std::uint64_t limit[4] = {0, m.vertices.size(), 2 * m.edges.size(), 2 * m.faces.size()};
    const char* what = kEntityNames[entity];
    if (base != filled[entity] || count > n[entity] - base)
        m.fail(at, std::string(what) + " span [" + std::to_string(base) + ", +" + std::to_string(count) +
                       ") does not continue the " + std::to_string(filled[entity]) + " read so far of " +
                       std::to_string(n[entity]));
    if (entity == 1 && valence != 2) m.fail(at + 13, "edge valence " + std::to_string(valence) + " (expected 2)");
    const int hb = intEncoding(handleEnc, m, at + 15, "handle");
    std::vector<std::uint64_t> valences(valence ? 0 : count, valence);
    if (valence == 0) {
        const int vb = intEncoding(valenceEnc, m, at + 14, "valence");
        r.need(count * static_cast<std::size_t>(vb), end, "TOPO valences");
        for (auto& v : valences) v = r.uint(vb, end, "TOPO valences");
    }
    for (std::uint64_t i = 0; i < count; ++i) {
        const std::uint64_t k = valence ? valence : valences[i];
        const std::size_t e = static_cast<std::size_t>(base + i);
        const long long here = static_cast<long long>(r.pos);
        if (k < (entity == 2 ? 3u : 1u) || k > (end - r.pos) / static_cast<std::size_t>(hb))
            m.fail(here, std::string(what) + " " + std::to_string(e) + ": invalid valence " + std::to_string(k));
        std::vector<int> handles(static_cast<std::size_t>(k));
        for (auto& h : handles) {
            const std::uint64_t v = r.uint(hb, end, "TOPO handles") + offset;
            if (v >= limit[entity] || v < offset)
                m.fail(static_cast<long long>(r.pos) - hb, std::string(what) + " " + std::to_string(e) + ": handle " +
                                                               std::to_string(v) + " out of range [0, " +
                                                               std::to_string(limit[entity]) + ")");
            h = static_cast<int>(v);
        }
        if (entity == 1) {
            if (handles[0] == handles[1])
                m.fail(here, "edge " + std::to_string(e) + " connects vertex " + std::to_string(handles[0]) + " to itself");
            m.edges[e] = {handles[0], handles[1]};
        } else {
            (entity == 2 ? m.faces : m.cells)[e] = std::move(handles);
            (entity == 2 ? m.facePos : m.cellPos)[e] = here;
        }
    }
    filled[entity] += count;
    if (r.pos != end) m.fail(static_cast<long long>(r.pos), "TOPO chunk has " + std::to_string(end - r.pos) + " extra bytes");
}

/// Appends the 16-byte header of a chunk of type @p type whose body has @p bodyBytes bytes;
/// @return the number of padding bytes to append after the body (to a multiple of 8).
std::size_t chunkHeader(detail::BlockOutput& o, const char* type, std::size_t bodyBytes) {
    const std::size_t pad = (8 - bodyBytes % 8) % 8;
    o << std::string_view(type, 4);
    o.le(0, 1);    // version
    o.le(pad, 1);  // padding bytes
    o.le(0, 1);    // no compression
    o.le(1, 1);    // flags
    o.le(bodyBytes + pad, 8);
    return pad;
}

/// Appends @p pad zero bytes.
void padding(detail::BlockOutput& o, std::size_t pad) { o << std::string_view("\0\0\0\0\0\0\0\0", pad); }

/// Smallest encoding (1, 2 or 4 bytes) that holds @p maxValue.
int encodingFor(std::uint64_t maxValue) { return maxValue < 256 ? 1 : maxValue < 65536 ? 2 : 4; }

/// Appends a TOPO chunk for the handle lists given by their @p count, @p length(i) and the
/// handles @p handles(i) as [begin, end) pointers (entity 1 edges, 2 faces, 3 cells);
/// @p contiguous if the lists lie back to back in memory.
template <class Length, class Handles>
void topoChunk(detail::BlockOutput& o, int entity, std::size_t count, Length length, Handles handles, bool contiguous,
               int threads = 1) {
    // Valences and the largest handle, in chunks of the lists (on @p threads threads for long ones).
    struct Range {
        std::size_t maxValence = 0, minValence = SIZE_MAX, total = 0;
        int maxHandle = 0;
    };
    std::vector<Range> ranges(static_cast<std::size_t>(count >= 100000 ? std::max(1, threads) : 1));
    parallelChunks(count, static_cast<int>(ranges.size()), [&](int c, std::size_t i0, std::size_t i1) {
        Range r;
        for (std::size_t i = i0; i < i1; ++i) {
            const std::size_t n = length(i);
            r.maxValence = std::max(r.maxValence, n);
            r.minValence = std::min(r.minValence, n);
            r.total += n;
            const auto [b, e] = handles(i);
            for (const int* h = b; h != e; ++h) r.maxHandle = std::max(r.maxHandle, *h);
        }
        ranges[static_cast<std::size_t>(c)] = r;
    });
    std::size_t maxValence = 0, minValence = SIZE_MAX, total = 0;
    int maxHandle = 0;
    for (const Range& r : ranges) {
        maxValence = std::max(maxValence, r.maxValence);
        minValence = std::min(minValence, r.minValence);
        total += r.total;
        maxHandle = std::max(maxHandle, r.maxHandle);
    }
    const bool fixed = count == 0 || (minValence == maxValence && maxValence < 256);
    const int hb = encodingFor(static_cast<std::uint64_t>(maxHandle)), vb = fixed ? 0 : encodingFor(maxValence);
    const std::size_t pad = chunkHeader(o, "TOPO", 24 + (fixed ? 0 : count * static_cast<std::size_t>(vb)) +
                                                      total * static_cast<std::size_t>(hb));
    o.le(0, 8);
    o.le(count, 4);
    o.le(static_cast<std::uint64_t>(entity), 1);
    o.le(fixed ? (count == 0 ? (entity == 1 ? 2 : entity == 2 ? 3 : 4) : maxValence) : 0, 1);
    o.le(static_cast<std::uint64_t>(vb), 1);
    o.le(static_cast<std::uint64_t>(hb), 1);
    o.le(0, 8);  // handle offset
    if (!fixed)
        for (std::size_t i = 0; i < count; ++i) o.le(length(i), vb);
    if (contiguous) {  // the lists lie back to back: all handles in one go
        o.leArray(handles(0).first, total, hb);
    } else {
        for (std::size_t i = 0; i < count; ++i) {
            const auto [b, e] = handles(i);
            for (const int* h = b; h != e; ++h) o.le(static_cast<std::uint32_t>(*h), hb);
        }
    }
    padding(o, pad);
}

/// Appends a TOPO chunk of @p lists (scanned on @p threads threads).
void topoChunk(detail::BlockOutput& o, int entity, const IntLists& lists, int threads) {
    topoChunk(
        o, entity, lists.size(), [&](std::size_t i) { return lists.length(i); },
        [&](std::size_t i) { return std::pair<const int*, const int*>(lists.begin(i), lists.end(i)); }, lists.size() > 0,
        threads);
}

} // namespace

OvmModel parseOvmBinary(std::string_view data, const std::string& name) {
    OvmModel m;
    m.name = name;
    m.binary = true;
    m.endPos = static_cast<long long>(data.size());
    ByteReader r(data, m);
    const std::size_t size = data.size();
    r.need(48, size, "header");
    if (std::memcmp(data.data(), kMagic, 8) != 0) m.fail(0, "not an OpenVolumeMesh binary file (bad magic bytes)");
    r.pos = 8;
    const auto fileVersion = r.uint(1, size, "header"), headerVersion = r.uint(1, size, "header");
    if (fileVersion != 1 || headerVersion != 1)
        m.fail(8, "unsupported file/header version " + std::to_string(fileVersion) + "/" + std::to_string(headerVersion) +
                      " (expected 1/1)");
    const auto dim = r.uint(1, size, "header"), topo = r.uint(1, size, "header");
    if (dim != 3) m.fail(10, "vertex dimension " + std::to_string(dim) + " (expected 3)");
    if (topo > 2) m.fail(11, "unknown topology type " + std::to_string(topo));
    m.topology = static_cast<OvmTopology>(topo);
    r.pos = 16;
    // Every entity needs at least this many bytes in the file: 4 per vertex coordinate
    // triple component, one per handle.
    const std::uint64_t minBytes[4] = {12, 2, 3, 1};
    std::uint64_t counts[4];
    for (int i = 0; i < 4; ++i) {
        counts[i] = r.uint(8, size, "header");
        if (counts[i] > size / minBytes[i] || counts[i] > INT_MAX / 2)
            m.fail(16 + 8 * i, std::string(i == 0 ? "vertex" : kEntityNames[i]) + " count " + std::to_string(counts[i]) +
                                   " is larger than the file can hold");
    }
    m.vertices.resize(counts[0]);
    m.edges.resize(counts[1]);
    m.faces.resize(counts[2]);
    m.facePos.resize(counts[2]);
    m.cells.resize(counts[3]);
    m.cellPos.resize(counts[3]);
    std::array<std::uint64_t, 4> filled{};  // vertices, edges, faces, cells read
    std::vector<DirEntry> dir;
    bool sawEof = false;
    while (r.pos < size && !sawEof) {
        const long long at = static_cast<long long>(r.pos);
        r.need(16, size, "chunk header");
        const std::string type(data.substr(r.pos, 4));
        r.pos += 4;
        const auto version = r.uint(1, size, "chunk header"), padding = r.uint(1, size, "chunk header");
        const auto compression = r.uint(1, size, "chunk header");
        r.uint(1, size, "chunk header");  // flags
        const std::uint64_t length = r.uint(8, size, "chunk header");
        if (length > size - r.pos || padding > length)
            m.fail(at + 8, "chunk '" + type + "' length " + std::to_string(length) + " exceeds the " +
                               std::to_string(size - r.pos) + " bytes left in the file");
        if (version != 0) m.fail(at + 4, "chunk '" + type + "' has unsupported version " + std::to_string(version));
        if (compression != 0) m.fail(at + 6, "chunk '" + type + "' is compressed (not supported)");
        const std::size_t end = r.pos + static_cast<std::size_t>(length - padding);
        if (type == "EOF ") {
            sawEof = true;
        } else if (type == "DIRP") {
            while (r.pos < end) {
                DirEntry e;
                e.entity = static_cast<int>(r.uint(1, end, "property directory"));
                if (e.entity > 6) m.fail(static_cast<long long>(r.pos) - 1, "invalid property entity " + std::to_string(e.entity));
                e.name = r.string4(end, "property directory");
                e.type = r.string4(end, "property directory");
                r.string4(end, "property directory");  // serialized default value
                e.param = e.entity == 5 && (e.type == "3d" || e.type == "3f" || e.type == "vec3d" || e.type == "vec3f") &&
                          isParametrizationName(e.name);
                const std::string label = std::string(kEntityNames[e.entity]) + " " + e.type + " \"" + e.name + "\"";
                if (e.param && !m.paramLabel.empty()) {
                    m.warnings.push_back(name + ": byte " + std::to_string(at) + ": ignoring parametrization property " +
                                         label + " (using " + m.paramLabel + ")");
                    e.param = false;
                } else if (e.param) {
                    m.paramLabel = label;
                } else {
                    m.skipped.push_back(label);
                }
                dir.push_back(std::move(e));
            }
        } else if (type == "VERT") {
            const std::uint64_t base = r.uint(8, end, "VERT chunk"), count = r.uint(4, end, "VERT chunk");
            const auto enc = r.uint(1, end, "VERT chunk");
            if (enc != 1 && enc != 2) m.fail(at + 28, "invalid vertex encoding " + std::to_string(enc) + " (expected 1 or 2)");
            r.pos += 3;
            if (base != filled[0] || count > counts[0] - base)
                m.fail(at + 16, "vertex span [" + std::to_string(base) + ", +" + std::to_string(count) +
                                    ") does not continue the " + std::to_string(filled[0]) + " read so far of " +
                                    std::to_string(counts[0]));
            const int bytes = enc == 2 ? 8 : 4;
            r.need(count * 3 * bytes, end, "VERT chunk");
            for (std::uint64_t i = 0; i < count; ++i)
                for (int k = 0; k < 3; ++k) m.vertices[base + i][k] = r.real(bytes, end, "vertex coordinate");
            filled[0] += count;
        } else if (type == "TOPO") {
            if (filled[0] != counts[0]) m.fail(at, "TOPO chunk before all vertices were read");
            readTopo(r, end, m, filled);
        } else if (type == "PROP") {
            const std::uint64_t base = r.uint(8, end, "PROP chunk"), count = r.uint(4, end, "PROP chunk");
            const std::uint64_t idx = r.uint(4, end, "PROP chunk");
            if (idx >= dir.size())
                m.fail(at + 28, "property index " + std::to_string(idx) + " not in the directory (" +
                                    std::to_string(dir.size()) + " entries)");
            DirEntry& e = dir[idx];
            if (e.param) {
                const int bytes = (e.type == "3d" || e.type == "vec3d") ? 8 : 4;
                if (base != e.filled || count > 2 * counts[2] - base || end - r.pos != count * 3 * bytes)
                    m.fail(at + 16, "property \"" + e.name + "\": span [" + std::to_string(base) + ", +" +
                                        std::to_string(count) + ") with " + std::to_string(end - r.pos) +
                                        " bytes does not continue the " + std::to_string(e.filled) + " values of " +
                                        std::to_string(2 * counts[2]));
                for (std::uint64_t i = 0; i < count; ++i) {
                    Vec3d& u = m.halffaceParams.emplace_back();
                    for (int k = 0; k < 3; ++k) u[k] = r.real(bytes, end, "parameter value");
                }
                e.filled += count;
            }
        } else {
            m.warnings.push_back(name + ": byte " + std::to_string(at) + ": skipped unknown chunk '" + type + "'");
        }
        r.pos = static_cast<std::size_t>(end + padding);
    }
    if (!sawEof) m.fail(static_cast<long long>(size), "no EOF chunk: the file is truncated");
    if (r.pos != size) m.fail(static_cast<long long>(r.pos), std::to_string(size - r.pos) + " bytes after the EOF chunk");
    for (int i = 0; i < 4; ++i)
        if (filled[i] != counts[i])
            m.fail(static_cast<long long>(size), "the file holds " + std::to_string(filled[i]) + " of the " +
                                                     std::to_string(counts[i]) + " " +
                                                     (i == 0 ? "vertice" : kEntityNames[i]) + "s of its header");
    for (const auto& e : dir)
        if (e.param && e.filled != 2 * counts[2])
            m.fail(static_cast<long long>(size), "property \"" + e.name + "\" has " + std::to_string(e.filled) +
                                                     " of " + std::to_string(2 * counts[2]) + " values");
    return m;
}

void writeOvmBinary(detail::BlockOutput& o, const OvmFlatMesh& m, int threads) {
    static_assert(sizeof(Vec3d) == 3 * sizeof(double) && sizeof(std::array<int, 2>) == 2 * sizeof(int),
                  "positions, map and edges are written straight from their arrays");
    const std::vector<Vec3d>& vertices = *m.vertices;
    o << std::string_view(kMagic, 8);
    o.le(1, 1);
    o.le(1, 1);
    o.le(3, 1);
    o.le(static_cast<std::uint64_t>(m.topology), 1);
    o.le(0, 4);
    for (const std::size_t n : {vertices.size(), m.edges.size(), m.faces.size(), m.cells.size()}) o.le(n, 8);
    const bool params = m.halffaceParams && !m.halffaceParams->empty();
    if (params) {
        const std::string_view pname = "HexHex::Parametrization";
        const std::size_t pad = chunkHeader(o, "DIRP", 1 + 4 + pname.size() + 4 + 2 + 4 + 24);
        o.le(5, 1);
        o.le(pname.size(), 4);
        o << pname;
        o.le(2, 4);
        o << std::string_view("3d");
        o.le(24, 4);
        for (int k = 0; k < 3; ++k) o.le(0, 8);
        padding(o, pad);
    }
    std::size_t pad = chunkHeader(o, "VERT", 16 + 24 * vertices.size());
    o.le(0, 8);
    o.le(vertices.size(), 4);
    o.le(2, 4);  // double encoding + 3 reserved bytes
    o.leArray(vertices.empty() ? nullptr : vertices[0].data(), 3 * vertices.size());
    padding(o, pad);
    topoChunk(
        o, 1, m.edges.size(), [](std::size_t) { return std::size_t(2); },
        [&](std::size_t i) { return std::pair<const int*, const int*>(m.edges[i].data(), m.edges[i].data() + 2); },
        !m.edges.empty(), threads);
    topoChunk(o, 2, m.faces, threads);
    topoChunk(o, 3, m.cells, threads);
    if (params) {
        const std::vector<Vec3d>& u = *m.halffaceParams;
        pad = chunkHeader(o, "PROP", 16 + 24 * u.size());
        o.le(0, 8);
        o.le(u.size(), 4);
        o.le(0, 4);  // property index
        o.leArray(u[0].data(), 3 * u.size());
        padding(o, pad);
    }
    chunkHeader(o, "EOF ", 0);
}

std::string writeOvmBinary(const OvmModel& m) {
    detail::BlockOutput o;
    writeOvmBinary(o, flatOvm(m));
    return o.take();
}

} // namespace HexEx
