#pragma once
/// @file MeshTraits.hh
/// @ingroup kernel
/// Mesh-kernel traits: the concept through which the templated extractHexMesh() (see
/// HexExTraits.hh) reads an input tet mesh with its integer-grid map and writes the output
/// hex mesh, the specializations for the built-in kernel (ParametrizedTetMesh, HexMesh),
/// and the conversion helpers toParametrizedTetMesh() and fromHexMesh().
///
/// Entities are addressed by dense indices `0..n-1` (std::size_t). A kernel whose handles
/// are not dense indices maps them in its traits (see Documentation/traits.md).

#include "../Core/Error.hh"
#include "../Core/Vec.hh"
#include "HexMesh.hh"
#include "ParametrizedTetMesh.hh"

#include <array>
#include <climits>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace HexEx {

/// Read access to a tet mesh with an integer-grid map (the input concept).
///
/// The primary template is deliberately left undefined; specialize it for your mesh type.
/// A specialization `TetMeshTraits<Mesh>` must provide these static member functions
/// (indices are dense, `0 <= v < n_vertices`, `0 <= t < n_tets`):
///
/// | Function | Meaning |
/// |---|---|
/// | `static std::size_t n_vertices(const Mesh&)` | number of vertices |
/// | `static Vec3d position(const Mesh&, std::size_t v)` | 3D position of vertex `v` |
/// | `static std::size_t n_tets(const Mesh&)` | number of tetrahedra |
/// | `static std::array<std::size_t, 4> tet_vertices(const Mesh&, std::size_t t)` | the four corners of tet `t` |
/// | `static Vec3d corner_param(const Mesh&, std::size_t t, int corner)` | parameter of corner `corner` (0..3) of tet `t`, in the chart of tet `t` |
///
/// Tets should be positively oriented in 3D (orient3d of the corner positions > 0). The
/// parameters are given per tet corner, so maps with seams (transition functions between
/// the charts of neighbouring tets) are expressed naturally; for a seamless map return the
/// parameter of the corner's vertex. Return types only need to convert to the listed ones.
/// Out-of-range vertex indices returned by tet_vertices() are reported as InputError by
/// toParametrizedTetMesh().
template <class Mesh>
struct TetMeshTraits;

/// Write access to an output hex mesh (the output concept).
///
/// The primary template is deliberately left undefined; specialize it for your mesh type.
/// A specialization `HexMeshOutputTraits<Mesh>` must provide these static member functions:
///
/// | Function | Meaning |
/// |---|---|
/// | `static void clear(Mesh&)` | removes everything, called once before writing |
/// | `static std::size_t add_vertex(Mesh&, const Vec3d& p)` | adds a vertex at `p`, returns its id |
/// | `static void add_hex(Mesh&, const std::array<std::size_t, 8>& v)` | adds a hexahedron, vertex ids in VTK order |
/// | `static void add_polyhedron(Mesh&, const std::vector<std::vector<std::size_t>>& faces)` | adds a non-hex cell, one outward-oriented vertex loop per face |
///
/// Optionally, `static void reserve(Mesh&, std::size_t n_vertices, std::size_t n_hexes)`:
/// called once after clear() with the numbers of vertices and hexahedra about to be added,
/// so that the kernel can allocate in bulk; and `static void finish(Mesh&)`: called once
/// after the last cell.
///
/// The ids passed to add_hex() and add_polyhedron() are those returned by add_vertex().
/// VTK order: bottom quad 0-1-2-3 counter-clockwise seen from the top quad 4-5-6-7,
/// vertex 4 above vertex 0 (see HexMesh). The extractor never drops a cell: cells that are
/// not hexahedra arrive through add_polyhedron(); a kernel that cannot store them may
/// ignore them (the ExtractionReport still counts them).
template <class Mesh>
struct HexMeshOutputTraits;

/// Input traits of the built-in kernel. Indices beyond `int` range are not representable
/// in a TetMesh, so the conversion never needs to narrow.
template <>
struct TetMeshTraits<ParametrizedTetMesh> {
    /// Number of vertices.
    static std::size_t n_vertices(const ParametrizedTetMesh& m) { return m.mesh.n_vertices(); }
    /// Position of vertex @p v.
    static Vec3d position(const ParametrizedTetMesh& m, std::size_t v) {
        return m.mesh.position(VertexHandle(static_cast<int>(v)));
    }
    /// Number of tets.
    static std::size_t n_tets(const ParametrizedTetMesh& m) { return m.mesh.n_cells(); }
    /// The four corners of tet @p t.
    static std::array<std::size_t, 4> tet_vertices(const ParametrizedTetMesh& m, std::size_t t) {
        const auto& cv = m.mesh.cell_vertices(CellHandle(static_cast<int>(t)));
        return {cv[0].uidx(), cv[1].uidx(), cv[2].uidx(), cv[3].uidx()};
    }
    /// Parameter of corner @p corner of tet @p t. Throws InputError if the mesh has no
    /// parameters for @p t.
    static Vec3d corner_param(const ParametrizedTetMesh& m, std::size_t t, int corner) {
        if (t >= m.params.size())
            throw InputError("tet " + std::to_string(t) + ": no corner parameters (" +
                             std::to_string(m.params.size()) + " parameter sets for " +
                             std::to_string(m.mesh.n_cells()) + " tets)");
        return m.params[t][static_cast<std::size_t>(corner)];
    }
};

/// Output traits of the built-in kernel.
template <>
struct HexMeshOutputTraits<HexMesh> {
    /// Removes all vertices and cells.
    static void clear(HexMesh& m) {
        m.vertices.clear();
        m.hexes.clear();
        m.polyhedra.clear();
    }
    /// Reserves room for @p nVertices vertices and @p nHexes hexahedra.
    static void reserve(HexMesh& m, std::size_t nVertices, std::size_t nHexes) {
        m.vertices.reserve(nVertices);
        m.hexes.reserve(nHexes);
    }
    /// Appends a vertex, returns its index.
    static std::size_t add_vertex(HexMesh& m, const Vec3d& p) {
        m.vertices.push_back(p);
        return m.vertices.size() - 1;
    }
    /// Appends a hexahedron (VTK order).
    static void add_hex(HexMesh& m, const std::array<std::size_t, 8>& v) {
        std::array<int, 8> h;
        for (std::size_t i = 0; i < 8; ++i) h[i] = static_cast<int>(v[i]);
        m.hexes.push_back(h);
    }
    /// Appends a polyhedron given by its outward-oriented faces.
    static void add_polyhedron(HexMesh& m, const std::vector<std::vector<std::size_t>>& faces) {
        Polyhedron p;
        p.faces.reserve(faces.size());
        for (const auto& f : faces) p.faces.emplace_back(f.begin(), f.end());
        m.polyhedra.push_back(std::move(p));
    }
};

/// Implementation details of the traits machinery.
namespace detail {

/// True if TetMeshTraits<M> is specialized with at least n_tets() (detection fallback).
template <class M, class = void>
struct HasTetMeshTraits : std::false_type {};
/// True if TetMeshTraits<M> is specialized with at least n_tets().
template <class M>
struct HasTetMeshTraits<M, std::void_t<decltype(TetMeshTraits<M>::n_tets(std::declval<const M&>()))>>
    : std::true_type {};

/// True if HexMeshOutputTraits<M> is specialized with at least clear() (detection fallback).
template <class M, class = void>
struct HasHexMeshOutputTraits : std::false_type {};
/// True if HexMeshOutputTraits<M> is specialized with at least clear().
template <class M>
struct HasHexMeshOutputTraits<M, std::void_t<decltype(HexMeshOutputTraits<M>::clear(std::declval<M&>()))>>
    : std::true_type {};

/// True if TetMeshTraits<M> provides every function of the input concept with usable
/// return types (detection fallback).
template <class M, class = void>
struct CompleteTetMeshTraits : std::false_type {};
/// True if TetMeshTraits<M> provides every function of the input concept with usable return types.
template <class M>
struct CompleteTetMeshTraits<
    M, std::void_t<decltype(std::size_t(TetMeshTraits<M>::n_vertices(std::declval<const M&>()))),
                   decltype(Vec3d(TetMeshTraits<M>::position(std::declval<const M&>(), std::size_t()))),
                   decltype(std::size_t(TetMeshTraits<M>::n_tets(std::declval<const M&>()))),
                   decltype(std::array<std::size_t, 4>(
                       TetMeshTraits<M>::tet_vertices(std::declval<const M&>(), std::size_t()))),
                   decltype(Vec3d(TetMeshTraits<M>::corner_param(std::declval<const M&>(), std::size_t(), 0)))>>
    : std::true_type {};

/// True if HexMeshOutputTraits<M> provides every function of the output concept
/// (detection fallback).
template <class M, class = void>
struct CompleteHexMeshOutputTraits : std::false_type {};
/// True if HexMeshOutputTraits<M> provides every function of the output concept.
template <class M>
struct CompleteHexMeshOutputTraits<
    M, std::void_t<decltype(HexMeshOutputTraits<M>::clear(std::declval<M&>())),
                   decltype(std::size_t(HexMeshOutputTraits<M>::add_vertex(std::declval<M&>(), std::declval<const Vec3d&>()))),
                   decltype(HexMeshOutputTraits<M>::add_hex(std::declval<M&>(),
                                                            std::declval<const std::array<std::size_t, 8>&>())),
                   decltype(HexMeshOutputTraits<M>::add_polyhedron(
                       std::declval<M&>(), std::declval<const std::vector<std::vector<std::size_t>>&>()))>>
    : std::true_type {};

/// True if HexMeshOutputTraits<M> has the optional reserve() (detection fallback).
template <class M, class = void>
struct HasOutputReserve : std::false_type {};
/// True if HexMeshOutputTraits<M> has the optional reserve(M&, n_vertices, n_hexes).
template <class M>
struct HasOutputReserve<M, std::void_t<decltype(HexMeshOutputTraits<M>::reserve(std::declval<M&>(), std::size_t(),
                                                                                 std::size_t()))>>
    : std::true_type {};

/// True if HexMeshOutputTraits<M> has the optional finish() (detection fallback).
template <class M, class = void>
struct HasOutputFinish : std::false_type {};
/// True if HexMeshOutputTraits<M> has the optional finish(M&).
template <class M>
struct HasOutputFinish<M, std::void_t<decltype(HexMeshOutputTraits<M>::finish(std::declval<M&>()))>> : std::true_type {};

/// A vertex index as text; values that wrapped around from a negative signed index
/// (above PTRDIFF_MAX) are printed as that negative number.
inline std::string indexToString(std::size_t v) {
    if (v > static_cast<std::size_t>(PTRDIFF_MAX)) return std::to_string(static_cast<long long>(v));
    return std::to_string(v);
}

} // namespace detail

/// True if @p M has input traits (a TetMeshTraits specialization).
template <class M>
inline constexpr bool hasTetMeshTraits = detail::HasTetMeshTraits<M>::value;

/// True if @p M has output traits (a HexMeshOutputTraits specialization).
template <class M>
inline constexpr bool hasHexMeshOutputTraits = detail::HasHexMeshOutputTraits<M>::value;

/// Copies any mesh with TetMeshTraits into the built-in kernel and builds its adjacency.
///
/// Throws InputError naming the tet if a tet references a vertex index out of range or
/// repeats a vertex, if the mesh is too large for `int` indices, and (from
/// TetMesh::build_adjacency()) if a face is shared by more than two tets.
template <class M>
ParametrizedTetMesh toParametrizedTetMesh(const M& in) {
    static_assert(hasTetMeshTraits<M>, "HexEx::TetMeshTraits<M> is not specialized for this mesh type");
    static_assert(detail::CompleteTetMeshTraits<M>::value,
                  "HexEx::TetMeshTraits<M> lacks a function of the concept (n_vertices, position, n_tets, "
                  "tet_vertices, corner_param) or one has an unusable signature; see MeshTraits.hh");
    using T = TetMeshTraits<M>;
    const std::size_t nv = T::n_vertices(in);
    const std::size_t nt = T::n_tets(in);
    constexpr std::size_t kMax = static_cast<std::size_t>(INT_MAX) / 4;
    if (nv > kMax || nt > kMax)
        throw InputError("mesh too large: " + std::to_string(nv) + " vertices, " + std::to_string(nt) +
                         " tets (at most " + std::to_string(kMax) + " each)");
    ParametrizedTetMesh pm;
    pm.mesh.reserve(nv, nt);
    pm.params.resize(nt);
    for (std::size_t v = 0; v < nv; ++v) pm.mesh.add_vertex(Vec3d(T::position(in, v)));
    for (std::size_t t = 0; t < nt; ++t) {
        const std::array<std::size_t, 4> tv = T::tet_vertices(in, t);
        std::array<VertexHandle, 4> h;
        for (int i = 0; i < 4; ++i) {
            const std::size_t v = tv[static_cast<std::size_t>(i)];
            if (v >= nv)
                throw InputError("tet " + std::to_string(t) + ": vertex index " + detail::indexToString(v) +
                                 " out of range (the mesh has " + std::to_string(nv) + " vertices)");
            for (int j = 0; j < i; ++j)
                if (tv[static_cast<std::size_t>(j)] == v)
                    throw InputError("tet " + std::to_string(t) + ": vertex " + detail::indexToString(v) +
                                     " appears twice");
            h[static_cast<std::size_t>(i)] = VertexHandle(static_cast<int>(v));
            pm.params[t][static_cast<std::size_t>(i)] = Vec3d(T::corner_param(in, t, i));
        }
        pm.mesh.add_cell(h);
    }
    pm.mesh.build_adjacency();
    return pm;
}

/// Writes @p hm into any mesh with HexMeshOutputTraits: clears @p out, adds all vertices,
/// then all hexahedra, then all polyhedra (vertex ids mapped through add_vertex()). Calls the
/// traits' optional reserve() after clear() and finish() after the last cell.
template <class M>
void fromHexMesh(const HexMesh& hm, M& out) {
    static_assert(hasHexMeshOutputTraits<M>, "HexEx::HexMeshOutputTraits<M> is not specialized for this mesh type");
    static_assert(detail::CompleteHexMeshOutputTraits<M>::value,
                  "HexEx::HexMeshOutputTraits<M> lacks a function of the concept (clear, add_vertex, add_hex, "
                  "add_polyhedron) or one has an unusable signature; see MeshTraits.hh");
    using T = HexMeshOutputTraits<M>;
    T::clear(out);
    if constexpr (detail::HasOutputReserve<M>::value) T::reserve(out, hm.vertices.size(), hm.hexes.size());
    std::vector<std::size_t> id(hm.vertices.size());
    for (std::size_t v = 0; v < hm.vertices.size(); ++v) id[v] = T::add_vertex(out, hm.vertices[v]);
    for (const auto& h : hm.hexes) {
        std::array<std::size_t, 8> hv;
        for (std::size_t i = 0; i < 8; ++i) hv[i] = id[static_cast<std::size_t>(h[i])];
        T::add_hex(out, hv);
    }
    std::vector<std::vector<std::size_t>> faces;
    for (const auto& p : hm.polyhedra) {
        faces.assign(p.faces.size(), {});
        for (std::size_t f = 0; f < p.faces.size(); ++f)
            for (int v : p.faces[f]) faces[f].push_back(id[static_cast<std::size_t>(v)]);
        T::add_polyhedron(out, faces);
    }
    if constexpr (detail::HasOutputFinish<M>::value) T::finish(out);
}

} // namespace HexEx
