// Face patches against the map itself: on valid generated maps, the six patches of every hex
// close exactly the 3D volume of the tet parts that the map sends into the hex's unit cube,
// computed independently of the extraction (ParametricHexVolumes.hh: tets clipped by the unit
// cubes of their charts, pulled back with the tets' affine maps).

#include "ParametricHexVolumes.hh"

#include <HexEx/Generators/Generators.hh>
#include <HexEx/Generators/Perturbation.hh>
#include <HexEx/HexEx.hh>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

using namespace HexEx;

namespace {

/// Volume closed by the six patches of hex @p h (divergence theorem: sum of p0 . (p1 x p2) / 6
/// over the triangles, each face oriented outward of the hex by hex_face_sign).
double patchClosedVolume(const HexArcs& a, std::size_t h) {
    double vol = 0;
    for (std::size_t k = 0; k < 6; ++k) {
        const std::size_t f = static_cast<std::size_t>(a.hex_faces[h][k]);
        double face = 0;
        for (std::size_t t = a.patch_offset[f]; t < a.patch_offset[f + 1]; ++t) {
            const auto& tri = a.patch_triangles[t];
            const Vec3d &p0 = a.patch_points[static_cast<std::size_t>(tri[0])], &p1 = a.patch_points[static_cast<std::size_t>(tri[1])],
                        &p2 = a.patch_points[static_cast<std::size_t>(tri[2])];
            face += (p0 | (p1 % p2)) / 6;
        }
        vol += a.hex_face_sign[h][k] * face;
    }
    return vol;
}

double boundingDiagonal(const TetMesh& m) {
    Vec3d lo(1e300, 1e300, 1e300), hi(-1e300, -1e300, -1e300);
    for (std::size_t v = 0; v < m.n_vertices(); ++v) {
        lo.minimize(m.position(VertexHandle(static_cast<int>(v))));
        hi.maximize(m.position(VertexHandle(static_cast<int>(v))));
    }
    return (hi - lo).norm();
}

/// Every hex's patch volume equals the volume of exactly one cube preimage, the one whose
/// corners are the hex's vertices, and every cube preimage is some hex's.
void expectHexVolumesMatch(const ParametrizedTetMesh& pm, const std::string& name, int threads) {
    SCOPED_TRACE(name + ", threads " + std::to_string(threads));
    ParametrizedTetMesh input = pm;
    input.mesh.build_adjacency();
    HexMesh hm;
    HexArcs arcs;
    ExtractionOptions opt;
    opt.threads = threads;
    opt.arcs = &arcs;
    const ExtractionReport rep = extractHexMesh(input, hm, opt);
    ASSERT_TRUE(rep.valid_all_hex);
    ASSERT_TRUE(arcs.failed_faces.empty());
    ASSERT_EQ(arcs.hex_faces.size(), hm.hexes.size());

    const double diag = boundingDiagonal(input.mesh);
    const std::vector<HexExTest::CubePreimage> cubes = HexExTest::cubePreimages(pm, hm, 1e-9 * diag);
    ASSERT_EQ(cubes.size(), hm.hexes.size());
    std::map<std::vector<int>, std::size_t> hexByCorners;
    for (std::size_t h = 0; h < hm.hexes.size(); ++h) {
        std::vector<int> c(hm.hexes[h].begin(), hm.hexes[h].end());
        std::sort(c.begin(), c.end());
        ASSERT_TRUE(hexByCorners.emplace(c, h).second);
    }
    std::vector<int> matched(hm.hexes.size(), 0);
    double worst = 0;
    for (const HexExTest::CubePreimage& cube : cubes) {
        ASSERT_EQ(cube.missing_corners, 0);
        ASSERT_EQ(cube.corners.size(), 8u);
        const auto it = hexByCorners.find(std::vector<int>(cube.corners.begin(), cube.corners.end()));
        ASSERT_NE(it, hexByCorners.end());
        ++matched[it->second];
        const double v = patchClosedVolume(arcs, it->second);
        worst = std::max(worst, std::abs(v - cube.volume) / cube.volume);
        EXPECT_NEAR(v, cube.volume, 1e-9 * cube.volume) << "hex " << it->second << " (" << cube.pieces << " tet pieces)";
    }
    EXPECT_EQ(std::count(matched.begin(), matched.end(), 1), static_cast<long>(hm.hexes.size()));
    EXPECT_LT(worst, 1e-9);
}

} // namespace

TEST(ArcsHexVolume, CubesIncludingRandomChartsAndImplicitCells) {
    expectHexVolumesMatch(generateCube(2, 2), "cube n=2 s=2", 1);
    expectHexVolumesMatch(generateCube(3, 2), "cube n=3 s=2 (tets across hexes)", 1);
    expectHexVolumesMatch(generateCube(2, 5), "cube n=2 s=5 (implicit cells)", 2);
    for (unsigned seed : {3u, 11u}) {
        ParametrizedTetMesh pm = generateCube(3, 4);
        applyRandomChartTransforms(pm, seed);
        expectHexVolumesMatch(pm, "cube n=3 s=4 random charts seed " + std::to_string(seed), 2);
    }
}

TEST(ArcsHexVolume, CylindersOfValenceThreeToSix) {
    for (int k = 3; k <= 6; ++k) {
        expectHexVolumesMatch(generateCylinder(k, 2, 2, 2, 1), "cylinder k=" + std::to_string(k), 1);
        ParametrizedTetMesh pm = generateCylinder(k, 2, 1, 3, 2);
        applyRandomChartTransforms(pm, static_cast<unsigned>(k));
        expectHexVolumesMatch(pm, "cylinder k=" + std::to_string(k) + " fine, random charts", 2);
    }
    // Moved vertex parameters (the same in all charts), no fold: the hexes are curved.
    ParametrizedTetMesh pm = generateCylinder(5, 3, 2, 2, 2);
    perturbParameters(pm, 0.15, 3);
    expectHexVolumesMatch(pm, "perturbed cylinder k=5", 1);
}

TEST(ArcsHexVolume, Rings) {
    expectHexVolumesMatch(generateRing(6, 2, 1, 4, 2, 1), "ring", 1);
    expectHexVolumesMatch(generateRing(5, 1, 2, 5, 3, 3), "ring fine", 2);
    expectHexVolumesMatch(generateTwistedRing(6, 2, 4, 2), "twisted ring", 1);
}
