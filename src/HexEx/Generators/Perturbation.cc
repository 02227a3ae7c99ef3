/// @file Perturbation.cc
/// Consistent, constraint-preserving parameter noise (paper section 5.1).

#include "Perturbation.hh"

#include "../Mesh/HexArcs.hh"
#include "../Mesh/HexMeshQuality.hh"
#include "../Preprocessing/Transitions.hh"
#include "RandomDraws.hh"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <stdexcept>

namespace HexEx {

namespace {

/// Local index of @p v in cell @p c, or -1.
int cornerOf(const TetMesh& mesh, CellHandle c, VertexHandle v) {
    const auto& cv = mesh.cell_vertices(c);
    for (int k = 0; k < 4; ++k)
        if (cv[k] == v) return k;
    return -1;
}

/// The reference-chart axis that rotation @p R maps onto axis @p k.
int preimageAxis(const Rotation& R, int k) {
    for (int j = 0; j < 3; ++j)
        if (R.perm(j) == k) return j;
    return k;
}

} // namespace

void perturbParameters(ParametrizedTetMesh& pm, double a, unsigned seed, PerturbStats* stats) {
    if (!(a >= 0) || !std::isfinite(a)) throw std::invalid_argument("perturbParameters: amplitude must be finite and >= 0");
    TetMesh& mesh = pm.mesh;
    if (pm.params.size() != mesh.n_cells())
        throw std::invalid_argument("perturbParameters: one parameter set per tet required");
    if (!mesh.has_adjacency()) mesh.build_adjacency();

    const Transitions tr = computeTransitions(mesh, pm.params);
    const Singularities sing = findSingularities(mesh, pm.params, tr);
    // Singular edges per vertex.
    std::vector<std::vector<EdgeHandle>> vertex_sing(mesh.n_vertices());
    for (const auto& se : sing.edges) {
        const auto ev = mesh.edge_vertices(se.edge);
        vertex_sing[ev[0].uidx()].push_back(se.edge);
        vertex_sing[ev[1].uidx()].push_back(se.edge);
    }

    PerturbStats st;
    std::mt19937 rng(seed);
    std::vector<int> star;
    std::vector<GridTransform> toChart;  // reference chart -> chart of star[q]
    std::vector<int> slot(mesh.n_cells(), -1);
    const CornerParams& P = pm.params;

    for (std::size_t vi = 0; vi < mesh.n_vertices(); ++vi) {
        // Always draw three numbers so that each vertex's noise depends only on its index.
        Vec3d d;
        for (int k = 0; k < 3; ++k) d[k] = a * (2.0 * uniform01(rng) - 1.0);

        const VertexHandle v(static_cast<int>(vi));
        const auto cells = mesh.vertex_cells(v);
        if (cells.first == cells.second) continue;
        ++st.vertices;

        // Breadth-first over the interior faces around v, starting at its lowest-index tet.
        star.assign(1, *cells.first);
        toChart.assign(1, GridTransform());
        slot[star[0]] = 0;
        for (std::size_t q = 0; q < star.size(); ++q) {
            const CellHandle c(star[q]);
            for (int j = 0; j < 4; ++j) {
                if (mesh.cell_vertex(c, j) == v) continue;
                const HalfFaceHandle hf = TetMesh::halfface(c, j);
                const HalfFaceHandle o = mesh.opposite_halfface(hf);
                if (!o.is_valid()) continue;
                const int n = TetMesh::cell(o).idx();
                if (slot[n] >= 0) continue;
                slot[n] = static_cast<int>(star.size());
                star.push_back(n);
                toChart.push_back(tr.halfface[hf.uidx()] * toChart[q]);
            }
        }

        bool free_axis[3] = {true, true, true};
        bool on_boundary_plane = false;
        // Boundary planes: boundary faces of v whose corners share an integer coordinate.
        for (std::size_t q = 0; q < star.size(); ++q) {
            const CellHandle c(star[q]);
            for (int j = 0; j < 4; ++j) {
                if (mesh.cell_vertex(c, j) == v) continue;
                const HalfFaceHandle hf = TetMesh::halfface(c, j);
                if (!mesh.is_boundary(hf)) continue;
                const auto& p = P[c.uidx()];
                const int* fc = TetMesh::kFaceCorners[j];
                for (int k = 0; k < 3; ++k) {
                    const double x = p[fc[0]][k];
                    if (p[fc[1]][k] == x && p[fc[2]][k] == x && std::nearbyint(x) == x) {
                        free_axis[preimageAxis(toChart[q].R, k)] = false;
                        on_boundary_plane = true;
                    }
                }
            }
        }
        // Singular edges: only the edge axis (in the reference chart) stays free.
        const auto& sedges = vertex_sing[vi];
        if (!sedges.empty()) {
            ++st.singular_vertices;
            int axis = -1;
            bool ok = true;
            for (const EdgeHandle e : sedges) {
                const auto ev = mesh.edge_vertices(e);
                const VertexHandle w = ev[0] == v ? ev[1] : ev[0];
                int found = -1;
                for (std::size_t q = 0; q < star.size() && found < 0; ++q) {
                    const CellHandle c(star[q]);
                    const int iv = cornerOf(mesh, c, v), iw = cornerOf(mesh, c, w);
                    if (iw < 0) continue;
                    const Vec3d dir = P[c.uidx()][iw] - P[c.uidx()][iv];
                    int nonzero = 0, k_nz = -1;
                    for (int k = 0; k < 3; ++k)
                        if (dir[k] != 0) {
                            ++nonzero;
                            k_nz = k;
                        }
                    found = nonzero == 1 ? preimageAxis(toChart[q].R, k_nz) : 3;  // 3: not aligned
                }
                if (found < 0 || found == 3 || (axis >= 0 && axis != found)) {
                    ok = false;
                    break;
                }
                axis = found;
            }
            for (int k = 0; k < 3; ++k)
                if (!ok || k != axis) free_axis[k] = false;
        }
        if (on_boundary_plane) ++st.boundary_vertices;
        for (int k = 0; k < 3; ++k)
            if (!free_axis[k]) d[k] = 0;
        if (!free_axis[0] && !free_axis[1] && !free_axis[2]) ++st.fixed_vertices;
        if (d[0] != 0 || d[1] != 0 || d[2] != 0) ++st.moved_vertices;
        st.max_displacement = std::max({st.max_displacement, std::fabs(d[0]), std::fabs(d[1]), std::fabs(d[2])});

        for (std::size_t q = 0; q < star.size(); ++q) {
            const int k = cornerOf(mesh, CellHandle(star[q]), v);
            pm.params[static_cast<std::size_t>(star[q])][k] += toChart[q].R.apply(d);
        }
        for (int c : star) slot[c] = -1;
    }
    if (stats) *stats = st;
}

namespace {

/// Hexes with a corner Jacobian <= 0 (or a non-finite one).
long countInverted(const HexMesh& mesh) {
    long n = 0;
    for (const auto& h : mesh.hexes) {
        std::array<Vec3d, 8> p;
        for (std::size_t k = 0; k < 8; ++k) p[k] = mesh.vertices[static_cast<std::size_t>(h[k])];
        const double sj = hexScaledJacobian(p);
        n += !(sj > 0);
    }
    return n;
}

} // namespace

void perturbHexMesh(HexMesh& mesh, double fraction, unsigned seed, HexPerturbStats* stats) {
    if (!(fraction >= 0) || !std::isfinite(fraction))
        throw std::invalid_argument("perturbHexMesh: fraction must be finite and >= 0");
    const std::size_t nv = mesh.vertices.size();
    for (const auto& h : mesh.hexes)
        for (const int v : h)
            if (v < 0 || static_cast<std::size_t>(v) >= nv)
                throw std::invalid_argument("perturbHexMesh: a hex references vertex " + std::to_string(v) + " of " +
                                            std::to_string(nv));
    HexPerturbStats st;
    st.vertices = nv;
    st.inverted_before = countInverted(mesh);
    // Mean incident edge length per vertex (every hex edge counted once per hex using it,
    // which weights shared edges equally on a regular mesh).
    std::vector<double> len_sum(nv, 0.0);
    std::vector<int> len_count(nv, 0), hex_count(nv, 0);
    for (const auto& h : mesh.hexes) {
        for (const int v : h) ++hex_count[static_cast<std::size_t>(v)];
        for (const auto& e : HexArcs::kHexEdges) {
            const int a = h[static_cast<std::size_t>(e[0])], b = h[static_cast<std::size_t>(e[1])];
            const double l = (mesh.vertices[static_cast<std::size_t>(a)] - mesh.vertices[static_cast<std::size_t>(b)]).norm();
            len_sum[static_cast<std::size_t>(a)] += l;
            len_sum[static_cast<std::size_t>(b)] += l;
            ++len_count[static_cast<std::size_t>(a)];
            ++len_count[static_cast<std::size_t>(b)];
        }
    }
    // Boundary: vertices of quads used by exactly one hex; polyhedron vertices stay too.
    std::vector<char> fixed(nv, 0);
    std::map<std::array<int, 4>, int> quad_uses;
    for (const auto& h : mesh.hexes)
        for (const auto& f : HexArcs::kHexFaces) {
            std::array<int, 4> q;
            for (std::size_t i = 0; i < 4; ++i) q[i] = h[static_cast<std::size_t>(f[i])];
            std::sort(q.begin(), q.end());
            ++quad_uses[q];
        }
    for (const auto& qu : quad_uses)
        if (qu.second == 1)
            for (const int v : qu.first) fixed[static_cast<std::size_t>(v)] = 1;
    for (const auto& p : mesh.polyhedra)
        for (const auto& f : p.faces)
            for (const int v : f)
                if (v >= 0 && static_cast<std::size_t>(v) < nv) fixed[static_cast<std::size_t>(v)] = 1;

    std::mt19937 gen(seed);
    for (std::size_t v = 0; v < nv; ++v) {
        Vec3d d;
        for (int k = 0; k < 3; ++k) d[k] = 2.0 * uniform01(gen) - 1.0;
        if (fixed[v] || hex_count[v] == 0) continue;
        ++st.interior_vertices;
        d *= fraction * len_sum[v] / static_cast<double>(len_count[v]);
        if (d[0] == 0 && d[1] == 0 && d[2] == 0) continue;
        mesh.vertices[v] += d;
        ++st.moved_vertices;
        st.max_displacement = std::max(st.max_displacement, d.norm());
    }
    st.inverted_after = countInverted(mesh);
    if (stats) *stats = st;
}

} // namespace HexEx
