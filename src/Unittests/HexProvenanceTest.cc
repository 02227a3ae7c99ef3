// Provenance of the extracted hexes (ExtractionOptions::provenance): source tet and grid cell
// per hex, grid coordinates per vertex, checked against known maps.

#include <HexEx/Generators/Generators.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/IO/HexExFile.hh>

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <cmath>
#include <vector>

namespace {

using HexEx::Vec3d;

/// Barycentric coordinates of @p u in the tet with corners @p p (parameter space).
std::array<double, 4> barycentric(const std::array<Vec3d, 4>& p, const Vec3d& u) {
    const Vec3d a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0], r = u - p[0];
    const auto det = [](const Vec3d& x, const Vec3d& y, const Vec3d& z) {
        return x[0] * (y[1] * z[2] - y[2] * z[1]) - x[1] * (y[0] * z[2] - y[2] * z[0]) + x[2] * (y[0] * z[1] - y[1] * z[0]);
    };
    const double d = det(a, b, c);
    const double l1 = det(r, b, c) / d, l2 = det(a, r, c) / d, l3 = det(a, b, r) / d;
    return {1 - l1 - l2 - l3, l1, l2, l3};
}

bool inside(const std::array<double, 4>& l, double tolerance = 1e-9) {
    for (double x : l)
        if (x < -tolerance) return false;
    return true;
}

Vec3d toVec(const std::array<int, 3>& z) { return Vec3d(z[0], z[1], z[2]); }

HexEx::HexProvenance extract(const HexEx::ParametrizedTetMesh& pm, HexEx::HexMesh& hm, int threads, bool implicit,
                             HexEx::ExtractionReport* report = nullptr) {
    HexEx::HexProvenance prov;
    HexEx::ExtractionOptions opt;
    opt.threads = threads;
    opt.implicit_cells = implicit;
    opt.provenance = &prov;
    const HexEx::ExtractionReport rep = HexEx::extractHexMesh(pm, hm, opt);
    if (report) *report = rep;
    return prov;
}

/// On a cube with parameter = s x position (one chart), every hex's grid cell and source tet
/// contain the parameter of its centre, and every vertex's grid coordinates are s x position.
void checkCube(int n, int s, bool implicit, long expectImplicit) {
    HexEx::ParametrizedTetMesh pm = HexEx::generateCube(n, s);
    pm.mesh.build_adjacency();
    HexEx::HexMesh hm;
    HexEx::ExtractionReport rep;
    const HexEx::HexProvenance prov = extract(pm, hm, 1, implicit, &rep);
    ASSERT_EQ(hm.hexes.size(), std::size_t(s) * s * s);
    if (expectImplicit >= 0) {
        EXPECT_EQ(rep.darts.implicit_cells, expectImplicit);
    } else {
        EXPECT_GT(rep.darts.implicit_cells, 0);
    }
    ASSERT_EQ(prov.hex_source_tet.size(), hm.hexes.size());
    ASSERT_EQ(prov.hex_grid_cell.size(), hm.hexes.size());
    ASSERT_EQ(prov.vertex_grid_coords.size(), hm.vertices.size());
    for (std::size_t h = 0; h < hm.hexes.size(); ++h) {
        Vec3d centre(0, 0, 0);
        for (int v : hm.hexes[h]) centre += hm.vertices[static_cast<std::size_t>(v)];
        const Vec3d u = centre * (double(s) / 8);
        const auto& cell = prov.hex_grid_cell[h];
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(u[k], cell[static_cast<std::size_t>(k)] + 0.5, 1e-9) << "hex " << h;
        }
        const int t = prov.hex_source_tet[h];
        ASSERT_GE(t, 0);
        ASSERT_LT(std::size_t(t), pm.params.size());
        EXPECT_TRUE(inside(barycentric(pm.params[static_cast<std::size_t>(t)], u))) << "hex " << h << " tet " << t;
    }
    for (std::size_t v = 0; v < hm.vertices.size(); ++v) {
        const int t = prov.vertex_source_tet[v];
        ASSERT_GE(t, 0) << "vertex " << v;
        const Vec3d z = toVec(prov.vertex_grid_coords[v]);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(z[k], s * hm.vertices[v][k], 1e-9) << "vertex " << v;
        EXPECT_TRUE(inside(barycentric(pm.params[static_cast<std::size_t>(t)], z))) << "vertex " << v;
    }
}

TEST(HexProvenance, CubeFromDarts) { checkCube(3, 2, false, 0); }

TEST(HexProvenance, CubeWithImplicitCells) { checkCube(1, 6, true, -1); }

TEST(HexProvenance, OffByDefaultAndSameMesh) {
    HexEx::ParametrizedTetMesh pm = HexEx::generateCube(2, 3);
    pm.mesh.build_adjacency();
    HexEx::HexMesh plain, withProv;
    HexEx::extractHexMesh(pm, plain, HexEx::ExtractionOptions{});
    extract(pm, withProv, 0, true);
    EXPECT_EQ(plain.hexes, withProv.hexes);
    EXPECT_EQ(plain.vertices, withProv.vertices);
}

/// On a singular cylinder every hex vertex's grid coordinates lie in its source tet's image
/// and map back to its position through that tet's map; each hex's cell centre lies in its
/// source tet; the same for 1 and 2 threads.
TEST(HexProvenance, SingularCylinderMapsBack) {
    for (bool implicit : {false, true}) {
        HexEx::ParametrizedTetMesh pm = HexEx::generateCylinder(3, 4, 2, 2, 1);
        pm.mesh.build_adjacency();
        HexEx::HexMesh hm, hm2;
        const HexEx::HexProvenance prov = extract(pm, hm, 1, implicit);
        const HexEx::HexProvenance prov2 = extract(pm, hm2, 2, implicit);
        ASSERT_EQ(hm.hexes.size(), std::size_t(3 * 4 * 4 * 2));
        EXPECT_EQ(prov.hex_source_tet, prov2.hex_source_tet);
        EXPECT_EQ(prov.hex_grid_cell, prov2.hex_grid_cell);
        EXPECT_EQ(prov.vertex_source_tet, prov2.vertex_source_tet);
        EXPECT_EQ(prov.vertex_grid_coords, prov2.vertex_grid_coords);
        for (std::size_t v = 0; v < hm.vertices.size(); ++v) {
            const int t = prov.vertex_source_tet[v];
            ASSERT_GE(t, 0) << "vertex " << v;
            const auto& params = pm.params[static_cast<std::size_t>(t)];
            const std::array<double, 4> l = barycentric(params, toVec(prov.vertex_grid_coords[v]));
            EXPECT_TRUE(inside(l)) << "vertex " << v;
            Vec3d x(0, 0, 0);
            for (int i = 0; i < 4; ++i)
                x += pm.mesh.position(pm.mesh.cell_vertex(HexEx::CellHandle(t), i)) * l[static_cast<std::size_t>(i)];
            EXPECT_NEAR((x - hm.vertices[v]).norm(), 0, 1e-9) << "vertex " << v;
        }
        for (std::size_t h = 0; h < hm.hexes.size(); ++h) {
            const int t = prov.hex_source_tet[h];
            ASSERT_GE(t, 0);
            const Vec3d c = toVec(prov.hex_grid_cell[h]) + Vec3d(0.5, 0.5, 0.5);
            EXPECT_TRUE(inside(barycentric(pm.params[static_cast<std::size_t>(t)], c))) << "hex " << h;
        }
    }
}

/// The sphere example has tets of zero parametric volume, which the walk to the hex centres
/// crosses: every hex's cell centre lies in its source tet (up to the sanitizer's snapping).
TEST(HexProvenance, SphereWalksThroughFlatTets) {
    HexEx::ParametrizedTetMesh pm = HexEx::readHexExFile(std::string(HEXEX_SOURCE_DIR) + "/Examples/data/sphere.hexex");
    HexEx::HexMesh hm;
    HexEx::ExtractionReport rep;
    const HexEx::HexProvenance prov = extract(pm, hm, 2, true, &rep);
    ASSERT_EQ(hm.hexes.size(), 216u);
    EXPECT_GT(rep.input.degenerate_tets, 0);
    for (std::size_t h = 0; h < hm.hexes.size(); ++h) {
        const Vec3d c = toVec(prov.hex_grid_cell[h]) + Vec3d(0.5, 0.5, 0.5);
        EXPECT_TRUE(inside(barycentric(pm.params[std::size_t(prov.hex_source_tet[h])], c), 1e-5)) << "hex " << h;
    }
    for (std::size_t v = 0; v < hm.vertices.size(); ++v) {
        ASSERT_GE(prov.vertex_source_tet[v], 0);
        EXPECT_TRUE(inside(barycentric(pm.params[std::size_t(prov.vertex_source_tet[v])], toVec(prov.vertex_grid_coords[v])), 1e-5))
            << "vertex " << v;
    }
}

} // namespace
