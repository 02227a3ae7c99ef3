/// @file QuadCompactTypesTest.cc
/// The compact types of the 2D pipeline against the general ones they replace:
/// PlanarTransform against GridTransform with a planar rotation (bit for bit, signed zeros
/// included), TriTransitions::at() against the transitions it encodes, and
/// validateQuadLinks() against validateQuadGMap() on the same map.

#include <HexEx/GMap/GMap.hh>
#include <HexEx/Grid/GridTransform.hh>
#include <HexEx/Grid/PlanarRotation.hh>
#include <HexEx/Quad/PlanarTransform.hh>
#include <HexEx/Quad/QuadGMapValidator.hh>
#include <HexEx/Quad/QuadGenerators.hh>
#include <HexEx/Quad/TrianglePreprocessing.hh>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

using namespace HexEx;

namespace {
/// The same double, bit for bit (so -0.0 differs from 0.0).
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

PlanarTransform planar(int k, int tu, int tv) {
    PlanarTransform t;
    t.k = k;
    t.tu = tu;
    t.tv = tv;
    return t;
}
} // namespace

TEST(QuadCompactTypes, PlanarTransformMatchesGridTransform) {
    std::mt19937 rng(7);
    const double values[] = {0.0, -0.0, 1.0, -2.5, 0.1, 1e9, -3.75};
    for (int k = 0; k < 4; ++k)
        for (int tu : {0, 3, -7})
            for (int tv : {0, -1, 12}) {
                const PlanarTransform p = planar(k, tu, tv);
                const GridTransform g(planarRotation(k), Vec3i(tu, tv, 0));
                EXPECT_EQ(p.is_identity(), g.is_identity());
                for (double x : values)
                    for (double y : values) {
                        const Vec2d a = p.apply(Vec2d(x, y));
                        const Vec3d b = g.apply(Vec3d(x, y, 0));
                        EXPECT_TRUE(sameBits(a[0], b[0]) && sameBits(a[1], b[1])) << k << " " << x << " " << y;
                        const Vec2d r = p.rotate(Vec2d(x, y));
                        const Vec3d s = g.R.apply(Vec3d(x, y, 0));
                        EXPECT_TRUE(sameBits(r[0], s[0]) && sameBits(r[1], s[1]));
                    }
                for (AxisDir d = 0; d < 4; ++d) EXPECT_EQ(p.applyDir(d), g.applyDir(d));
                int x = 0, y = 0;
                p.apply(5, -9, x, y);
                EXPECT_EQ(Vec3i(x, y, 0), g.apply(Vec3i(5, -9, 0)));
                const PlanarTransform pi = p.inverse();
                const GridTransform gi = g.inverse();
                EXPECT_EQ(planarQuarterTurns(gi.R), pi.k);
                EXPECT_EQ(Vec3i(pi.tu, pi.tv, 0), gi.t);
                EXPECT_TRUE((p * pi).is_identity());
                for (int k2 = 0; k2 < 4; ++k2) {
                    const int u2 = static_cast<int>(rng() % 21) - 10, v2 = static_cast<int>(rng() % 21) - 10;
                    const PlanarTransform c = p * planar(k2, u2, v2);
                    const GridTransform h = g * GridTransform(planarRotation(k2), Vec3i(u2, v2, 0));
                    EXPECT_EQ(planarQuarterTurns(h.R), c.k);
                    EXPECT_EQ(Vec3i(c.tu, c.tv, 0), h.t);
                }
            }
}

TEST(QuadCompactTypes, TransitionsKeepSeamsOnly) {
    // The quarter-turn seam: interior edges across the seam carry a rotation, all others
    // the identity; random charts make every interior transition non-trivial.
    for (bool charts : {false, true}) {
        ParametrizedTriMesh m = generateQuarterTurnSeam(4, 4);
        if (charts) applyRandomTriCharts(m, 3);
        const TriAdjacency adj = buildTriAdjacency(m);
        const TriParams params(m.params.begin(), m.params.end());
        const TriTransitions tr = computeTriTransitions(m, adj, params, nullptr, 2);
        ASSERT_EQ(tr.kind.size(), adj.opposite.size());
        ASSERT_EQ(tr.seam.size(), tr.seam_transform.size());
        long nonIdentity = 0;
        for (std::size_t h = 0; h < adj.opposite.size(); ++h) {
            const PlanarTransform t = tr.at(h);
            EXPECT_EQ(t.is_identity(), tr.is_identity(h));
            EXPECT_EQ(t.k, tr.kind[h] & 3);
            const int o = adj.opposite[h];
            if (o < 0) {
                EXPECT_TRUE(t.is_identity());
                continue;
            }
            EXPECT_TRUE((t * tr.at(static_cast<std::size_t>(o))).is_identity());
            nonIdentity += t.is_identity() ? 0 : 1;
            // The transition maps this triangle's corners onto the neighbour's (exact map).
            const std::size_t f = h / 3, g = static_cast<std::size_t>(o) / 3;
            for (int c = 0; c < 3; ++c)
                for (int j = 0; j < 3; ++j)
                    if (m.triangles[f][static_cast<std::size_t>(c)] == m.triangles[g][static_cast<std::size_t>(j)] &&
                        c != static_cast<int>(h % 3)) {
                        const Vec2d w = t.apply(params[f][static_cast<std::size_t>(c)]);
                        EXPECT_EQ(w, params[g][static_cast<std::size_t>(j)]);
                    }
        }
        EXPECT_EQ(static_cast<long>(tr.seam.size()), nonIdentity);
        EXPECT_GT(nonIdentity, 0);
        if (charts) {
            EXPECT_GT(nonIdentity, static_cast<long>(adj.opposite.size()) / 2);
        }
    }
}

TEST(QuadCompactTypes, LinksValidatorMatchesGMapValidator) {
    // A 2 x 1 strip of quads: 16 darts, alpha_2 linking the shared edge, the rest free.
    QuadLinks links(16);
    for (int q = 0; q < 2; ++q)
        for (int k = 0; k < 8; ++k) {
            const int d = 8 * q + k;
            links[static_cast<std::size_t>(d)] = {k % 2 == 0 ? d + 1 : d - 1, k % 2 == 1 ? 8 * q + (k + 1) % 8 : 8 * q + (k + 7) % 8, d};
        }
    // Edge of darts 2,3 (quad 0) glued to the edge of darts 15,14 (quad 1).
    links[2][2] = 15;
    links[15][2] = 2;
    links[3][2] = 14;
    links[14][2] = 3;
    GMap<2> g;
    g.assign_links(std::vector<std::array<int, 3>>(links.begin(), links.end()));
    for (int threads : {1, 2}) {
        QuadOrbitLabels a, b;
        const QuadGMapValidation va = validateQuadLinks(links, &a, threads);
        const QuadGMapValidation vb = validateQuadGMap(g, &b, threads);
        EXPECT_TRUE(va.valid()) << va.summary();
        EXPECT_EQ(va.summary(), vb.summary());
        EXPECT_EQ(va.darts, 16);
        EXPECT_EQ(va.boundary_darts, 12);
        EXPECT_EQ(a.n_faces, 2);
        EXPECT_EQ(a.n_vertices, 6);
        EXPECT_EQ(a.n_edges, 7);
        EXPECT_EQ(a.n_faces, b.n_faces);
        EXPECT_EQ(a.n_vertices, b.n_vertices);
        EXPECT_EQ(a.n_edges, b.n_edges);
        EXPECT_TRUE(std::equal(a.face.begin(), a.face.end(), b.face.begin(), b.face.end()));
        EXPECT_TRUE(std::equal(a.vertex.begin(), a.vertex.end(), b.vertex.begin(), b.vertex.end()));
        EXPECT_TRUE(std::equal(a.edge.begin(), a.edge.end(), b.edge.begin(), b.edge.end()));
    }
    // An erased dart in the GMap gets label -1 in every labelling.
    g.erase(DartHandle(5));
    QuadOrbitLabels c;
    const QuadGMapValidation vc = validateQuadGMap(g, &c, 2);
    EXPECT_FALSE(vc.valid());
    EXPECT_EQ(vc.darts, 15);
    EXPECT_EQ(c.face[5], -1);
    EXPECT_EQ(c.vertex[5], -1);
    EXPECT_EQ(c.edge[5], -1);
}
