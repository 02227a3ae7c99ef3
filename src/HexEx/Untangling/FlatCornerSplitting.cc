/// @file FlatCornerSplitting.cc
/// Local pillows of the hexes at flat corners along feature curves (see FlatCornerSplitting.hh).

#include "FlatCornerSplitting.hh"
#include "FeatureCorners.hh"

#include "../Mesh/HexArcs.hh"
#include "../Mesh/HexFaceRecords.hh"
#include "../Mesh/HexValidity.hh"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace HexEx {

namespace {

/// Hex @p h renumbered so that its face @p face (HexArcs::kHexFaces, outward) is the top
/// quad 4-7 in the face's loop order; the same hex, positively ordered like the input.
std::array<int, 8> withTopFace(const std::array<int, 8>& h, int face) {
    std::array<int, 8> out{};
    for (int k = 0; k < 4; ++k) {
        const int l = HexArcs::kHexFaces[face][k];
        out[static_cast<std::size_t>(4 + k)] = h[static_cast<std::size_t>(l)];
        for (const auto& e : HexArcs::kHexEdges) {  // the edge from l that leaves the face
            const int o = e[0] == l ? e[1] : e[1] == l ? e[0] : -1;
            if (o < 0) continue;
            bool in_face = false;
            for (int j = 0; j < 4; ++j) in_face = in_face || HexArcs::kHexFaces[face][j] == o;
            if (!in_face) out[static_cast<std::size_t>(k)] = h[static_cast<std::size_t>(o)];
        }
    }
    return out;
}

/// The 8 positions of hex @p h.
std::array<Vec3d, 8> positions(const HexMesh& mesh, const std::array<int, 8>& h) {
    std::array<Vec3d, 8> p;
    for (std::size_t k = 0; k < 8; ++k) p[k] = mesh.vertices[static_cast<std::size_t>(h[k])];
    return p;
}

} // namespace

FlatCornerReport splitFlatFeatureCorners(HexMesh& mesh, const FlatCornerOptions& options) {
    FlatCornerReport rep;
    const std::size_t nv = mesh.vertices.size(), nh = mesh.hexes.size();
    for (std::size_t c = 0; c < nh; ++c)
        for (const int v : mesh.hexes[c])
            if (v < 0 || static_cast<std::size_t>(v) >= nv)
                throw std::invalid_argument("flat corner splitting: hex " + std::to_string(c) + " references vertex " +
                                            std::to_string(v) + " of " + std::to_string(nv));
    // Boundary quads (outward loops) in hex, face order, and boundary faces per hex.
    const std::vector<HexFaceRecord> rec = sortedHexFaces(mesh);
    std::vector<std::pair<int, int>> bnd;
    std::vector<int> boundary_faces(nh, 0);
    for (std::size_t i = 0; i < rec.size();) {
        std::size_t j = i;
        while (j < rec.size() && rec[j].key == rec[i].key) ++j;
        if (j - i == 1) {
            bnd.emplace_back(rec[i].hex, rec[i].face);
            ++boundary_faces[static_cast<std::size_t>(rec[i].hex)];
        }
        i = j;
    }
    std::sort(bnd.begin(), bnd.end());
    std::vector<std::array<int, 4>> quads;
    std::vector<char> on_boundary(nv, 0);
    for (const auto& hf : bnd) {
        std::array<int, 4> q{};
        for (int k = 0; k < 4; ++k) {
            q[static_cast<std::size_t>(k)] =
                mesh.hexes[static_cast<std::size_t>(hf.first)][static_cast<std::size_t>(HexArcs::kHexFaces[hf.second][k])];
            on_boundary[static_cast<std::size_t>(q[static_cast<std::size_t>(k)])] = 1;
        }
        quads.push_back(q);
    }
    // Feature edges: the two quads' normals differ by more than the feature angle, or the
    // edge is not in exactly two boundary quads.
    const std::vector<QuadEdge> edges = sortedQuadEdges(quads);
    const double cos_feature = std::cos(options.feature_angle_deg * M_PI / 180.0);
    FeatureEdges feature;
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j].a == edges[i].a && edges[j].b == edges[i].b) ++j;
        if (j - i != 2 || (quadUnitNormal(mesh, quads[static_cast<std::size_t>(edges[i].q)]) |
                           quadUnitNormal(mesh, quads[static_cast<std::size_t>(edges[i + 1].q)])) < cos_feature)
            feature.sorted.emplace_back(edges[i].a, edges[i].b);
        i = j;
    }
    const double cos_flat = std::cos(options.flat_angle_deg * M_PI / 180.0);
    std::vector<char> used(nv, 0);  // vertices of hexes split so far
    for (std::size_t i = 0; i < quads.size(); ++i) {
        const auto& q = quads[i];
        int flat = -1;  // the flattest corner of q between two feature edges, if flat
        double flat_cos = cos_flat;
        for (std::size_t k = 0; k < 4; ++k) {
            double cs = 0;
            if (!featureCornerCosine(mesh, q, k, feature, cs)) continue;
            if (cs < cos_flat) ++rep.flat_corners;
            if (cs < flat_cos) {
                flat_cos = cs;
                flat = static_cast<int>(k);
            }
        }
        if (flat < 0) continue;
        const std::size_t c = static_cast<std::size_t>(bnd[i].first);
        const std::array<int, 8> h = withTopFace(mesh.hexes[c], bnd[i].second);
        bool ok = boundary_faces[c] == 1 && classifyHexValidity(positions(mesh, h)) == HexValidity::Valid;
        for (std::size_t k = 0; k < 8 && ok; ++k) {
            const std::size_t v = static_cast<std::size_t>(h[k]);
            ok = !used[v] && (k >= 4 || !on_boundary[v]);
        }
        if (!ok) {
            ++rep.skipped_hexes;
            continue;
        }
        // h: inner quad F = 0-3, boundary quad Q = 4-7, F[k] below Q[k]; q[flat] is Q[flat].
        const std::array<Vec3d, 8> p = positions(mesh, h);
        const Vec3d mid = (p[static_cast<std::size_t>(4 + flat)] + p[static_cast<std::size_t>(4 + (flat + 2) % 4)]) * 0.5;
        Vec3d centre(0, 0, 0);
        for (const Vec3d& x : p) centre += x * 0.125;
        const int base = static_cast<int>(mesh.vertices.size());
        // Local corner j of h -> its copy: Q[k] -> base + k, F[k] -> base + 4 + k.
        auto copyOf = [&](int j) { return j >= 4 ? base + (j - 4) : base + 4 + j; };
        std::array<std::array<int, 8>, 6> cells{};
        for (std::size_t k = 0; k < 8; ++k) cells[0][k] = copyOf(static_cast<int>(k));  // H*
        for (int f = 0, n = 1; f < 6; ++f) {
            if (f == 1) continue;  // the boundary quad: no hex on it
            for (std::size_t k = 0; k < 4; ++k) {
                const int j = HexArcs::kHexFaces[f][k];
                cells[static_cast<std::size_t>(n)][k] = copyOf(j);
                cells[static_cast<std::size_t>(n)][k + 4] = h[static_cast<std::size_t>(j)];
            }
            ++n;
        }
        bool placed = false;
        for (int r = 0; r <= options.max_halvings && !placed; ++r) {
            const double t = std::ldexp(options.width, -r);
            mesh.vertices.resize(static_cast<std::size_t>(base) + 8);
            for (std::size_t k = 0; k < 4; ++k) {
                const Vec3d top = mid + (p[4 + k] - mid) * (1 - t);
                mesh.vertices[static_cast<std::size_t>(base) + k] = top;
                mesh.vertices[static_cast<std::size_t>(base) + 4 + k] = p[k] + (centre - p[k]) * t;
            }
            placed = true;
            for (std::size_t n = 0; n < 6 && placed; ++n)
                placed = classifyHexValidity(positions(mesh, cells[n])) == HexValidity::Valid;
        }
        if (!placed) {
            mesh.vertices.resize(static_cast<std::size_t>(base));
            ++rep.skipped_hexes;
            continue;
        }
        for (const int v : h) used[static_cast<std::size_t>(v)] = 1;
        mesh.hexes[c] = cells[0];
        for (std::size_t n = 1; n < 6; ++n) mesh.hexes.push_back(cells[n]);
        ++rep.split_hexes;
        rep.hexes_added += 5;
        rep.vertices_added += 8;
    }
    return rep;
}

} // namespace HexEx
