// Seeded mutation fuzzing of every mesh file reader (.ovm, .ovmb, .vtu in all encodings,
// legacy .vtk ASCII and binary, .mesh, the 2D pipeline's .obj): truncations, flipped bytes, huge numbers, deleted
// and repeated ranges. Each mutant must read or fail with an InputError that names the
// file; nothing else may escape (no crash, no std::bad_alloc). Bounded in time.

#include "TestMeshChecks.hh"

#include <HexEx/Core/Error.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/IO/HexMeshWriters.hh>
#include <HexEx/IO/OvmTetReader.hh>
#include <HexEx/Quad/TextMeshWriters.hh>
#include <HexEx/Quad/QuadGenerators.hh>
#include <HexEx/Quad/TriObjReader.hh>

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <functional>
#include <random>
#include <set>
#include <sstream>

using namespace HexEx;

namespace {

/// Big-endian bytes of @p v (legacy binary VTK).
template <class T>
std::string bigEndian(T v) {
    std::string s(sizeof(T), '\0');
    std::memcpy(&s[0], &v, sizeof(T));
    std::reverse(s.begin(), s.end());
    return s;
}

/// A legacy binary VTK file with one unit hex (cell list in version 4.2 layout).
std::string legacyBinaryHex() {
    std::string t = "# vtk DataFile Version 4.2\nhand made\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 8 double\n";
    for (int i = 0; i < 8; ++i)
        for (const double x : {double(i & 1), double((i >> 1) & 1), double(i >> 2)}) t += bigEndian(x);
    t += "\nCELLS 1 9\n";
    for (const int v : {8, 0, 1, 3, 2, 4, 5, 7, 6}) t += bigEndian<std::int32_t>(v);
    t += "\nCELL_TYPES 1\n" + bigEndian<std::int32_t>(12) + "\nCELL_DATA 1\nSCALARS q float 1\nLOOKUP_TABLE default\n" +
         bigEndian(1.5f) + "\n";
    return t;
}

/// Applies one random mutation to @p s.
std::string mutate(std::string s, std::mt19937& rng) {
    if (s.empty()) return s;
    auto pos = [&] { return std::uniform_int_distribution<std::size_t>(0, s.size() - 1)(rng); };
    switch (std::uniform_int_distribution<int>(0, 5)(rng)) {
    case 0: s.resize(pos()); break;                                                         // truncate
    case 1: s[pos()] = static_cast<char>(std::uniform_int_distribution<int>(0, 255)(rng)); break;  // flip a byte
    case 2: s.insert(pos(), "99999999999"); break;                                          // huge count
    case 3: {                                                                               // 0xff run
        const std::size_t p = pos();
        for (std::size_t i = p; i < std::min(s.size(), p + 8); ++i) s[i] = '\xff';
        break;
    }
    case 4: {  // delete a range
        const std::size_t p = pos();
        s.erase(p, std::uniform_int_distribution<std::size_t>(1, 64)(rng));
        break;
    }
    default: {  // repeat a range
        const std::size_t p = pos();
        s.insert(p, s.substr(p, std::uniform_int_distribution<std::size_t>(1, 64)(rng)));
    }
    }
    return s;
}

/// Fuzzes @p read on mutants of @p seed; every failure must be an InputError naming @p name.
void fuzz(const std::string& seed, const std::string& name, const std::function<void(const std::string&)>& read,
          unsigned rngSeed) {
    ASSERT_NO_THROW(read(seed)) << name << ": the seed itself must read";
    std::mt19937 rng(rngSeed);
    const auto t0 = std::chrono::steady_clock::now();
    int runs = 0, errors = 0;
    std::set<std::string> unplaced;
    for (; runs < 1500 && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(2); ++runs) {
        std::string m = mutate(seed, rng);
        if (runs % 3 == 0) m = mutate(m, rng);
        try {
            read(m);
        } catch (const InputError& e) {
            ++errors;
            const std::string msg = e.what();
            ASSERT_EQ(msg.rfind(name + ":", 0), 0u) << msg;
            const std::string rest = msg.substr(name.size() + 1);
            if (!(std::isdigit(static_cast<unsigned char>(rest[0])) || rest.rfind(" byte ", 0) == 0))
                unplaced.insert(rest.substr(0, 60));
        } catch (const std::exception& e) {
            FAIL() << name << ": mutant " << runs << " threw " << typeid(e).name() << ": " << e.what();
        }
    }
    EXPECT_GT(errors, runs / 4) << name;  // the mutations do break files
    for (const auto& u : unplaced) std::cout << "  " << name << " error without position:" << u << "\n";
}

} // namespace

TEST(FormatFuzz, OpenVolumeMeshReaders) {
    const ParametrizedTetMesh cube = generateCube(1, 2);
    const OvmModel tets = ovmFromTetMesh(cube);
    const auto readTet = [](const std::string& n) { return [n](const std::string& s) { readOvmTetBuffer(s, n); }; };
    fuzz(writeOvmAscii(tets), "t.ovm", readTet("t.ovm"), 1);
    fuzz(writeOvmBinary(tets), "t.ovmb", readTet("t.ovmb"), 2);
    const HexMesh hm = HexExTest::extracted(cube);
    const OvmModel hexes = ovmFromHexMesh(hm);
    fuzz(writeOvmBinary(hexes), "h.ovmb", [](const std::string& s) { readHexMeshBuffer(s, HexMeshFormat::Ovmb, "h.ovmb"); }, 3);
    fuzz(writeOvmAscii(hexes), "h.ovm", [](const std::string& s) { readHexMeshBuffer(s, HexMeshFormat::Ovm, "h.ovm"); }, 4);
}

TEST(FormatFuzz, VtkReaders) {
    HexMesh hm = HexExTest::extracted(generateCube(1, 2));
    Polyhedron p;  // a pyramid on hex 0
    const auto& h = hm.hexes[0];
    hm.vertices.push_back(Vec3d(0.2, 0.3, -2));
    const int a = static_cast<int>(hm.vertices.size()) - 1;
    p.faces = {{h[0], h[1], h[2], h[3]}, {h[1], h[0], a}, {h[2], h[1], a}, {h[3], h[2], a}, {h[0], h[3], a}};
    hm.polyhedra.push_back(p);
    unsigned seed = 10;
    for (const VtuEncoding enc : {VtuEncoding::Binary, VtuEncoding::Compressed, VtuEncoding::Ascii}) {
        std::ostringstream out;
        writeHexMeshStream(out, hm, HexMeshFormat::Vtu, enc);
        fuzz(out.str(), "m.vtu", [](const std::string& s) { readHexMeshBuffer(s, HexMeshFormat::Vtu, "m.vtu"); }, seed++);
    }
    std::ostringstream vtk;
    writeHexMeshStream(vtk, hm, HexMeshFormat::Vtk);
    const auto readVtk = [](const std::string& s) { readHexMeshBuffer(s, HexMeshFormat::Vtk, "m.vtk"); };
    fuzz(vtk.str(), "m.vtk", readVtk, seed++);
    fuzz(legacyBinaryHex(), "m.vtk", readVtk, seed++);
    std::ostringstream medit;
    writeHexMeshStream(medit, hm, HexMeshFormat::Medit);
    fuzz(medit.str(), "m.mesh", [](const std::string& s) { readHexMeshBuffer(s, HexMeshFormat::Medit, "m.mesh"); }, seed++);
}

TEST(FormatFuzz, LegacyBinaryVtkReadsAndHugeCountsAreRejected) {
    const HexMesh m = readHexMeshBuffer(legacyBinaryHex(), HexMeshFormat::Vtk, "b.vtk");
    ASSERT_EQ(m.hexes.size(), 1u);
    EXPECT_EQ(m.hexes[0], (std::array<int, 8>{{0, 1, 3, 2, 4, 5, 7, 6}}));
    EXPECT_EQ(m.vertices[6], Vec3d(0, 1, 1));
    const auto error = [](const std::string& text, HexMeshFormat f, const std::string& name) {
        try {
            readHexMeshBuffer(text, f, name);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    std::string huge = legacyBinaryHex();
    huge.replace(huge.find("POINTS 8"), 8, "POINTS 80000000");
    EXPECT_EQ(error(huge, HexMeshFormat::Vtk, "b.vtk"), "b.vtk:5: number of points 80000000 is larger than the file can hold");
    // .ovmb header counts beyond the file size.
    std::string ovmb = writeOvmBinary(ovmFromTetMesh(generateCube(1, 1)));
    ovmb[16 + 8 * 2 + 5] = 1;  // faces: 2^40 + ...
    EXPECT_NE(error(ovmb, HexMeshFormat::Ovmb, "c.ovmb").find("c.ovmb: byte 32: face count "), std::string::npos);
}

TEST(FormatFuzz, QuadObjReader) {
    // A perturbed cone disk (flipped triangles, full-precision parameters) as our writer
    // writes it, plus a hand-made file with comments, normals and relative indices.
    ParametrizedTriMesh disk = generateConeDisk(5, 2, 2);
    perturbTriParameters(disk, 0.4, 3);
    const auto read = [](const std::string& s) { parseTriObj(s, "q.obj"); };
    fuzz(formatTriObj(disk), "q.obj", read, 40);
    fuzz("# c\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0 0\nvt 0 1\nvn 0 0 1\nf 1/1/1 2/2/1 3/3/1\nf -3/-3 -2/-2 -1/-1\n", "q.obj",
         read, 41);
}
