// Our .vtu output read by an independent reader: Python meshio (Debian python3-meshio).

#include <HexEx/Generators/Generators.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/IO/HexMeshWriters.hh>

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>
#include <unistd.h>

using namespace HexEx;

namespace {
/// Runs @p cmd and returns its stdout ("" if it could not run).
std::string capture(const std::string& cmd) {
    std::unique_ptr<FILE, int (*)(FILE*)> p(popen(cmd.c_str(), "r"), pclose);
    if (!p) return {};
    std::string out;
    char buf[256];
    while (std::fgets(buf, sizeof buf, p.get())) out += buf;
    return out;
}
} // namespace

TEST(MeshioInterop, ReadsOurVtuWithTheRightCounts) {
    const std::string python = "/usr/bin/python3";
    if (capture(python + " -c 'import meshio; print(1)' 2>/dev/null") != "1\n")
        GTEST_SKIP() << "Python meshio not available (Debian package python3-meshio)";
    for (int k : {3, 5}) {
        auto pm = generateCylinder(k, 2, 2, 1, 1);
        pm.mesh.build_adjacency();
        HexMesh hm;
        const auto r = extractHexMesh(pm, hm);
        ASSERT_TRUE(r.valid_all_hex);
        const std::string path = ::testing::TempDir() + "meshio_" + std::to_string(::getpid()) + ".vtu";
        writeHexMesh(path, hm);
        const std::string out = capture(
            python + " -c 'import meshio, sys; m = meshio.read(sys.argv[1]); "
                     "print(len(m.points), sum(len(c.data) for c in m.cells if c.type == \"hexahedron\"))' '" +
            path + "' 2>&1");
        std::remove(path.c_str());
        EXPECT_EQ(out, std::to_string(hm.vertices.size()) + " " + std::to_string(hm.hexes.size()) + "\n");
    }
}
