// Edge arcs and face patches (ExtractionOptions::arcs): measured against the geometry they
// must reproduce (straight/planar under a linear map, hex vertices at the arc ends, the tet
// boundary tiled by boundary patches, hex volumes closed by patches, the singular axis).

#include <HexEx/Core/Error.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/Generators/Perturbation.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/IO/ArcWriters.hh>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

using namespace HexEx;

namespace {

struct Extracted {
    HexMesh hm;
    HexArcs arcs;
    ExtractionReport rep;
};

Extracted extractWithArcs(ParametrizedTetMesh pm, int threads = 1) {
    pm.mesh.build_adjacency();
    Extracted e;
    ExtractionOptions opt;
    opt.threads = threads;
    opt.arcs = &e.arcs;
    e.rep = extractHexMesh(pm, e.hm, opt);
    return e;
}

double boundingDiagonal(const TetMesh& m) {
    Vec3d lo(1e300, 1e300, 1e300), hi(-1e300, -1e300, -1e300);
    for (std::size_t v = 0; v < m.n_vertices(); ++v)
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], m.position(VertexHandle(static_cast<int>(v)))[k]);
            hi[k] = std::max(hi[k], m.position(VertexHandle(static_cast<int>(v)))[k]);
        }
    return (hi - lo).norm();
}

/// 3D volume of the tet mesh and area of its boundary.
std::pair<double, double> volumeAndBoundaryArea(TetMesh m) {
    m.build_adjacency();
    double vol = 0, area = 0;
    for (std::size_t c = 0; c < m.n_cells(); ++c) {
        const auto& v = m.cell_vertices(CellHandle(static_cast<int>(c)));
        vol += tetVolume(m.position(v[0]), m.position(v[1]), m.position(v[2]), m.position(v[3]));
        for (int i = 0; i < 4; ++i) {
            const HalfFaceHandle hf = TetMesh::halfface(CellHandle(static_cast<int>(c)), i);
            if (!m.is_boundary(hf)) continue;
            const auto f = m.halfface_vertices(hf);
            area += 0.5 * ((m.position(f[1]) - m.position(f[0])) % (m.position(f[2]) - m.position(f[0]))).norm();
        }
    }
    return {vol, area};
}

/// Volume closed by the six patches of hex @p h (divergence theorem, outward orientation).
double closedVolume(const HexArcs& a, std::size_t h) {
    double vol = 0;
    for (int k = 0; k < 6; ++k) {
        const std::size_t f = static_cast<std::size_t>(a.hex_faces[h][static_cast<std::size_t>(k)]);
        for (std::size_t t = a.patch_offset[f]; t < a.patch_offset[f + 1]; ++t) {
            const auto& tri = a.patch_triangles[t];
            const Vec3d &p0 = a.patch_points[static_cast<std::size_t>(tri[0])], &p1 = a.patch_points[static_cast<std::size_t>(tri[1])],
                        &p2 = a.patch_points[static_cast<std::size_t>(tri[2])];
            vol += a.hex_face_sign[h][static_cast<std::size_t>(k)] * ((p0 % p1) | p2) / 6;
        }
    }
    return vol;
}

double patchArea(const HexArcs& a, std::size_t f) {
    double area = 0;
    for (std::size_t t = a.patch_offset[f]; t < a.patch_offset[f + 1]; ++t) {
        const auto& tri = a.patch_triangles[t];
        area += 0.5 * ((a.patch_points[static_cast<std::size_t>(tri[1])] - a.patch_points[static_cast<std::size_t>(tri[0])]) %
                       (a.patch_points[static_cast<std::size_t>(tri[2])] - a.patch_points[static_cast<std::size_t>(tri[0])]))
                          .norm();
    }
    return area;
}

/// Largest distance of an arc's end points from its hex vertices, over the formed arcs.
double worstEndpointError(const Extracted& e) {
    double worst = 0;
    for (std::size_t k = 0; k < e.arcs.edges.size(); ++k) {
        const std::size_t b = e.arcs.arc_offset[k], n = e.arcs.arc_offset[k + 1];
        if (b == n) continue;
        worst = std::max(worst, (e.arcs.arc_points[b] - e.hm.vertices[static_cast<std::size_t>(e.arcs.edges[k][0])]).norm());
        worst = std::max(worst, (e.arcs.arc_points[n - 1] - e.hm.vertices[static_cast<std::size_t>(e.arcs.edges[k][1])]).norm());
    }
    return worst;
}

/// Checks of a valid map: nothing failed, arc ends at the hex vertices, boundary patches
/// tile the boundary, every hex closes a positive volume and all of them the mesh's volume.
void expectValidArcs(const ParametrizedTetMesh& pm, const Extracted& e, const std::string& name) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(e.rep.valid_all_hex);
    EXPECT_EQ(e.arcs.failed_edges.size(), 0u);
    EXPECT_EQ(e.arcs.failed_faces.size(), 0u);
    EXPECT_EQ(e.rep.arcs.edges, static_cast<long>(e.arcs.edges.size()));
    const double diag = boundingDiagonal(pm.mesh);
    EXPECT_LT(worstEndpointError(e), 1e-9 * diag);
    const auto [vol, area] = volumeAndBoundaryArea(pm.mesh);
    std::vector<int> uses(e.arcs.faces.size(), 0);
    for (const auto& hf : e.arcs.hex_faces)
        for (int f : hf) ++uses[static_cast<std::size_t>(f)];
    double boundaryArea = 0;
    for (std::size_t f = 0; f < uses.size(); ++f)
        if (uses[f] == 1) boundaryArea += patchArea(e.arcs, f);
    EXPECT_NEAR(boundaryArea, area, 1e-9 * area);
    double total = 0, smallest = 1e300;
    for (std::size_t h = 0; h < e.hm.hexes.size(); ++h) {
        const double v = closedVolume(e.arcs, h);
        total += v;
        smallest = std::min(smallest, v);
    }
    EXPECT_GT(smallest, 0);
    EXPECT_NEAR(total, vol, 1e-9 * vol);
}

} // namespace

TEST(Arcs, CubeWithLinearMapHasStraightArcsAndPlanarPatches) {
    for (const auto& [n, s] : {std::pair<int, int>{2, 2}, {3, 2}, {2, 3}}) {
        SCOPED_TRACE("n=" + std::to_string(n) + " s=" + std::to_string(s));
        const ParametrizedTetMesh pm = generateCube(n, s);
        const Extracted e = extractWithArcs(pm);
        expectValidArcs(pm, e, "cube");
        EXPECT_EQ(e.arcs.edges.size(), static_cast<std::size_t>(3 * s * (s + 1) * (s + 1)));
        EXPECT_EQ(e.arcs.faces.size(), static_cast<std::size_t>(3 * s * s * (s + 1)));
        // Straight: every arc point on the segment between the two hex vertices, in order.
        double worst = 0;
        for (std::size_t k = 0; k < e.arcs.edges.size(); ++k) {
            const Vec3d a = e.hm.vertices[static_cast<std::size_t>(e.arcs.edges[k][0])];
            const Vec3d b = e.hm.vertices[static_cast<std::size_t>(e.arcs.edges[k][1])];
            const Vec3d dir = (b - a) / (b - a).norm();
            double last = -1e-12;
            ASSERT_GE(e.arcs.arc_offset[k + 1] - e.arcs.arc_offset[k], 2u);
            for (std::size_t p = e.arcs.arc_offset[k]; p < e.arcs.arc_offset[k + 1]; ++p) {
                const Vec3d x = e.arcs.arc_points[p] - a;
                const double along = x | dir;
                worst = std::max(worst, (x - dir * along).norm());
                EXPECT_GE(along, last - 1e-12);
                last = along;
            }
        }
        EXPECT_LT(worst, 1e-12);
        // Planar: every patch point in the plane of its quad (axis-aligned here), and each
        // hex closes exactly its cube's volume.
        double off = 0;
        for (std::size_t f = 0; f < e.arcs.faces.size(); ++f) {
            const auto& q = e.arcs.faces[f];
            int axis = -1;
            for (int k = 0; k < 3; ++k)
                if (std::abs(e.hm.vertices[static_cast<std::size_t>(q[0])][k] - e.hm.vertices[static_cast<std::size_t>(q[2])][k]) < 1e-12) axis = k;
            ASSERT_GE(axis, 0);
            const double c = e.hm.vertices[static_cast<std::size_t>(q[0])][axis];
            ASSERT_GT(e.arcs.patch_offset[f + 1], e.arcs.patch_offset[f]);
            for (std::size_t t = e.arcs.patch_offset[f]; t < e.arcs.patch_offset[f + 1]; ++t)
                for (int i : e.arcs.patch_triangles[t]) off = std::max(off, std::abs(e.arcs.patch_points[static_cast<std::size_t>(i)][axis] - c));
            EXPECT_NEAR(patchArea(e.arcs, f), 1.0 / (s * s), 1e-12);
        }
        EXPECT_LT(off, 1e-12);
        for (std::size_t h = 0; h < e.hm.hexes.size(); ++h) EXPECT_NEAR(closedVolume(e.arcs, h), 1.0 / (s * s * s), 1e-12);
    }
}

TEST(Arcs, GeneratedValidMapsTileBoundaryAndCloseVolumes) {
    std::vector<std::pair<std::string, ParametrizedTetMesh>> cases;
    cases.emplace_back("cylinder k=3", generateCylinder(3, 2, 2, 2, 1));
    cases.emplace_back("cylinder k=5", generateCylinder(5, 2, 1, 3, 2));
    cases.emplace_back("cylinder k=6 coarse", generateCylinder(6, 3, 2, 1, 1));
    cases.emplace_back("ring", generateRing(6, 2, 1, 4, 2, 1));
    cases.emplace_back("twisted ring", generateTwistedRing(6, 2, 4, 2));
    {
        ParametrizedTetMesh pm = generateCylinder(4, 2, 2, 2, 1);
        applyRandomChartTransforms(pm, 7);
        cases.emplace_back("cylinder k=4 random charts", std::move(pm));
    }
    {
        ParametrizedTetMesh pm = generateCube(2, 5);  // large tets: implicit cells
        cases.emplace_back("cube implicit cells", std::move(pm));
    }
    {
        // Moved vertex parameters (consistent in all charts), no fold: a curved map.
        ParametrizedTetMesh pm = generateCylinder(5, 3, 2, 2, 2);
        perturbParameters(pm, 0.15, 3);
        cases.emplace_back("perturbed cylinder k=5", std::move(pm));
    }
    for (const auto& c : cases) {
        const Extracted e = extractWithArcs(c.second);
        expectValidArcs(c.second, e, c.first);
    }
}

TEST(Arcs, SingularAxisArcsLieOnTheAxis) {
    for (int k : {3, 5, 6}) {
        SCOPED_TRACE("valence " + std::to_string(k));
        const ParametrizedTetMesh pm = generateCylinder(k, 2, 3, 2, 2);
        const Extracted e = extractWithArcs(pm);
        ASSERT_TRUE(e.rep.valid_all_hex);
        auto onAxis = [&](const Vec3d& x) { return std::hypot(x[0], x[1]); };
        int axisArcs = 0;
        double worst = 0;
        for (std::size_t a = 0; a < e.arcs.edges.size(); ++a) {
            if (onAxis(e.hm.vertices[static_cast<std::size_t>(e.arcs.edges[a][0])]) > 1e-12 ||
                onAxis(e.hm.vertices[static_cast<std::size_t>(e.arcs.edges[a][1])]) > 1e-12)
                continue;
            ++axisArcs;
            for (std::size_t p = e.arcs.arc_offset[a]; p < e.arcs.arc_offset[a + 1]; ++p)
                worst = std::max(worst, onAxis(e.arcs.arc_points[p]));
            EXPECT_GE(e.arcs.arc_offset[a + 1] - e.arcs.arc_offset[a], 2u);
        }
        EXPECT_EQ(axisArcs, 3);  // H = 3 hex edges along the axis
        EXPECT_LT(worst, 1e-12);
    }
}

TEST(Arcs, DefectiveMapsReportFailuresAndNeverCrash) {
    long flippedSeen = 0;
    for (unsigned seed : {1u, 2u, 3u}) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        ParametrizedTetMesh pm = generateCylinder(3, 3, 2, 3, 2);
        perturbParameters(pm, 0.4, seed);
        const Extracted e = extractWithArcs(pm);
        flippedSeen += e.rep.input.flipped_tets;
        EXPECT_EQ(e.arcs.hex_edges.size(), e.hm.hexes.size());
        EXPECT_EQ(e.rep.arcs.failed_edges, static_cast<long>(e.arcs.failed_edges.size()));
        EXPECT_EQ(e.rep.arcs.failed_faces, static_cast<long>(e.arcs.failed_faces.size()));
        EXPECT_LE(e.rep.arcs.failed_edge_ids.size(), ExtractionReport::Arcs::kMaxListed);
        EXPECT_TRUE(std::is_sorted(e.arcs.failed_edges.begin(), e.arcs.failed_edges.end()));
        for (int f : e.arcs.failed_faces) EXPECT_EQ(e.arcs.patch_offset[static_cast<std::size_t>(f)], e.arcs.patch_offset[static_cast<std::size_t>(f) + 1]);
        for (int a : e.arcs.failed_edges) EXPECT_EQ(e.arcs.arc_offset[static_cast<std::size_t>(a)], e.arcs.arc_offset[static_cast<std::size_t>(a) + 1]);
        // Formed arcs end at the hex vertices, as on valid maps.
        EXPECT_LT(worstEndpointError(e), 1e-9 * boundingDiagonal(pm.mesh));
        if (e.rep.arcs.failed_edges + e.rep.arcs.failed_faces > 0) {
            EXPECT_FALSE(e.rep.warnings.empty());
        }
    }
    EXPECT_GT(flippedSeen, 0);  // the perturbation did produce folds
}

TEST(Arcs, ExtremeFoldsListTheFacesWithoutCompletePatch) {
    // Amplitude 3 on a valence-3 cylinder: the hex mesh is still valid, but some faces'
    // preimages fall apart into pieces no corner dart reaches; they must be reported.
    ParametrizedTetMesh pm = generateCylinder(3, 3, 2, 3, 2);
    perturbParameters(pm, 3.0, 1);
    const Extracted e = extractWithArcs(pm);
    ASSERT_TRUE(e.rep.valid_all_hex);
    ASSERT_GT(e.rep.arcs.failed_faces, 0);
    EXPECT_EQ(e.rep.arcs.failed_face_ids, e.arcs.failed_faces);  // fewer than kMaxListed here
    const std::string w = std::to_string(e.rep.arcs.failed_faces) + " of " + std::to_string(e.arcs.faces.size()) + " hex faces have no complete patch";
    bool found = false;
    for (const auto& s : e.rep.warnings) found = found || s.find(w) != std::string::npos;
    EXPECT_TRUE(found);
    // Every other face's patch has signed parametric area 1, so in 3D it is non-empty.
    for (std::size_t f = 0; f < e.arcs.faces.size(); ++f) {
        if (!std::binary_search(e.arcs.failed_faces.begin(), e.arcs.failed_faces.end(), static_cast<int>(f))) {
            EXPECT_GT(patchArea(e.arcs, f), 0);
        }
    }
}

TEST(Arcs, OffByDefaultAndSameMeshWhenOn) {
    ParametrizedTetMesh pm = generateCylinder(5, 2, 2, 2, 1);
    pm.mesh.build_adjacency();
    HexMesh plain;
    const ExtractionReport rep = extractHexMesh(pm, plain);
    EXPECT_EQ(rep.arcs.edges, 0);
    EXPECT_EQ(rep.timings_s.arcs, 0.0);
    const Extracted e = extractWithArcs(pm);
    EXPECT_EQ(e.hm.hexes, plain.hexes);
    EXPECT_EQ(e.hm.vertices, plain.vertices);
    EXPECT_GT(e.rep.arcs.edges, 0);
}

TEST(Arcs, SameArcsForAnyThreadCount) {
    // The stage traces blocks of 256 hexes: the cubes have 1,728 and 512 hexes, so several
    // threads take blocks and append them out of order of completion.
    ParametrizedTetMesh charts = generateCube(6, 12);
    applyRandomChartTransforms(charts, 5);
    ParametrizedTetMesh folded = generateCube(8, 8);
    perturbParameters(folded, 1.0, 1);
    for (const ParametrizedTetMesh* pm : {&charts, &folded}) {
        const Extracted a = extractWithArcs(*pm, 1);
        ASSERT_GT(a.hm.hexes.size(), 2u * 256u - 1u);
        for (int threads : {2, 3}) {
            SCOPED_TRACE("threads " + std::to_string(threads));
            const Extracted b = extractWithArcs(*pm, threads);
            EXPECT_EQ(a.arcs.edges, b.arcs.edges);
            EXPECT_EQ(a.arcs.faces, b.arcs.faces);
            EXPECT_EQ(a.arcs.hex_edges, b.arcs.hex_edges);
            EXPECT_EQ(a.arcs.hex_faces, b.arcs.hex_faces);
            EXPECT_EQ(a.arcs.hex_face_sign, b.arcs.hex_face_sign);
            EXPECT_EQ(a.arcs.arc_offset, b.arcs.arc_offset);
            EXPECT_EQ(a.arcs.arc_points, b.arcs.arc_points);
            EXPECT_EQ(a.arcs.patch_offset, b.arcs.patch_offset);
            EXPECT_EQ(a.arcs.patch_triangles, b.arcs.patch_triangles);
            EXPECT_EQ(a.arcs.patch_points, b.arcs.patch_points);
            EXPECT_EQ(a.arcs.failed_edges, b.arcs.failed_edges);
            EXPECT_EQ(a.arcs.failed_faces, b.arcs.failed_faces);
        }
    }
}

TEST(Arcs, VtuWritersWriteOneCellPerArcAndTriangle) {
    const Extracted e = extractWithArcs(generateCube(2, 2));
    const std::string a = ::testing::TempDir() + "arcs_test_arcs.vtu", p = ::testing::TempDir() + "arcs_test_patches.vtu";
    writeEdgeArcsVtu(a, e.arcs);
    writeFacePatchesVtu(p, e.arcs);
    auto read = [](const std::string& path) {
        std::ifstream in(path);
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    };
    const std::string arcs = read(a), patches = read(p);
    EXPECT_NE(arcs.find("NumberOfCells=\"" + std::to_string(e.arcs.edges.size()) + "\""), std::string::npos);
    EXPECT_NE(arcs.find("Name=\"edge_id\""), std::string::npos);
    EXPECT_NE(patches.find("NumberOfCells=\"" + std::to_string(e.arcs.patch_triangles.size()) + "\""), std::string::npos);
    EXPECT_NE(patches.find("Name=\"face_id\""), std::string::npos);
    std::remove(a.c_str());
    std::remove(p.c_str());
    EXPECT_THROW(writeEdgeArcsVtu("/nonexistent-dir/x.vtu", e.arcs), InputError);
}
