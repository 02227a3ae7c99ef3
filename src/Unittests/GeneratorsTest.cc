#include <HexEx/Generators/Generators.hh>
#include <HexEx/Predicates/ExactPredicates.hh>

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <stdexcept>

using namespace HexEx;

namespace {

/// Number of tets that are not strictly positive in 3D (first) and in parameter space (second).
std::pair<int, int> countNonPositive(const ParametrizedTetMesh& pm) {
    int bad3d = 0, badParam = 0;
    for (std::size_t c = 0; c < pm.mesh.n_cells(); ++c) {
        const auto& cv = pm.mesh.cell_vertices(CellHandle(static_cast<int>(c)));
        const auto& m = pm.mesh;
        if (orient3d(m.position(cv[0]), m.position(cv[1]), m.position(cv[2]), m.position(cv[3])) <= 0) ++bad3d;
        const auto& q = pm.params[c];
        if (orient3d(q[0], q[1], q[2], q[3]) <= 0) ++badParam;
    }
    return {bad3d, badParam};
}

/// The grid automorphism mapping each p[i] to q[i] (within @p tol), if any.
std::optional<GridTransform> findTransform(const Vec3d* p, const Vec3d* q, int count, double tol = 1e-9) {
    std::optional<GridTransform> found;
    for (int r = 0; r < Rotation::kCount; ++r) {
        const Rotation R(r);
        const Vec3d rp = R.apply(p[0]);
        Vec3i t;
        bool ok = true;
        for (int d = 0; d < 3; ++d) {
            const double td = q[0][d] - rp[d];
            t[d] = static_cast<int>(std::lround(td));
            if (std::abs(td - t[d]) > tol) ok = false;
        }
        if (!ok) continue;
        const GridTransform g(R, t);
        for (int i = 1; i < count && ok; ++i)
            if ((g.apply(p[i]) - q[i]).norm() > tol) ok = false;
        if (!ok) continue;
        if (found) return std::nullopt;  // ambiguous
        found = g;
    }
    return found;
}

/// Transition from the chart of cell(hf) into the chart of the neighbour across hf,
/// computed from the parameters of the three shared vertices.
GridTransform transitionAcross(const ParametrizedTetMesh& pm, HalfFaceHandle hf) {
    const TetMesh& m = pm.mesh;
    const HalfFaceHandle opp = m.opposite_halfface(hf);
    const CellHandle a = TetMesh::cell(hf), b = TetMesh::cell(opp);
    Vec3d p[3], q[3];
    for (int k = 0; k < 3; ++k) {
        const int ca = TetMesh::kFaceCorners[TetMesh::opposite_corner(hf)][k];
        const VertexHandle v = m.cell_vertex(a, ca);
        int cb = 0;
        while (m.cell_vertex(b, cb) != v) ++cb;
        p[k] = pm.params[a.uidx()][ca];
        q[k] = pm.params[b.uidx()][cb];
    }
    auto g = findTransform(p, q, 3);
    if (!g) throw std::runtime_error("no grid transition across halfface " + std::to_string(hf.idx()));
    return *g;
}

/// The halfface of cell @p c across which cell @p next lies and which contains edge @p e.
HalfFaceHandle sharedHalfface(const TetMesh& m, CellHandle c, CellHandle next, EdgeHandle e) {
    const auto ev = m.edge_vertices(e);
    for (int j = 0; j < 4; ++j) {
        const HalfFaceHandle hf = TetMesh::halfface(c, j);
        if (m.is_boundary(hf) || TetMesh::cell(m.opposite_halfface(hf)) != next) continue;
        const auto fv = m.halfface_vertices(hf);
        int hits = 0;
        for (auto v : fv) hits += (v == ev[0] || v == ev[1]) ? 1 : 0;
        if (hits == 2) return hf;
    }
    return HalfFaceHandle();
}

/// The accumulated transition once around interior edge @p e, starting in its first cell.
GridTransform edgeHolonomy(const ParametrizedTetMesh& pm, EdgeHandle e) {
    const auto range = pm.mesh.edge_cells(e);
    const int n = static_cast<int>(range.second - range.first);
    GridTransform acc;
    for (int i = 0; i < n; ++i) {
        const CellHandle c(range.first[i]), next(range.first[(i + 1) % n]);
        const HalfFaceHandle hf = sharedHalfface(pm.mesh, c, next, e);
        if (!hf.is_valid()) throw std::runtime_error("edge ring not cyclic");
        acc = transitionAcross(pm, hf) * acc;
    }
    return acc;
}

/// Checks adjacency, manifoldness and the Euler characteristic V - E + F - C.
void checkTopology(ParametrizedTetMesh& pm, int euler) {
    ASSERT_NO_THROW(pm.mesh.build_adjacency());
    EXPECT_EQ(pm.mesh.check_manifold(), "");
    const TetMesh& m = pm.mesh;
    EXPECT_EQ(2 * m.n_faces(), 4 * m.n_cells() + m.n_boundary_faces());
    const long long chi = static_cast<long long>(m.n_vertices()) - static_cast<long long>(m.n_edges()) +
                          static_cast<long long>(m.n_faces()) - static_cast<long long>(m.n_cells());
    EXPECT_EQ(chi, euler);
}

/// The quarter turn (a,b,h) -> (b,-a,h) of the cylinder's gluing.
Rotation quarterTurnZ() { return Rotation(Rotation::fromColumns({makeDir(1, -1), makeDir(0, 1), makeDir(2, 1)})); }

} // namespace

TEST(Generators, CubeCountsVolumeOrientation) {
    for (int n : {1, 2, 3, 5}) {
        for (int s : {1, 2, 3, 4, 7}) {
            SCOPED_TRACE("n=" + std::to_string(n) + " s=" + std::to_string(s));
            ParametrizedTetMesh pm = generateCube(n, s);
            EXPECT_EQ(pm.mesh.n_cells(), 6u * n * n * n);
            EXPECT_EQ(pm.mesh.n_vertices(), static_cast<std::size_t>((n + 1) * (n + 1) * (n + 1)));
            EXPECT_EQ(pm.params.size(), pm.mesh.n_cells());
            EXPECT_NEAR(totalParametricVolume(pm), double(s) * s * s, 1e-9);
            EXPECT_EQ(countNonPositive(pm), std::make_pair(0, 0));
            checkTopology(pm, 1);
            EXPECT_EQ(pm.mesh.n_boundary_faces(), 12u * n * n);
            // Identity transitions everywhere.
            for (std::size_t hf = 0; hf < pm.mesh.n_halffaces(); ++hf)
                if (!pm.mesh.is_boundary(HalfFaceHandle(static_cast<int>(hf)))) {
                    EXPECT_TRUE(transitionAcross(pm, HalfFaceHandle(static_cast<int>(hf))).is_identity());
                }
        }
    }
}

TEST(Generators, InvalidArgumentsThrow) {
    EXPECT_THROW(generateCube(0, 1), std::invalid_argument);
    EXPECT_THROW(generateCylinder(2, 1, 1, 1, 1), std::invalid_argument);
    EXPECT_THROW(generateRing(4, 1, 1, 2, 1, 1), std::invalid_argument);
    EXPECT_THROW(generateTwistedRing(4, 1, 4, 3), std::invalid_argument);
}

TEST(Generators, CylinderCountsVolumeOrientation) {
    for (int k : {3, 4, 5, 6}) {
        for (int n : {1, 2, 3, 4, 8}) {
            for (int R : {1, 2, 3}) {
                const int H = 2, m = (n % 2) + 1;
                SCOPED_TRACE("k=" + std::to_string(k) + " n=" + std::to_string(n) + " R=" + std::to_string(R));
                ParametrizedTetMesh pm = generateCylinder(k, R, H, n, m);
                EXPECT_EQ(pm.mesh.n_cells(), 6u * k * n * n * m);
                EXPECT_EQ(pm.mesh.n_vertices(), static_cast<std::size_t>((m + 1) * (1 + k * n * (n + 1))));
                EXPECT_NEAR(totalParametricVolume(pm), double(k) * R * R * H, 1e-9);
                EXPECT_EQ(countNonPositive(pm), std::make_pair(0, 0));
                checkTopology(pm, 1);
                EXPECT_EQ(pm.mesh.n_boundary_faces(), 4u * k * n * m + 4u * k * n * n);
            }
        }
    }
}

TEST(Generators, CylinderBenchmarkSizeIsValid) {
    // "R = H = 64, each wedge one box of 6 tets".
    for (int k : {3, 4, 5, 6}) {
        ParametrizedTetMesh pm = generateCylinder(k, 64, 64, 1, 1);
        EXPECT_EQ(pm.mesh.n_cells(), 6u * k);
        EXPECT_NEAR(totalParametricVolume(pm), double(k) * 64 * 64 * 64, 1e-6);
        EXPECT_EQ(countNonPositive(pm), std::make_pair(0, 0));
        checkTopology(pm, 1);
    }
}

/// Walks every interior edge: the accumulated transition is a rotation by k*90 degrees about
/// the axis for axis edges and the identity elsewhere. Run with and without random charts.
TEST(Generators, CylinderHolonomyAroundAxis) {
    for (bool randomCharts : {false, true}) {
        for (int k : {3, 4, 5, 6}) {
            for (int n : {1, 2, 3}) {
                SCOPED_TRACE("k=" + std::to_string(k) + " n=" + std::to_string(n) + " random=" + std::to_string(randomCharts));
                const int m = 2;
                ParametrizedTetMesh pm = generateCylinder(k, 2, 2, n, m);
                if (randomCharts) applyRandomChartTransforms(pm, 17u * k + n);
                pm.mesh.build_adjacency();
                const TetMesh& mesh = pm.mesh;
                Rotation expected;
                for (int i = 0; i < k; ++i) expected = quarterTurnZ() * expected;
                const int expectedClass = (k % 4 == 0) ? 0 : (k % 2 == 0) ? 2 : 1;
                int axisEdges = 0;
                for (std::size_t e = 0; e < mesh.n_edges(); ++e) {
                    const EdgeHandle eh(static_cast<int>(e));
                    if (mesh.is_boundary(eh)) continue;
                    const GridTransform T = edgeHolonomy(pm, eh);
                    const auto ev = mesh.edge_vertices(eh);
                    const bool onAxis = ev[0].idx() <= m && ev[1].idx() <= m;  // axis vertices come first
                    if (!onAxis) {
                        EXPECT_TRUE(T.is_identity()) << "edge " << e;
                        continue;
                    }
                    ++axisEdges;
                    const auto range = mesh.edge_cells(eh);
                    EXPECT_EQ(range.second - range.first, 2 * k) << "two tets per wedge around an axis edge";
                    EXPECT_EQ(T.R.angleClass(), expectedClass);
                    EXPECT_EQ(T.is_identity(), k == 4);
                    // T fixes the edge (its rotation axis) in the first cell's chart.
                    const CellHandle c0(range.first[0]);
                    for (auto v : ev) {
                        int corner = 0;
                        while (mesh.cell_vertex(c0, corner) != v) ++corner;
                        const Vec3d x = pm.params[c0.uidx()][corner];
                        EXPECT_EQ(T.apply(x), x);
                    }
                    if (!randomCharts) {
                        EXPECT_TRUE(T.R == expected || T.R == expected.inverse());
                        EXPECT_EQ(T.t, Vec3i(0, 0, 0));
                    }
                }
                EXPECT_EQ(axisEdges, m);
            }
        }
    }
}

TEST(Generators, RingIsClosedAcrossSeam) {
    for (int nu : {3, 4, 7}) {
        for (int nv : {1, 2, 3}) {
            const int L = 5, W = 2, H = 3, nw = 2;
            SCOPED_TRACE("nu=" + std::to_string(nu) + " nv=" + std::to_string(nv));
            ParametrizedTetMesh pm = generateRing(L, W, H, nu, nv, nw);
            EXPECT_EQ(pm.mesh.n_cells(), 6u * nu * nv * nw);
            EXPECT_EQ(pm.mesh.n_vertices(), static_cast<std::size_t>(nu * (nv + 1) * (nw + 1)));
            EXPECT_NEAR(totalParametricVolume(pm), double(L) * W * H, 1e-9);
            EXPECT_EQ(countNonPositive(pm), std::make_pair(0, 0));
            checkTopology(pm, 0);  // solid torus
            EXPECT_EQ(pm.mesh.n_boundary_faces(), 4u * nu * (nv + nw));
            int seam = 0;
            for (std::size_t hf = 0; hf < pm.mesh.n_halffaces(); ++hf) {
                const HalfFaceHandle h(static_cast<int>(hf));
                if (pm.mesh.is_boundary(h)) continue;
                const GridTransform g = transitionAcross(pm, h);
                if (g.is_identity()) continue;
                ++seam;
                EXPECT_TRUE(g.R.is_identity());
                EXPECT_TRUE(g.t == Vec3i(L, 0, 0) || g.t == Vec3i(-L, 0, 0));
            }
            EXPECT_EQ(seam, 2 * 2 * nv * nw);  // both halffaces of each seam triangle
            for (std::size_t e = 0; e < pm.mesh.n_edges(); ++e)
                if (!pm.mesh.is_boundary(EdgeHandle(static_cast<int>(e)))) {
                    EXPECT_TRUE(edgeHolonomy(pm, EdgeHandle(static_cast<int>(e))).is_identity());
                }
        }
    }
}

TEST(Generators, TwistedRingSeamIsQuarterTurn) {
    for (int nu : {3, 4, 6}) {
        for (int nv : {2, 4}) {
            for (int W : {1, 2, 3}) {
                const int L = 4;
                SCOPED_TRACE("nu=" + std::to_string(nu) + " nv=" + std::to_string(nv) + " W=" + std::to_string(W));
                ParametrizedTetMesh pm = generateTwistedRing(L, W, nu, nv);
                EXPECT_EQ(pm.mesh.n_cells(), 6u * nu * nv * nv);
                EXPECT_NEAR(totalParametricVolume(pm), double(L) * W * W, 1e-9);
                EXPECT_EQ(countNonPositive(pm), std::make_pair(0, 0));
                checkTopology(pm, 0);
                EXPECT_EQ(pm.mesh.n_boundary_faces(), 8u * nu * nv);
                const GridTransform seamMap(
                    Rotation(Rotation::fromColumns({makeDir(0, 1), makeDir(2, 1), makeDir(1, -1)})), Vec3i(-L, W, 0));
                int seam = 0;
                for (std::size_t hf = 0; hf < pm.mesh.n_halffaces(); ++hf) {
                    const HalfFaceHandle h(static_cast<int>(hf));
                    if (pm.mesh.is_boundary(h)) continue;
                    const GridTransform g = transitionAcross(pm, h);
                    if (g.is_identity()) continue;
                    ++seam;
                    EXPECT_TRUE(g == seamMap || g == seamMap.inverse());
                    EXPECT_EQ(g.R.angleClass(), 1);
                }
                EXPECT_EQ(seam, 2 * 2 * nv * nv);
                for (std::size_t e = 0; e < pm.mesh.n_edges(); ++e)
                    if (!pm.mesh.is_boundary(EdgeHandle(static_cast<int>(e)))) {
                        EXPECT_TRUE(edgeHolonomy(pm, EdgeHandle(static_cast<int>(e))).is_identity());
                    }
            }
        }
    }
}

TEST(Generators, RandomChartTransformsAreGridAutomorphisms) {
    ParametrizedTetMesh original = generateCube(3, 6);  // params are multiples of 2: exact
    ParametrizedTetMesh pm = generateCube(3, 6);
    const std::vector<GridTransform> applied = applyRandomChartTransforms(pm, 42);
    ASSERT_EQ(applied.size(), pm.mesh.n_cells());
    int nonIdentity = 0;
    std::array<int, 24> rotationsSeen{};
    for (std::size_t c = 0; c < pm.params.size(); ++c) {
        for (int i = 0; i < 4; ++i) EXPECT_EQ(pm.params[c][i], applied[c].apply(original.params[c][i]));
        auto g = findTransform(original.params[c].data(), pm.params[c].data(), 4, 0.0);
        ASSERT_TRUE(g.has_value());
        EXPECT_EQ(*g, applied[c]);
        for (int d = 0; d < 3; ++d) {
            EXPECT_LE(applied[c].t[d], 5);
            EXPECT_GE(applied[c].t[d], -5);
        }
        nonIdentity += applied[c].is_identity() ? 0 : 1;
        ++rotationsSeen[applied[c].R.index()];
    }
    EXPECT_GT(nonIdentity, static_cast<int>(pm.params.size()) - 5);
    for (int r = 0; r < 24; ++r) EXPECT_GT(rotationsSeen[r], 0) << "rotation " << r << " never drawn";
    EXPECT_NEAR(totalParametricVolume(pm), 216.0, 1e-9);
    EXPECT_EQ(countNonPositive(pm), std::make_pair(0, 0));
    // Deterministic for a seed, different for another seed.
    ParametrizedTetMesh again = generateCube(3, 6);
    EXPECT_EQ(applyRandomChartTransforms(again, 42), applied);
    EXPECT_EQ(again.params, pm.params);
    ParametrizedTetMesh other = generateCube(3, 6);
    EXPECT_NE(applyRandomChartTransforms(other, 43), applied);
    // Transitions across interior faces are now non-trivial but still grid automorphisms,
    // and each equals applied[b] * applied[a]^-1.
    pm.mesh.build_adjacency();
    for (std::size_t hf = 0; hf < pm.mesh.n_halffaces(); ++hf) {
        const HalfFaceHandle h(static_cast<int>(hf));
        if (pm.mesh.is_boundary(h)) continue;
        const std::size_t a = TetMesh::cell(h).uidx(), b = TetMesh::cell(pm.mesh.opposite_halfface(h)).uidx();
        EXPECT_EQ(transitionAcross(pm, h), applied[b] * applied[a].inverse());
    }
}

TEST(Generators, RandomChartTransformsKeepRingHolonomyTrivial) {
    ParametrizedTetMesh ring = generateTwistedRing(4, 2, 4, 2);
    applyRandomChartTransforms(ring, 7);
    EXPECT_NEAR(totalParametricVolume(ring), 16.0, 1e-9);
    EXPECT_EQ(countNonPositive(ring), std::make_pair(0, 0));
    ring.mesh.build_adjacency();
    for (std::size_t e = 0; e < ring.mesh.n_edges(); ++e)
        if (!ring.mesh.is_boundary(EdgeHandle(static_cast<int>(e)))) {
            EXPECT_TRUE(edgeHolonomy(ring, EdgeHandle(static_cast<int>(e))).is_identity());
        }
}

TEST(Generators, ParameterNoiseKeepsBoundaryPlanes) {
    const double a = 1e-11;
    ParametrizedTetMesh original = generateCube(3, 4);
    ParametrizedTetMesh pm = generateCube(3, 4);
    applyRandomChartTransforms(original, 5);
    applyRandomChartTransforms(pm, 5);
    applyParameterNoise(pm, a, 99);
    ASSERT_TRUE(pm.mesh.has_adjacency());
    int changed = 0, kept = 0;
    for (std::size_t c = 0; c < pm.params.size(); ++c) {
        bool onPlane[4][3] = {};
        for (int j = 0; j < 4; ++j) {
            const HalfFaceHandle hf = TetMesh::halfface(CellHandle(static_cast<int>(c)), j);
            if (!pm.mesh.is_boundary(hf)) continue;
            const int* f = TetMesh::kFaceCorners[j];
            const auto& q = original.params[c];
            int planes = 0;
            for (int d = 0; d < 3; ++d)
                if (q[f[0]][d] == q[f[1]][d] && q[f[1]][d] == q[f[2]][d]) {
                    ++planes;
                    for (int k = 0; k < 3; ++k) onPlane[f[k]][d] = true;
                    // The boundary face is still exactly on its plane.
                    const auto& p = pm.params[c];
                    EXPECT_EQ(p[f[0]][d], q[f[0]][d]);
                    EXPECT_EQ(p[f[1]][d], q[f[0]][d]);
                    EXPECT_EQ(p[f[2]][d], q[f[0]][d]);
                }
            EXPECT_EQ(planes, 1) << "cube boundary faces lie in exactly one grid plane";
        }
        for (int i = 0; i < 4; ++i)
            for (int d = 0; d < 3; ++d) {
                const double diff = pm.params[c][i][d] - original.params[c][i][d];
                EXPECT_LE(std::abs(diff), a * 1.000001);
                if (onPlane[i][d]) {
                    EXPECT_EQ(diff, 0.0);
                    ++kept;
                } else {
                    changed += diff != 0.0 ? 1 : 0;
                }
            }
    }
    EXPECT_GT(kept, 0);
    EXPECT_GT(changed, 0);
    EXPECT_NEAR(totalParametricVolume(pm), 64.0, 1e-6);
    // Deterministic for a seed.
    ParametrizedTetMesh again = generateCube(3, 4);
    applyRandomChartTransforms(again, 5);
    applyParameterNoise(again, a, 99);
    EXPECT_EQ(again.params, pm.params);
    ParametrizedTetMesh other = generateCube(3, 4);
    applyRandomChartTransforms(other, 5);
    applyParameterNoise(other, a, 100);
    EXPECT_NE(other.params, pm.params);
}

TEST(Generators, TetVolume) {
    const Vec3d o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    EXPECT_DOUBLE_EQ(tetVolume(o, x, y, z), 1.0 / 6.0);
    EXPECT_DOUBLE_EQ(tetVolume(o, y, x, z), -1.0 / 6.0);
    EXPECT_EQ(tetVolume(o, x, y, x + y), 0.0);
}
