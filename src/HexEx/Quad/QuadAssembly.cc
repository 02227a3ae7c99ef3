#include "QuadAssembly.hh"

#include "../Core/Parallel.hh"

#include <algorithm>

namespace HexEx {

namespace {
/// +1 if the dart's frame turns counter-clockwise in parameter space (relative to its sign).
int frameOrientation(const TriDart& d) {
    const Vec3i a = dirVec(d.d1), b = dirVec(d.d2);
    return (a[0] * b[1] - a[1] * b[0]) * d.sign;
}

/// Position of grid point (x, y) of triangle f by barycentric coordinates.
Vec3d pointOf(const ParametrizedTriMesh& mesh, const TriParams& params, const TriDart& d) {
    const auto& p = params[static_cast<std::size_t>(d.tri)];
    const auto& t = mesh.triangles[static_cast<std::size_t>(d.tri)];
    auto area = [](const Vec2d& a, const Vec2d& b, double x, double y) {
        return (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]);
    };
    const double total = area(p[0], p[1], p[2][0], p[2][1]);
    Vec3d r(0, 0, 0);
    for (int i = 0; i < 3; ++i) {
        const double w = area(p[(i + 1) % 3], p[(i + 2) % 3], d.x, d.y) / total;
        r += w * mesh.points[static_cast<std::size_t>(t[i])];
    }
    return r;
}
} // namespace

QuadAssemblyStats assembleQuadMesh(const QuadLinks& L, const TriDartVector& darts, const QuadOrbitLabels& labels,
                                   const ParametrizedTriMesh& mesh, const TriParams& params, QuadMesh& out, int threads) {
    QuadAssemblyStats st;
    out = QuadMesh();
    const std::size_t n = L.size();
    const int chunks = std::max(1, threads);
    const std::size_t nv = static_cast<std::size_t>(labels.n_vertices);
    out.vertices.resize(nv);
    parallelChunks(nv, chunks, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t v = b; v < e; ++v)
            out.vertices[v] = pointOf(mesh, params, darts[static_cast<std::size_t>(labels.vertex_first[v])]);
    });
    // An edge is on the boundary if any of its darts has a free alpha_2 (flags set with
    // relaxed atomic stores: every writer stores the same value).
    std::vector<char> edgeBoundary(static_cast<std::size_t>(labels.n_edges), 0);
    parallelChunks(n, chunks, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t d = b; d < e; ++d)
            if (labels.edge[d] >= 0 && L[d][2] == static_cast<int>(d))
                __atomic_store_n(&edgeBoundary[static_cast<std::size_t>(labels.edge[d])], 1, __ATOMIC_RELAXED);
    });
    for (char b : edgeBoundary) st.boundary_edges += b;
    // Faces in label order, i.e. by smallest dart: per chunk of labels, concatenated in order.
    struct Part {
        std::vector<std::array<int, 4>> quads;
        std::vector<std::vector<int>> polygons;
        QuadAssemblyStats st;
    };
    std::vector<Part> parts(static_cast<std::size_t>(chunks));
    parallelChunks(static_cast<std::size_t>(labels.n_faces), chunks, [&](int c, std::size_t fb, std::size_t fe) {
        Part& part = parts[static_cast<std::size_t>(c)];
        std::vector<int> loop, distinct;
        for (std::size_t f = fb; f < fe; ++f) {
            const std::size_t s = static_cast<std::size_t>(labels.face_first[f]);
            int start = static_cast<int>(s);
            if (frameOrientation(darts[s]) < 0 && L[s][0] != start) start = L[s][0];
            loop.clear();
            int d = start;
            bool closed = false;
            for (int step = 0; step < static_cast<int>(n); ++step) {
                loop.push_back(labels.vertex[static_cast<std::size_t>(d)]);
                const int a = L[static_cast<std::size_t>(d)][0];
                if (a == d) break;
                const int b = L[static_cast<std::size_t>(a)][1];
                if (b == a) break;
                d = b;
                if (d == start) {
                    closed = true;
                    break;
                }
            }
            distinct = loop;
            std::sort(distinct.begin(), distinct.end());
            distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
            if (closed && loop.size() == 4 && distinct.size() == 4) {
                part.quads.push_back({loop[0], loop[1], loop[2], loop[3]});
                ++part.st.quads;
            } else if (distinct.size() >= 3) {
                part.polygons.push_back(loop);
                ++part.st.polygons;
            } else {
                ++part.st.dropped_faces;
            }
        }
    });
    std::size_t nq = 0;
    for (const Part& p : parts) nq += p.quads.size();
    out.quads.reserve(nq);
    for (Part& p : parts) {
        out.quads.insert(out.quads.end(), p.quads.begin(), p.quads.end());
        for (auto& poly : p.polygons) out.polygons.push_back(std::move(poly));
        st.quads += p.st.quads;
        st.polygons += p.st.polygons;
        st.dropped_faces += p.st.dropped_faces;
    }
    return st;
}

} // namespace HexEx
