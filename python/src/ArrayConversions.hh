#pragma once
/// @file ArrayConversions.hh
/// Conversions between numpy arrays (nanobind ndarrays) and the library's C++ types. The
/// Python layer (hexex/_arrays.py) has already checked shapes and dtypes and made the
/// arrays C-contiguous, so these functions only move data.

#include <HexEx/Mesh/HexMesh.hh>
#include <HexEx/Mesh/MeshTraits.hh>
#include <HexEx/Mesh/ParametrizedTetMesh.hh>
#include <HexEx/Untangling/TriangleSurface.hh>

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <vector>

namespace HexExPython {

namespace nb = nanobind;

/// Read-only C-contiguous float64 array of any shape (points (n,3), params (m,4,3)).
using DoubleArray = nb::ndarray<const double, nb::c_contig, nb::device::cpu>;
/// Read-only C-contiguous int32 array (tets, hexes, rotations).
using Int32Array = nb::ndarray<const std::int32_t, nb::c_contig, nb::device::cpu>;
/// Read-only C-contiguous int64 array (tets as numpy makes them by default).
using Int64Array = nb::ndarray<const std::int64_t, nb::c_contig, nb::device::cpu>;
/// A numpy float64 array handed to Python.
using NumpyDoubles = nb::ndarray<nb::numpy, double>;
/// A numpy int32 array handed to Python.
using NumpyInts = nb::ndarray<nb::numpy, std::int32_t>;

/// Non-owning view of a tet mesh with its map held in numpy buffers; read through
/// HexEx::TetMeshTraits by HexEx::toParametrizedTetMesh(), which validates the indices.
template <class Index>
struct TetArraysRef {
    const double* points = nullptr;  ///< n_vertices x 3
    std::size_t n_vertices = 0;      ///< number of vertices
    const Index* tets = nullptr;     ///< n_tets x 4 vertex indices
    std::size_t n_tets = 0;          ///< number of tets
    const double* params = nullptr;  ///< n_tets x 4 x 3 corner parameters
};

/// The tet vertex indices of a map: an int32 or an int64 (m,4) buffer.
struct TetIndices {
    const std::int32_t* i32 = nullptr;  ///< the indices if the array is int32
    const std::int64_t* i64 = nullptr;  ///< the indices if the array is int64
    std::size_t n_tets = 0;             ///< number of rows
};

/// Throws std::invalid_argument (ValueError in Python) unless @p shape matches @p expected
/// (-1 matches any extent). @p name names the array in the message.
void requireShape(const char* name, const std::vector<std::size_t>& shape, std::initializer_list<long> expected);

/// requireShape() for an ndarray @p a.
template <class Array>
void requireArrayShape(const char* name, const Array& a, std::initializer_list<long> expected) {
    std::vector<std::size_t> shape(a.ndim());
    for (std::size_t i = 0; i < shape.size(); ++i) shape[i] = a.shape(i);
    requireShape(name, shape, expected);
}

/// The tet indices of @p tets, an (m,4) int32 or int64 C-contiguous array; needs the GIL.
/// Throws std::invalid_argument (ValueError) otherwise.
TetIndices tetIndices(const nb::handle& tets);

/// Copies the arrays into the library's tet mesh (the one copy the extractor needs), builds
/// its adjacency and checks that it is a manifold; throws HexEx::InputError for bad indices
/// or non-manifold meshes. Needs no GIL: the caller keeps the arrays alive.
HexEx::ParametrizedTetMesh toTetMesh(const DoubleArray& points, const TetIndices& tets, const DoubleArray& params);

/// The map as three new numpy arrays (points float64 (n,3), tets int32 (m,4), params
/// float64 (m,4,3)), returned as a tuple.
nb::tuple mapToArrays(const HexEx::ParametrizedTetMesh& pm);

/// Moves @p mesh to the heap and returns (points, hexes, polyhedra): the two arrays view
/// its buffers without copying and keep it alive; polyhedra is a list of faces per cell.
nb::tuple hexMeshToArrays(HexEx::HexMesh&& mesh);

/// Builds a HexMesh from arrays and a sequence of polyhedra (list of faces, each a
/// sequence of vertex indices). Index ranges are checked by the consumers (writers, checker).
HexEx::HexMesh hexMeshFromArrays(const DoubleArray& points, const Int32Array& hexes, const nb::handle& polyhedra);

/// Fills @p surface from optional (n, 3) points and (t, 3) triangles (the `surface=` argument
/// of untangle and optimize); returns false (and leaves @p surface empty) unless both are
/// given. @throws std::invalid_argument for a wrong shape or a point index out of range.
bool surfaceFromArrays(const std::optional<DoubleArray>& points, const std::optional<Int32Array>& triangles,
                       HexEx::TriangleSurface& surface);

} // namespace HexExPython

/// TetMeshTraits of the numpy view: dense indices, parameters per tet corner.
template <class Index>
struct HexEx::TetMeshTraits<HexExPython::TetArraysRef<Index>> {
    /// Alias of the view type.
    using Ref = HexExPython::TetArraysRef<Index>;
    /// Number of vertices.
    static std::size_t n_vertices(const Ref& m) { return m.n_vertices; }
    /// Position of vertex @p v.
    static Vec3d position(const Ref& m, std::size_t v) {
        const double* p = m.points + 3 * v;
        return Vec3d(p[0], p[1], p[2]);
    }
    /// Number of tets.
    static std::size_t n_tets(const Ref& m) { return m.n_tets; }
    /// Corners of tet @p t; negative indices wrap around and are reported as out of range.
    static std::array<std::size_t, 4> tet_vertices(const Ref& m, std::size_t t) {
        const Index* c = m.tets + 4 * t;
        return {static_cast<std::size_t>(c[0]), static_cast<std::size_t>(c[1]), static_cast<std::size_t>(c[2]),
                static_cast<std::size_t>(c[3])};
    }
    /// Parameter of corner @p corner of tet @p t.
    static Vec3d corner_param(const Ref& m, std::size_t t, int corner) {
        const double* p = m.params + 12 * t + 3 * static_cast<std::size_t>(corner);
        return Vec3d(p[0], p[1], p[2]);
    }
};
