#pragma once
/// @file QuadTraits.hh
/// @ingroup quad
/// The 2D one-call API for any mesh kernel: extractQuadMesh() templated over the input
/// triangle mesh and the output polygon mesh, read and written through TriMeshTraits and
/// QuadMeshOutputTraits (the 2D twins of TetMeshTraits and HexMeshOutputTraits). Ready
/// specializations: the built-in ParametrizedTriMesh / QuadMesh, plain arrays
/// (TriArraysView in, QuadMesh out) and OpenMesh (any TriMesh_ArrayKernelT in, with the
/// parameters in its halfedge texcoord2D property, the way OpenMesh's OBJ reader stores
/// `vt`; any PolyMesh_ArrayKernelT out).

#include "../Core/Error.hh"
#include "QuadExtraction.hh"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <array>
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

namespace HexEx {

/// Read access to a triangle mesh with per-corner parameters (the 2D input concept).
/// A specialization must provide (indices dense, `0 <= v < n_vertices`, `0 <= f < n_triangles`):
///
/// | Function | Meaning |
/// |---|---|
/// | `static std::size_t n_vertices(const Mesh&)` | number of vertices |
/// | `static Vec3d position(const Mesh&, std::size_t v)` | 3D position of vertex `v` |
/// | `static std::size_t n_triangles(const Mesh&)` | number of triangles |
/// | `static std::array<std::size_t, 3> triangle_vertices(const Mesh&, std::size_t f)` | corners of `f`, counter-clockwise (the surface's orientation) |
/// | `static Vec2d corner_param(const Mesh&, std::size_t f, int k)` | parameter (u, v) of corner `k` of `f` in `f`'s chart |
template <class Mesh, class Enable = void>
struct TriMeshTraits;

/// Write access to an output polygon mesh (the 2D output concept):
///
/// | Function | Meaning |
/// |---|---|
/// | `static void clear(Mesh&)` | removes everything, called once before writing |
/// | `static std::size_t add_vertex(Mesh&, const Vec3d& p)` | adds a vertex, returns its id |
/// | `static void add_face(Mesh&, const std::vector<std::size_t>& loop)` | adds a face (quads and the rest) |
template <class Mesh, class Enable = void>
struct QuadMeshOutputTraits;

/// Plain arrays in: 3 doubles per vertex, 3 vertex ids per triangle, 6 parameters
/// (u0 v0 u1 v1 u2 v2) per triangle. The view does not own the data.
struct TriArraysView {
    const double* points = nullptr;   ///< 3 n_vertices doubles
    std::size_t n_vertices = 0;       ///< number of vertices
    const int* triangles = nullptr;   ///< 3 n_triangles ids
    const double* params = nullptr;   ///< 6 n_triangles doubles
    std::size_t n_triangles = 0;      ///< number of triangles
};

/// Traits of the built-in input.
template <>
struct TriMeshTraits<ParametrizedTriMesh> {
    /// Number of vertices.
    static std::size_t n_vertices(const ParametrizedTriMesh& m) { return m.points.size(); }
    /// Position of vertex @p v.
    static Vec3d position(const ParametrizedTriMesh& m, std::size_t v) { return m.points[v]; }
    /// Number of triangles.
    static std::size_t n_triangles(const ParametrizedTriMesh& m) { return m.triangles.size(); }
    /// Corners of triangle @p f (negative ids become huge and are reported as out of range).
    static std::array<std::size_t, 3> triangle_vertices(const ParametrizedTriMesh& m, std::size_t f) {
        const auto& t = m.triangles[f];
        return {static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]), static_cast<std::size_t>(t[2])};
    }
    /// Parameter of corner @p k of triangle @p f.
    static Vec2d corner_param(const ParametrizedTriMesh& m, std::size_t f, int k) { return m.params[f][static_cast<std::size_t>(k)]; }
};

/// Traits of plain arrays.
template <>
struct TriMeshTraits<TriArraysView> {
    /// Number of vertices.
    static std::size_t n_vertices(const TriArraysView& m) { return m.n_vertices; }
    /// Position of vertex @p v.
    static Vec3d position(const TriArraysView& m, std::size_t v) { return Vec3d(m.points[3 * v], m.points[3 * v + 1], m.points[3 * v + 2]); }
    /// Number of triangles.
    static std::size_t n_triangles(const TriArraysView& m) { return m.n_triangles; }
    /// Corners of triangle @p f.
    static std::array<std::size_t, 3> triangle_vertices(const TriArraysView& m, std::size_t f) {
        return {static_cast<std::size_t>(m.triangles[3 * f]), static_cast<std::size_t>(m.triangles[3 * f + 1]),
                static_cast<std::size_t>(m.triangles[3 * f + 2])};
    }
    /// Parameter of corner @p k of triangle @p f.
    static Vec2d corner_param(const TriArraysView& m, std::size_t f, int k) {
        return Vec2d(m.params[6 * f + 2 * static_cast<std::size_t>(k)], m.params[6 * f + 2 * static_cast<std::size_t>(k) + 1]);
    }
};

/// Traits of OpenMesh triangle meshes: faces and vertices by index (the mesh must hold no
/// deleted elements: call garbage_collection() first), corner k of face f is the k-th
/// halfedge of the face's circulator, its parameter the halfedge's texcoord2D (the
/// halfedge's to-vertex in that face, as OpenMesh's OBJ reader stores `vt`).
template <class T>
struct TriMeshTraits<OpenMesh::TriMesh_ArrayKernelT<T>> {
    /// The mesh type.
    using Mesh = OpenMesh::TriMesh_ArrayKernelT<T>;
    /// Number of vertices.
    static std::size_t n_vertices(const Mesh& m) { return m.n_vertices(); }
    /// Position of vertex @p v.
    static Vec3d position(const Mesh& m, std::size_t v) {
        const auto& p = m.point(typename Mesh::VertexHandle(static_cast<int>(v)));
        return Vec3d(p[0], p[1], p[2]);
    }
    /// Number of faces.
    static std::size_t n_triangles(const Mesh& m) { return m.n_faces(); }
    /// Corners of face @p f (the to-vertices of its halfedges).
    static std::array<std::size_t, 3> triangle_vertices(const Mesh& m, std::size_t f) {
        auto h = m.halfedge_handle(typename Mesh::FaceHandle(static_cast<int>(f)));
        std::array<std::size_t, 3> r{};
        for (int k = 0; k < 3; ++k, h = m.next_halfedge_handle(h)) r[static_cast<std::size_t>(k)] = static_cast<std::size_t>(m.to_vertex_handle(h).idx());
        return r;
    }
    /// Parameter of corner @p k of face @p f (its halfedge's texcoord2D).
    static Vec2d corner_param(const Mesh& m, std::size_t f, int k) {
        auto h = m.halfedge_handle(typename Mesh::FaceHandle(static_cast<int>(f)));
        for (int i = 0; i < k; ++i) h = m.next_halfedge_handle(h);
        const auto& t = m.texcoord2D(h);
        return Vec2d(t[0], t[1]);
    }
};

/// Output traits of the built-in QuadMesh.
template <>
struct QuadMeshOutputTraits<QuadMesh> {
    /// Removes everything.
    static void clear(QuadMesh& m) { m = QuadMesh(); }
    /// Adds a vertex.
    static std::size_t add_vertex(QuadMesh& m, const Vec3d& p) { m.vertices.push_back(p); return m.vertices.size() - 1; }
    /// Adds a face: a quad if it has four corners, a polygon otherwise.
    static void add_face(QuadMesh& m, const std::vector<std::size_t>& loop) {
        if (loop.size() == 4) {
            m.quads.push_back({static_cast<int>(loop[0]), static_cast<int>(loop[1]), static_cast<int>(loop[2]), static_cast<int>(loop[3])});
        } else {
            m.polygons.emplace_back(loop.begin(), loop.end());
        }
    }
};

/// Output traits of OpenMesh polygon meshes. Faces OpenMesh refuses (complex vertices or
/// edges in defective output) are skipped by OpenMesh with a message on its error stream.
template <class T>
struct QuadMeshOutputTraits<OpenMesh::PolyMesh_ArrayKernelT<T>> {
    /// The mesh type.
    using Mesh = OpenMesh::PolyMesh_ArrayKernelT<T>;
    /// Removes everything.
    static void clear(Mesh& m) { m.clean(); }
    /// Adds a vertex.
    static std::size_t add_vertex(Mesh& m, const Vec3d& p) {
        return static_cast<std::size_t>(m.add_vertex(typename Mesh::Point(p[0], p[1], p[2])).idx());
    }
    /// Adds a face.
    static void add_face(Mesh& m, const std::vector<std::size_t>& loop) {
        std::vector<typename Mesh::VertexHandle> vh;
        for (std::size_t v : loop) vh.push_back(typename Mesh::VertexHandle(static_cast<int>(v)));
        m.add_face(vh);
    }
};

namespace detail {
/// True if @p Mesh has TriMeshTraits.
template <class Mesh, class = void>
inline constexpr bool hasTriMeshTraits = false;
/// Specialization for meshes with traits.
template <class Mesh>
inline constexpr bool hasTriMeshTraits<Mesh, std::void_t<decltype(TriMeshTraits<Mesh>::n_triangles(std::declval<const Mesh&>()))>> = true;
/// True if @p Mesh has QuadMeshOutputTraits.
template <class Mesh, class = void>
inline constexpr bool hasQuadMeshOutputTraits = false;
/// Specialization for meshes with traits.
template <class Mesh>
inline constexpr bool hasQuadMeshOutputTraits<Mesh, std::void_t<decltype(QuadMeshOutputTraits<Mesh>::clear(std::declval<Mesh&>()))>> = true;
} // namespace detail

/// Copies any mesh with TriMeshTraits into the built-in ParametrizedTriMesh. Throws
/// InputError for vertex ids out of range.
template <class Mesh>
ParametrizedTriMesh toParametrizedTriMesh(const Mesh& in) {
    using Tr = TriMeshTraits<Mesh>;
    ParametrizedTriMesh m;
    const std::size_t nv = Tr::n_vertices(in), nf = Tr::n_triangles(in);
    m.points.resize(nv);
    for (std::size_t v = 0; v < nv; ++v) m.points[v] = Tr::position(in, v);
    m.triangles.resize(nf);
    m.params.resize(nf);
    for (std::size_t f = 0; f < nf; ++f) {
        const std::array<std::size_t, 3> t = Tr::triangle_vertices(in, f);
        for (int k = 0; k < 3; ++k) {
            if (t[static_cast<std::size_t>(k)] >= nv)
                throw InputError("triangle " + std::to_string(f) + ": vertex index out of range (" + std::to_string(nv) + " vertices)");
            m.triangles[f][static_cast<std::size_t>(k)] = static_cast<int>(t[static_cast<std::size_t>(k)]);
            m.params[f][static_cast<std::size_t>(k)] = Tr::corner_param(in, f, k);
        }
    }
    return m;
}

/// Writes @p qm into any mesh with QuadMeshOutputTraits (cleared first): vertices, then
/// quads, then the other polygons.
template <class Mesh>
void fromQuadMesh(const QuadMesh& qm, Mesh& out) {
    using Tr = QuadMeshOutputTraits<Mesh>;
    Tr::clear(out);
    std::vector<std::size_t> id(qm.vertices.size());
    for (std::size_t v = 0; v < qm.vertices.size(); ++v) id[v] = Tr::add_vertex(out, qm.vertices[v]);
    std::vector<std::size_t> loop;
    for (const auto& q : qm.quads) {
        loop.clear();
        for (int v : q) loop.push_back(id[static_cast<std::size_t>(v)]);
        Tr::add_face(out, loop);
    }
    for (const auto& p : qm.polygons) {
        loop.clear();
        for (int v : p) loop.push_back(id[static_cast<std::size_t>(v)]);
        Tr::add_face(out, loop);
    }
}

/// Extracts the quad mesh of @p input, any mesh with TriMeshTraits, into @p output, any
/// mesh with QuadMeshOutputTraits (the 2D twin of the templated extractHexMesh()). Takes
/// part only when the pair is not exactly (ParametrizedTriMesh, QuadMesh), which the
/// non-template overload handles.
template <class InMesh, class OutMesh,
          std::enable_if_t<detail::hasTriMeshTraits<InMesh> && detail::hasQuadMeshOutputTraits<OutMesh> &&
                               !(std::is_same_v<InMesh, ParametrizedTriMesh> && std::is_same_v<OutMesh, QuadMesh>),
                           int> = 0>
QuadExtractionReport extractQuadMesh(const InMesh& input, OutMesh& output, const QuadExtractionOptions& options = {}) {
    auto run = [&](const ParametrizedTriMesh& pm) {
        if constexpr (std::is_same_v<OutMesh, QuadMesh>) {
            return extractQuadMesh(pm, output, options);
        } else {
            QuadMesh qm;
            QuadExtractionReport report = extractQuadMesh(pm, qm, options);
            fromQuadMesh(qm, output);
            return report;
        }
    };
    if constexpr (std::is_same_v<InMesh, ParametrizedTriMesh>) return run(input);
    else return run(toParametrizedTriMesh(input));
}

} // namespace HexEx
