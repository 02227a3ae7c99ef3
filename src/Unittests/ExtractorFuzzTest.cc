// Robustness of the extractor on destroyed maps: random charts, large perturbations and
// independent per-corner noise (which breaks the consistency across faces). Whatever the
// input, the extractor must return a report and a mesh whose indices are in range, or
// throw InputError; never crash or hang. Bounded in iterations and time.

#include <HexEx/Core/Error.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/Generators/Perturbation.hh>
#include <HexEx/HexEx.hh>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <random>

using namespace HexEx;

TEST(ExtractorFuzz, DestroyedMapsNeverCrash) {
    const int iterations = std::getenv("HEXEX_FUZZ_ITERATIONS") ? std::atoi(std::getenv("HEXEX_FUZZ_ITERATIONS")) : 300;
    const auto start = std::chrono::steady_clock::now();
    std::mt19937 rng(12345);
    int ran = 0, notAllHex = 0;
    for (int it = 0; it < iterations; ++it) {
        if (std::chrono::steady_clock::now() - start > std::chrono::seconds(20)) break;
        const unsigned seed = rng();
        ParametrizedTetMesh pm;
        switch (seed % 3) {
            case 0: pm = generateCube(2 + static_cast<int>(seed % 3), 2 + static_cast<int>((seed / 3) % 3)); break;
            case 1: pm = generateCylinder(3 + static_cast<int>(seed % 4), 2, 2, 1 + static_cast<int>(seed % 2), 1); break;
            default: pm = generateRing(6, 2, 2, 6, 2, 1); break;
        }
        if (seed & 8) applyRandomChartTransforms(pm, seed);
        if (seed & 16) perturbParameters(pm, 0.5 + (seed % 7) * 0.5, seed);
        if (seed & 32) applyParameterNoise(pm, (seed % 5) * 0.1, seed);
        pm.mesh.build_adjacency();
        HexMesh hm;
        ExtractionOptions o;
        o.threads = 1 + static_cast<int>(seed % 2);
        try {
            const auto r = extractHexMesh(pm, hm, o);
            ++ran;
            if (!r.valid_all_hex) ++notAllHex;
            EXPECT_EQ(r.output.hexes, static_cast<long>(hm.hexes.size()));
            const int nv = static_cast<int>(hm.vertices.size());
            for (const auto& h : hm.hexes)
                for (int v : h) ASSERT_TRUE(v >= 0 && v < nv);
            for (const auto& p : hm.polyhedra)
                for (const auto& f : p.faces) {
                    EXPECT_GE(f.size(), 3u);
                    for (int v : f) ASSERT_TRUE(v >= 0 && v < nv);
                }
        } catch (const InputError&) {
            ++ran;
        }
    }
    EXPECT_GT(ran, 0);
    EXPECT_GT(notAllHex, 0);  // the corpus must include maps that cannot give an all-hex mesh
}
