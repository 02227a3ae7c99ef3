// VTK files in every encoding: .vtu written by meshio (ascii, binary, zlib, UInt32/UInt64
// headers) and legacy .vtk (ascii, binary, versions 4.2 and 5.1), hand-made appended
// base64 / big-endian files, and our own binary, compressed and ascii output read by meshio.

#include "TestMeshChecks.hh"

#include <HexEx/Core/Error.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/IO/HexMeshWriters.hh>
#include <HexEx/IO/VtkDataBlocks.hh>
#include <HexEx/Mesh/HexMeshCheck.hh>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <sstream>
#include <unistd.h>
#include <vector>

using namespace HexEx;

namespace {

const std::string kPython = "/usr/bin/python3";  // Debian's python, which has python3-meshio

std::string capture(const std::string& cmd) {
    std::unique_ptr<FILE, int (*)(FILE*)> p(popen(cmd.c_str(), "r"), pclose);
    std::string out;
    if (!p) return out;
    char buf[256];
    while (std::fgets(buf, sizeof buf, p.get())) out += buf;
    return out;
}

bool haveMeshio() { return capture(kPython + " -c 'import meshio; print(1)' 2>/dev/null") == "1\n"; }

std::string tempPath(const std::string& file) {
    return ::testing::TempDir() + "vtkenc_" + std::to_string(::getpid()) + "_" + file;
}

/// A small extracted hex mesh (27 hexes) plus one pyramid polyhedron on top of hex 0.
HexMesh sampleMesh(bool withPolyhedron) {
    HexMesh hm = HexExTest::extracted(generateCube(2, 3));
    if (withPolyhedron) {
        const auto& h = hm.hexes[0];
        const int apex = static_cast<int>(hm.vertices.size());
        hm.vertices.push_back(Vec3d(0.1, 0.2, -5));
        Polyhedron p;
        p.faces = {{h[0], h[1], h[2], h[3]}, {h[1], h[0], apex}, {h[2], h[1], apex}, {h[3], h[2], apex}, {h[0], h[3], apex}};
        hm.polyhedra.push_back(p);
    }
    return hm;
}

/// Same cells and vertices (positions within @p tolerance; 0: bit-identical).
void expectSame(const HexMesh& a, const HexMesh& b, const std::string& what, double tolerance = 0) {
    ASSERT_EQ(a.vertices.size(), b.vertices.size()) << what;
    for (std::size_t i = 0; i < a.vertices.size(); ++i)
        ASSERT_LE((a.vertices[i] - b.vertices[i]).norm(), tolerance) << what << " vertex " << i;
    EXPECT_EQ(a.hexes, b.hexes) << what;
    ASSERT_EQ(a.polyhedra.size(), b.polyhedra.size()) << what;
    for (std::size_t i = 0; i < a.polyhedra.size(); ++i) EXPECT_EQ(a.polyhedra[i].faces, b.polyhedra[i].faces) << what;
}

/// A one-hex .vtu whose arrays are stored by @p store(name, type, bytes) -> DataArray attributes+body.
std::string oneHexVtu(const std::string& rootAttrs, const std::function<std::string(const std::string&)>& store,
                      const std::string& appended = "") {
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" " + rootAttrs + ">\n<UnstructuredGrid>\n"
           "<Piece NumberOfPoints=\"8\" NumberOfCells=\"1\">\n<Points>\n" + store("points") + "</Points>\n<Cells>\n" +
           store("connectivity") + store("offsets") + store("types") + "</Cells>\n</Piece>\n</UnstructuredGrid>\n" +
           appended + "</VTKFile>\n";
}

/// Little- or big-endian bytes of the one-hex arrays.
std::string hexArrayBytes(const std::string& name, bool bigEndian) {
    std::string b;
    auto put = [&](const void* p, std::size_t n) {
        std::string s(static_cast<const char*>(p), n);
        if (bigEndian) std::reverse(s.begin(), s.end());
        b += s;
    };
    if (name == "points")
        for (int i = 0; i < 8; ++i)
            for (const double x : {double(i & 1), double((i >> 1) & 1), double(i >> 2)}) put(&x, 8);
    if (name == "connectivity")
        for (const std::int32_t v : {0, 1, 3, 2, 4, 5, 7, 6}) put(&v, 4);
    if (name == "offsets") {
        const std::int64_t v = 8;
        put(&v, 8);
    }
    if (name == "types") b += '\x0c';
    return b;
}

std::string arrayHead(const std::string& name) {
    if (name == "points") return "<DataArray type=\"Float64\" NumberOfComponents=\"3\" ";
    if (name == "connectivity") return "<DataArray type=\"Int32\" Name=\"connectivity\" ";
    if (name == "offsets") return "<DataArray type=\"Int64\" Name=\"offsets\" ";
    return "<DataArray type=\"UInt8\" Name=\"types\" ";
}

/// UInt32 little-endian header of @p n.
std::string header32(std::size_t n, bool bigEndian = false) {
    std::string h(4, '\0');
    for (int k = 0; k < 4; ++k) h[static_cast<std::size_t>(bigEndian ? 3 - k : k)] = static_cast<char>((n >> (8 * k)) & 0xff);
    return h;
}

} // namespace

TEST(VtkEncodings, MeshioWrittenVtuInEveryEncodingReads) {
    if (!haveMeshio()) GTEST_SKIP() << "Python meshio not available (Debian package python3-meshio)";
    const HexMesh hm = sampleMesh(false);
    const std::string src = tempPath("src.vtk");
    writeHexMesh(src, hm);
    struct Case {
        const char* name;
        const char* call;
    };
    const Case cases[] = {
        {"ascii", "meshio.vtu.write(o, m, binary=False)"},
        {"binary", "meshio.vtu.write(o, m, binary=True, compression=None)"},
        {"zlib", "meshio.vtu.write(o, m)"},
        {"zlib-uint64", "meshio.vtu.write(o, m, header_type='UInt64')"},
        {"binary-uint64", "meshio.vtu.write(o, m, compression=None, header_type='UInt64')"},
        {"legacy-binary-5.1", "meshio.vtk.write(o, m, binary=True)"},
        {"legacy-binary-4.2", "meshio.vtk.write(o, m, fmt_version='4.2', binary=True)"},
        {"legacy-ascii-4.2", "meshio.vtk.write(o, m, fmt_version='4.2', binary=False)"},
    };
    // One Python run writes every file (starting Python and meshio dominates the time).
    std::string script = "import meshio, sys; m = meshio.read(sys.argv[1])";
    std::vector<std::string> outs;
    for (const Case& c : cases) {
        outs.push_back(tempPath(std::string(c.name) + (std::strncmp(c.name, "legacy", 6) ? ".vtu" : ".vtk")));
        script += "; o = '" + outs.back() + "'; " + c.call;
    }
    const std::string lz = tempPath("lzma.vtu");
    script += "; meshio.vtu.write('" + lz + "', m, compression='lzma'); print('ok')";
    ASSERT_EQ(capture(kPython + " -c \"" + script + "\" '" + src + "' 2>/dev/null"), "ok\n");
    for (std::size_t i = 0; i < outs.size(); ++i) {
        const Case& c = cases[i];
        HexMesh back;
        ASSERT_NO_THROW(back = readHexMesh(outs[i])) << c.name;
        // meshio's ASCII writers print fewer digits than a double has.
        expectSame(hm, back, c.name, std::strstr(c.name, "ascii") ? 1e-9 : 0.0);
        EXPECT_TRUE(checkHexMesh(back).valid_all_hex) << c.name;
        std::remove(outs[i].c_str());
    }
    // meshio's lzma compressor is rejected with a clear message.
    try {
        readHexMesh(lz);
        ADD_FAILURE() << "lzma file was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("unsupported compressor 'vtkLZMADataCompressor'"), std::string::npos) << e.what();
    }
    std::remove(lz.c_str());
    std::remove(src.c_str());
}

TEST(VtkEncodings, MeshioReadsOurOutputInEveryEncoding) {
    if (!haveMeshio()) GTEST_SKIP() << "Python meshio not available (Debian package python3-meshio)";
    const HexMesh hm = sampleMesh(false);
    std::string paths;
    for (const char* enc : {"binary", "compressed", "ascii"}) {
        const std::string path = tempPath(std::string("ours_") + enc + ".vtu");
        writeHexMesh(path, hm, vtuEncodingFromName(enc));
        paths += " '" + path + "'";
    }
    const std::string out = capture(kPython + " -c \"import meshio, sys\nfor p in sys.argv[1:]:\n m = meshio.read(p); "
                                              "print(len(m.points), sum(len(c.data) for c in m.cells), m.cells[0].type, "
                                              "float(m.points[:, 2].max()))\"" + paths + " 2>/dev/null");
    EXPECT_EQ(out, "64 27 hexahedron 1.0\n64 27 hexahedron 1.0\n64 27 hexahedron 1.0\n");
    for (const char* enc : {"binary", "compressed", "ascii"}) std::remove(tempPath(std::string("ours_") + enc + ".vtu").c_str());
}

TEST(VtkEncodings, OwnEncodingsRoundTripWithPolyhedra) {
    const HexMesh hm = sampleMesh(true);
    std::string sizes;
    for (const VtuEncoding enc : {VtuEncoding::Binary, VtuEncoding::Compressed, VtuEncoding::Ascii}) {
        std::ostringstream out;
        writeHexMeshStream(out, hm, HexMeshFormat::Vtu, enc);
        expectSame(hm, readHexMeshBuffer(out.str(), HexMeshFormat::Vtu, "own.vtu"), "own vtu");
        sizes += std::to_string(out.str().size()) + " ";
    }
    std::ostringstream vtk;
    writeHexMeshStream(vtk, hm, HexMeshFormat::Vtk);
    EXPECT_EQ(readHexMeshBuffer(vtk.str(), HexMeshFormat::Vtk, "own.vtk").polyhedra.size(), 1u);
    EXPECT_EQ(readHexMeshBuffer(vtk.str(), HexMeshFormat::Vtk, "own.vtk").hexes, hm.hexes);
}

TEST(VtkEncodings, HandMadeBlockLayoutsRead) {
    const auto check = [](const std::string& text, const std::string& what) {
        HexMesh m;
        ASSERT_NO_THROW(m = readHexMeshBuffer(text, HexMeshFormat::Vtu, what)) << what << "\n" << text;
        ASSERT_EQ(m.hexes.size(), 1u) << what;
        EXPECT_EQ(m.hexes[0], (std::array<int, 8>{{0, 1, 3, 2, 4, 5, 7, 6}})) << what;
        EXPECT_EQ(m.vertices[7], Vec3d(1, 1, 1)) << what;
    };
    // Inline base64, header and data encoded separately (as VTK does) and together (as meshio does).
    for (const bool separate : {true, false})
        check(oneHexVtu("byte_order=\"LittleEndian\"", [&](const std::string& n) {
                  const std::string d = hexArrayBytes(n, false);
                  const std::string b64 = separate ? detail::base64Encode(header32(d.size())) + detail::base64Encode(d)
                                                   : detail::base64Encode(header32(d.size()) + d);
                  return arrayHead(n) + "format=\"binary\">\n   " + b64 + "\n</DataArray>\n";
              }),
              separate ? "inline separate" : "inline together");
    // Appended base64 and raw, big-endian, with offsets.
    for (const bool base64 : {true, false}) {
        std::string appended;
        const std::string text = oneHexVtu("byte_order=\"BigEndian\"", [&](const std::string& n) {
            const std::string d = hexArrayBytes(n, true);
            const std::string block = base64 ? detail::base64Encode(header32(d.size(), true)) + detail::base64Encode(d)
                                             : header32(d.size(), true) + d;
            const std::string head = arrayHead(n) + "format=\"appended\" offset=\"" + std::to_string(appended.size()) + "\"/>\n";
            appended += block;
            return head;
        });
        const std::size_t end = text.rfind("</VTKFile>");
        check(text.substr(0, end) + "<AppendedData encoding=\"" + (base64 ? "base64" : "raw") + "\">\n  _" + appended +
                  "\n</AppendedData>\n</VTKFile>\n",
              base64 ? "appended base64" : "appended raw");
    }
    // Inline zlib with a UInt64 header (our block writer).
    check(oneHexVtu("header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\"", [](const std::string& n) {
              return arrayHead(n) + "format=\"binary\">" + detail::base64Encode(detail::makeVtkBlock(hexArrayBytes(n, false), true)) +
                     "</DataArray>\n";
          }),
          "inline zlib uint64");
}

TEST(VtkEncodings, BadBlocksNameFileLineAndReason) {
    const auto error = [](const std::string& text) {
        try {
            readHexMeshBuffer(text, HexMeshFormat::Vtu, "bad.vtu");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const auto inlineVtu = [](const std::string& attrs, const std::function<std::string(const std::string&)>& body) {
        return oneHexVtu(attrs, [&](const std::string& n) {
            return arrayHead(n) + "format=\"binary\">" + body(n) + "</DataArray>\n";
        });
    };
    // Bad base64 character: reported at the points DataArray (line 5).
    EXPECT_EQ(error(inlineVtu("", [](const std::string&) { return "AAA*AAAA"; })),
              "bad.vtu:6: DataArray point coordinate (binary): invalid base64 character '*' before character 4");
    // Truncated data: the header promises more than the array holds.
    EXPECT_EQ(error(inlineVtu("", [](const std::string& n) {
                  return detail::base64Encode(header32(1000) + hexArrayBytes(n, false));
              })),
              "bad.vtu:6: DataArray point coordinate (binary): needs 1000 bytes, at most 194 left");
    // Corrupt zlib stream.
    const std::string corrupt = error(inlineVtu("header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\"", [](const std::string& n) {
        std::string block = detail::makeVtkBlock(hexArrayBytes(n, false), true);
        block[block.size() - 3] ^= 0x55;
        return detail::base64Encode(block);
    }));
    EXPECT_NE(corrupt.find("bad.vtu:6: DataArray point coordinate (binary): corrupt zlib data in compressed block 0"),
              std::string::npos) << corrupt;
    // A compressed header claiming a huge block is rejected before inflating.
    std::string bomb(24, '\0');
    bomb[0] = 1;                                   // one block
    bomb[8 + 5] = 1;                               // of 2^40 bytes
    bomb[16 + 5] = 1;
    bomb += std::string("\x08\0\0\0\0\0\0\0", 8) + std::string(8, 'x');
    EXPECT_NE(error(inlineVtu("header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\"",
                              [&](const std::string&) { return detail::base64Encode(bomb); }))
                  .find("claims 1099511627776 bytes from 8"),
              std::string::npos);
    // Wrong type tag and unknown format.
    EXPECT_EQ(error(oneHexVtu("", [](const std::string& n) {
                  return "<DataArray type=\"Float128\" Name=\"" + n + "\" NumberOfComponents=\"3\" format=\"binary\">AAAA</DataArray>\n";
              })),
              "bad.vtu:6: DataArray point coordinate has unsupported type 'Float128'");
    // Appended offset outside the data.
    EXPECT_EQ(error(oneHexVtu("", [](const std::string& n) { return arrayHead(n) + "format=\"appended\" offset=\"99\"/>\n"; },
                              "<AppendedData encoding=\"raw\">_abc</AppendedData>\n")),
              "bad.vtu:6: DataArray point coordinate: appended offset '99' is missing or outside the 30 bytes of appended data");
}
