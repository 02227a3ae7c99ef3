#pragma once
/// @file OpenVolumeMeshT_impl.hh
/// Template bodies of the OpenVolumeMesh adapter's one-call overloads of extractHexMesh()
/// (declared in OpenVolumeMesh.hh, which includes this file): the tet mesh is read straight
/// into the built-in kernel (no per-tet cache, one copy of the parameters), extracted, freed,
/// and the result written into the user's mesh in bulk.

#include "../Core/Error.hh"
#include "../Core/Parallel.hh"
#include "../Core/Vec.hh"
#include "../HexExTraits.hh"
#include "../Mesh/HexProvenance.hh"

#include <algorithm>
#include <array>
#include <climits>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace HexEx {
namespace detail {

/// Reads the loop of face @p f of @p mesh (along its halfface 0) into @p out; false if the
/// face is not a triangle. Reads the edges' stored endpoints (halfedge 2e + 1 is edge e
/// reversed) instead of building a halfedge per vertex.
template <class Mesh>
bool ovmFaceLoop(const Mesh& mesh, const OpenVolumeMesh::FaceHandle& f, OpenVolumeMesh::VertexHandle out[3]) {
    const std::vector<OpenVolumeMesh::HalfEdgeHandle>& hes = mesh.face(f).halfedges();
    if (hes.size() != 3) return false;
    for (std::size_t i = 0; i < 3; ++i) {
        const auto& e = mesh.edge(hes[i].edge_handle());
        out[i] = (hes[i].idx() & 1) ? e.to_vertex() : e.from_vertex();
    }
    return true;
}

template <class Mesh>
void ovmTetCorners(const Mesh& mesh, std::size_t c, std::array<OpenVolumeMesh::VertexHandle, 4>& cv,
                   std::array<OpenVolumeMesh::HalfFaceHandle, 4>& opposite) {
    using VH = OpenVolumeMesh::VertexHandle;
    const std::vector<OpenVolumeMesh::HalfFaceHandle>& hfs =
        mesh.cell(OpenVolumeMesh::CellHandle(static_cast<int>(c))).halffaces();
    const auto fail = [c](const std::string& why) {
        throw InputError("OpenVolumeMesh cell " + std::to_string(c) + why);
    };
    if (hfs.size() != 4) fail(" has " + std::to_string(hfs.size()) + " halffaces, not a tetrahedron");
    VH loops[4][3];
    for (std::size_t k = 0; k < 4; ++k) {
        // The face's halfedges run along its halfface 0; halfface 1 is the reversed loop.
        if (!ovmFaceLoop(mesh, hfs[k].face_handle(), loops[k])) fail(" has a halfface that is not a triangle");
        if (hfs[k].idx() & 1) std::swap(loops[k][1], loops[k][2]);
    }
    // q: the first loop, then the first other vertex met; mask[k]: which of q are in loop k.
    VH q[4] = {loops[0][0], loops[0][1], loops[0][2], VH()};
    unsigned mask[4] = {0, 0, 0, 0};
    for (std::size_t k = 0; k < 4; ++k)
        for (const VH& v : loops[k]) {
            const unsigned p = v == q[0] ? 0u : v == q[1] ? 1u : v == q[2] ? 2u : 3u;
            if (p == 3) {
                if (!q[3].is_valid()) q[3] = v;
                else if (v != q[3]) fail(" spans more than four vertices");
            }
            mask[k] |= 1u << p;
        }
    if (!q[3].is_valid() || q[0] == q[1] || q[1] == q[2] || q[0] == q[2]) fail(" spans fewer than four vertices");
    // Rotate the first three so that corner 0 is the vertex opposite the last halfface.
    unsigned perm[4] = {0, 1, 2, 3};
    for (int r = 0; r < 3 && (mask[3] >> perm[0] & 1u); ++r) {
        const unsigned t = perm[0];
        perm[0] = perm[1];
        perm[1] = perm[2];
        perm[2] = t;
    }
    for (std::size_t i = 0; i < 4; ++i) {
        cv[i] = q[perm[i]];
        std::size_t k = 4;
        for (std::size_t j = 0; j < 4; ++j)
            if (!(mask[j] >> perm[i] & 1u)) k = j;
        if (k == 4) fail(": no halfface opposite vertex " + std::to_string(cv[i].idx()));
        opposite[i] = hfs[k];
    }
}

/// Asks the processor to start loading what ovmTetCorners() will read for cell @p c, one
/// level of OpenVolumeMesh's indirections per @p stage: 0 the cell's halfface list, 1 its
/// faces, 2 their halfedge lists, 3 the edges. A hint only (no effect on results); called
/// ahead of the cells being read, it overlaps the cache misses of consecutive cells.
template <class Mesh>
void ovmPrefetchCell(const Mesh& mesh, std::size_t c, int stage) {
#if defined(__GNUC__)
    const std::vector<OpenVolumeMesh::HalfFaceHandle>& hfs =
        mesh.cell(OpenVolumeMesh::CellHandle(static_cast<int>(c))).halffaces();
    if (stage == 0) {
        __builtin_prefetch(hfs.data());
        return;
    }
    for (const OpenVolumeMesh::HalfFaceHandle& hf : hfs) {
        const auto& face = mesh.face(hf.face_handle());
        if (stage == 1) {
            __builtin_prefetch(&face);
        } else if (stage == 2) {
            __builtin_prefetch(face.halfedges().data());
        } else {
            for (const OpenVolumeMesh::HalfEdgeHandle& he : face.halfedges()) __builtin_prefetch(&mesh.edge(he.edge_handle()));
        }
    }
#else
    (void)mesh;
    (void)c;
    (void)stage;
#endif
}

/// Copies the tets of @p mesh into the built-in kernel, corners as OvmTetMesh reads them, the
/// parameter of corner `v` opposite halfface `hf` of cell `c` being `paramOf(hf, c, v)`
/// (indexable by 0..2), and builds the adjacency with @p threads threads. With @p given,
/// fills @p givenOut with its value per built-in halfface (4 c + corner).
template <class Mesh, class ParamOf>
ParametrizedTetMesh ovmToParametrizedTetMesh(const Mesh& mesh, ParamOf&& paramOf, int threads,
                                             const OpenVolumeMesh::HalfFacePropertyT<int>* given = nullptr,
                                             std::vector<int>* givenOut = nullptr) {
    if (mesh.needs_garbage_collection())
        throw InputError("OpenVolumeMesh mesh has deleted entities: call collect_garbage() first");
    const std::size_t nv = mesh.n_vertices(), nc = mesh.n_cells();
    constexpr std::size_t kMax = static_cast<std::size_t>(INT_MAX) / 4;
    if (nv > kMax || nc > kMax)
        throw InputError("mesh too large: " + std::to_string(nv) + " vertices, " + std::to_string(nc) +
                         " tets (at most " + std::to_string(kMax) + " each)");
    // Filled once each (reserve + push_back, no zeroing pass) and moved into the kernel.
    std::vector<Vec3d> positions;
    std::vector<std::array<VertexHandle, 4>> cells;
    ParametrizedTetMesh pm;
    positions.reserve(nv);
    cells.reserve(nc);
    pm.params.reserve(nc);
    if (given) givenOut->assign(4 * nc, 0);
    for (std::size_t v = 0; v < nv; ++v) {
        const auto& p = mesh.vertex(OpenVolumeMesh::VertexHandle(static_cast<int>(v)));
        positions.emplace_back(p[0], p[1], p[2]);
    }
    std::array<OpenVolumeMesh::VertexHandle, 4> cv;
    std::array<OpenVolumeMesh::HalfFaceHandle, 4> opposite;
    std::array<VertexHandle, 4> h;
    std::array<Vec3d, 4> u;
    double volume = 0;
    // Cells are read in order; the records of the next cells are requested ahead, one
    // indirection level per distance (see ovmPrefetchCell()).
    constexpr std::size_t kAhead[4] = {16, 12, 8, 4};
    for (std::size_t c = 0; c < nc; ++c) {
        for (int stage = 0; stage < 4; ++stage)
            if (c + kAhead[stage] < nc) ovmPrefetchCell(mesh, c + kAhead[stage], stage);
        ovmTetCorners(mesh, c, cv, opposite);
        const OpenVolumeMesh::CellHandle ch(static_cast<int>(c));
        for (std::size_t i = 0; i < 4; ++i) {
            h[i] = VertexHandle(cv[i].idx());
            const auto& ui = paramOf(opposite[i], ch, cv[i]);
            u[i] = Vec3d(ui[0], ui[1], ui[2]);
            if (given) {
                const int r = (*given)[opposite[i]];
                const bool interior = mesh.incident_cell(mesh.opposite_halfface_handle(opposite[i])).is_valid();
                if (interior && (r < 0 || r > 23))
                    throw InputError("OpenVolumeMesh halfface " + std::to_string(opposite[i].idx()) + ": given rotation " +
                                     std::to_string(r) + " is not a rotation index (0..23)");
                (*givenOut)[4 * c + i] = interior ? r : 0;
            }
        }
        pm.params.push_back(u);
        const Vec3d& a = positions[h[0].uidx()];
        const Vec3d e1 = positions[h[1].uidx()] - a, e2 = positions[h[2].uidx()] - a, e3 = positions[h[3].uidx()] - a;
        volume += e1[0] * (e2[1] * e3[2] - e2[2] * e3[1]) - e1[1] * (e2[0] * e3[2] - e2[2] * e3[0]) +
                  e1[2] * (e2[0] * e3[1] - e2[1] * e3[0]);
        cells.push_back(h);
    }
    if (volume < 0)  // stored with outward halffaces: turn every tet the other way
        for (std::size_t c = 0; c < nc; ++c) {
            std::swap(cells[c][1], cells[c][2]);
            std::swap(pm.params[c][1], pm.params[c][2]);
            if (given) std::swap((*givenOut)[4 * c + 1], (*givenOut)[4 * c + 2]);
        }
    pm.mesh.assign(std::move(positions), std::move(cells));
    pm.mesh.build_adjacency(threads);
    return pm;
}

/// Writes the transitions and singular edges of @p pm (read from @p tetMesh by
/// ovmToParametrizedTetMesh()) into the properties named by @p results (written entries only).
template <class TetMeshT>
void writeOvmTetProperties(const TetMeshT& tetMesh, const ParametrizedTetMesh& pm, const ExtractionOptions& options,
                        const OvmTetProperties& results) {
    if (!results.rotation && !results.translation && !results.singular_valence) return;
    const int threads = resolveThreadCount(options.threads);
    const Transitions tr = computeTransitions(pm.mesh, pm.params, options.given_rotations, threads);
    if (results.rotation || results.translation) {
        std::array<OpenVolumeMesh::VertexHandle, 4> cv;
        std::array<OpenVolumeMesh::HalfFaceHandle, 4> opposite;
        for (std::size_t c = 0; c < pm.mesh.n_cells(); ++c) {
            ovmTetCorners(tetMesh, c, cv, opposite);
            for (int i = 0; i < 4; ++i) {
                // Corner i of the built-in tet is the OpenVolumeMesh corner with its vertex
                // (corners 1 and 2 were swapped if the mesh had outward halffaces).
                const int v = pm.mesh.cell_vertex(CellHandle(static_cast<int>(c)), i).idx();
                std::size_t k = 0;
                while (cv[k].idx() != v) ++k;
                const GridTransform g = tr.halfface[4 * c + static_cast<std::size_t>(i)];
                if (results.rotation) (*results.rotation)[opposite[k]] = g.R.index();
                if (results.translation)
                    (*results.translation)[opposite[k]] = OpenVolumeMesh::Geometry::Vec3i(g.t[0], g.t[1], g.t[2]);
            }
        }
    }
    if (results.singular_valence) {
        for (std::size_t e = 0; e < tetMesh.n_edges(); ++e) (*results.singular_valence)[OpenVolumeMesh::EdgeHandle(static_cast<int>(e))] = 0;
        const Singularities s = findSingularities(pm.mesh, pm.params, tr, threads);
        for (const SingularEdge& e : s.edges) {
            const auto& ev = pm.mesh.edge_vertices(e.edge);
            const OpenVolumeMesh::HalfEdgeHandle he =
                tetMesh.find_halfedge(OpenVolumeMesh::VertexHandle(ev[0].idx()), OpenVolumeMesh::VertexHandle(ev[1].idx()));
            if (he.is_valid()) (*results.singular_valence)[he.edge_handle()] = e.valence;
        }
    }
}

/// Writes @p prov into the properties of @p out's mesh named by @p names (hexes are the
/// first cells of @p out, vertices numbered as extracted).
template <class HexMeshT>
void writeOvmHexProperties(OvmHexOutput<HexMeshT>& out, const HexProvenance& prov, const OvmHexProperties& names) {
    HexMeshT& mesh = out.mesh();
    using Vec3i = OpenVolumeMesh::Geometry::Vec3i;
    const auto vec = [](const std::array<int, 3>& z) { return Vec3i(z[0], z[1], z[2]); };
    const std::vector<OpenVolumeMesh::CellHandle>& cells = out.cells();
    const std::size_t nh = std::min(prov.hex_source_tet.size(), cells.size());
    if (!names.source_tet.empty()) {
        auto p = mesh.template request_cell_property<int>(names.source_tet, -1);
        mesh.set_persistent(p, true);
        for (std::size_t h = 0; h < nh; ++h)
            if (cells[h].is_valid()) p[cells[h]] = prov.hex_source_tet[h];
    }
    if (!names.grid_cell.empty()) {
        auto p = mesh.template request_cell_property<Vec3i>(names.grid_cell, Vec3i(0, 0, 0));
        mesh.set_persistent(p, true);
        for (std::size_t h = 0; h < nh; ++h)
            if (cells[h].is_valid()) p[cells[h]] = vec(prov.hex_grid_cell[h]);
    }
    const std::size_t nv = std::min(prov.vertex_source_tet.size(), mesh.n_vertices());
    if (!names.grid_coords.empty()) {
        auto p = mesh.template request_vertex_property<Vec3i>(names.grid_coords, Vec3i(0, 0, 0));
        mesh.set_persistent(p, true);
        for (std::size_t v = 0; v < nv; ++v)
            p[OpenVolumeMesh::VertexHandle(static_cast<int>(v))] = vec(prov.vertex_grid_coords[v]);
    }
    if (!names.vertex_source_tet.empty()) {
        auto p = mesh.template request_vertex_property<int>(names.vertex_source_tet, -1);
        mesh.set_persistent(p, true);
        for (std::size_t v = 0; v < nv; ++v)
            p[OpenVolumeMesh::VertexHandle(static_cast<int>(v))] = prov.vertex_source_tet[v];
    }
}

/// Body of both one-call overloads: read, extract (and write @p results), free the copy,
/// write the hex mesh in bulk (and @p hexResults into it).
template <class TetMeshT, class HexMeshT, class ParamOf>
ExtractionReport extractOvm(const TetMeshT& tetMesh, ParamOf&& paramOf, HexMeshT& hexMesh,
                            const ExtractionOptions& options, const OvmTetProperties& results,
                            const OvmHexProperties& hexResults) {
    HexMesh hm;
    ExtractionReport report;
    HexProvenance prov;
    {
        std::vector<int> given;
        ExtractionOptions opt = options;
        ParametrizedTetMesh pm =
            ovmToParametrizedTetMesh(tetMesh, paramOf, options.threads, results.given_rotation, &given);
        if (results.given_rotation) opt.given_rotations = &given;
        if (hexResults.any() && !opt.provenance) opt.provenance = &prov;
        // The pipeline takes the parameters over unless the transitions are written from them.
        if (results.rotation || results.translation || results.singular_valence) report = extractHexMesh(pm, hm, opt);
        else report = extractHexMesh(std::move(pm), hm, opt);
        writeOvmTetProperties(tetMesh, pm, opt, results);
    }  // the copy of the input is freed before the output is written
    OvmHexOutput<HexMeshT> out(hexMesh);
    out.deferIncidences();
    fromHexMesh(hm, out);
    hm = HexMesh();  // freed before OpenVolumeMesh builds its incidences (the peak of the writing)
    if (hexResults.any()) writeOvmHexProperties(out, options.provenance ? *options.provenance : prov, hexResults);
    out.restoreIncidences();
    return report;
}

} // namespace detail

template <class TetMeshT, class VecT, class HexMeshT, std::enable_if_t<detail::isOvmMeshPair<TetMeshT, HexMeshT>, int>>
ExtractionReport extractHexMesh(const TetMeshT& tetMesh,
                                const OpenVolumeMesh::CellPropertyT<std::map<OpenVolumeMesh::VertexHandle, VecT>>& parameters,
                                HexMeshT& hexMesh, const ExtractionOptions& options, const OvmTetProperties& results,
                                const OvmHexProperties& hexResults) {
    return detail::extractOvm(
        tetMesh,
        [&](const OpenVolumeMesh::HalfFaceHandle&, const OpenVolumeMesh::CellHandle& ch,
            const OpenVolumeMesh::VertexHandle& v) -> const VecT& {
            const auto& m = parameters[ch];
            const auto it = m.find(v);
            if (it == m.end())
                throw InputError("OpenVolumeMesh cell " + std::to_string(ch.idx()) + ": property '" +
                                 parameters.name() + "' has no parameter for vertex " + std::to_string(v.idx()));
            return it->second;
        },
        hexMesh, options, results, hexResults);
}

template <class TetMeshT, class VecT, class HexMeshT, std::enable_if_t<detail::isOvmMeshPair<TetMeshT, HexMeshT>, int>>
ExtractionReport extractHexMesh(const TetMeshT& tetMesh, const OpenVolumeMesh::HalfFacePropertyT<VecT>& parameters,
                                HexMeshT& hexMesh, const ExtractionOptions& options, const OvmTetProperties& results,
                                const OvmHexProperties& hexResults) {
    return detail::extractOvm(
        tetMesh,
        [&](const OpenVolumeMesh::HalfFaceHandle& hf, const OpenVolumeMesh::CellHandle&,
            const OpenVolumeMesh::VertexHandle&) -> const VecT& { return parameters[hf]; },
        hexMesh, options, results, hexResults);
}

} // namespace HexEx
