#pragma once
/// @file ArrayMeshTraits.hh
/// @ingroup adapters
/// Plain-array meshes: a non-owning view of tets with corner parameters as input
/// (TetArraysView) and an owning set of arrays as output (HexArrays), with their traits.

#include "../Core/Error.hh"
#include "../Core/Vec.hh"
#include "MeshTraits.hh"

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace HexEx {

/// Non-owning view of a tet mesh with an integer-grid map held in plain arrays.
///
/// All three pointers must be set and stay valid while the view is used; `tets` and
/// `corner_params` must have the same length. `corner_params[t][i]` is the parameter of
/// corner `i` of tet `t` in the chart of tet `t`. Vertex indices are validated on access:
/// an index outside `[0, positions->size())` throws InputError naming the tet.
struct TetArraysView {
    const std::vector<Vec3d>* positions = nullptr;                ///< vertex positions
    const std::vector<std::array<int, 4>>* tets = nullptr;        ///< four vertex indices per tet
    const std::vector<std::array<Vec3d, 4>>* corner_params = nullptr;  ///< per-tet corner parameters
};

/// Output as plain arrays: positions, hexahedra (VTK order) and polyhedra (per cell a list
/// of faces, per face an outward-oriented vertex loop).
struct HexArrays {
    std::vector<Vec3d> positions;                          ///< vertex positions
    std::vector<std::array<int, 8>> hexes;                 ///< hexahedra, VTK order
    std::vector<std::vector<std::vector<int>>> polyhedra;  ///< non-hex cells as face lists
};

/// Input traits of TetArraysView. Throws InputError if a pointer is null, if the tet and
/// parameter arrays differ in length, or if a tet references a vertex out of range.
template <>
struct TetMeshTraits<TetArraysView> {
    /// Number of vertices.
    static std::size_t n_vertices(const TetArraysView& m) {
        if (!m.positions) throw InputError("TetArraysView: positions is null");
        return m.positions->size();
    }
    /// Position of vertex @p v.
    static Vec3d position(const TetArraysView& m, std::size_t v) { return (*m.positions)[v]; }
    /// Number of tets.
    static std::size_t n_tets(const TetArraysView& m) {
        if (!m.tets) throw InputError("TetArraysView: tets is null");
        if (!m.corner_params) throw InputError("TetArraysView: corner_params is null");
        if (m.tets->size() != m.corner_params->size())
            throw InputError("TetArraysView: " + std::to_string(m.tets->size()) + " tets but " +
                             std::to_string(m.corner_params->size()) + " corner parameter sets");
        return m.tets->size();
    }
    /// The four corners of tet @p t; throws InputError naming the tet on an index out of range.
    static std::array<std::size_t, 4> tet_vertices(const TetArraysView& m, std::size_t t) {
        const std::array<int, 4>& tv = (*m.tets)[t];
        const std::size_t nv = m.positions ? m.positions->size() : 0;
        std::array<std::size_t, 4> r;
        for (std::size_t i = 0; i < 4; ++i) {
            if (tv[i] < 0 || static_cast<std::size_t>(tv[i]) >= nv)
                throw InputError("tet " + std::to_string(t) + ": vertex index " + std::to_string(tv[i]) +
                                 " out of range (the mesh has " + std::to_string(nv) + " vertices)");
            r[i] = static_cast<std::size_t>(tv[i]);
        }
        return r;
    }
    /// Parameter of corner @p corner of tet @p t.
    static Vec3d corner_param(const TetArraysView& m, std::size_t t, int corner) {
        return (*m.corner_params)[t][static_cast<std::size_t>(corner)];
    }
};

/// Output traits of HexArrays.
template <>
struct HexMeshOutputTraits<HexArrays> {
    /// Removes all vertices and cells.
    static void clear(HexArrays& m) {
        m.positions.clear();
        m.hexes.clear();
        m.polyhedra.clear();
    }
    /// Appends a vertex, returns its index.
    static std::size_t add_vertex(HexArrays& m, const Vec3d& p) {
        m.positions.push_back(p);
        return m.positions.size() - 1;
    }
    /// Appends a hexahedron (VTK order).
    static void add_hex(HexArrays& m, const std::array<std::size_t, 8>& v) {
        std::array<int, 8> h;
        for (std::size_t i = 0; i < 8; ++i) h[i] = static_cast<int>(v[i]);
        m.hexes.push_back(h);
    }
    /// Appends a polyhedron given by its outward-oriented faces.
    static void add_polyhedron(HexArrays& m, const std::vector<std::vector<std::size_t>>& faces) {
        std::vector<std::vector<int>> cell(faces.size());
        for (std::size_t f = 0; f < faces.size(); ++f)
            for (std::size_t v : faces[f]) cell[f].push_back(static_cast<int>(v));
        m.polyhedra.push_back(std::move(cell));
    }
};

} // namespace HexEx
