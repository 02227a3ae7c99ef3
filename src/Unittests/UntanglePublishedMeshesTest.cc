/// @file UntanglePublishedMeshesTest.cc
/// untangleHexMesh() on folded maps of the shared published hex meshes
/// (`../shared/data/hexmeshes/*.vtk.xz`, or $HEXEX_HEXMESH_DIR): `from-hex` maps with face
/// and cell centres moved by 0.8 grid units give inverted hexes; after untangling none
/// remain except next to non-hex cells (whose vertices do not move). Skipped when the data
/// or the `xz` program is absent. (cfpc16_hollow8 seed 1 used to give 8 -> 1 next to non-hex
/// cells, then 11 -> 0; since the vertex placement on heavy folds changed, the hollow8 maps
/// extract without inverted hexes and the pig maps of seeds 1 and 5 give 1 and 4. Since the
/// annihilation retries other orders where it leaves broken cells, the pig maps give the
/// source mesh too, so the test extracts without those retries.)

#include "SharedData.hh"

#include <HexEx/Generators/MapFromHexMesh.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/Mesh/HexMeshQuality.hh>
#include <HexEx/Untangling/Untangler.hh>

#include <gtest/gtest.h>

#include <cstdlib>
#include <set>
#include <string>

using namespace HexEx;

namespace {

/// The published mesh @p name (../shared/data/hexmeshes, or $HEXEX_HEXMESH_DIR); empty mesh
/// if unavailable.
HexMesh publishedMesh(const std::string& name) {
    const char* env = std::getenv("HEXEX_HEXMESH_DIR");
    const std::string file = name + ".vtk.xz";
    const std::string text = env ? HexExTest::readXzFile(std::string(env) + "/" + file)
                                 : HexExTest::readSharedXz("hexmeshes/" + file);
    if (text.empty()) return {};
    return readHexMeshBuffer(text, HexMeshFormat::Vtk, name);
}

} // namespace

TEST(UntanglePublishedMeshes, FromHexMapsAtAmplitude08) {
    struct Case {
        const char* mesh;
        unsigned seed;
    };
    long inverted_before = 0;
    int cases = 0;
    for (const Case& c : {Case{"cfpc16_hollow8", 1}, Case{"cfpc16_hollow8", 2}, Case{"cfpc16_hollow8", 3},
                          Case{"sss19_pig_in", 1}, Case{"sss19_pig_in", 5}}) {
        const HexMesh source = publishedMesh(c.mesh);
        if (source.hexes.empty()) continue;
        ++cases;
        MapFromHexOptions mo;
        mo.perturb = 0.8;
        mo.seed = c.seed;
        MapFromHexResult map = mapFromHexMesh(source, mo);
        map.map.mesh.build_adjacency();
        HexMesh hm;
        // Without the annihilation's retries: with them these maps give the source mesh
        // back, with no inverted hex left to untangle.
        ExtractionOptions eo;
        eo.annihilation_retries = false;
        extractHexMesh(map.map, hm, eo);
        const TriangleSurface surface = tetMeshBoundary(map.map.mesh);
        UntangleOptions uo;
        uo.threads = 2;
        const UntangleReport r = untangleHexMesh(hm, uo, &surface);
        inverted_before += r.inverted_before;
        // Hexes that share a vertex with a non-hex cell cannot always be fixed (those
        // vertices stay); every other hex must end positive.
        std::set<int> poly;
        for (const auto& p : hm.polyhedra)
            for (const auto& f : p.faces) poly.insert(f.begin(), f.end());
        const std::vector<double> sj = scaledJacobians(hm);
        long bad = 0;
        for (std::size_t h = 0; h < hm.hexes.size(); ++h) {
            bool at_poly = false;
            for (const int v : hm.hexes[h]) at_poly = at_poly || poly.count(v) > 0;
            bad += sj[h] <= 0 && !at_poly;
        }
        EXPECT_EQ(bad, 0) << c.mesh << " seed " << c.seed << ": " << r.message;
        if (hm.polyhedra.empty()) {
            EXPECT_EQ(r.inverted_after, 0) << c.mesh << " seed " << c.seed << ": " << r.message;
        }
        std::printf("%s seed %u: %ld hexes, %ld polyhedra, inverted %ld -> %ld, min sj %.3g, %.2f s\n", c.mesh, c.seed,
                    r.hexes, static_cast<long>(hm.polyhedra.size()), r.inverted_before, r.inverted_after,
                    r.min_scaled_jacobian_after, r.seconds);
    }
    if (cases == 0) GTEST_SKIP() << "published hex meshes not found (set HEXEX_HEXMESH_DIR)";
    EXPECT_GT(inverted_before, 0) << "the folded maps should give inverted hexes";
}
