#include <HexEx/Core/Error.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/Mesh/TetMesh.hh>

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>

using namespace HexEx;

namespace {

/// A cube mesh with adjacency built.
TetMesh cubeMesh(int n) {
    TetMesh m = generateCube(n, 1).mesh;
    m.build_adjacency();
    return m;
}

/// True if all three vertices of halfface @p hf are among @p vs.
bool halffaceContains(const TetMesh& m, HalfFaceHandle hf, std::initializer_list<VertexHandle> vs) {
    const auto fv = m.halfface_vertices(hf);
    for (auto v : vs)
        if (std::find(fv.begin(), fv.end(), v) == fv.end()) return false;
    return true;
}

/// True if @p p lies on the boundary of the unit cube.
bool onUnitCubeBoundary(const Vec3d& p) {
    for (int d = 0; d < 3; ++d)
        if (p[d] == 0.0 || p[d] == 1.0) return true;
    return false;
}

/// True if all points share a boundary plane of the unit cube.
bool onCommonCubeFace(std::initializer_list<Vec3d> ps) {
    for (int d = 0; d < 3; ++d)
        for (double plane : {0.0, 1.0}) {
            bool all = true;
            for (const auto& p : ps) all = all && p[d] == plane;
            if (all) return true;
        }
    return false;
}

/// A mesh made of the given tets over vertices with the given positions (no adjacency yet).
TetMesh makeMesh(const std::vector<Vec3d>& pts, const std::vector<std::array<int, 4>>& tets) {
    TetMesh m;
    for (const auto& p : pts) m.add_vertex(p);
    for (const auto& t : tets) m.add_cell({VertexHandle(t[0]), VertexHandle(t[1]), VertexHandle(t[2]), VertexHandle(t[3])});
    return m;
}

} // namespace

TEST(TetMesh, OppositeHalffaceSymmetry) {
    for (int n : {1, 2, 4}) {
        const TetMesh m = cubeMesh(n);
        ASSERT_TRUE(m.has_adjacency());
        for (std::size_t i = 0; i < m.n_halffaces(); ++i) {
            const HalfFaceHandle hf(static_cast<int>(i));
            if (m.is_boundary(hf)) {
                EXPECT_FALSE(m.opposite_halfface(hf).is_valid());
                continue;
            }
            const HalfFaceHandle opp = m.opposite_halfface(hf);
            ASSERT_TRUE(opp.is_valid());
            EXPECT_EQ(m.opposite_halfface(opp), hf);
            EXPECT_NE(TetMesh::cell(opp), TetMesh::cell(hf));
            EXPECT_EQ(m.face(opp), m.face(hf));
            // Same triangle, opposite orientation.
            auto a = m.halfface_vertices(hf), b = m.halfface_vertices(opp);
            std::reverse(b.begin(), b.end());
            while (b[0] != a[0]) std::rotate(b.begin(), b.begin() + 1, b.end());
            EXPECT_EQ(a, b);
        }
    }
}

TEST(TetMesh, HalffaceIndexing) {
    const CellHandle c(7);
    for (int i = 0; i < 4; ++i) {
        const HalfFaceHandle hf = TetMesh::halfface(c, i);
        EXPECT_EQ(hf.idx(), 4 * 7 + i);
        EXPECT_EQ(TetMesh::cell(hf), c);
        EXPECT_EQ(TetMesh::opposite_corner(hf), i);
    }
}

TEST(TetMesh, FaceAndEdgeCounts) {
    for (int n : {1, 2, 3, 5}) {
        const TetMesh m = cubeMesh(n);
        EXPECT_EQ(m.n_cells(), 6u * n * n * n);
        EXPECT_EQ(m.n_boundary_faces(), 12u * n * n);
        EXPECT_EQ(2 * m.n_faces(), 4 * m.n_cells() + m.n_boundary_faces());
        // Euler characteristic of a ball.
        EXPECT_EQ(static_cast<long long>(m.n_vertices()) - static_cast<long long>(m.n_edges()) +
                      static_cast<long long>(m.n_faces()) - static_cast<long long>(m.n_cells()),
                  1);
        // Faces list their halffaces consistently.
        std::size_t boundary = 0;
        for (std::size_t f = 0; f < m.n_faces(); ++f) {
            const FaceHandle fh(static_cast<int>(f));
            const auto hfs = m.face_halffaces(fh);
            ASSERT_TRUE(hfs[0].is_valid());
            EXPECT_EQ(m.face(hfs[0]), fh);
            EXPECT_EQ(m.is_boundary(fh), !hfs[1].is_valid());
            if (hfs[1].is_valid()) {
                EXPECT_EQ(m.face(hfs[1]), fh);
                EXPECT_EQ(m.opposite_halfface(hfs[0]), hfs[1]);
            } else {
                ++boundary;
            }
        }
        EXPECT_EQ(boundary, m.n_boundary_faces());
        EXPECT_EQ(m.check_manifold(), "");
    }
}

TEST(TetMesh, EdgesAndFindEdge) {
    const TetMesh m = cubeMesh(3);
    std::set<std::pair<int, int>> pairs;
    for (std::size_t e = 0; e < m.n_edges(); ++e) {
        const auto ev = m.edge_vertices(EdgeHandle(static_cast<int>(e)));
        EXPECT_LT(ev[0], ev[1]);
        EXPECT_TRUE(pairs.insert({ev[0].idx(), ev[1].idx()}).second) << "duplicate edge";
        EXPECT_EQ(m.find_edge(ev[0], ev[1]).idx(), static_cast<int>(e));
        EXPECT_EQ(m.find_edge(ev[1], ev[0]).idx(), static_cast<int>(e));
    }
    for (std::size_t c = 0; c < m.n_cells(); ++c)
        for (int k = 0; k < 6; ++k) {
            const CellHandle ch(static_cast<int>(c));
            const EdgeHandle e = m.cell_edge(ch, k);
            const auto ev = m.edge_vertices(e);
            const VertexHandle a = m.cell_vertex(ch, TetMesh::kEdgeCorners[k][0]);
            const VertexHandle b = m.cell_vertex(ch, TetMesh::kEdgeCorners[k][1]);
            EXPECT_EQ(std::min(a, b), ev[0]);
            EXPECT_EQ(std::max(a, b), ev[1]);
        }
    // Vertex (i,j,k) has index i + 4j + 16k. Grid-line neighbours and box main diagonals are
    // edges; vertices two steps apart and face anti-diagonals are not.
    EXPECT_TRUE(m.find_edge(VertexHandle(1), VertexHandle(2)).is_valid());
    EXPECT_TRUE(m.find_edge(VertexHandle(0), VertexHandle(1)).is_valid());
    EXPECT_FALSE(m.find_edge(VertexHandle(0), VertexHandle(2)).is_valid());
    EXPECT_TRUE(m.find_edge(VertexHandle(0), VertexHandle(1 + 4 + 16)).is_valid());  // box diagonal
    EXPECT_FALSE(m.find_edge(VertexHandle(1), VertexHandle(4)).is_valid());          // face anti-diagonal
}

TEST(TetMesh, VertexCells) {
    const TetMesh m = cubeMesh(2);
    std::vector<std::vector<int>> expected(m.n_vertices());
    for (std::size_t c = 0; c < m.n_cells(); ++c)
        for (auto v : m.cell_vertices(CellHandle(static_cast<int>(c)))) expected[v.uidx()].push_back(static_cast<int>(c));
    for (std::size_t v = 0; v < m.n_vertices(); ++v) {
        const auto r = m.vertex_cells(VertexHandle(static_cast<int>(v)));
        EXPECT_EQ(std::vector<int>(r.first, r.second), expected[v]);
    }
}

TEST(TetMesh, EdgeRingsAreCyclic) {
    const TetMesh m = cubeMesh(3);
    std::vector<int> cellsPerEdge(m.n_edges(), 0);
    for (std::size_t c = 0; c < m.n_cells(); ++c)
        for (int k = 0; k < 6; ++k) ++cellsPerEdge[m.cell_edge(CellHandle(static_cast<int>(c)), k).uidx()];
    for (std::size_t e = 0; e < m.n_edges(); ++e) {
        const EdgeHandle eh(static_cast<int>(e));
        const auto ev = m.edge_vertices(eh);
        const auto r = m.edge_cells(eh);
        const int n = static_cast<int>(r.second - r.first);
        ASSERT_EQ(n, cellsPerEdge[e]);
        EXPECT_EQ(std::set<int>(r.first, r.second).size(), static_cast<std::size_t>(n)) << "cells repeat";
        // Consecutive cells share a face containing the edge.
        auto shareFace = [&](int c0, int c1) {
            for (int j = 0; j < 4; ++j) {
                const HalfFaceHandle hf = TetMesh::halfface(CellHandle(c0), j);
                if (m.is_boundary(hf)) continue;
                if (TetMesh::cell(m.opposite_halfface(hf)).idx() == c1 && halffaceContains(m, hf, {ev[0], ev[1]}))
                    return true;
            }
            return false;
        };
        auto boundaryFaceOnEdge = [&](int c) {
            for (int j = 0; j < 4; ++j) {
                const HalfFaceHandle hf = TetMesh::halfface(CellHandle(c), j);
                if (m.is_boundary(hf) && halffaceContains(m, hf, {ev[0], ev[1]})) return true;
            }
            return false;
        };
        for (int i = 0; i + 1 < n; ++i) EXPECT_TRUE(shareFace(r.first[i], r.first[i + 1])) << "edge " << e << " pos " << i;
        if (m.is_boundary(eh)) {
            EXPECT_TRUE(boundaryFaceOnEdge(r.first[0]));
            EXPECT_TRUE(boundaryFaceOnEdge(r.first[n - 1]));
        } else {
            EXPECT_TRUE(shareFace(r.first[n - 1], r.first[0])) << "ring of edge " << e << " does not close";
        }
    }
}

TEST(TetMesh, BoundaryDetection) {
    const TetMesh m = cubeMesh(3);
    for (std::size_t v = 0; v < m.n_vertices(); ++v) {
        const VertexHandle vh(static_cast<int>(v));
        EXPECT_EQ(m.is_boundary(vh), onUnitCubeBoundary(m.position(vh))) << "vertex " << v;
    }
    for (std::size_t e = 0; e < m.n_edges(); ++e) {
        const EdgeHandle eh(static_cast<int>(e));
        const auto ev = m.edge_vertices(eh);
        EXPECT_EQ(m.is_boundary(eh), onCommonCubeFace({m.position(ev[0]), m.position(ev[1])})) << "edge " << e;
    }
    for (std::size_t i = 0; i < m.n_halffaces(); ++i) {
        const HalfFaceHandle hf(static_cast<int>(i));
        const auto fv = m.halfface_vertices(hf);
        EXPECT_EQ(m.is_boundary(hf), onCommonCubeFace({m.position(fv[0]), m.position(fv[1]), m.position(fv[2])}));
        if (!m.is_boundary(hf)) continue;
        // Outward orientation: the halfface normal points away from its cell's opposite corner.
        const Vec3d a = m.position(fv[0]), b = m.position(fv[1]), c = m.position(fv[2]);
        const Vec3d inner = m.position(m.cell_vertex(TetMesh::cell(hf), TetMesh::opposite_corner(hf)));
        const Vec3d nrm = (b - a) % (c - a);
        EXPECT_LT((inner - a) | nrm, 0.0);
    }
}

TEST(TetMesh, TwoTetsSharingOnlyAVertexAreNamed) {
    // Vertex 0 is shared; the tets touch nowhere else.
    TetMesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, 0, -1}, {0, -1, 0}},
                         {{0, 1, 2, 3}, {0, 4, 5, 6}});
    ASSERT_NO_THROW(m.build_adjacency());
    const std::string msg = m.check_manifold();
    EXPECT_NE(msg.find("non-manifold vertex 0"), std::string::npos) << msg;
    EXPECT_EQ(m.n_boundary_faces(), 8u);
}

TEST(TetMesh, TwoTetsSharingOnlyAnEdgeAreNamed) {
    TetMesh m = makeMesh({{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}},
                         {{0, 2, 3, 1}, {0, 4, 5, 1}});
    ASSERT_NO_THROW(m.build_adjacency());
    const std::string msg = m.check_manifold();
    EXPECT_NE(msg.find("non-manifold edge"), std::string::npos) << msg;
    EXPECT_NE(msg.find("(0, 1)"), std::string::npos) << msg;
}

TEST(TetMesh, ThreeTetsOnOneFaceThrow) {
    TetMesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}, {1, 1, 1}},
                         {{0, 1, 2, 3}, {0, 2, 1, 4}, {0, 1, 2, 5}});
    try {
        m.build_adjacency();
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("non-manifold"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(m.has_adjacency());
}

TEST(TetMesh, ManifoldPairAndAdjacencyInvalidation) {
    TetMesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}}, {{0, 1, 2, 3}, {0, 2, 1, 4}});
    m.build_adjacency();
    EXPECT_EQ(m.check_manifold(), "");
    EXPECT_EQ(m.n_faces(), 7u);
    EXPECT_EQ(m.n_boundary_faces(), 6u);
    EXPECT_EQ(m.n_edges(), 9u);
    EXPECT_EQ(m.opposite_halfface(TetMesh::halfface(CellHandle(0), 3)), TetMesh::halfface(CellHandle(1), 3));
    m.swap_corners(CellHandle(1), 1, 2);
    EXPECT_FALSE(m.has_adjacency());
    m.build_adjacency();
    EXPECT_TRUE(m.has_adjacency());
    m.add_cell({VertexHandle(1), VertexHandle(2), VertexHandle(3), VertexHandle(4)});
    EXPECT_FALSE(m.has_adjacency());
}

TEST(TetMesh, PropertiesByNameAndType) {
    TetMesh m = cubeMesh(1);
    auto mark = m.cell_props().request<int>("mark", -1);
    ASSERT_TRUE(mark.is_valid());
    EXPECT_EQ(mark.size(), m.n_cells());
    EXPECT_EQ(mark[CellHandle(3)], -1);
    mark[CellHandle(3)] = 42;
    // Requesting the same name again shares the storage.
    auto again = m.cell_props().request<int>("mark");
    EXPECT_EQ(again[CellHandle(3)], 42);
    EXPECT_TRUE(m.cell_props().exists("mark"));
    // Same name, other type: logic_error.
    EXPECT_THROW(m.cell_props().request<double>("mark"), std::logic_error);
    // Properties follow the entity count.
    auto hfp = m.halfface_props().request<double>("weight", 0.5);
    auto vp = m.vertex_props().request<Vec3d>("param", Vec3d(0, 0, 0));  // Vec3d() leaves its entries uninitialized
    auto cp = m.corner_props().request<char>("flag", 1);
    EXPECT_EQ(hfp.size(), m.n_halffaces());
    EXPECT_EQ(vp.size(), m.n_vertices());
    EXPECT_EQ(cp.size(), 4 * m.n_cells());
    m.add_vertex(Vec3d(2, 2, 2));
    m.add_cell({VertexHandle(1), VertexHandle(3), VertexHandle(2), VertexHandle(8)});
    EXPECT_EQ(mark.size(), m.n_cells());
    EXPECT_EQ(mark[CellHandle(static_cast<int>(m.n_cells()) - 1)], -1);
    EXPECT_EQ(hfp.size(), m.n_halffaces());
    EXPECT_EQ(hfp[HalfFaceHandle(static_cast<int>(m.n_halffaces()) - 1)], 0.5);
    EXPECT_EQ(vp.size(), m.n_vertices());
    EXPECT_EQ(cp.size(), 4 * m.n_cells());
    EXPECT_EQ(again[CellHandle(3)], 42);
    // Removing by name keeps taken handles alive but forgets the name.
    m.cell_props().remove("mark");
    EXPECT_FALSE(m.cell_props().exists("mark"));
    EXPECT_EQ(mark[CellHandle(3)], 42);
    auto fresh = m.cell_props().request<double>("mark", 1.5);
    EXPECT_EQ(fresh[CellHandle(3)], 1.5);
}

TEST(TetMesh, NonManifoldVertexNamedTheSameOnAnyThreadCount) {
    // A cube of 29,791 vertices (vertex stars checked in chunks on several threads) with a
    // bow tie of two tets sharing only a new vertex at the end, then also a tet touching the
    // cube only at vertex 0: the first bad vertex in vertex order is named either way.
    TetMesh m = generateCube(30, 1).mesh;
    ASSERT_GE(m.n_vertices(), 20000u);
    ASSERT_EQ(m.position(VertexHandle(0)), Vec3d(0, 0, 0));
    const auto add = [&](const Vec3d& p) { return m.add_vertex(p); };
    const VertexHandle w = add({5, 5, 5});
    const VertexHandle a = add({6, 5, 5}), b = add({5, 6, 5}), c = add({5, 5, 6});
    const VertexHandle d = add({4, 5, 5}), e = add({5, 4, 5}), f = add({5, 5, 4});
    m.add_cell({w, a, b, c});
    m.add_cell({w, d, e, f});
    m.build_adjacency(2);
    const std::string late = "non-manifold vertex " + std::to_string(w.idx()) + ": its 2 tets form more than one connected fan";
    EXPECT_EQ(m.check_manifold(1), late);
    EXPECT_EQ(m.check_manifold(2), late);
    EXPECT_EQ(m.check_manifold(3), late);
    const VertexHandle g = add({-1, 0, 0}), h = add({0, -1, 0}), k = add({0, 0, -1});
    m.add_cell({VertexHandle(0), g, h, k});
    m.build_adjacency(2);
    const std::string first = m.check_manifold(1);
    EXPECT_EQ(first.rfind("non-manifold vertex 0: its ", 0), 0u) << first;
    EXPECT_EQ(m.check_manifold(2), first);
    EXPECT_EQ(m.check_manifold(3), first);
    EXPECT_EQ(m.check_manifold(0), first);
}
