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
#include <iterator>
#include <memory>
#include <cstddef>
#include <string>
#include <type_traits>
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

/// Corners of cell @p c (halffaces @p hfs) from the loops of its four halffaces
/// (@p loops[k]: the vertices of halfface hfs[k] in its own orientation): the core of
/// ovmTetCorners(), which reads the loops from the mesh, and of the table-driven read of
/// ovmToParametrizedTetMesh(). Throws InputError naming @p c if the loops do not span a
/// tetrahedron.
inline void ovmCornersFromLoops(std::size_t c, const std::vector<OpenVolumeMesh::HalfFaceHandle>& hfs,
                                const OpenVolumeMesh::VertexHandle (&loops)[4][3],
                                std::array<OpenVolumeMesh::VertexHandle, 4>& cv,
                                std::array<OpenVolumeMesh::HalfFaceHandle, 4>& opposite) {
    using VH = OpenVolumeMesh::VertexHandle;
    const auto fail = [c](const std::string& why) {
        throw InputError("OpenVolumeMesh cell " + std::to_string(c) + why);
    };
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

template <class Mesh>
void ovmTetCorners(const Mesh& mesh, std::size_t c, std::array<OpenVolumeMesh::VertexHandle, 4>& cv,
                   std::array<OpenVolumeMesh::HalfFaceHandle, 4>& opposite) {
    using VH = OpenVolumeMesh::VertexHandle;
    const std::vector<OpenVolumeMesh::HalfFaceHandle>& hfs =
        mesh.cell(OpenVolumeMesh::CellHandle(static_cast<int>(c))).halffaces();
    if (hfs.size() != 4)
        throw InputError("OpenVolumeMesh cell " + std::to_string(c) + " has " + std::to_string(hfs.size()) +
                         " halffaces, not a tetrahedron");
    VH loops[4][3];
    for (std::size_t k = 0; k < 4; ++k) {
        // The face's halfedges run along its halfface 0; halfface 1 is the reversed loop.
        if (!ovmFaceLoop(mesh, hfs[k].face_handle(), loops[k]))
            throw InputError("OpenVolumeMesh cell " + std::to_string(c) + " has a halfface that is not a triangle");
        if (hfs[k].idx() & 1) std::swap(loops[k][1], loops[k][2]);
    }
    ovmCornersFromLoops(c, hfs, loops, cv, opposite);
}

/// The vertex loop of every face of @p mesh along its halfface 0, read once per face (a
/// face is shared by two cells) on @p threads threads: entry f holds face f's three vertex
/// indices, or -1 in all three if the face is not a triangle.
template <class Mesh>
std::unique_ptr<std::array<int, 3>[]> ovmFaceLoopTable(const Mesh& mesh, int threads) {
    const std::size_t nf = mesh.n_faces();
    std::unique_ptr<std::array<int, 3>[]> table(new std::array<int, 3>[nf]);  // not zeroed: every entry is written
    parallelChunks(nf, threads, [&](int, std::size_t b, std::size_t e) {
        // The halfedge list of the face ahead is requested; the edges are not (consecutive
        // faces share edges made at about the same time: requesting them cost more calls
        // into OpenVolumeMesh than it saved, 24 % of this loop's CPU on cube20).
        constexpr std::size_t kAhead = 16;
        for (std::size_t f = b; f < e; ++f) {
#if defined(__GNUC__)
            if (f + kAhead < e)
                __builtin_prefetch(mesh.face(OpenVolumeMesh::FaceHandle(static_cast<int>(f + kAhead))).halfedges().data());
#endif
            OpenVolumeMesh::VertexHandle loop[3];
            if (ovmFaceLoop(mesh, OpenVolumeMesh::FaceHandle(static_cast<int>(f)), loop))
                table[f] = {loop[0].idx(), loop[1].idx(), loop[2].idx()};
            else
                table[f] = {-1, -1, -1};
        }
    });
    return table;
}

/// True if @p P has `prefetch(HalfFaceHandle, CellHandle)`: a parameter accessor of
/// ovmToParametrizedTetMesh() whose values can be requested ahead of their reading.
template <class P, class = void>
struct hasParamPrefetch : std::false_type {};
/// Specialization for accessors with `prefetch()`.
template <class P>
struct hasParamPrefetch<P, std::void_t<decltype(std::declval<const P&>().prefetch(OpenVolumeMesh::HalfFaceHandle(),
                                                                                  OpenVolumeMesh::CellHandle()))>>
    : std::true_type {};

/// Parameter accessor of ovmToParametrizedTetMesh() for HexHex's convention: the value of a
/// halfface property read from the property's storage (OpenVolumeMesh's public
/// `data_vector()`), one load per value instead of two through the property's shared
/// storage pointer, and requested ahead of its reading by prefetch().
template <class VecT>
struct OvmHalffaceParams {
    const VecT* values;  ///< the property's values, indexed by halfface

    /// Parameter of the corner opposite @p hf (the cell and vertex are not needed).
    const VecT& operator()(const OpenVolumeMesh::HalfFaceHandle& hf, const OpenVolumeMesh::CellHandle&,
                           const OpenVolumeMesh::VertexHandle&) const {
        return values[hf.uidx()];
    }
    /// Requests the value of @p hf into the cache (both ends: a value may span two lines).
    void prefetch(const OpenVolumeMesh::HalfFaceHandle& hf, const OpenVolumeMesh::CellHandle&) const {
#if defined(__GNUC__)
        const char* p = reinterpret_cast<const char*>(values + hf.uidx());
        __builtin_prefetch(p);
        __builtin_prefetch(p + sizeof(VecT) - 1);
#else
        (void)hf;
#endif
    }
};

/// Forward iterator over the cells of a read (ovmToParametrizedTetMesh()) giving each cell's
/// four corner parameters from the accessor, corner i's value on the halfface opposite it:
/// the parameter array is assigned from it in one pass (allocated once, each value written
/// once, no zeroing of the array first), the values of the cells ahead requested early.
template <class ParamOf>
struct OvmParamIterator {
    using iterator_category = std::forward_iterator_tag;  ///< one pass
    using value_type = std::array<Vec3d, 4>;               ///< a cell's corner parameters
    using difference_type = std::ptrdiff_t;                ///< cells between two iterators
    using pointer = const value_type*;                     ///< unused
    using reference = value_type;                          ///< values are computed

    const ParamOf* paramOf = nullptr;                                 ///< the accessor (with prefetch())
    const std::array<int, 4>* opposite = nullptr;                     ///< per cell: halfface opposite corner i
    const std::array<VertexHandle, 4>* corners = nullptr;             ///< per cell: its corners
    std::size_t cell = 0, end = 0;                                    ///< position, number of cells
    bool swap12 = false;                                              ///< corners 1 and 2 exchanged (outward mesh)

    /// Corner parameters of the current cell (corners 1 and 2 exchanged if #swap12).
    value_type operator*() const {
        constexpr std::size_t kAhead = 8;
        if (cell + kAhead < end) {
            const OpenVolumeMesh::CellHandle ah(static_cast<int>(cell + kAhead));
            for (const int hf : opposite[cell + kAhead]) paramOf->prefetch(OpenVolumeMesh::HalfFaceHandle(hf), ah);
        }
        const OpenVolumeMesh::CellHandle ch(static_cast<int>(cell));
        value_type u;
        for (std::size_t i = 0; i < 4; ++i) {
            const auto& ui = (*paramOf)(OpenVolumeMesh::HalfFaceHandle(opposite[cell][i]), ch,
                                        OpenVolumeMesh::VertexHandle(corners[cell][i].idx()));
            u[i] = Vec3d(ui[0], ui[1], ui[2]);
        }
        if (swap12) std::swap(u[1], u[2]);
        return u;
    }
    /// Next cell.
    OvmParamIterator& operator++() {
        ++cell;
        return *this;
    }
    /// Next cell (postfix).
    OvmParamIterator operator++(int) {
        OvmParamIterator old = *this;
        ++cell;
        return old;
    }
    /// Same position.
    bool operator==(const OvmParamIterator& o) const { return cell == o.cell; }
    /// Different position.
    bool operator!=(const OvmParamIterator& o) const { return cell != o.cell; }
};

/// Cells per block of the parallel read (ovmToParametrizedTetMesh()): the signed volume is
/// summed per block and the block sums in block order, so the orientation test rounds the
/// same for any thread count.
constexpr std::size_t kOvmReadBlock = std::size_t(1) << 14;

/// Copies the tets of @p mesh into the built-in kernel, corners as OvmTetMesh reads them, the
/// parameter of corner `v` opposite halfface `hf` of cell `c` being `paramOf(hf, c, v)`
/// (indexable by 0..2), and builds the adjacency with @p threads threads. With @p given,
/// fills @p givenOut with its value per built-in halfface (4 c + corner). The cells are read
/// on @p threads threads (0 = all hardware threads) in contiguous ranges, each writing its
/// own cells' slots (OpenVolumeMesh's const accessors and properties only read), so the
/// copy is the same for any thread count; the error of the first bad cell is reported.
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
    // Sized once (Vec3d's constructor leaves the parameters and positions untouched; the
    // corner handles are filled with -1), written in parallel, moved into the kernel.
    std::vector<Vec3d> positions(nv);
    std::vector<std::array<VertexHandle, 4>> cells(nc);
    ParametrizedTetMesh pm;
    // An accessor with prefetch() (a plain halfface property) is read after the corners, in
    // one pass that assigns the parameter array (no zeroing of 96 B per tet first); the
    // others (a map per cell, slow to look up) are read on the threads into the sized array.
    constexpr bool kParamPass = hasParamPrefetch<std::decay_t<ParamOf>>::value;
    std::unique_ptr<std::array<int, 4>[]> oppositeTable;  // per cell: the halfface opposite corner i
    if constexpr (kParamPass) oppositeTable.reset(new std::array<int, 4>[nc]);  // not zeroed: every entry is written
    else pm.params.resize(nc);
    if (given) givenOut->assign(4 * nc, 0);
    const int nThreads = nc < 2 * kOvmReadBlock ? 1 : resolveThreadCount(threads);
    parallelChunks(nv, nThreads, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t v = b; v < e; ++v) {
            const auto& p = mesh.vertex(OpenVolumeMesh::VertexHandle(static_cast<int>(v)));
            positions[v] = Vec3d(p[0], p[1], p[2]);
        }
    });
    // Each face's loop is read once (OpenVolumeMesh keeps it as halfedges with stored edge
    // endpoints, three indirections), then every cell looks its four up.
    std::unique_ptr<std::array<int, 3>[]> loopTable = ovmFaceLoopTable(mesh, nThreads);
    const std::array<int, 3>* const loopOf = loopTable.get();
    const std::size_t nBlocks = (nc + kOvmReadBlock - 1) / kOvmReadBlock;
    std::vector<double> blockVolume(nBlocks, 0.0);
    parallelChunks(nBlocks, nThreads, [&](int, std::size_t bBegin, std::size_t bEnd) {
        std::array<OpenVolumeMesh::VertexHandle, 4> cv;
        std::array<OpenVolumeMesh::HalfFaceHandle, 4> opposite;
        std::array<VertexHandle, 4> h;
        OpenVolumeMesh::VertexHandle loops[4][3];
        // Cells are read in order; the halfface list of a cell ahead is requested, and the
        // loop entries of the one half as far ahead.
        constexpr std::size_t kAhead = 16;
        const std::size_t c0 = bBegin * kOvmReadBlock, cEnd = std::min(nc, bEnd * kOvmReadBlock);
        const auto prefetchAhead = [&](std::size_t a) {
#if defined(__GNUC__)
            __builtin_prefetch(mesh.cell(OpenVolumeMesh::CellHandle(static_cast<int>(a))).halffaces().data());
            if (a >= kAhead / 2 + c0)
                for (const OpenVolumeMesh::HalfFaceHandle& hf :
                     mesh.cell(OpenVolumeMesh::CellHandle(static_cast<int>(a - kAhead / 2))).halffaces())
                    __builtin_prefetch(&loopOf[static_cast<std::size_t>(hf.face_handle().idx())]);
#else
            (void)a;
#endif
        };
        for (std::size_t block = bBegin; block < bEnd; ++block) {
            double volume = 0;
            const std::size_t blockEnd = std::min(nc, (block + 1) * kOvmReadBlock);
            for (std::size_t c = block * kOvmReadBlock; c < blockEnd; ++c) {
                if (c + kAhead < cEnd) prefetchAhead(c + kAhead);
                const std::vector<OpenVolumeMesh::HalfFaceHandle>& hfs =
                    mesh.cell(OpenVolumeMesh::CellHandle(static_cast<int>(c))).halffaces();
                if (hfs.size() != 4)
                    throw InputError("OpenVolumeMesh cell " + std::to_string(c) + " has " + std::to_string(hfs.size()) +
                                     " halffaces, not a tetrahedron");
                for (std::size_t k = 0; k < 4; ++k) {
                    const std::array<int, 3>& l = loopOf[static_cast<std::size_t>(hfs[k].face_handle().idx())];
                    if (l[0] < 0)
                        throw InputError("OpenVolumeMesh cell " + std::to_string(c) + " has a halfface that is not a triangle");
                    const bool reversed = hfs[k].idx() & 1;  // halfface 1 is the reversed loop
                    loops[k][0] = OpenVolumeMesh::VertexHandle(l[0]);
                    loops[k][1] = OpenVolumeMesh::VertexHandle(l[reversed ? 2 : 1]);
                    loops[k][2] = OpenVolumeMesh::VertexHandle(l[reversed ? 1 : 2]);
                }
                ovmCornersFromLoops(c, hfs, loops, cv, opposite);
                const OpenVolumeMesh::CellHandle ch(static_cast<int>(c));
                for (std::size_t i = 0; i < 4; ++i) {
                    h[i] = VertexHandle(cv[i].idx());
                    if constexpr (kParamPass) {
                        oppositeTable[c][i] = opposite[i].idx();
                    } else {
                        const auto& ui = paramOf(opposite[i], ch, cv[i]);
                        pm.params[c][i] = Vec3d(ui[0], ui[1], ui[2]);
                    }
                    if (given) {
                        const int r = (*given)[opposite[i]];
                        const bool interior = mesh.incident_cell(mesh.opposite_halfface_handle(opposite[i])).is_valid();
                        if (interior && (r < 0 || r > 23))
                            throw InputError("OpenVolumeMesh halfface " + std::to_string(opposite[i].idx()) +
                                             ": given rotation " + std::to_string(r) + " is not a rotation index (0..23)");
                        (*givenOut)[4 * c + i] = interior ? r : 0;
                    }
                }
                cells[c] = h;
                const Vec3d& a = positions[h[0].uidx()];
                const Vec3d e1 = positions[h[1].uidx()] - a, e2 = positions[h[2].uidx()] - a,
                            e3 = positions[h[3].uidx()] - a;
                volume += e1[0] * (e2[1] * e3[2] - e2[2] * e3[1]) - e1[1] * (e2[0] * e3[2] - e2[2] * e3[0]) +
                          e1[2] * (e2[0] * e3[1] - e2[1] * e3[0]);
            }
            blockVolume[block] = volume;
        }
    });
    loopTable.reset();  // freed before the adjacency is built
    double volume = 0;
    for (const double v : blockVolume) volume += v;
    const bool outward = volume < 0;  // stored with outward halffaces: turn every tet the other way
    if constexpr (kParamPass) {
        using It = OvmParamIterator<std::decay_t<ParamOf>>;
        pm.params.assign(It{&paramOf, oppositeTable.get(), cells.data(), 0, nc, outward},
                         It{&paramOf, oppositeTable.get(), cells.data(), nc, nc, outward});
        oppositeTable.reset();
    }
    if (outward)
        parallelChunks(nc, nThreads, [&](int, std::size_t b, std::size_t e) {
            for (std::size_t c = b; c < e; ++c) {
                std::swap(cells[c][1], cells[c][2]);
                if (!kParamPass) std::swap(pm.params[c][1], pm.params[c][2]);
                if (given) std::swap((*givenOut)[4 * c + 1], (*givenOut)[4 * c + 2]);
            }
        });
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
        detail::OvmHalffaceParams<VecT>{parameters.data_vector().data()}, hexMesh, options, results, hexResults);
}

} // namespace HexEx
