/// @file HalffaceTransitionsTest.cc
/// Tests of the compact per-halfface transition storage against a plain array of
/// GridTransform: sparse and dense translations, overwriting and clearing; all_identity() and
/// the singularities of a one-chart map (found without walking the edges).

#include <HexEx/Generators/Generators.hh>
#include <HexEx/Preprocessing/Transitions.hh>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

using namespace HexEx;

namespace {

GridTransform randomTransform(std::mt19937& rng, bool translated) {
    std::uniform_int_distribution<int> rot(0, Rotation::kCount - 1), tr(-5, 5);
    Vec3i t(0, 0, 0);
    if (translated)
        while (t == Vec3i(0, 0, 0)) t = Vec3i(tr(rng), tr(rng), tr(rng));
    return GridTransform(Rotation(rot(rng)), t);
}

void expectSame(const HalffaceTransitions& h, const std::vector<GridTransform>& ref) {
    ASSERT_EQ(h.size(), ref.size());
    for (std::size_t i = 0; i < ref.size(); ++i) {
        EXPECT_EQ(h[i], ref[i]) << "halfface " << i;
        EXPECT_EQ(h.is_identity(i), ref[i].is_identity()) << "halfface " << i;
    }
}

} // namespace

TEST(HalffaceTransitions, ResetIsIdentity) {
    HalffaceTransitions h;
    h.reset(10);
    expectSame(h, std::vector<GridTransform>(10));
}

TEST(HalffaceTransitions, SparseThenDenseTranslations) {
    // Few translations stay sparse; a second batch makes them many (dense). Both must read
    // back exactly, together with rotation-only entries.
    for (int batches : {1, 2}) {
        std::mt19937 rng(7 + static_cast<unsigned>(batches));
        const std::size_t n = 400;
        HalffaceTransitions h;
        h.reset(n);
        std::vector<GridTransform> ref(n);
        std::vector<std::pair<int, Vec3i>> list;
        for (std::size_t i = 0; i < n; i += 3) {
            const GridTransform g = randomTransform(rng, i % 9 == 0);
            ref[i] = g;
            h.set_rotation_only(i, g.R);
            if (!(g.t == Vec3i(0, 0, 0))) list.emplace_back(static_cast<int>(i), g.t);
        }
        std::reverse(list.begin(), list.end());  // any order
        h.add_translations(list);
        if (batches == 2) {
            list.clear();
            for (std::size_t i = 1; i < n; i += 2) {
                const GridTransform g = randomTransform(rng, true);
                ref[i] = g;
                h.set_rotation_only(i, g.R);
                list.emplace_back(static_cast<int>(i), g.t);
            }
            h.add_translations(list);
        }
        expectSame(h, ref);
        // Overwrite: translated -> other translation, translated -> none, none -> translated.
        for (std::size_t i = 0; i < n; i += 5) {
            const GridTransform g = randomTransform(rng, i % 10 == 0);
            ref[i] = g;
            h.set(i, g);
        }
        expectSame(h, ref);
    }
}

TEST(HalffaceTransitions, AllIdentitySeesEveryHalfface) {
    // A non-identity entry anywhere (first, last, across the scan's blocks of 4096 bytes, a
    // translation without rotation) makes all_identity() false; setting it back makes it true.
    const std::size_t n = 3 * 4096 + 17;
    HalffaceTransitions h;
    h.reset(0);
    EXPECT_TRUE(h.all_identity());
    h.reset(n);
    EXPECT_TRUE(h.all_identity());
    for (std::size_t i : {std::size_t(0), std::size_t(4095), std::size_t(4096), std::size_t(2 * 4096 + 5), n - 1}) {
        h.set(i, GridTransform(Rotation(5), Vec3i(0, 0, 0)));
        EXPECT_FALSE(h.all_identity()) << "rotation at " << i;
        h.set(i, GridTransform(Rotation(), Vec3i(0, 2, 0)));
        EXPECT_FALSE(h.all_identity()) << "translation at " << i;
        h.set(i, GridTransform());
        EXPECT_TRUE(h.all_identity()) << "cleared at " << i;
    }
}

TEST(HalffaceTransitions, OneChartMapHasNoSingularities) {
    // The cube has one chart: no singular edge or vertex, the per-vertex flags all zero; a
    // valence-3 cylinder (not one chart) still has its axis.
    ParametrizedTetMesh cube = generateCube(3, 2);
    cube.mesh.build_adjacency();
    const Transitions tc = computeTransitions(cube.mesh, cube.params);
    EXPECT_TRUE(tc.halfface.all_identity());
    for (int threads : {1, 2}) {
        const Singularities s = findSingularities(cube.mesh, cube.params, tc, threads);
        EXPECT_TRUE(s.edges.empty());
        EXPECT_TRUE(s.vertices.empty());
        EXPECT_EQ(s.is_singular_vertex, std::vector<char>(cube.mesh.n_vertices(), 0));
    }
    ParametrizedTetMesh cyl = generateCylinder(3, 2, 2, 1, 1);
    cyl.mesh.build_adjacency();
    const Transitions ty = computeTransitions(cyl.mesh, cyl.params);
    EXPECT_FALSE(ty.halfface.all_identity());
    const Singularities s = findSingularities(cyl.mesh, cyl.params, ty, 2);
    ASSERT_FALSE(s.edges.empty());
    for (const SingularEdge& e : s.edges) EXPECT_EQ(e.valence, 3);
}
