/// @file HalffaceTransitionsTest.cc
/// Tests of the compact per-halfface transition storage against a plain array of
/// GridTransform: sparse and dense translations, overwriting and clearing.

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
