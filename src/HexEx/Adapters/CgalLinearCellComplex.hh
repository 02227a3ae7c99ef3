#pragma once
/// @file CgalLinearCellComplex.hh
/// @ingroup adapters
/// Adapter for CGAL's Linear_cell_complex (3D combinatorial maps): extract the hex mesh of
/// an LCC of tetrahedra whose integer-grid map is stored per dart (or per (cell, vertex)
/// through a caller-supplied accessor) into an LCC of hexahedra, 3-sewn along shared faces.
///
/// Header-only and compiled only when included (it needs CGAL's headers, which the library
/// itself does not expose). Usage:
/// @code
/// HexEx::LccTetMesh input(tets, HexEx::LccDartInfoParameter{});   // map in lcc.info(dart)
/// HexEx::LccHexOutput<HexLcc> output(hexes);                       // fills `hexes`
/// HexEx::ExtractionReport report = HexEx::extractHexMesh(input, output);
/// @endcode
/// See Documentation/traits.md.

#include "../Core/Error.hh"
#include "../Core/Vec.hh"
#include "../HexExTraits.hh"
#include "../Mesh/HexProvenance.hh"
#include "LccVertexNumbering.hh"

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace HexEx {

namespace detail {

/// True if @p T has x(), y() and z() (CGAL points and vectors) (detection fallback).
template <class T, class = void>
struct HasXyz : std::false_type {};
/// True if @p T has x(), y() and z() (CGAL points and vectors).
template <class T>
struct HasXyz<T, std::void_t<decltype(std::declval<const T&>().x()), decltype(std::declval<const T&>().y()),
                             decltype(std::declval<const T&>().z())>> : std::true_type {};

/// Converts a CGAL point or vector (x(), y(), z(); any number type with CGAL::to_double) or
/// an indexable triple (std::array<double, 3>, HexEx::Vec3d) to a Vec3d.
template <class T>
Vec3d lccToVec3d(const T& p) {
    if constexpr (HasXyz<T>::value) {
        return Vec3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    } else {
        return Vec3d(static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2]));
    }
}

} // namespace detail

/// Parameter accessor for LccTetMesh that reads the map from the darts' information
/// (`lcc.info(d)`, the `Dart_info` type of the LCC's items): the parameter of the vertex
/// of dart `d` in the chart of the volume of `d`. `Dart_info` may be a CGAL point or
/// vector or an indexable triple of numbers. Only one dart per (volume, vertex) is read:
/// the darts that LccTetMesh::cornerDart() names.
struct LccDartInfoParameter {
    /// The parameter stored in dart @p d of @p lcc.
    template <class LCC>
    Vec3d operator()(const LCC& lcc, typename LCC::Dart_const_handle d) const {
        return detail::lccToVec3d(lcc.info(d));
    }
};

namespace detail {

/// True if @p T looks like a CGAL Linear_cell_complex of dimension 3 in 3D (detection fallback).
template <class T, class = void>
struct IsLcc3 : std::false_type {};
/// True if @p T looks like a CGAL Linear_cell_complex of dimension 3 in 3D.
template <class T>
struct IsLcc3<T, std::void_t<typename T::Dart_const_handle, typename T::Vertex_attribute_const_handle,
                             decltype(T::dimension), decltype(T::ambient_dimension)>>
    : std::bool_constant<T::dimension == 3 && T::ambient_dimension == 3> {};

/// True if the volume of @p d is a closed combinatorial tetrahedron (see lccIsClosedTet());
/// then @p faces holds its 12 darts, face by face: the face of @p d from @p d on, then the
/// faces 2-sewn to its darts in order.
template <class LCC>
bool lccClosedTetFaces(const LCC& lcc, typename LCC::Dart_const_handle d, typename LCC::Dart_const_handle (&faces)[4][3]) {
    using Dart = typename LCC::Dart_const_handle;
    // The face of d, then the faces across its three edges; every dart 1- and 2-sewn.
    const auto triangle = [&](Dart x, Dart* out) {
        for (int i = 0; i < 3; ++i) {
            if (lcc.template is_free<1>(x) || lcc.template is_free<2>(x)) return false;
            out[i] = x;
            x = lcc.beta(x, 1);
        }
        return x == out[0];
    };
    if (!triangle(d, faces[0])) return false;
    for (int k = 1; k < 4; ++k)
        if (!triangle(lcc.beta(faces[0][k - 1], 2), faces[k])) return false;
    // The 12 darts distinct: a beta1 cycle that closes after three steps has one or three
    // darts, and two cycles are equal or disjoint, so it suffices that each face has two
    // different darts and that no face starts inside an earlier one.
    for (int k = 0; k < 4; ++k) {
        if (faces[k][0] == faces[k][1]) return false;
        for (int j = 0; j < k; ++j)
            if (faces[k][0] == faces[j][0] || faces[k][0] == faces[j][1] || faces[k][0] == faces[j][2]) return false;
    }
    // Each face 2-sewn to the three others: face 0 is by construction (its dart i is sewn
    // to the first dart of face i + 1); the darts of faces 1..3 are looked up.
    const auto faceOf = [&](Dart x) {
        for (int k = 0; k < 4; ++k)
            if (faces[k][0] == x || faces[k][1] == x || faces[k][2] == x) return k;
        return -1;
    };
    for (int k = 1; k < 4; ++k) {
        unsigned neighbours = 0;
        for (int i = 0; i < 3; ++i) {
            const int n = faceOf(lcc.beta(faces[k][i], 2));
            if (n < 0 || n == k) return false;
            neighbours |= 1u << n;
        }
        if (neighbours != (15u & ~(1u << k))) return false;
    }
    return true;
}

/// True if the volume of @p d is a closed combinatorial tetrahedron: four distinct
/// triangles (beta1 cycles of three darts: the face of @p d and the faces 2-sewn to its
/// darts), each 2-sewn to the three others. The condition of CGAL's
/// is_volume_combinatorial_tetrahedron(), checked on the volume's 12 darts without the
/// marks and the queue of CGAL's traversal.
template <class LCC>
bool lccIsClosedTet(const LCC& lcc, typename LCC::Dart_const_handle d) {
    typename LCC::Dart_const_handle faces[4][3];
    return lccClosedTetFaces(lcc, d, faces);
}

/// The four corner darts of the tet volume of @p d (first dart of tet number @p t, for the
/// error message): the darts of its corners in LccTetMesh's order. With @p faces, also the
/// volume's 12 darts (see lccClosedTetFaces()). Throws InputError if the volume is not a
/// closed combinatorial tetrahedron.
template <class LCC>
std::array<typename LCC::Dart_const_handle, 4> lccTetCornerDarts(const LCC& lcc, typename LCC::Dart_const_handle d,
                                                                 std::size_t t,
                                                                 typename LCC::Dart_const_handle (*faces)[4][3] = nullptr) {
    typename LCC::Dart_const_handle own[4][3];
    if (!lccClosedTetFaces(lcc, d, faces ? *faces : own))
        throw InputError("LCC volume " + std::to_string(t) + " is not a closed combinatorial tetrahedron");
    return {d, lcc.beta(d, 1), lcc.beta(d, 1, 1), lcc.beta(d, 2, 0)};
}

/// The number (LccVertexNumbering of @p lcc) of the vertex of dart @p d of tet @p t (with
/// @p hint: LccVertexNumbering::find()'s run hint, kept by the caller); throws
/// InputError if the dart has no vertex attribute or one that is not among the LCC's.
template <class LCC>
std::size_t lccVertexOf(const LCC& lcc, const LccVertexNumbering& index, typename LCC::Dart_const_handle d,
                        std::size_t t, std::size_t* hint = nullptr) {
    const auto va = lcc.vertex_attribute(d);
    if (va == nullptr) throw InputError("LCC volume " + std::to_string(t) + ": a dart has no vertex attribute");
    const std::size_t v = hint ? index.find(static_cast<const void*>(&*va), *hint) : index.find(static_cast<const void*>(&*va));
    if (v == LccVertexNumbering::npos)
        throw InputError("LCC volume " + std::to_string(t) + ": a dart's vertex attribute is not one of the LCC's");
    return v;
}

} // namespace detail

/// What the one-call CGAL overloads of extractHexMesh() read (a given matching) or report
/// (what the extraction found) besides the hex mesh, through callables (each optional: an
/// empty one reads or reports nothing, and the extraction computes only what is asked for).
/// A Linear_cell_complex has no named properties, so results are handed to the caller with
/// the darts and vertex attributes they belong to; the caller stores them where it likes
/// (dart info, attributes, its own maps).
///
/// A tet face is named by a dart of it in its volume ("face dart"); the tet numbers are
/// those of the extraction (the order of `one_dart_per_cell<3>()`), passed together with
/// the first dart of the tet's volume in that order.
template <class TetLcc, class HexLcc>
struct LccResults {
    /// Dart of the tet LCC.
    using TetDart = typename TetLcc::Dart_const_handle;
    /// Dart of the hex LCC.
    using HexDart = typename HexLcc::Dart_handle;
    /// Vertex attribute of the hex LCC.
    using HexVertex = typename HexLcc::Vertex_attribute_handle;

    /// Read: called once per interior tet face (face dart) of every tet, it returns the
    /// rotation index (0..23, see Rotation) of the transition from the chart of the dart's
    /// volume into the chart of the volume across the face, used instead of inferring it
    /// (ExtractionOptions::given_rotations). A value outside 0..23 is an InputError.
    std::function<int(const TetLcc&, TetDart)> given_rotation;
    /// Report: per tet face (face dart, every face of every tet): the transition `u' = R u + t`
    /// from the chart of the dart's volume into the chart of the volume across, as the rotation
    /// index of R and t (identity on the boundary). The transitions HexEx uses
    /// (computeTransitions(), with #given_rotation when set).
    std::function<void(TetDart, int rotation, const std::array<int, 3>& translation)> transition;
    /// Report: per singular edge of the input (singularityGraph()): a dart of the edge (its
    /// vertex is one end, the vertex of `beta(d, 1)` the other) and its valence.
    std::function<void(TetDart, int valence)> singular_edge;
    /// Report: per hex (in order; its dart in LccHexOutput::cellDarts()): its source tet (number
    /// and first dart) and its integer grid cell in that tet's chart (HexProvenance).
    std::function<void(HexDart, std::size_t tet, TetDart, const std::array<int, 3>& grid_cell)> hex_provenance;
    /// Report: per output vertex that belongs to a hex: a tet whose closed parameter image
    /// contains it (number and first dart) and its integer grid coordinates in that tet's chart.
    std::function<void(HexVertex, std::size_t tet, TetDart, const std::array<int, 3>& grid_coords)> vertex_provenance;

    /// True if any callable is set.
    bool any() const { return given_rotation || transition || singular_edge || hex_provenance || vertex_provenance; }
};

/// Extracts the hex mesh of the CGAL Linear_cell_complex of tets @p tets, whose darts carry
/// the map (`tets.info(d)`: the parameter of the vertex of `d` in the chart of its volume; a
/// CGAL point or vector or an indexable triple), into the Linear_cell_complex @p hexes
/// (cleared first; written as LccHexOutput writes: one volume per cell, 3-sewn).
///
/// The tets are read straight into the built-in kernel (vertex and tet order, corner order
/// as LccTetMesh reads them; no per-tet cache), extracted, and the copy is freed before the
/// output is written. @p results reads a given matching and reports transitions, singular
/// edges and the hexes' provenance (LccResults). Throws InputError if a volume is not a closed
/// combinatorial tetrahedron or the input is otherwise unusable.
template <class TetLcc, class HexLcc,
          std::enable_if_t<detail::IsLcc3<TetLcc>::value && detail::IsLcc3<HexLcc>::value, int> = 0>
ExtractionReport extractHexMesh(const TetLcc& tets, HexLcc& hexes, const ExtractionOptions& options = {},
                                const LccResults<TetLcc, HexLcc>& results = {});

/// As the overload above, the map read through @p param: called as `param(tets, d)` with a
/// dart `d` (Dart_const_handle), it returns the parameter of the vertex of `d` in the chart of
/// the volume of `d` as a CGAL `Point_3` or `Vector_3` (any number type with
/// CGAL::to_double), a HexEx::Vec3d or an indexable triple of numbers.
template <class TetLcc, class ParamFn, class HexLcc,
          std::enable_if_t<detail::IsLcc3<TetLcc>::value && detail::IsLcc3<HexLcc>::value, int> = 0>
ExtractionReport extractHexMesh(const TetLcc& tets, const ParamFn& param, HexLcc& hexes,
                                const ExtractionOptions& options = {}, const LccResults<TetLcc, HexLcc>& results = {});

/// Input view of a CGAL Linear_cell_complex of dimension 3 whose volumes are tetrahedra,
/// read by the templated extractHexMesh() through TetMeshTraits.
///
/// Vertices are numbered in the order of `lcc.vertex_attributes()`, tets in the order of
/// `lcc.one_dart_per_cell<3>()` (for an LCC built volume by volume: creation order). The
/// corners of a tet whose first dart is `d` are the vertices of `d`, `beta1(d)`,
/// `beta1(beta1(d))` and `beta0(beta2(d))`: CGAL orients the faces of a volume so that
/// their normals point into it (as `make_tetrahedron()` does), which makes this corner
/// order positively oriented. The parameter of a corner is `param(lcc, cornerDart(t, i))`,
/// so @p ParamFn decides where the map lives: per dart (LccDartInfoParameter) or per
/// (cell, vertex) in any storage reachable from a dart (its volume attribute, its vertex
/// attribute, an external table).
///
/// The constructor scans the LCC once (a vertex index table and four darts per tet) and
/// throws InputError if a volume is not a combinatorial tetrahedron, a dart has no vertex
/// attribute, or a volume is open (a free beta1 or beta2). The LCC must stay alive and
/// unchanged while the view is used.
template <class LCC, class ParamFn = LccDartInfoParameter>
class LccTetMesh {
public:
    /// Dart handle type of the LCC.
    using Dart = typename LCC::Dart_const_handle;

    /// Scans @p lcc; @p param returns the parameter of the vertex of a dart in the chart of
    /// the dart's volume (anything convertible to Vec3d).
    explicit LccTetMesh(const LCC& lcc, ParamFn param = ParamFn()) : lcc_(&lcc), param_(std::move(param)) {
        static_assert(LCC::dimension == 3 && LCC::ambient_dimension == 3,
                      "HexEx::LccTetMesh needs a Linear_cell_complex of dimension 3 in 3D");
        const detail::LccVertexNumbering index(lcc);
        for (auto it = lcc.vertex_attributes().begin(); it != lcc.vertex_attributes().end(); ++it)
            vertices_.push_back(it);
        for (auto it = lcc.template one_dart_per_cell<3>().begin(); it != lcc.template one_dart_per_cell<3>().end();
             ++it) {
            const std::size_t t = darts_.size();
            const std::array<Dart, 4> c = detail::lccTetCornerDarts(lcc, Dart(it), t);
            std::array<std::size_t, 4> v{};
            for (std::size_t i = 0; i < 4; ++i) v[i] = detail::lccVertexOf(lcc, index, c[i], t);
            darts_.push_back(c);
            corners_.push_back(v);
        }
    }

    /// The viewed LCC.
    const LCC& lcc() const { return *lcc_; }
    /// Number of vertices (vertex attributes).
    std::size_t n_vertices() const { return vertices_.size(); }
    /// Number of tets (volumes).
    std::size_t n_tets() const { return darts_.size(); }
    /// Position of vertex @p v.
    Vec3d position(std::size_t v) const { return detail::lccToVec3d(vertices_[v]->point()); }
    /// Vertex index of corner @p i (0..3) of tet @p t.
    std::size_t corner(std::size_t t, int i) const { return corners_[t][static_cast<std::size_t>(i)]; }
    /// The dart of tet @p t whose vertex is corner @p i (the one passed to the parameter accessor).
    Dart cornerDart(std::size_t t, int i) const { return darts_[t][static_cast<std::size_t>(i)]; }
    /// Parameter of corner @p i of tet @p t.
    Vec3d param(std::size_t t, int i) const { return detail::lccToVec3d(param_(*lcc_, cornerDart(t, i))); }

private:
    const LCC* lcc_;
    ParamFn param_;
    std::vector<typename LCC::Vertex_attribute_const_handle> vertices_;
    std::vector<std::array<Dart, 4>> darts_;
    std::vector<std::array<std::size_t, 4>> corners_;
};

/// Output into a CGAL Linear_cell_complex of dimension 3: every cell becomes a volume
/// (hexahedra as CGAL combinatorial hexahedra, other cells as closed polyhedral volumes),
/// all volumes share one vertex attribute per output vertex, and two volumes with a
/// common face (same vertices, opposite orientation) are 3-sewn, so `lcc.is_valid()` holds
/// and each hex volume satisfies `is_volume_combinatorial_hexahedron()`.
///
/// Faces are oriented as CGAL's make_hexahedron() orients them (normals into the volume).
/// Only vertex attributes are created; other enabled attributes are left unset. A face
/// met a third time (non-manifold output), or twice with the same orientation, stays
/// 3-free and is counted in unsewnFaces(). Written to through HexMeshOutputTraits; the
/// LCC must outlive this object.
template <class LCC>
class LccHexOutput {
public:
    /// Dart handle type of the LCC.
    using Dart = typename LCC::Dart_handle;

    /// Writes into @p lcc (cleared by the first clear()).
    explicit LccHexOutput(LCC& lcc) : lcc_(&lcc) {
        static_assert(LCC::dimension == 3 && LCC::ambient_dimension == 3,
                      "HexEx::LccHexOutput needs a Linear_cell_complex of dimension 3 in 3D");
    }

    /// The LCC written into.
    LCC& lcc() { return *lcc_; }
    /// One dart per output cell, hexahedra first, then polyhedra (the order of the
    /// extractor's HexMesh::hexes and HexMesh::polyhedra): attach per-cell data to them.
    const std::vector<Dart>& cellDarts() const { return cells_; }
    /// One vertex attribute per output vertex, in the extractor's vertex order.
    const std::vector<typename LCC::Vertex_attribute_handle>& vertexAttributes() const { return vertices_; }
    /// Number of faces left 3-free because they could not be paired consistently.
    std::size_t unsewnFaces() const { return unsewn_; }

    /// Removes everything from the LCC and from this object's bookkeeping.
    void clear() {
        lcc_->clear();
        vertices_.clear();
        cells_.clear();
        open_.clear();
        unsewn_ = 0;
    }
    /// Makes room for @p nVertices vertices and the faces of @p nHexes hexahedra in this
    /// object's bookkeeping (the LCC itself grows as it goes).
    void reserve(std::size_t nVertices, std::size_t nHexes) {
        vertices_.reserve(nVertices);
        cells_.reserve(nHexes);
        open_.reserve(nHexes + nHexes / 2);
    }
    /// Adds a vertex attribute at @p p and returns its index.
    std::size_t addVertex(const Vec3d& p) {
        vertices_.push_back(lcc_->create_vertex_attribute(typename LCC::Point(p[0], p[1], p[2])));
        return vertices_.size() - 1;
    }
    /// Adds a hexahedron (vertex indices in VTK order) and returns its first dart.
    Dart addHex(const std::array<std::size_t, 8>& v) {
        static constexpr int kFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                             {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
        std::vector<std::vector<std::size_t>>& faces = scratch_;
        faces.resize(6);
        for (std::size_t f = 0; f < 6; ++f) {
            faces[f].resize(4);
            for (std::size_t i = 0; i < 4; ++i) faces[f][i] = v[static_cast<std::size_t>(kFaces[f][i])];
        }
        return addVolume(faces);
    }
    /// Adds a closed volume given by its faces, each an outward-oriented loop of vertex
    /// indices, and returns its first dart.
    Dart addVolume(const std::vector<std::vector<std::size_t>>& faces) {
        std::vector<Dart>& darts = darts_;
        std::vector<std::pair<std::size_t, std::size_t>>& ends = ends_;  // (origin, target) per dart
        std::vector<std::size_t>& faceStart = faceStart_;
        darts.clear();
        ends.clear();
        faceStart.clear();
        for (const auto& loop : faces) {
            const std::size_t n = loop.size(), first = darts.size();
            faceStart.push_back(first);
            // CGAL orients a volume's faces inward: walk the outward loop backwards.
            for (std::size_t k = 0; k < n; ++k) {
                const std::size_t a = loop[(n - k) % n], b = loop[(2 * n - k - 1) % n];
                darts.push_back(lcc_->create_dart(vertices_.at(a)));
                ends.emplace_back(a, b);
            }
            for (std::size_t k = 0; k < n; ++k) lcc_->basic_link_beta_1(darts[first + k], darts[first + (k + 1) % n]);
        }
        // beta2 inside the volume: the dart a->b meets the dart b->a of another face.
        for (std::size_t i = 0; i < darts.size(); ++i) {
            if (!lcc_->template is_free<2>(darts[i])) continue;
            for (std::size_t j = i + 1; j < darts.size(); ++j)
                if (ends[j].first == ends[i].second && ends[j].second == ends[i].first &&
                    lcc_->template is_free<2>(darts[j])) {
                    lcc_->template basic_link_beta_for_involution<2>(darts[i], darts[j]);
                    break;
                }
        }
        for (std::size_t f = 0; f < faces.size(); ++f)
            if (!faces[f].empty()) sewFace(faces[f], darts[faceStart[f]]);
        const Dart first = darts.empty() ? lcc_->null_dart_handle : darts.front();
        cells_.push_back(first);
        return first;
    }

private:
    /// Key of a face: its (up to) four smallest vertex indices and its size.
    struct Key {
        std::array<std::size_t, 4> v{};  ///< smallest indices, ascending, padded with SIZE_MAX
        std::size_t n = 0;               ///< number of vertices
        /// Equality.
        bool operator==(const Key& o) const { return v == o.v && n == o.n; }
    };
    /// Hash of a Key.
    struct KeyHash {
        /// Mixes the key's numbers.
        std::size_t operator()(const Key& k) const {
            std::uint64_t h = k.n * 0x9E3779B97F4A7C15ull;
            for (std::size_t x : k.v) h = (h ^ x) * 0xBF58476D1CE4E5B9ull;
            return static_cast<std::size_t>(h ^ (h >> 31));
        }
    };

    /// Pairs the face whose first dart is @p d (outward loop @p loop; the dart goes from
    /// loop[0] to loop[n-1]) with an earlier face on the same vertices and opposite
    /// orientation, or remembers it.
    void sewFace(const std::vector<std::size_t>& loop, Dart d) {
        Key key;
        key.n = loop.size();
        // The four smallest indices, ascending (insertion into a padded array: no allocation).
        key.v.fill(SIZE_MAX);
        for (std::size_t x : loop)
            for (std::size_t i = 0; i < 4; ++i)
                if (x < key.v[i]) {
                    for (std::size_t j = 3; j > i; --j) key.v[j] = key.v[j - 1];
                    key.v[i] = x;
                    break;
                }
        auto [it, inserted] = open_.emplace(key, d);
        if (inserted) return;
        // d runs from vertex a to b; its partner runs from b to a in the other face.
        const auto va = lcc_->vertex_attribute(d), vb = lcc_->vertex_attribute(lcc_->beta(d, 1));
        Dart e = it->second, partner = lcc_->null_dart_handle;
        for (std::size_t k = 0; k < key.n; ++k, e = lcc_->beta(e, 1))
            if (lcc_->vertex_attribute(e) == vb && lcc_->vertex_attribute(lcc_->beta(e, 1)) == va) partner = e;
        bool ok = partner != lcc_->null_dart_handle && lcc_->template is_free<3>(it->second);
        // Walking d forward and the partner backward must meet the same vertices.
        Dart x = d, y = partner;
        for (std::size_t k = 0; ok && k < key.n; ++k, x = lcc_->beta(x, 1), y = lcc_->beta(y, 0))
            ok = lcc_->vertex_attribute(x) == lcc_->vertex_attribute(lcc_->beta(y, 1));
        if (!ok) {
            ++unsewn_;
            return;
        }
        x = d;
        y = partner;
        for (std::size_t k = 0; k < key.n; ++k, x = lcc_->beta(x, 1), y = lcc_->beta(y, 0))
            lcc_->template basic_link_beta_for_involution<3>(x, y);
        open_.erase(it);
    }

    LCC* lcc_;
    std::vector<typename LCC::Vertex_attribute_handle> vertices_;
    std::vector<Dart> cells_;
    std::unordered_map<Key, Dart, KeyHash> open_;
    std::vector<std::vector<std::size_t>> scratch_;
    std::vector<Dart> darts_;                                  // addVolume() scratch: darts
    std::vector<std::pair<std::size_t, std::size_t>> ends_;    // addVolume() scratch: dart ends
    std::vector<std::size_t> faceStart_;                       // addVolume() scratch: first dart per face
    std::size_t unsewn_ = 0;
};

/// Input traits of LccTetMesh (see TetMeshTraits).
template <class LCC, class ParamFn>
struct TetMeshTraits<LccTetMesh<LCC, ParamFn>> {
    /// Number of vertices.
    static std::size_t n_vertices(const LccTetMesh<LCC, ParamFn>& m) { return m.n_vertices(); }
    /// Position of vertex @p v.
    static Vec3d position(const LccTetMesh<LCC, ParamFn>& m, std::size_t v) { return m.position(v); }
    /// Number of tets.
    static std::size_t n_tets(const LccTetMesh<LCC, ParamFn>& m) { return m.n_tets(); }
    /// The four corners of tet @p t.
    static std::array<std::size_t, 4> tet_vertices(const LccTetMesh<LCC, ParamFn>& m, std::size_t t) {
        return {m.corner(t, 0), m.corner(t, 1), m.corner(t, 2), m.corner(t, 3)};
    }
    /// Parameter of corner @p i of tet @p t.
    static Vec3d corner_param(const LccTetMesh<LCC, ParamFn>& m, std::size_t t, int i) { return m.param(t, i); }
};

/// Output traits of LccHexOutput (see HexMeshOutputTraits).
template <class LCC>
struct HexMeshOutputTraits<LccHexOutput<LCC>> {
    /// Clears the LCC.
    static void clear(LccHexOutput<LCC>& m) { m.clear(); }
    /// Makes room for @p nVertices vertices and @p nHexes hexahedra.
    static void reserve(LccHexOutput<LCC>& m, std::size_t nVertices, std::size_t nHexes) {
        m.reserve(nVertices, nHexes);
    }
    /// Adds a vertex attribute.
    static std::size_t add_vertex(LccHexOutput<LCC>& m, const Vec3d& p) { return m.addVertex(p); }
    /// Adds a hexahedron (VTK order).
    static void add_hex(LccHexOutput<LCC>& m, const std::array<std::size_t, 8>& v) { m.addHex(v); }
    /// Adds a polyhedron given by its outward-oriented faces.
    static void add_polyhedron(LccHexOutput<LCC>& m, const std::vector<std::vector<std::size_t>>& faces) {
        m.addVolume(faces);
    }
};

} // namespace HexEx

#include "CgalLinearCellComplexT_impl.hh"
