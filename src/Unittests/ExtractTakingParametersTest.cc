// extractHexMesh(ParametrizedTetMesh&&, ...): the pipeline takes the input's parameters over
// as its working copy instead of copying them; the result is the same as with the const
// overload, the input's parameters are left empty and its mesh unchanged.

#include <HexEx/Generators/Generators.hh>
#include <HexEx/Core/Error.hh>
#include <HexEx/HexEx.hh>

#include <gtest/gtest.h>

#include <utility>

namespace {

/// Extracts @p pm once through the const overload (1 thread) and once through the taking
/// one (2 threads).
void checkSameAsCopying(HexEx::ParametrizedTetMesh pm, std::size_t expectedHexes) {
    pm.mesh.build_adjacency();
    HexEx::HexMesh copied, taken;
    HexEx::ExtractionOptions one;
    one.threads = 1;
    const HexEx::ExtractionReport a = HexEx::extractHexMesh(pm, copied, one);
    const std::size_t cells = pm.mesh.n_cells(), faces = pm.mesh.n_faces();
    HexEx::ExtractionOptions opt;
    opt.threads = 2;
    const HexEx::ExtractionReport b = HexEx::extractHexMesh(std::move(pm), taken, opt);
    EXPECT_TRUE(pm.params.empty());  // NOLINT(bugprone-use-after-move): what the overload promises
    EXPECT_EQ(pm.mesh.n_cells(), cells);
    EXPECT_EQ(pm.mesh.n_faces(), faces);
    EXPECT_TRUE(pm.mesh.has_adjacency());
    ASSERT_EQ(copied.hexes.size(), expectedHexes);
    EXPECT_EQ(copied.hexes, taken.hexes);
    EXPECT_EQ(copied.vertices, taken.vertices);
    EXPECT_EQ(copied.polyhedra.size(), taken.polyhedra.size());
    EXPECT_EQ(a.output.hexes, b.output.hexes);
}

} // namespace

TEST(ExtractTakingParameters, CubeSameAsCopying) { checkSameAsCopying(HexEx::generateCube(3, 5), 125u); }

TEST(ExtractTakingParameters, SingularCylinderSameAsCopying) {
    HexEx::ParametrizedTetMesh pm = HexEx::generateCylinder(3, 2, 3, 1, 1);
    HexEx::ParametrizedTetMesh ref = pm;
    ref.mesh.build_adjacency();
    HexEx::HexMesh hm;
    HexEx::extractHexMesh(ref, hm);
    checkSameAsCopying(std::move(pm), hm.hexes.size());
}

TEST(ExtractTakingParameters, WrongParameterCountStillRefused) {
    HexEx::ParametrizedTetMesh pm = HexEx::generateCube(2, 2);
    pm.mesh.build_adjacency();
    pm.params.pop_back();
    HexEx::HexMesh hm;
    try {
        HexEx::extractHexMesh(std::move(pm), hm);
        FAIL() << "no error";
    } catch (const HexEx::InputError& e) {
        EXPECT_STREQ(e.what(), "extractHexMesh: one parameter set per tet required");
    }
}
