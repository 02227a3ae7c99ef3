#include <HexEx/Core/Error.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/Mesh/TetMesh.hh>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
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
        EXPECT_STREQ(e.what(), "non-manifold mesh: face (0, 2, 1) of tet 0 is shared by 3 tets");
    }
    EXPECT_FALSE(m.has_adjacency());
}

TEST(TetMesh, FirstNonManifoldFaceNamedTheSameOnAnyThreadCount) {
    // A cube of 29,791 vertices (faces matched in blocks of vertices on several threads)
    // with two faces made non-manifold by extra tets on them: one interior face of tet 20000
    // shared by 3 tets, one of tet 100 shared by 4. The face whose smallest halfface comes
    // first is named, with its tet count, for any thread count.
    TetMesh clean = generateCube(30, 1).mesh;
    ASSERT_GE(clean.n_vertices(), 20000u);
    clean.build_adjacency(1);
    auto interiorFace = [&](int c) {
        for (int i = 0; i < 4; ++i)
            if (clean.opposite_halfface(TetMesh::halfface(CellHandle(c), i)).is_valid()) return i;
        return -1;
    };
    const int fLate = interiorFace(20000), fEarly = interiorFace(100);
    ASSERT_GE(fLate, 0);
    ASSERT_GE(fEarly, 0);
    const int nbrEarly = TetMesh::cell(clean.opposite_halfface(TetMesh::halfface(CellHandle(100), fEarly))).idx();
    TetMesh m = generateCube(30, 1).mesh;
    auto addOnFace = [&](int c, int i, const Vec3d& apex) {
        const VertexHandle x = m.add_vertex(apex);
        const auto cv = m.cell_vertices(CellHandle(c));
        m.add_cell({cv[TetMesh::kFaceCorners[i][0]], cv[TetMesh::kFaceCorners[i][1]], cv[TetMesh::kFaceCorners[i][2]], x});
    };
    addOnFace(20000, fLate, {5, 5, 5});
    addOnFace(100, fEarly, {6, 5, 5});
    addOnFace(100, fEarly, {7, 5, 5});
    const int named = std::min(100, nbrEarly);
    std::string first;
    for (int threads = 1; threads <= 3; ++threads) {
        try {
            m.build_adjacency(threads);
            ADD_FAILURE() << "expected InputError at " << threads << " threads";
        } catch (const InputError& e) {
            const std::string msg = e.what();
            EXPECT_EQ(msg.rfind("non-manifold mesh: face (", 0), 0u) << msg;
            EXPECT_NE(msg.find(") of tet " + std::to_string(named) + " is shared by 4 tets"), std::string::npos) << msg;
            if (threads == 1) first = msg;
            EXPECT_EQ(msg, first) << threads << " threads";
        }
    }
}

TEST(TetMesh, AdjacencyMatchesABruteForceReferenceOnAnyThreadCount) {
    // A cube mesh large enough for the parallel paths (>= 20,000 vertices, >= 50,000 tets),
    // its vertices and tets shuffled so that no order is inherited from the generator.
    const TetMesh cube = generateCube(28, 1).mesh;
    const std::size_t nv = cube.n_vertices(), nc = cube.n_cells();
    ASSERT_GE(nv, 20000u);
    ASSERT_GE(nc, 50000u);
    std::vector<int> vperm(nv), cperm(nc);
    for (std::size_t i = 0; i < nv; ++i) vperm[i] = int(i);
    for (std::size_t i = 0; i < nc; ++i) cperm[i] = int(i);
    std::uint64_t seed = 12345;
    auto next = [&](std::size_t bound) {
        seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
        return std::size_t(seed >> 33) % bound;
    };
    for (std::size_t i = nv - 1; i > 0; --i) std::swap(vperm[i], vperm[next(i + 1)]);
    for (std::size_t i = nc - 1; i > 0; --i) std::swap(cperm[i], cperm[next(i + 1)]);
    std::vector<Vec3d> pts(nv);
    for (std::size_t v = 0; v < nv; ++v) pts[std::size_t(vperm[v])] = cube.position(VertexHandle(int(v)));
    std::vector<std::array<int, 4>> tets(nc);
    for (std::size_t c = 0; c < nc; ++c)
        for (int i = 0; i < 4; ++i)
            tets[std::size_t(cperm[c])][std::size_t(i)] = vperm[cube.cell_vertex(CellHandle(int(c)), i).uidx()];

    // Reference opposites: halffaces keyed by their sorted vertices.
    std::map<std::array<int, 3>, std::vector<int>> byFace;
    for (std::size_t c = 0; c < nc; ++c)
        for (int i = 0; i < 4; ++i) {
            std::array<int, 3> key;
            for (int k = 0; k < 3; ++k) key[std::size_t(k)] = tets[c][std::size_t(TetMesh::kFaceCorners[i][k])];
            std::sort(key.begin(), key.end());
            byFace[key].push_back(int(4 * c) + i);
        }
    std::vector<int> refOpposite(4 * nc, -1);
    for (const auto& f : byFace) {
        ASSERT_LE(f.second.size(), 2u);
        if (f.second.size() == 2) {
            refOpposite[std::size_t(f.second[0])] = f.second[1];
            refOpposite[std::size_t(f.second[1])] = f.second[0];
        }
    }

    std::vector<TetMesh> meshes;
    for (int threads = 1; threads <= 3; ++threads) {
        meshes.push_back(makeMesh(pts, tets));
        meshes.back().build_adjacency(threads);
    }
    const TetMesh& m = meshes[0];
    for (std::size_t hf = 0; hf < 4 * nc; ++hf)
        ASSERT_EQ(m.opposite_halfface(HalfFaceHandle(int(hf))).idx(), refOpposite[hf]) << "halfface " << hf;
    // Every tet edge slot names the edge with its two corners; the ring of an edge holds
    // exactly the tets that contain it and starts where the documented rule says: the
    // last tet (in tet order) with a boundary face through the edge, else the first tet.
    std::map<int, std::vector<int>> tetsOfEdge;
    std::map<int, int> startOfEdge;
    for (std::size_t c = 0; c < nc; ++c)
        for (int k = 0; k < 6; ++k) {
            const EdgeHandle e = m.cell_edge(CellHandle(int(c)), k);
            const auto ev = m.edge_vertices(e);
            const int a = TetMesh::kEdgeCorners[k][0], b = TetMesh::kEdgeCorners[k][1];
            const int x = tets[c][std::size_t(a)], y = tets[c][std::size_t(b)];
            ASSERT_EQ(ev[0].idx(), std::min(x, y));
            ASSERT_EQ(ev[1].idx(), std::max(x, y));
            tetsOfEdge[e.idx()].push_back(int(c));
            for (int j = 0; j < 4; ++j)
                if (j != a && j != b && refOpposite[4 * c + std::size_t(j)] < 0) startOfEdge[e.idx()] = int(c);
            startOfEdge.emplace(e.idx(), int(c));
        }
    ASSERT_EQ(tetsOfEdge.size(), m.n_edges());
    for (const auto& [e, cells] : tetsOfEdge) {
        const auto ring = m.edge_cells(EdgeHandle(e));
        std::vector<int> got(ring.first, ring.second);
        ASSERT_EQ(got.front(), startOfEdge.at(e)) << "edge " << e;
        // Consecutive ring tets share a face through the edge; the edge is a boundary edge
        // exactly when a boundary face passes through it.
        const auto ev = m.edge_vertices(EdgeHandle(e));
        auto sharesFace = [&](int c, int d) {
            for (int j = 0; j < 4; ++j)
                if (refOpposite[4 * std::size_t(c) + std::size_t(j)] >= 0 &&
                    refOpposite[4 * std::size_t(c) + std::size_t(j)] / 4 == d && tets[std::size_t(c)][std::size_t(j)] != ev[0].idx() &&
                    tets[std::size_t(c)][std::size_t(j)] != ev[1].idx())
                    return true;
            return false;
        };
        for (std::size_t i = 0; i + 1 < got.size(); ++i) ASSERT_TRUE(sharesFace(got[i], got[i + 1])) << "edge " << e;
        bool boundary = false;
        for (const int c : cells)
            for (int j = 0; j < 4; ++j)
                boundary |= refOpposite[4 * std::size_t(c) + std::size_t(j)] < 0 && tets[std::size_t(c)][std::size_t(j)] != ev[0].idx() &&
                            tets[std::size_t(c)][std::size_t(j)] != ev[1].idx();
        ASSERT_EQ(m.is_boundary(EdgeHandle(e)), boundary) << "edge " << e;
        if (!boundary) {
            ASSERT_TRUE(sharesFace(got.back(), got.front())) << "edge " << e;
        }
        // Edges are numbered by smaller, then larger endpoint; find_edge() finds them.
        if (e > 0) {
            const auto pv = m.edge_vertices(EdgeHandle(e - 1));
            ASSERT_TRUE(pv[0] < ev[0] || (pv[0] == ev[0] && pv[1] < ev[1])) << "edge " << e;
        }
        ASSERT_EQ(m.find_edge(ev[1], ev[0]).idx(), e);
        std::sort(got.begin(), got.end());
        ASSERT_EQ(got, cells) << "edge " << e;
    }
    // A vertex is a boundary vertex exactly when it lies on a boundary face.
    std::vector<char> refBoundaryVertex(nv, 0);
    for (std::size_t hf = 0; hf < 4 * nc; ++hf)
        if (refOpposite[hf] < 0)
            for (int k = 0; k < 3; ++k) refBoundaryVertex[std::size_t(tets[hf / 4][std::size_t(TetMesh::kFaceCorners[hf % 4][k])])] = 1;
    for (std::size_t v = 0; v < nv; ++v) ASSERT_EQ(m.is_boundary(VertexHandle(int(v))), refBoundaryVertex[v] != 0) << "vertex " << v;
    // The same arrays for any thread count.
    for (std::size_t t = 1; t < meshes.size(); ++t) {
        const TetMesh& o = meshes[t];
        ASSERT_EQ(o.n_faces(), m.n_faces());
        ASSERT_EQ(o.n_edges(), m.n_edges());
        for (std::size_t hf = 0; hf < 4 * nc; ++hf) {
            ASSERT_EQ(o.opposite_halfface(HalfFaceHandle(int(hf))), m.opposite_halfface(HalfFaceHandle(int(hf))));
            ASSERT_EQ(o.face(HalfFaceHandle(int(hf))), m.face(HalfFaceHandle(int(hf))));
        }
        for (std::size_t c = 0; c < nc; ++c)
            for (int k = 0; k < 6; ++k) ASSERT_EQ(o.cell_edge(CellHandle(int(c)), k), m.cell_edge(CellHandle(int(c)), k));
        for (std::size_t e = 0; e < m.n_edges(); ++e) {
            const auto a = m.edge_cells(EdgeHandle(int(e))), b = o.edge_cells(EdgeHandle(int(e)));
            ASSERT_TRUE(std::equal(a.first, a.second, b.first, b.second)) << "edge " << e << ", " << t + 1 << " threads";
            ASSERT_EQ(o.is_boundary(EdgeHandle(int(e))), m.is_boundary(EdgeHandle(int(e))));
        }
        for (std::size_t v = 0; v < nv; ++v) ASSERT_EQ(o.is_boundary(VertexHandle(int(v))), m.is_boundary(VertexHandle(int(v))));
        // The vertex -> tets table (counted and filled in chunks of tets on several threads).
        for (std::size_t v = 0; v < nv; ++v) {
            const auto a = m.vertex_cells(VertexHandle(int(v))), b = o.vertex_cells(VertexHandle(int(v)));
            ASSERT_TRUE(std::equal(a.first, a.second, b.first, b.second)) << "vertex " << v << ", " << t + 1 << " threads";
        }
    }
    // Each vertex's tets: exactly the tets that contain it, ascending.
    std::vector<std::vector<int>> refStar(nv);
    for (std::size_t c = 0; c < nc; ++c)
        for (int i = 0; i < 4; ++i) refStar[std::size_t(tets[c][std::size_t(i)])].push_back(int(c));
    for (std::size_t v = 0; v < nv; ++v) {
        const auto a = m.vertex_cells(VertexHandle(int(v)));
        ASSERT_EQ(std::vector<int>(a.first, a.second), refStar[v]) << "vertex " << v;
    }
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
