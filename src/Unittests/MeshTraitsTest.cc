// Mesh-kernel traits: extraction from and into a user-defined kernel, plain arrays and the
// built-in kernel through the templated extractHexMesh(); overload resolution; index errors.

#include <HexEx/Generators/Generators.hh>
#include <HexEx/HexExTraits.hh>

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace {

// ---------------------------------------------------------------------------------------
// A stand-in for an existing volume-mesh kernel: its own handle and point types, cells
// that store handles, and the map as a cell property (12 doubles: 4 corners x uvw).
// ---------------------------------------------------------------------------------------
namespace my {

struct VertexHandle { int id = -1; };
struct CellHandle { int id = -1; };
struct Point { double x = 0, y = 0, z = 0; };

struct VolumeMesh {
    std::vector<Point> verts;
    std::vector<std::array<VertexHandle, 4>> cells;
    std::map<int, std::array<double, 12>> cellParams;  // CellHandle::id -> (u,v,w) per corner

    VertexHandle add_vertex(const Point& p) {
        verts.push_back(p);
        return VertexHandle{static_cast<int>(verts.size()) - 1};
    }
    CellHandle add_cell(const std::array<VertexHandle, 4>& c) {
        cells.push_back(c);
        return CellHandle{static_cast<int>(cells.size()) - 1};
    }
};

struct HexMeshOut {
    std::vector<Point> points;
    std::vector<std::array<VertexHandle, 8>> hexes;
    std::vector<std::vector<std::vector<VertexHandle>>> others;
};

/// Output kernel whose vertex ids start at 100.
struct ShiftedIds {
    std::vector<std::array<std::size_t, 8>> hexes;
    std::vector<std::vector<std::vector<std::size_t>>> polys;
    std::size_t n = 0;
};

} // namespace my
} // namespace

// ---- The traits for the stand-in kernel (what Documentation/traits.md describes). ----
namespace HexEx {

template <>
struct TetMeshTraits<my::VolumeMesh> {
    static std::size_t n_vertices(const my::VolumeMesh& m) { return m.verts.size(); }
    static Vec3d position(const my::VolumeMesh& m, std::size_t v) {
        const my::Point& p = m.verts[v];
        return Vec3d(p.x, p.y, p.z);
    }
    static std::size_t n_tets(const my::VolumeMesh& m) { return m.cells.size(); }
    static std::array<std::size_t, 4> tet_vertices(const my::VolumeMesh& m, std::size_t t) {
        std::array<std::size_t, 4> r;
        for (std::size_t i = 0; i < 4; ++i) r[i] = static_cast<std::size_t>(m.cells[t][i].id);
        return r;
    }
    static Vec3d corner_param(const my::VolumeMesh& m, std::size_t t, int corner) {
        const std::array<double, 12>& p = m.cellParams.at(static_cast<int>(t));
        return Vec3d(p[3 * corner], p[3 * corner + 1], p[3 * corner + 2]);
    }
};

template <>
struct HexMeshOutputTraits<my::HexMeshOut> {
    static void clear(my::HexMeshOut& m) { m = my::HexMeshOut(); }
    static std::size_t add_vertex(my::HexMeshOut& m, const Vec3d& p) {
        m.points.push_back({p[0], p[1], p[2]});
        return m.points.size() - 1;
    }
    static void add_hex(my::HexMeshOut& m, const std::array<std::size_t, 8>& v) {
        std::array<my::VertexHandle, 8> h;
        for (std::size_t i = 0; i < 8; ++i) h[i] = my::VertexHandle{static_cast<int>(v[i])};
        m.hexes.push_back(h);
    }
    static void add_polyhedron(my::HexMeshOut& m, const std::vector<std::vector<std::size_t>>& faces) {
        std::vector<std::vector<my::VertexHandle>> cell;
        for (const auto& f : faces) {
            cell.emplace_back();
            for (std::size_t v : f) cell.back().push_back(my::VertexHandle{static_cast<int>(v)});
        }
        m.others.push_back(cell);
    }
};

template <>
struct HexMeshOutputTraits<my::ShiftedIds> {
    static void clear(my::ShiftedIds& s) { s = my::ShiftedIds(); }
    static std::size_t add_vertex(my::ShiftedIds& s, const Vec3d&) { return 100 + s.n++; }
    static void add_hex(my::ShiftedIds& s, const std::array<std::size_t, 8>& v) { s.hexes.push_back(v); }
    static void add_polyhedron(my::ShiftedIds& s, const std::vector<std::vector<std::size_t>>& f) {
        s.polys.push_back(f);
    }
};

} // namespace HexEx

using namespace HexEx;

namespace {

/// Copies a generated mesh into the stand-in kernel.
my::VolumeMesh toMyMesh(const ParametrizedTetMesh& pm) {
    my::VolumeMesh m;
    for (std::size_t v = 0; v < pm.mesh.n_vertices(); ++v) {
        const Vec3d& p = pm.mesh.position(VertexHandle(static_cast<int>(v)));
        m.add_vertex({p[0], p[1], p[2]});
    }
    for (std::size_t c = 0; c < pm.mesh.n_cells(); ++c) {
        const auto& cv = pm.mesh.cell_vertices(CellHandle(static_cast<int>(c)));
        const my::CellHandle ch = m.add_cell({my::VertexHandle{cv[0].idx()}, my::VertexHandle{cv[1].idx()},
                                              my::VertexHandle{cv[2].idx()}, my::VertexHandle{cv[3].idx()}});
        std::array<double, 12> p;
        for (int i = 0; i < 4; ++i)
            for (int k = 0; k < 3; ++k) p[static_cast<std::size_t>(3 * i + k)] = pm.params[c][static_cast<std::size_t>(i)][k];
        m.cellParams[ch.id] = p;
    }
    return m;
}

/// The six-tet unit cube with parameters 2 * position: 8 hexes, 27 vertices.
ParametrizedTetMesh cube() { return generateCube(1, 2); }

ExtractionOptions oneThread() {
    ExtractionOptions o;
    o.threads = 1;
    return o;
}

void expectCubeReport(const ExtractionReport& r) {
    EXPECT_EQ(r.output.hexes, 8);
    EXPECT_EQ(r.output.vertices, 27);
    EXPECT_EQ(r.output.non_hex_cells, 0);
    EXPECT_TRUE(r.valid_all_hex);
}

/// Every hex vertex index valid, all positions inside the unit cube.
template <class Points, class Hexes, class Coord, class Id>
void expectConsistent(const Points& points, const Hexes& hexes, Coord coord, Id id) {
    for (const auto& p : points)
        for (int k = 0; k < 3; ++k) {
            EXPECT_GE(coord(p, k), -1e-12);
            EXPECT_LE(coord(p, k), 1 + 1e-12);
        }
    for (const auto& h : hexes)
        for (const auto& v : h) {
            EXPECT_GE(id(v), 0);
            EXPECT_LT(id(v), static_cast<long>(points.size()));
        }
}

// Overload resolution: the templated overload never competes with the built-in one.
static_assert(!detail::useTraitsOverload<ParametrizedTetMesh, HexMesh>);
static_assert(detail::useTraitsOverload<ParametrizedTetMesh, HexArrays>);
static_assert(detail::useTraitsOverload<TetArraysView, HexMesh>);
static_assert(detail::useTraitsOverload<my::VolumeMesh, my::HexMeshOut>);
static_assert(!detail::useTraitsOverload<HexMesh, HexMesh>);  // no input traits for HexMesh
static_assert(!hasTetMeshTraits<int> && !hasHexMeshOutputTraits<int>);
static_assert(hasTetMeshTraits<TetArraysView> && hasHexMeshOutputTraits<HexArrays>);
static_assert(detail::CompleteTetMeshTraits<my::VolumeMesh>::value &&
              detail::CompleteTetMeshTraits<ParametrizedTetMesh>::value &&
              detail::CompleteTetMeshTraits<TetArraysView>::value);
static_assert(detail::CompleteHexMeshOutputTraits<my::HexMeshOut>::value &&
              detail::CompleteHexMeshOutputTraits<my::ShiftedIds>::value &&
              detail::CompleteHexMeshOutputTraits<HexMesh>::value &&
              detail::CompleteHexMeshOutputTraits<HexArrays>::value);

struct DerivedParametrizedTetMesh : ParametrizedTetMesh {};

} // namespace

TEST(MeshTraitsTest, UserKernelCube) {
    const my::VolumeMesh in = toMyMesh(cube());
    my::HexMeshOut out;
    const ExtractionReport r = extractHexMesh(in, out, oneThread());
    expectCubeReport(r);
    EXPECT_EQ(out.hexes.size(), 8u);
    EXPECT_EQ(out.points.size(), 27u);
    EXPECT_TRUE(out.others.empty());
    expectConsistent(
        out.points, out.hexes,
        [](const my::Point& p, int k) { return k == 0 ? p.x : k == 1 ? p.y : p.z; },
        [](const my::VertexHandle& v) { return static_cast<long>(v.id); });
}

TEST(MeshTraitsTest, UserKernelWithChartTransformsMatchesBuiltIn) {
    // Non-trivial transitions between tets: the per-corner parameters must reach the
    // extractor unchanged, so the result is the built-in kernel's, vertex for vertex.
    ParametrizedTetMesh pm = generateCube(2, 2);
    applyRandomChartTransforms(pm, 7);
    pm.mesh.build_adjacency();
    HexMesh ref;
    const ExtractionReport rr = extractHexMesh(pm, ref, oneThread());
    expectCubeReport(rr);

    my::HexMeshOut out;
    const ExtractionReport r = extractHexMesh(toMyMesh(pm), out, oneThread());
    expectCubeReport(r);
    ASSERT_EQ(out.points.size(), ref.vertices.size());
    ASSERT_EQ(out.hexes.size(), ref.hexes.size());
    for (std::size_t v = 0; v < ref.vertices.size(); ++v) {
        EXPECT_EQ(out.points[v].x, ref.vertices[v][0]);
        EXPECT_EQ(out.points[v].y, ref.vertices[v][1]);
        EXPECT_EQ(out.points[v].z, ref.vertices[v][2]);
    }
    for (std::size_t h = 0; h < ref.hexes.size(); ++h)
        for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(out.hexes[h][i].id, ref.hexes[h][i]);
}

namespace {
/// The vertices and tets of @p pm as plain arrays (the input of the array traits).
void toArrays(const ParametrizedTetMesh& pm, std::vector<Vec3d>& positions, std::vector<std::array<int, 4>>& tets) {
    for (std::size_t v = 0; v < pm.mesh.n_vertices(); ++v)
        positions.push_back(pm.mesh.position(VertexHandle(static_cast<int>(v))));
    for (std::size_t c = 0; c < pm.mesh.n_cells(); ++c) {
        const auto& cv = pm.mesh.cell_vertices(CellHandle(static_cast<int>(c)));
        tets.push_back({cv[0].idx(), cv[1].idx(), cv[2].idx(), cv[3].idx()});
    }
}
} // namespace

TEST(MeshTraitsTest, ArrayTraitsCube) {
    const ParametrizedTetMesh pm = cube();
    std::vector<Vec3d> positions;
    std::vector<std::array<int, 4>> tets;
    toArrays(pm, positions, tets);
    const TetArraysView view{&positions, &tets, &pm.params};
    HexArrays out;
    const ExtractionReport r = extractHexMesh(view, out, oneThread());
    expectCubeReport(r);
    EXPECT_EQ(out.hexes.size(), 8u);
    EXPECT_EQ(out.positions.size(), 27u);
    EXPECT_TRUE(out.polyhedra.empty());
    expectConsistent(
        out.positions, out.hexes, [](const Vec3d& p, int k) { return p[k]; },
        [](int v) { return static_cast<long>(v); });

    // Array input into the built-in output kernel.
    HexMesh hm;
    expectCubeReport(extractHexMesh(view, hm, oneThread()));
    EXPECT_EQ(hm.hexes, out.hexes);
    EXPECT_EQ(hm.vertices, out.positions);
}

TEST(MeshTraitsTest, BuiltInKernelThroughBothOverloads) {
    ParametrizedTetMesh pm = cube();
    pm.mesh.build_adjacency();
    const ParametrizedTetMesh& cpm = pm;

    // These resolve to the non-template overload (an ambiguity would not compile).
    HexMesh a, b;
    expectCubeReport(extractHexMesh(pm, a));
    expectCubeReport(extractHexMesh(cpm, b, oneThread()));
    EXPECT_EQ(a.hexes, b.hexes);
    DerivedParametrizedTetMesh derived;
    static_cast<ParametrizedTetMesh&>(derived) = toParametrizedTetMesh(pm);
    HexMesh c;
    expectCubeReport(extractHexMesh(derived, c, oneThread()));
    EXPECT_EQ(c.hexes, a.hexes);

    // Built-in input into other outputs: the templated overload.
    HexArrays arrays;
    expectCubeReport(extractHexMesh(pm, arrays, oneThread()));
    EXPECT_EQ(arrays.hexes, a.hexes);
    my::HexMeshOut mine;
    expectCubeReport(extractHexMesh(cpm, mine, oneThread()));
    EXPECT_EQ(mine.hexes.size(), 8u);

    // Without adjacency the templated overload builds it on a copy.
    const ParametrizedTetMesh raw = cube();
    ASSERT_FALSE(raw.mesh.has_adjacency());
    HexArrays fromRaw;
    expectCubeReport(extractHexMesh(raw, fromRaw, oneThread()));
    EXPECT_EQ(fromRaw.hexes, a.hexes);
    EXPECT_FALSE(raw.mesh.has_adjacency());
}

TEST(MeshTraitsTest, ToParametrizedTetMeshCopiesEverything) {
    const my::VolumeMesh in = toMyMesh(generateCube(2, 3));
    const ParametrizedTetMesh pm = toParametrizedTetMesh(in);
    EXPECT_TRUE(pm.mesh.has_adjacency());
    ASSERT_EQ(pm.mesh.n_vertices(), in.verts.size());
    ASSERT_EQ(pm.mesh.n_cells(), in.cells.size());
    ASSERT_EQ(pm.params.size(), in.cells.size());
    EXPECT_EQ(pm.mesh.n_boundary_faces(), 48u);
    for (std::size_t c = 0; c < in.cells.size(); ++c)
        for (int i = 0; i < 4; ++i) {
            EXPECT_EQ(pm.mesh.cell_vertex(CellHandle(static_cast<int>(c)), i).idx(),
                      in.cells[c][static_cast<std::size_t>(i)].id);
            for (int k = 0; k < 3; ++k)
                EXPECT_EQ(pm.params[c][static_cast<std::size_t>(i)][k],
                          in.cellParams.at(static_cast<int>(c))[static_cast<std::size_t>(3 * i + k)]);
        }
}

TEST(MeshTraitsTest, FromHexMeshMapsVertexIdsAndKeepsPolyhedra) {
    HexMesh hm;
    for (int i = 0; i < 9; ++i) hm.vertices.push_back(Vec3d(i, 0, 0));
    hm.hexes.push_back({1, 2, 3, 4, 5, 6, 7, 8});
    Polyhedron tet;
    tet.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
    hm.polyhedra.push_back(tet);

    HexArrays arrays;
    arrays.positions.push_back(Vec3d(42, 0, 0));  // cleared before writing
    fromHexMesh(hm, arrays);
    EXPECT_EQ(arrays.positions, hm.vertices);
    EXPECT_EQ(arrays.hexes, hm.hexes);
    ASSERT_EQ(arrays.polyhedra.size(), 1u);
    EXPECT_EQ(arrays.polyhedra[0], tet.faces);

    // A kernel whose vertex ids are not 0..n-1: hex and face ids are remapped.
    my::ShiftedIds shifted;
    shifted.n = 5;
    fromHexMesh(hm, shifted);
    EXPECT_EQ(shifted.n, 9u);
    ASSERT_EQ(shifted.hexes.size(), 1u);
    for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(shifted.hexes[0][i], 100 + static_cast<std::size_t>(hm.hexes[0][i]));
    ASSERT_EQ(shifted.polys.size(), 1u);
    ASSERT_EQ(shifted.polys[0].size(), 4u);
    EXPECT_EQ(shifted.polys[0][3], (std::vector<std::size_t>{102, 100, 103}));
}

TEST(MeshTraitsTest, OutOfRangeVertexIndexNamesTheTet) {
    const ParametrizedTetMesh pm = cube();
    std::vector<Vec3d> positions;
    std::vector<std::array<int, 4>> tets;
    toArrays(pm, positions, tets);
    auto messageOf = [](auto&& f) -> std::string {
        try {
            f();
        } catch (const InputError& e) {
            return e.what();
        } catch (...) {
            return "unexpected exception type";
        }
        return "no exception";
    };

    HexArrays out;
    out.positions.push_back(Vec3d(1, 2, 3));  // must survive a failed extraction
    {
        auto bad = tets;
        bad[3][2] = 8;
        const TetArraysView view{&positions, &bad, &pm.params};
        EXPECT_EQ(messageOf([&] { extractHexMesh(view, out); }),
                  "tet 3: vertex index 8 out of range (the mesh has 8 vertices)");
    }
    {
        auto bad = tets;
        bad[5][0] = -1;
        const TetArraysView view{&positions, &bad, &pm.params};
        EXPECT_EQ(messageOf([&] { extractHexMesh(view, out); }),
                  "tet 5: vertex index -1 out of range (the mesh has 8 vertices)");
    }
    {
        auto bad = tets;
        bad[2][3] = bad[2][1];
        const TetArraysView view{&positions, &bad, &pm.params};
        EXPECT_NE(messageOf([&] { extractHexMesh(view, out); }).find("tet 2: vertex"), std::string::npos);
    }
    {
        const CornerParams fewer(pm.params.begin(), pm.params.end() - 1);
        const TetArraysView view{&positions, &tets, &fewer};
        EXPECT_EQ(messageOf([&] { extractHexMesh(view, out); }), "TetArraysView: 6 tets but 5 corner parameter sets");
    }
    {
        const TetArraysView view{&positions, nullptr, &pm.params};
        EXPECT_EQ(messageOf([&] { extractHexMesh(view, out); }), "TetArraysView: tets is null");
    }
    ASSERT_EQ(out.positions.size(), 1u);
    EXPECT_EQ(out.positions[0], Vec3d(1, 2, 3));

    // A user kernel with a dangling handle: reported by toParametrizedTetMesh().
    my::VolumeMesh in = toMyMesh(pm);
    in.cells[4][1].id = 1000;
    my::HexMeshOut mine;
    EXPECT_EQ(messageOf([&] { extractHexMesh(in, mine); }),
              "tet 4: vertex index 1000 out of range (the mesh has 8 vertices)");
    in.cells[4][1].id = -7;  // wraps to a huge std::size_t: still out of range
    EXPECT_EQ(messageOf([&] { extractHexMesh(in, mine); }),
              "tet 4: vertex index -7 out of range (the mesh has 8 vertices)");
    EXPECT_TRUE(mine.hexes.empty());
}
