/// @file DartExtractionTest.cc
/// Tests of extractDarts() (counted, then written in place): every dart equals a direct
/// enumeration (every grid point of every tet's box, every frame, the symbolic-perturbation
/// test), for any thread count; the dense indices find every dart; the cap on the number of
/// darts refuses before any dart is stored.

#include <HexEx/Core/Error.hh>
#include <HexEx/Extraction/DartExtraction.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/Generators/Perturbation.hh>
#include <HexEx/Pipeline/DartStage.hh>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace HexEx;

namespace {

/// The darts of @p tets by the definition: for every non-degenerate tet, every grid point
/// of its bounding box in x-major order and every frame in order, the dart exists if the
/// perturbed point z + e d1 + e^2 d2 + e^3 d3 lies in the tet.
std::vector<Dart> directDarts(const std::vector<TetSoS>& tets) {
    std::vector<Dart> out;
    for (std::size_t c = 0; c < tets.size(); ++c) {
        const TetSoS& T = tets[c];
        if (T.vol == 0) continue;
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            double mn = T.p[0][a], mx = T.p[0][a];
            for (int i = 1; i < 4; ++i) {
                mn = std::min(mn, T.p[i][a]);
                mx = std::max(mx, T.p[i][a]);
            }
            lo[a] = static_cast<int>(std::ceil(mn));
            hi[a] = static_cast<int>(std::floor(mx));
        }
        for (int x = lo[0]; x <= hi[0]; ++x)
            for (int y = lo[1]; y <= hi[1]; ++y)
                for (int z = lo[2]; z <= hi[2]; ++z) {
                    const Vec3i p(x, y, z);
                    const std::array<int, 4> oz = T.sides(Vec3d(x, y, z));
                    for (const auto& f : allFrames())
                        if (T.contains(oz, f[0], f[1], f[2])) {
                            Dart d;
                            d.tet = static_cast<int>(c);
                            d.z = p;
                            d.d = f;
                            d.sign = static_cast<signed char>(T.vol);
                            out.push_back(d);
                        }
                }
    }
    return out;
}

/// extractDarts() on @p tets (without implicit cells) equals directDarts() for 1, 2 and 3
/// threads, and DartSet::find() returns every dart's own index.
void expectDirectDartsOf(const std::vector<TetSoS>& tets) {
    const std::vector<Dart> expected = directDarts(tets);
    EXPECT_FALSE(expected.empty());
    for (int threads : {1, 2, 3}) {
        SCOPED_TRACE("threads = " + std::to_string(threads));
        const DartSet ds = extractDarts(tets, threads);
        EXPECT_EQ(ds.darts.size(), expected.size());
        if (ds.darts.size() != expected.size()) continue;
        long mismatches = 0;
        for (std::size_t i = 0; i < expected.size(); ++i) {
            const Dart& a = ds.darts[i];
            const Dart& b = expected[i];
            if (a.tet != b.tet || !samePoint(a.z, b.z) || !sameFrame(a.d, b.d) || a.sign != b.sign) ++mismatches;
        }
        EXPECT_EQ(mismatches, 0);
        EXPECT_EQ(ds.tet_begin.size(), tets.size() + 1);
        long misplaced = 0;
        for (std::size_t c = 0; c + 1 < ds.tet_begin.size(); ++c)
            for (std::size_t i = ds.tet_begin[c]; i < ds.tet_begin[c + 1]; ++i) misplaced += ds.darts[i].tet != static_cast<int>(c);
        EXPECT_EQ(misplaced, 0);
        long lost = 0;
        for (std::size_t i = 0; i < ds.darts.size(); ++i)
            if (ds.find(ds.darts[i].tet, ds.darts[i].z, ds.darts[i].d) != static_cast<long>(i)) ++lost;
        EXPECT_EQ(lost, 0);
    }
}

/// expectDirectDartsOf() on the tets of @p pm. Returns the number of flipped tets (with
/// flipped tets the darts are counted first, without they are not).
long expectDirectDarts(ParametrizedTetMesh pm) {
    const std::vector<TetSoS> tets = buildTetSoS(pm.params, 1);
    expectDirectDartsOf(tets);
    long flipped = 0;
    for (const TetSoS& T : tets) flipped += T.vol < 0;
    return flipped;
}

} // namespace

TEST(DartExtraction, FoldedCubeEqualsTheDirectEnumeration) {
    // Small tets (sorted search), flipped tets (anti darts) and grid points on faces.
    ParametrizedTetMesh pm = generateCube(4, 3);
    perturbParameters(pm, 0.8, 3);
    EXPECT_GT(expectDirectDarts(pm), 0);
}

TEST(DartExtraction, LargeTetsWithDenseIndicesEqualTheDirectEnumeration) {
    // 6 tets of over 64 grid points each: dense indices; grid points on faces and edges.
    EXPECT_EQ(expectDirectDarts(generateCube(1, 7)), 0);
    // Large flipped tets: one corner of a 9-unit cube moved through the opposite face.
    ParametrizedTetMesh pm = generateCube(2, 9);
    for (auto& corners : pm.params)
        for (auto& p : corners)
            if (p[0] == 4.5 && p[1] == 4.5 && p[2] == 4.5) p[2] = 13.25;
    EXPECT_GT(expectDirectDarts(pm), 0);
}

TEST(DartExtraction, FoldedMapWithSmallAndLargeTetsEqualsTheDirectEnumeration) {
    // Flipped tets make the extraction count first and write second; the writing pass
    // expands the points recorded for the small tets and enumerates the dense ones again, so
    // both kinds alternate within one chunk here.
    ParametrizedTetMesh pm = generateCube(3, 10);  // cells of 10/3 units: boxes of 27 to 64 points
    const double c = 10.0 / 3.0;
    for (auto& corners : pm.params)
        for (auto& p : corners)
            if (std::fabs(p[0] - c) < 1e-9 && std::fabs(p[1] - c) < 1e-9 && std::fabs(p[2] - c) < 1e-9)
                p[2] = 7.25;  // an interior vertex moved through the cells above it
    const std::vector<TetSoS> tets = buildTetSoS(pm.params, 1);
    const DartSet ds = extractDarts(tets, 1);
    EXPECT_GT(ds.dense.size(), 0u);
    EXPECT_LT(ds.dense.size(), tets.size() / 2);
    EXPECT_GT(expectDirectDarts(pm), 0);
}

TEST(DartExtraction, ChunksThatOutgrowTheirGuessEqualTheDirectEnumeration) {
    // Without flipped tets each chunk writes into a region sized from its parameter volume
    // (48 darts per unit cell and a margin of 3 % and 4096 darts). Tiny tets around grid
    // points own all 48 frames there with almost no volume: 3000 of them overflow every
    // chunk's region at 2 and 3 threads, so the darts also go through the joining of the
    // chunks' own vectors. Tets of two sizes alternate, so the regions moved down in the
    // usual case are covered by the other tests.
    CornerParams params;
    for (int i = 0; i < 3000; ++i) {
        const double x = i, r = i % 2 ? 0.01 : 0.03;
        params.push_back({Vec3d(x - r, -r, -r), Vec3d(x + 3 * r, -r, -r), Vec3d(x - r, 3 * r, -r), Vec3d(x - r, -r, 3 * r)});
    }
    const std::vector<TetSoS> tets = buildTetSoS(params, 1);
    for (const TetSoS& T : tets) ASSERT_EQ(T.vol, 1);  // no flipped tets: the one-pass path
    expectDirectDartsOf(tets);
    EXPECT_EQ(extractDarts(tets, 2).darts.size(), 48u * 3000);
}

TEST(DartExtraction, ImplicitCellsAreTheSameForAnyThreadCount) {
    const ParametrizedTetMesh pm = generateCube(2, 12);  // TetSoS points into its parameters
    const std::vector<TetSoS> tets = buildTetSoS(pm.params, 1);
    const std::vector<FaceMask> anyFace(tets.size(), FaceMask(0x0F));  // corners may lie on any face
    const DartSet ref = extractDarts(tets, 1, 1e9, true, &anyFace);
    EXPECT_GT(ref.n_implicit_cells, 0);
    for (int threads : {2, 3}) {
        const DartSet ds = extractDarts(tets, threads, 1e9, true, &anyFace);
        ASSERT_EQ(ds.darts.size(), ref.darts.size());
        EXPECT_EQ(ds.tet_begin, ref.tet_begin);
        EXPECT_EQ(ds.n_implicit_cells, ref.n_implicit_cells);
        EXPECT_EQ(ds.n_occurrences, ref.n_occurrences);
        long mismatches = 0;
        for (std::size_t i = 0; i < ds.darts.size(); ++i)
            if (ds.darts[i].tet != ref.darts[i].tet || !samePoint(ds.darts[i].z, ref.darts[i].z) || !sameFrame(ds.darts[i].d, ref.darts[i].d))
                ++mismatches;
        EXPECT_EQ(mismatches, 0);
    }
}

TEST(DartExtraction, FrameIndexIsThePositionInAllFrames) {
    const auto& all = allFrames();
    for (int k = 0; k < 48; ++k) EXPECT_EQ(frameIndex(all[static_cast<std::size_t>(k)]), k);
}

TEST(DartExtraction, FindAnswersEveryFrameAtEveryPointByScanning) {
    // DartSet::find() with dense indices takes a point's dart at its frameIndex() when the
    // point has all 48 and stops its scan at the first larger key otherwise; a plain scan of
    // the tet's darts must give the same answer for every frame at every point with darts,
    // present or absent (points with 48 darts, with some of them, implicit cells around).
    for (const bool implicit : {false, true}) {
        SCOPED_TRACE(implicit ? "implicit cells" : "all darts stored");
        const ParametrizedTetMesh pm = generateCube(2, 12);
        const std::vector<TetSoS> tets = buildTetSoS(pm.params, 1);
        const std::vector<FaceMask> anyFace(tets.size(), FaceMask(0x0F));
        const DartSet ds = extractDarts(tets, 2, 1e9, implicit, implicit ? &anyFace : nullptr);
        ASSERT_FALSE(ds.dense.empty());
        long full = 0, partial = 0, wrong = 0;
        for (std::size_t c = 0; c + 1 < ds.tet_begin.size(); ++c)
            for (std::size_t b = ds.tet_begin[c]; b < ds.tet_begin[c + 1];) {
                std::size_t e = b;
                while (e < ds.tet_begin[c + 1] && samePoint(ds.darts[e].z, ds.darts[b].z)) ++e;
                (e - b == 48 ? full : partial) += 1;
                // Frames that repeat an axis are never stored (frameIndex() of {5, 5, 5} is 51,
                // beyond the point's 48 darts): find() says -1.
                for (const std::array<AxisDir, 3> bad : {std::array<AxisDir, 3>{0, 1, 2}, std::array<AxisDir, 3>{5, 5, 5}})
                    wrong += ds.find(static_cast<int>(c), ds.darts[b].z, bad) != -1;
                for (const auto& f : allFrames()) {
                    long expected = -1;
                    for (std::size_t k = b; k < e && expected < 0; ++k)  // the point's darts are contiguous
                        if (sameFrame(ds.darts[k].d, f)) expected = static_cast<long>(k);
                    wrong += ds.find(static_cast<int>(c), ds.darts[b].z, f) != expected;
                }
                b = e;
            }
        if (!implicit) {  // with implicit cells a point keeps fewer than 48
            EXPECT_GT(full, 0);
        }
        EXPECT_GT(partial, 0);
        EXPECT_EQ(wrong, 0);
    }
}

TEST(DartExtraction, CapRefusesWithTheBudgetMessage) {
    for (const bool fold : {false, true}) {
        ParametrizedTetMesh pm = generateCube(2, 4);
        if (fold) perturbParameters(pm, 0.9, 5);
        const std::vector<TetSoS> tets = buildTetSoS(pm.params, 1);
        const std::size_t all = extractDarts(tets, 1).darts.size();
        if (!fold) {
            EXPECT_EQ(all, 48u * 64u);  // 48 darts per unit cell of the 4^3 cube
        }
        EXPECT_EQ(extractDarts(tets, 2, 1e9, false, nullptr, 0, all).darts.size(), all);
        try {
            extractDarts(tets, 2, 1e9, false, nullptr, 0, all - 1);
            ADD_FAILURE() << "no ResourceError";
        } catch (const ResourceError& e) {
            EXPECT_NE(std::string(e.what()).find("the most the memory budget allows"), std::string::npos) << e.what();
        }
    }
}

TEST(DartExtraction, ExactAndFilteredFaceSignsEqualTheDirectEnumeration) {
    // The face signs of a grid point come three ways: at a tet corner without arithmetic,
    // from exact doubles when every corner is a small dyadic number (multiples of 1/64 up to
    // 512), else through the floating-point filter with its exact fallback. Maps without
    // flipped tets (one pass) whose grid points lie at corners, on edges and on faces:
    // corners at multiples of 0.75 (exact path), at multiples of 2/3 (filtered: grid points
    // on edges and faces need the exact fallback), shifted by 1/3 or by 600 (dyadic, but
    // beyond 512: filtered), and perturbed corners (filtered, points off the faces).
    EXPECT_EQ(expectDirectDarts(generateCube(4, 3)), 0);
    EXPECT_EQ(expectDirectDarts(generateCube(3, 2)), 0);
    for (const double shift : {1.0 / 3.0, 600.0}) {
        ParametrizedTetMesh pm = generateCube(4, 3);
        for (auto& corners : pm.params)
            for (auto& p : corners) p += Vec3d(shift, -shift, shift);
        EXPECT_EQ(expectDirectDarts(pm), 0);
    }
    ParametrizedTetMesh pm = generateCube(3, 3);
    perturbParameters(pm, 0.2, 7);
    expectDirectDarts(pm);
}

TEST(DartExtraction, StageSignsAreTheDartsSignsForAnyThreadCount) {
    // The stage fills the per-dart signs from the darts or from the tets' volume signs: they
    // must be the darts' own signs, and the anti count theirs, on a folded map (anti darts in
    // small tets) and on an unfolded one with large tets (a few tets hold most darts: chunks
    // split inside tets).
    ParametrizedTetMesh folded = generateCube(4, 3);
    perturbParameters(folded, 0.8, 3);
    const ParametrizedTetMesh large = generateCube(2, 12);
    const ParametrizedTetMesh* const maps[] = {&folded, &large};
    for (const ParametrizedTetMesh* pm : maps) {
        const std::vector<TetSoS> tets = buildTetSoS(pm->params, 1);
        for (int threads : {1, 2, 3}) {
            SCOPED_TRACE("threads = " + std::to_string(threads));
            const DartStageOutput out = extractDartStage({&pm->mesh, &tets, 0, false, threads});
            ASSERT_EQ(out.sign.size(), out.darts.darts.size());
            long anti = 0, wrong = 0;
            for (std::size_t d = 0; d < out.sign.size(); ++d) {
                anti += out.darts.darts[d].sign < 0;
                wrong += out.sign[d] != out.darts.darts[d].sign;
            }
            EXPECT_EQ(wrong, 0);
            EXPECT_EQ(out.anti, anti);
            EXPECT_EQ(anti > 0, pm == &folded);
            // Both ways of filling are used: per dart (few darts per tet), per tet (many).
            EXPECT_EQ(out.darts.darts.size() >= 8 * tets.size(), pm == &large);
        }
    }
}
