#include "QuadAssembly.hh"

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
    auto area = [](const Vec3d& a, const Vec3d& b, double x, double y) {
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

QuadAssemblyStats assembleQuadMesh(const GMap<2>& g, const std::vector<TriDart>& darts, const QuadOrbitLabels& labels,
                                   const ParametrizedTriMesh& mesh, const TriParams& params, QuadMesh& out) {
    QuadAssemblyStats st;
    out = QuadMesh();
    const auto& L = g.links();
    const std::size_t n = L.size();
    out.vertices.assign(static_cast<std::size_t>(labels.n_vertices), Vec3d(0, 0, 0));
    std::vector<char> placed(static_cast<std::size_t>(labels.n_vertices), 0);
    for (std::size_t d = 0; d < n; ++d) {
        const int v = labels.vertex[d];
        if (v < 0 || placed[static_cast<std::size_t>(v)]) continue;
        placed[static_cast<std::size_t>(v)] = 1;
        out.vertices[static_cast<std::size_t>(v)] = pointOf(mesh, params, darts[d]);
    }
    std::vector<char> edgeBoundary(static_cast<std::size_t>(labels.n_edges), 0);
    for (std::size_t d = 0; d < n; ++d)
        if (labels.edge[d] >= 0 && L[d][2] == static_cast<int>(d)) edgeBoundary[static_cast<std::size_t>(labels.edge[d])] = 1;
    for (char b : edgeBoundary) st.boundary_edges += b;
    std::vector<char> done(static_cast<std::size_t>(labels.n_faces), 0);
    std::vector<int> loop;
    for (std::size_t s = 0; s < n; ++s) {
        const int f = labels.face[s];
        if (f < 0 || done[static_cast<std::size_t>(f)]) continue;
        done[static_cast<std::size_t>(f)] = 1;
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
        std::vector<int> distinct = loop;
        std::sort(distinct.begin(), distinct.end());
        distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
        if (closed && loop.size() == 4 && distinct.size() == 4) {
            out.quads.push_back({loop[0], loop[1], loop[2], loop[3]});
            ++st.quads;
        } else if (distinct.size() >= 3) {
            out.polygons.push_back(loop);
            ++st.polygons;
        } else {
            ++st.dropped_faces;
        }
    }
    return st;
}

} // namespace HexEx
