#include <HexEx/Grid/GridTransform.hh>

#include <gtest/gtest.h>

using namespace HexEx;

TEST(Rotation, GroupAxioms) {
    for (int a = 0; a < 24; ++a) {
        Rotation ra(a);
        EXPECT_EQ((ra * ra.inverse()).index(), 0);
        EXPECT_EQ((Rotation(0) * ra).index(), a);
        for (int b = 0; b < 24; ++b)
            for (int c = 0; c < 24; ++c)
                EXPECT_EQ(((ra * Rotation(b)) * Rotation(c)).index(), (ra * (Rotation(b) * Rotation(c))).index());
    }
}
