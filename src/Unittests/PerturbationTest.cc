/// @file PerturbationTest.cc
/// Tests of perturbParameters(): constraints, reproducibility, chart consistency.

#include <HexEx/Generators/Generators.hh>
#include <HexEx/Generators/Perturbation.hh>
#include <HexEx/Preprocessing/Transitions.hh>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace HexEx;

namespace {

/// Local index of @p v in cell @p c.
int cornerIndex(const TetMesh& m, CellHandle c, VertexHandle v) {
    for (int k = 0; k < 4; ++k)
        if (m.cell_vertex(c, k) == v) return k;
    return -1;
}

} // namespace

TEST(PerturbationTest, CubeKeepsBoundaryPlanesAndCorners) {
    ParametrizedTetMesh pm = generateCube(3, 3);
    const ParametrizedTetMesh orig = pm;
    PerturbStats st;
    perturbParameters(pm, 0.3, 7, &st);
    EXPECT_EQ(st.vertices, 64u);
    EXPECT_EQ(st.fixed_vertices, 8u);
    EXPECT_EQ(st.boundary_vertices, 56u);
    EXPECT_EQ(st.singular_vertices, 0u);
    EXPECT_EQ(st.moved_vertices, 56u);  // all but the 8 corners
    EXPECT_LE(st.max_displacement, 0.3);
    EXPECT_GT(st.max_displacement, 0.0);

    int moved_edge_axes = 0, edge_vertex_coords = 0;
    for (std::size_t c = 0; c < pm.mesh.n_cells(); ++c) {
        const CellHandle ch(static_cast<int>(c));
        for (int i = 0; i < 4; ++i) {
            const Vec3d x = pm.mesh.position(pm.mesh.cell_vertex(ch, i));
            const Vec3d& p = pm.params[c][i];
            const Vec3d& q = orig.params[c][i];
            int planes = 0;
            for (int k = 0; k < 3; ++k) {
                EXPECT_LE(std::fabs(p[k] - q[k]), 0.3);
                if (x[k] == 0 || x[k] == 1) {
                    ++planes;
                    EXPECT_EQ(p[k], q[k]) << "boundary coordinate moved, cell " << c << " corner " << i;
                }
            }
            if (planes == 3) {
                EXPECT_EQ(p, q) << "corner moved";
            }
            if (planes == 2) {
                for (int k = 0; k < 3; ++k)
                    if (x[k] != 0 && x[k] != 1) {
                        ++edge_vertex_coords;
                        if (p[k] != q[k]) ++moved_edge_axes;
                    }
            }
        }
    }
    // Vertices on boundary edges still move along the edge.
    EXPECT_GT(edge_vertex_coords, 0);
    EXPECT_EQ(moved_edge_axes, edge_vertex_coords);
}

TEST(PerturbationTest, SameSeedSameOutputDifferentSeedDifferent) {
    ParametrizedTetMesh a = generateCube(3, 3), b = generateCube(3, 3), c = generateCube(3, 3);
    perturbParameters(a, 0.3, 42);
    perturbParameters(b, 0.3, 42);
    perturbParameters(c, 0.3, 43);
    EXPECT_EQ(a.params, b.params);
    EXPECT_NE(a.params, c.params);
}

TEST(PerturbationTest, ZeroAmplitudeIsIdentity) {
    ParametrizedTetMesh pm = generateCube(2, 2);
    const ParametrizedTetMesh orig = pm;
    PerturbStats st;
    perturbParameters(pm, 0.0, 3, &st);
    EXPECT_EQ(pm.params, orig.params);
    EXPECT_EQ(st.moved_vertices, 0u);
}

TEST(PerturbationTest, RejectsBadAmplitude) {
    ParametrizedTetMesh pm = generateCube(1, 1);
    EXPECT_THROW(perturbParameters(pm, -0.1, 1), std::invalid_argument);
    EXPECT_THROW(perturbParameters(pm, std::nan(""), 1), std::invalid_argument);
    EXPECT_THROW(perturbParameters(pm, INFINITY, 1), std::invalid_argument);
}

TEST(PerturbationTest, ConsistentAcrossCharts) {
    ParametrizedTetMesh pm = generateCube(3, 3);
    applyRandomChartTransforms(pm, 5);
    pm.mesh.build_adjacency();
    const Transitions before = computeTransitions(pm.mesh, pm.params);
    const ParametrizedTetMesh orig = pm;
    PerturbStats st;
    perturbParameters(pm, 0.3, 11, &st);
    EXPECT_EQ(st.fixed_vertices, 8u);
    EXPECT_EQ(st.moved_vertices, 56u);
    const TetMesh& m = pm.mesh;
    for (std::size_t h = 0; h < m.n_halffaces(); ++h) {
        const HalfFaceHandle hf(static_cast<int>(h));
        const HalfFaceHandle o = m.opposite_halfface(hf);
        if (!o.is_valid()) continue;
        const CellHandle a = TetMesh::cell(hf), b = TetMesh::cell(o);
        const GridTransform& T = before.halfface[h];
        for (const VertexHandle v : m.halfface_vertices(hf)) {
            const Vec3d pa = pm.params[a.uidx()][cornerIndex(m, a, v)];
            const Vec3d pb = pm.params[b.uidx()][cornerIndex(m, b, v)];
            EXPECT_LE((T.apply(pa) - pb).norm(), 1e-12) << "halfface " << h;
        }
    }
    // The transitions themselves are unchanged.
    const Transitions after = computeTransitions(pm.mesh, pm.params);
    for (std::size_t h = 0; h < m.n_halffaces(); ++h) EXPECT_EQ(after.halfface[h], before.halfface[h]);
    // Boundary planes still hold in every chart: each boundary face keeps the constant
    // coordinates it had.
    for (std::size_t h = 0; h < m.n_halffaces(); ++h) {
        const HalfFaceHandle hf(static_cast<int>(h));
        if (!m.is_boundary(hf)) continue;
        const std::size_t c = static_cast<std::size_t>(TetMesh::cell(hf).idx());
        const int* fc = TetMesh::kFaceCorners[TetMesh::opposite_corner(hf)];
        for (int k = 0; k < 3; ++k) {
            const double x = orig.params[c][fc[0]][k];
            if (orig.params[c][fc[1]][k] != x || orig.params[c][fc[2]][k] != x) continue;
            for (int j = 0; j < 3; ++j) EXPECT_EQ(pm.params[c][fc[j]][k], x);
        }
    }
}

TEST(PerturbationTest, SingularAxisMovesOnlyAlongItself) {
    ParametrizedTetMesh pm = generateCylinder(3, 2, 3, 2, 3);
    pm.mesh.build_adjacency();
    const ParametrizedTetMesh orig = pm;
    PerturbStats st;
    perturbParameters(pm, 0.3, 9, &st);
    EXPECT_GT(st.singular_vertices, 0u);
    int axis_interior = 0, axis_moved = 0;
    for (std::size_t c = 0; c < pm.mesh.n_cells(); ++c) {
        const CellHandle ch(static_cast<int>(c));
        for (int i = 0; i < 4; ++i) {
            const Vec3d& q = orig.params[c][i];
            const Vec3d& p = pm.params[c][i];
            if (q[0] != 0 || q[1] != 0) continue;  // not on the axis (a = b = 0)
            EXPECT_EQ(p[0], 0.0);
            EXPECT_EQ(p[1], 0.0);
            const bool cap = q[2] == 0 || q[2] == 3;
            if (cap) {
                EXPECT_EQ(p[2], q[2]);
            } else {
                ++axis_interior;
                if (p[2] != q[2]) ++axis_moved;
                EXPECT_LE(std::fabs(p[2] - q[2]), 0.3);
            }
        }
    }
    EXPECT_GT(axis_interior, 0);
    EXPECT_EQ(axis_moved, axis_interior);
}
