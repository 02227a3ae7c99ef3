/// @file BoundaryPillowing.cc
/// One layer of hexes along the boundary of an all-hex mesh (see BoundaryPillowing.hh).

#include "BoundaryPillowing.hh"

#include "../Core/Parallel.hh"
#include "../Core/UnionFind.hh"
#include "FeatureCorners.hh"
#include "../Mesh/HexArcs.hh"
#include "../Mesh/HexFaceRecords.hh"
#include "../Mesh/HexMeshQuality.hh"
#include "../Mesh/HexValidity.hh"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace HexEx {

namespace {

/// "(a b c d)" for messages.
std::string quadText(const std::array<int, 4>& q) {
    return "(" + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) + " " +
           std::to_string(q[3]) + ")";
}

/// Outward boundary quads of @p mesh (loops oriented outward), in hex then face order;
/// @p owner gets the hex of each, @p owner_face its face number (HexArcs::kHexFaces).
/// Throws std::invalid_argument on the input errors listed in pillowBoundary().
std::vector<std::array<int, 4>> boundaryQuads(const HexMesh& mesh, std::vector<int>& owner, std::vector<int>& owner_face) {
    const long nv = static_cast<long>(mesh.vertices.size());
    for (std::size_t c = 0; c < mesh.hexes.size(); ++c) {
        const auto& h = mesh.hexes[c];
        for (std::size_t i = 0; i < 8; ++i) {
            if (h[i] < 0 || h[i] >= nv)
                throw std::invalid_argument("pillowing: hex " + std::to_string(c) + " references vertex " +
                                            std::to_string(h[i]) + " of " + std::to_string(nv));
            for (std::size_t j = 0; j < i; ++j)
                if (h[i] == h[j])
                    throw std::invalid_argument("pillowing: hex " + std::to_string(c) + " has the vertex " +
                                                std::to_string(h[i]) + " twice");
        }
    }
    const std::vector<HexFaceRecord> rec = sortedHexFaces(mesh);
    std::vector<std::pair<int, int>> bnd;  // (hex, face), sorted below
    for (std::size_t i = 0; i < rec.size();) {
        std::size_t j = i;
        while (j < rec.size() && rec[j].key == rec[i].key) ++j;
        if (j - i > 2)
            throw std::invalid_argument("pillowing: the quad " + quadText(rec[i].key) + " is shared by " +
                                        std::to_string(j - i) + " hexes (non-manifold mesh)");
        if (j - i == 1) bnd.emplace_back(rec[i].hex, rec[i].face);
        i = j;
    }
    std::sort(bnd.begin(), bnd.end());
    std::vector<std::array<int, 4>> quads;
    quads.reserve(bnd.size());
    owner.clear();
    owner_face.clear();
    for (const auto& hf : bnd) {
        owner.push_back(hf.first);
        owner_face.push_back(hf.second);
        std::array<int, 4> q;
        for (int k = 0; k < 4; ++k)
            q[static_cast<std::size_t>(k)] = mesh.hexes[static_cast<std::size_t>(hf.first)][static_cast<std::size_t>(HexArcs::kHexFaces[hf.second][k])];
        quads.push_back(q);
    }
    return quads;
}

/// Checks that every boundary edge is in exactly two boundary quads and that the boundary
/// quads at every boundary vertex form one connected fan. @p vq / @p vq_off: quads per vertex (CSR).
void checkManifold(const std::vector<std::array<int, 4>>& quads, const std::vector<int>& vq,
                   const std::vector<int>& vq_off) {
    std::vector<std::pair<int, int>> edges;
    edges.reserve(quads.size() * 4);
    for (const auto& q : quads)
        for (std::size_t k = 0; k < 4; ++k) edges.emplace_back(std::min(q[k], q[(k + 1) % 4]), std::max(q[k], q[(k + 1) % 4]));
    std::sort(edges.begin(), edges.end());
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        if (j - i != 2)
            throw std::invalid_argument("pillowing: non-manifold boundary: the edge (" + std::to_string(edges[i].first) +
                                        " " + std::to_string(edges[i].second) + ") is in " + std::to_string(j - i) +
                                        " boundary quads (expected 2)");
        i = j;
    }
    // Fans: quads at v joined when they share an edge at v.
    for (std::size_t v = 0; v + 1 < vq_off.size(); ++v) {
        const int b = vq_off[v], e = vq_off[v + 1];
        if (e - b < 2) continue;
        UnionFind sheet(static_cast<std::size_t>(e - b));
        std::vector<std::pair<int, int>> nb;  // (neighbour vertex along an edge at v, local quad)
        for (int i = b; i < e; ++i) {
            const auto& q = quads[static_cast<std::size_t>(vq[static_cast<std::size_t>(i)])];
            for (std::size_t k = 0; k < 4; ++k)
                if (q[k] == static_cast<int>(v)) {
                    nb.emplace_back(q[(k + 1) % 4], i - b);
                    nb.emplace_back(q[(k + 3) % 4], i - b);
                }
        }
        std::sort(nb.begin(), nb.end());
        for (std::size_t i = 0; i + 1 < nb.size(); ++i)
            if (nb[i].first == nb[i + 1].first) {
                sheet.unite(nb[i].second, nb[i + 1].second);
            }
        int sheets = 0;
        for (int i = 0; i < e - b; ++i) sheets += sheet.find(i) == i;
        if (sheets > 1)
            throw std::invalid_argument("pillowing: non-manifold boundary: " + std::to_string(sheets) +
                                        " separate sheets of the boundary meet at vertex " + std::to_string(v));
    }
}

/// Which boundary quads get a new hex: all, except the quads of patches (regions bounded by
/// feature edges) that have a quad with two edges on the patch border at a corner angle
/// above PillowOptions::skip_patch_angle_deg. Fills the patch counts of @p rep.
std::vector<char> layerQuads(const HexMesh& mesh, const std::vector<std::array<int, 4>>& quads,
                             const PillowOptions& opt, PillowReport& rep) {
    const std::size_t nq = quads.size();
    std::vector<Vec3d> normal(nq);
    for (std::size_t i = 0; i < nq; ++i) normal[i] = quadUnitNormal(mesh, quads[i]);
    // Edges (min, max, quad), sorted: each boundary edge has exactly two quads (checked).
    const std::vector<QuadEdge> edges = sortedQuadEdges(quads);
    const double cos_feature = std::cos(opt.feature_angle_deg * M_PI / 180.0);
    UnionFind patch(nq);
    FeatureEdges feature;
    for (std::size_t i = 0; i + 1 < edges.size(); i += 2) {
        const int q1 = edges[i].q, q2 = edges[i + 1].q;
        if ((normal[static_cast<std::size_t>(q1)] | normal[static_cast<std::size_t>(q2)]) < cos_feature) {
            feature.sorted.emplace_back(edges[i].a, edges[i].b);
        } else {
            patch.unite(q1, q2);
        }
    }
    const double cos_skip = std::cos(opt.skip_patch_angle_deg * M_PI / 180.0);
    std::vector<char> skip(nq, 0);
    for (std::size_t i = 0; i < nq; ++i) {
        const auto& q = quads[i];
        for (std::size_t k = 0; k < 4; ++k) {
            double cs = 0;
            if (featureCornerCosine(mesh, q, k, feature, cs) && cs < cos_skip)
                skip[static_cast<std::size_t>(patch.find(static_cast<int>(i)))] = 1;
        }
    }
    std::vector<char> in(nq, 1);
    for (std::size_t i = 0; i < nq; ++i) {
        const int r = patch.find(static_cast<int>(i));
        rep.boundary_patches += r == static_cast<int>(i);
        rep.skipped_patches += r == static_cast<int>(i) && skip[i];
        in[i] = !skip[static_cast<std::size_t>(r)];
    }
    return in;
}

/// Calls @p f(e1, e2) for every corner at the boundary vertex @p v of the layer quads at
/// @p v, with e1, e2 the quad's edges at v ordered so that -(e1 x e2) is the inward normal
/// (the quads are oriented outward: (next - v) x (prev - v) points outward at v).
template <class F>
void forLayerCorners(const HexMesh& mesh, const std::vector<std::array<int, 4>>& quads, const std::vector<int>& vq,
                     const std::vector<int>& vq_off, const std::vector<char>& in_layer, int v, F&& f) {
    const Vec3d& p = mesh.vertices[static_cast<std::size_t>(v)];
    for (int k = vq_off[static_cast<std::size_t>(v)]; k < vq_off[static_cast<std::size_t>(v) + 1]; ++k) {
        const std::size_t qi = static_cast<std::size_t>(vq[static_cast<std::size_t>(k)]);
        if (!in_layer[qi]) continue;
        const auto& q = quads[qi];
        for (std::size_t j = 0; j < 4; ++j) {
            if (q[j] != v) continue;
            f(mesh.vertices[static_cast<std::size_t>(q[(j + 1) % 4])] - p, mesh.vertices[static_cast<std::size_t>(q[(j + 3) % 4])] - p);
        }
    }
}

/// Smallest scaled Jacobian, over the layer quads at @p v, of the new hex's corner at @p v
/// when its copy lies in the unit direction @p d: det(e1, e2, d) / (|e1| |e2|), with e1, e2
/// the quad's edges at v in the order that makes it positive for an inward d.
double cornerMeasure(const HexMesh& mesh, const std::vector<std::array<int, 4>>& quads, const std::vector<int>& vq,
                     const std::vector<int>& vq_off, const std::vector<char>& in_layer, int v, const Vec3d& d) {
    double worst = 2;
    forLayerCorners(mesh, quads, vq, vq_off, in_layer, v, [&](const Vec3d& e1, const Vec3d& e2) {
        const double l = e1.norm() * e2.norm();
        worst = std::min(worst, l > 0 ? -((e1 % e2) | d) / l : -1.0);
    });
    return worst;
}

/// Inward direction (unit) for the copy of the boundary vertex @p v: the mean inward normal
/// @p start, improved by steps towards the inward normal of the worst new corner
/// (cornerMeasure()) while the worst rises (a max-min ascent on the sphere).
Vec3d inwardDirection(const HexMesh& mesh, const std::vector<std::array<int, 4>>& quads, const std::vector<int>& vq,
                      const std::vector<int>& vq_off, const std::vector<char>& in_layer, int v, const Vec3d& start) {
    if (!(start.norm() > 0)) return Vec3d(0, 0, 0);
    Vec3d dir = start;
    double best = cornerMeasure(mesh, quads, vq, vq_off, in_layer, v, dir);
    // Max-min ascent on the sphere: move towards the inward normal of the worst corner.
    for (int it = 0; it < 30; ++it) {
        Vec3d worst_n(0, 0, 0);
        double worst = 2;
        forLayerCorners(mesh, quads, vq, vq_off, in_layer, v, [&](const Vec3d& e1, const Vec3d& e2) {
            const Vec3d n = -(e1 % e2);
            const double l = e1.norm() * e2.norm();
            if (!(l > 0)) return;
            const double m = (n | dir) / l;
            if (m < worst) {
                worst = m;
                worst_n = n.norm() > 0 ? n / n.norm() : n;
            }
        });
        bool improved = false;
        for (double step = 0.5; step > 1e-3 && !improved; step *= 0.5) {
            Vec3d t = dir + worst_n * step;
            if (!(t.norm() > 0)) continue;
            t /= t.norm();
            const double m = cornerMeasure(mesh, quads, vq, vq_off, in_layer, v, t);
            if (m > best + 1e-12) {
                best = m;
                dir = t;
                improved = true;
            }
        }
        if (!improved) break;
    }
    return dir;
}

} // namespace

namespace {

/// One layer (see pillowBoundary()). With @p layered_from >= 0 the patch rule is off and the
/// layer goes on every boundary quad except the outer quads (face 1) of the hexes from
/// @p layered_from on (a layer that is already there).
PillowReport pillowPass(HexMesh& mesh, const PillowOptions& options, long layered_from) {
    const auto t0 = std::chrono::steady_clock::now();
    PillowReport rep;
    if (!mesh.polyhedra.empty())
        throw std::invalid_argument("pillowing needs an all-hex mesh: the mesh has " + std::to_string(mesh.polyhedra.size()) +
                                    " polyhedra");
    if (mesh.hexes.empty()) throw std::invalid_argument("pillowing: the mesh has no hexes");
    const int threads = resolveThreadCount(options.threads);
    const std::size_t nv = mesh.vertices.size(), nh = mesh.hexes.size();
    rep.hexes_before = static_cast<long>(nh);
    rep.vertices_before = static_cast<long>(nv);

    std::vector<int> owner, owner_face;
    const std::vector<std::array<int, 4>> quads = boundaryQuads(mesh, owner, owner_face);
    std::vector<int> vq_off(nv + 1, 0), vq(quads.size() * 4);
    for (const auto& q : quads)
        for (const int v : q) ++vq_off[static_cast<std::size_t>(v) + 1];
    for (std::size_t v = 0; v < nv; ++v) vq_off[v + 1] += vq_off[v];
    {
        std::vector<int> fill(vq_off.begin(), vq_off.end() - 1);
        for (std::size_t i = 0; i < quads.size(); ++i)
            for (const int v : quads[i]) vq[static_cast<std::size_t>(fill[static_cast<std::size_t>(v)]++)] = static_cast<int>(i);
    }
    checkManifold(quads, vq, vq_off);
    std::vector<char> in_layer;
    if (layered_from < 0) {
        in_layer = layerQuads(mesh, quads, options, rep);
    } else {
        in_layer.assign(quads.size(), 1);
        for (std::size_t i = 0; i < quads.size(); ++i)
            if (owner[i] >= layered_from && owner_face[i] == 1) in_layer[i] = 0;
    }
    // Vertices of layer quads get copies; "rim" vertices are also in a skipped quad. The
    // layer and the skipped quads must each form one fan at a rim vertex.
    std::vector<char> rim(nv, 0);
    auto fansAt = [&](std::size_t v, bool layer) {
        std::vector<int> local;
        for (int k = vq_off[v]; k < vq_off[v + 1]; ++k)
            if ((in_layer[static_cast<std::size_t>(vq[static_cast<std::size_t>(k)])] != 0) == layer)
                local.push_back(vq[static_cast<std::size_t>(k)]);
        UnionFind fan(local.size());
        std::vector<std::pair<int, int>> nb;
        for (std::size_t i = 0; i < local.size(); ++i) {
            const auto& q = quads[static_cast<std::size_t>(local[i])];
            for (std::size_t k = 0; k < 4; ++k)
                if (q[k] == static_cast<int>(v)) {
                    nb.emplace_back(q[(k + 1) % 4], static_cast<int>(i));
                    nb.emplace_back(q[(k + 3) % 4], static_cast<int>(i));
                }
        }
        std::sort(nb.begin(), nb.end());
        for (std::size_t i = 0; i + 1 < nb.size(); ++i)
            if (nb[i].first == nb[i + 1].first) {
                fan.unite(nb[i].second, nb[i + 1].second);
            }
        int fans = 0;
        for (std::size_t i = 0; i < local.size(); ++i) fans += fan.find(static_cast<int>(i)) == static_cast<int>(i);
        return fans;
    };
    // Marks the rim vertices; false if the layer would end on itself at a vertex.
    auto rimOk = [&]() {
        std::fill(rim.begin(), rim.end(), 0);
        for (std::size_t v = 0; v < nv; ++v) {
            int n_in = 0, n_skip = 0;
            for (int k = vq_off[v]; k < vq_off[v + 1]; ++k) (in_layer[static_cast<std::size_t>(vq[static_cast<std::size_t>(k)])] ? n_in : n_skip)++;
            if (n_in == 0 || n_skip == 0) continue;
            rim[v] = 1;
            if (fansAt(v, true) != 1 || fansAt(v, false) != 1) return false;
        }
        return true;
    };
    if (layered_from >= 0 && !rimOk()) {
        rep.message = "the second layer would end on itself at a vertex: not placed";
        rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return rep;
    }
    if (rep.skipped_patches > 0 && !rimOk()) {
        std::fill(in_layer.begin(), in_layer.end(), 1);
        std::fill(rim.begin(), rim.end(), 0);
        rep.skipped_patches = 0;
        rep.message = "the layer would end on itself at a vertex: the whole boundary is pillowed";
    }
    // Validity of the input (old hexes that were not Valid need not become so). Their
    // boundary quads get no new hex if the layer can end there: a new hex on a quad of a hex
    // that is not valid inherits that quad, often the cause (a fold of the boundary quads).
    const std::vector<HexValidity> before = hexValidities(mesh, threads);
    for (const auto v : before) rep.invalid_before += v != HexValidity::Valid;
    {
        const std::vector<char> saved = in_layer;
        std::vector<char> skip(quads.size(), 0);
        long n_skip = 0;
        for (std::size_t i = 0; i < quads.size(); ++i)
            if (in_layer[i] && before[static_cast<std::size_t>(owner[i])] != HexValidity::Valid) {
                skip[i] = 1;
                ++n_skip;
            }
        // Where the layer would end on itself, grow the skipped region by the quads around it
        // (vertex neighbours), at most 6 times.
        bool ok = n_skip == 0;
        for (int grow = 0; n_skip > 0 && grow <= 6; ++grow) {
            for (std::size_t i = 0; i < quads.size(); ++i) in_layer[i] = saved[i] && !skip[i];
            if ((ok = rimOk())) break;
            std::vector<char> near(nv, 0);
            for (std::size_t i = 0; i < quads.size(); ++i)
                if (skip[i])
                    for (const int v : quads[i]) near[static_cast<std::size_t>(v)] = 1;
            for (std::size_t i = 0; i < quads.size(); ++i)
                for (const int v : quads[i])
                    if (near[static_cast<std::size_t>(v)]) skip[i] = 1;
        }
        if (ok) {
            for (std::size_t i = 0; i < quads.size(); ++i) rep.skipped_quads += saved[i] && !in_layer[i];
        } else {
            in_layer = saved;
            rimOk();
        }
    }

    std::vector<int> copy(nv, -1);
    for (std::size_t i = 0; i < quads.size(); ++i)
        if (in_layer[i])
            for (const int v : quads[i]) copy[static_cast<std::size_t>(v)] = 0;
    std::vector<int> bverts;
    for (std::size_t v = 0; v < nv; ++v)
        if (copy[v] == 0) {
            copy[v] = static_cast<int>(nv + bverts.size());
            bverts.push_back(static_cast<int>(v));
        }


    // Mean edge length at each boundary vertex (hex edges, counted once per hex).
    std::vector<double> edge_sum(nv, 0);
    std::vector<int> edge_n(nv, 0);
    for (const auto& h : mesh.hexes)
        for (const auto& ed : HexArcs::kHexEdges) {
            const int a = h[static_cast<std::size_t>(ed[0])], b = h[static_cast<std::size_t>(ed[1])];
            if (copy[static_cast<std::size_t>(a)] < 0 && copy[static_cast<std::size_t>(b)] < 0) continue;
            const double l = (mesh.vertices[static_cast<std::size_t>(a)] - mesh.vertices[static_cast<std::size_t>(b)]).norm();
            for (const int v : {a, b}) {
                edge_sum[static_cast<std::size_t>(v)] += l;
                ++edge_n[static_cast<std::size_t>(v)];
            }
        }
    // Full-depth offset of each copy: along the mean inward normal of its quads, lengthened by
    // 1 / (smallest cosine to a quad normal), at most 2, so the copy lies about equally deep
    // below each quad. A rim vertex's copy goes along the skipped quads instead, towards
    // their centres (it stays on their surface where that is flat).
    std::vector<Vec3d> offset(bverts.size(), Vec3d(0, 0, 0));
    for (std::size_t i = 0; i < bverts.size(); ++i) {
        const std::size_t v = static_cast<std::size_t>(bverts[i]);
        const double h = edge_n[v] > 0 ? edge_sum[v] / edge_n[v] : 0.0;
        if (rim[v]) {
            Vec3d dir(0, 0, 0);
            for (int k = vq_off[v]; k < vq_off[v + 1]; ++k) {
                const std::size_t qi = static_cast<std::size_t>(vq[static_cast<std::size_t>(k)]);
                if (in_layer[qi]) continue;
                Vec3d c(0, 0, 0);
                for (const int w : quads[qi]) c += mesh.vertices[static_cast<std::size_t>(w)] * 0.25;
                const Vec3d d = c - mesh.vertices[v];
                if (d.norm() > 0) dir += d / d.norm();
            }
            if (dir.norm() > 1e-12) offset[i] = dir * (options.depth * h / dir.norm());
            continue;
        }
        std::vector<Vec3d> normals;
        Vec3d sum(0, 0, 0);
        for (int k = vq_off[v]; k < vq_off[v + 1]; ++k) {
            const Vec3d n = quadUnitNormal(mesh, quads[static_cast<std::size_t>(vq[static_cast<std::size_t>(k)])]);
            if (n.norm() == 0) continue;
            normals.push_back(n);
            sum += n;
        }
        const double slen = sum.norm();
        const Vec3d dir = inwardDirection(mesh, quads, vq, vq_off, in_layer, static_cast<int>(v),
                                          slen > 1e-12 && std::isfinite(slen) ? sum / -slen : Vec3d(0, 0, 0));
        if (dir.norm() == 0) continue;  // no inward direction: stays, found invalid below
        double cmin = 1;
        for (const auto& n : normals) cmin = std::min(cmin, -(n | dir));
        const double stretch = 1.0 / std::max(cmin, 0.5);
        offset[i] = dir * (options.depth * h * stretch);
    }

    // The result: copies appended, old hexes re-pointed, one new hex per boundary quad
    // (inner quad at the bottom, the outer quad on top: VTK order, positively oriented).
    HexMesh out;
    out.vertices = mesh.vertices;
    out.vertices.resize(nv + bverts.size());
    out.hexes = mesh.hexes;
    for (auto& h : out.hexes)
        for (auto& v : h)
            if (copy[static_cast<std::size_t>(v)] >= 0) v = copy[static_cast<std::size_t>(v)];
    std::vector<int> layer_quad;  // new hex nh + i is on the boundary quad layer_quad[i]
    for (std::size_t i = 0; i < quads.size(); ++i) {
        if (!in_layer[i]) continue;
        const auto& q = quads[i];
        layer_quad.push_back(static_cast<int>(i));
        out.hexes.push_back({{copy[static_cast<std::size_t>(q[0])], copy[static_cast<std::size_t>(q[1])],
                              copy[static_cast<std::size_t>(q[2])], copy[static_cast<std::size_t>(q[3])], q[0], q[1], q[2], q[3]}});
    }
    // Hexes to check: the new ones and the old ones at a boundary vertex.
    std::vector<int> check;
    for (std::size_t c = 0; c < nh; ++c)
        for (const int v : mesh.hexes[c])
            if (copy[static_cast<std::size_t>(v)] >= 0) {
                check.push_back(static_cast<int>(c));
                break;
            }
    for (std::size_t c = nh; c < out.hexes.size(); ++c) check.push_back(static_cast<int>(c));
    std::vector<int> halvings(bverts.size(), 0);
    auto place = [&](std::size_t i) {
        out.vertices[nv + i] = mesh.vertices[static_cast<std::size_t>(bverts[i])] + offset[i] * std::ldexp(1.0, -halvings[i]);
    };
    for (std::size_t i = 0; i < bverts.size(); ++i) place(i);
    auto corners = [&](int c) {
        std::array<Vec3d, 8> p;
        for (std::size_t k = 0; k < 8; ++k) p[k] = out.vertices[static_cast<std::size_t>(out.hexes[static_cast<std::size_t>(c)][k])];
        return p;
    };
    std::vector<char> bad(check.size(), 0);
    long failing = 0;
    for (int round = 0;; ++round) {
        parallelChunks(check.size(), check.size() < 2048 ? 1 : threads, [&](int, std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e; ++i) {
                const int c = check[i];
                // Old hexes that were valid must stay so, new ones must be valid unless the
                // hex whose face they sit on was not (its boundary face may be what is wrong).
                const std::size_t old = static_cast<std::size_t>(c) >= nh
                                            ? static_cast<std::size_t>(owner[static_cast<std::size_t>(layer_quad[static_cast<std::size_t>(c) - nh])])
                                            : static_cast<std::size_t>(c);
                const bool required = before[old] == HexValidity::Valid;
                bad[i] = required && classifyHexValidity(corners(c)) != HexValidity::Valid;
            }
        });
        failing = std::count(bad.begin(), bad.end(), 1);
        if (failing == 0 || round >= options.max_halvings) break;
        std::vector<char> shrink(bverts.size(), 0);
        for (std::size_t i = 0; i < check.size(); ++i) {
            if (!bad[i]) continue;
            for (const int v : out.hexes[static_cast<std::size_t>(check[i])])
                if (static_cast<std::size_t>(v) >= nv) shrink[static_cast<std::size_t>(v) - nv] = 1;
        }
        for (std::size_t i = 0; i < bverts.size(); ++i)
            if (shrink[i]) {
                ++halvings[i];
                place(i);
            }
    }
    if (failing > 0 && !options.allow_invalid) {
        int first = -1;
        for (std::size_t i = 0; i < check.size() && first < 0; ++i)
            if (bad[i]) first = check[i];
        rep.success = false;
        rep.message = "pillowing: " + std::to_string(failing) + " hexes could not be made certified valid by placing the "
                      "inner copies closer to the boundary (first: " +
                      (static_cast<std::size_t>(first) >= nh ? "the new hex on the boundary quad " +
                                                                    quadText(quads[static_cast<std::size_t>(layer_quad[static_cast<std::size_t>(first) - nh])])
                                                              : "hex " + std::to_string(first)) +
                      "); the mesh is unchanged";
        rep.invalid_after = rep.invalid_before;
        rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return rep;
    }
    for (std::size_t i = 0; i < bverts.size(); ++i)
        if (halvings[i] > 0) {
            ++rep.shrunk_vertices;
            rep.min_depth_fraction = std::min(rep.min_depth_fraction, std::ldexp(1.0, -halvings[i]));
        }
    if (failing > 0)
        rep.message = "pillowing: " + std::to_string(failing) +
                      " hexes could not be made certified valid by placing the inner copies closer to the boundary";
    rep.hexes_added = static_cast<long>(layer_quad.size());
    rep.vertices_added = static_cast<long>(bverts.size());
    // Old hexes that were not Valid and are not re-checked keep their state; count all.
    for (const auto v : hexValidities(out, threads)) rep.invalid_after += v != HexValidity::Valid;
    mesh = std::move(out);
    rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return rep;
}

} // namespace

PillowReport pillowBoundary(HexMesh& mesh, const PillowOptions& options) {
    const long nh = static_cast<long>(mesh.hexes.size());
    if (options.layered_from >= 0) {
        PillowReport rep = pillowPass(mesh, options, options.layered_from);
        rep.second_layer_hexes = rep.hexes_added;
        return rep;
    }
    PillowReport rep = pillowPass(mesh, options, -1);
    if (!rep.success || rep.skipped_patches == 0 || !options.second_layer || rep.hexes_added == 0) return rep;
    // The skipped patches now have their strips: give them (and the strips) a layer too.
    const PillowReport second = pillowPass(mesh, options, nh);
    if (!second.success || second.hexes_added == 0) {
        if (!second.message.empty()) rep.message = second.message;
        return rep;
    }
    rep.hexes_added += second.hexes_added;
    rep.vertices_added += second.vertices_added;
    rep.second_layer_hexes = second.hexes_added;
    rep.shrunk_vertices += second.shrunk_vertices;
    rep.min_depth_fraction = std::min(rep.min_depth_fraction, second.min_depth_fraction);
    rep.invalid_after = second.invalid_after;
    rep.seconds += second.seconds;
    if (!second.message.empty()) rep.message = second.message;
    return rep;
}

} // namespace HexEx
