#pragma once
/// @file OpenVolumeMesh.hh
/// @ingroup adapters
/// Adapter for OpenVolumeMesh (3.x): extract the hex mesh of an OpenVolumeMesh tet mesh
/// (tetrahedral or polyhedral kernel with Vec3d geometry) whose integer-grid map is the
/// halfface property `HexHex::Parametrization` (the convention of HexHex and the AlgoHex
/// tools) or a cell property mapping each of the cell's vertices to its parameter, and write
/// the result into an OpenVolumeMesh hexahedral mesh (or a polyhedral one, which also keeps
/// non-hex cells). Reverse helper: per-cell data back as an OpenVolumeMesh cell property.
///
/// Header-only and compiled only when included; the program must find and link
/// OpenVolumeMesh itself (`find_package(OpenVolumeMesh)`, target `OpenVolumeMesh::OpenVolumeMesh`).
/// @code
/// OpenVolumeMesh::GeometricTetrahedralMeshV3d tets;          // e.g. read with IO::read_file
/// OpenVolumeMesh::GeometricHexahedralMeshV3d hexes;
/// HexEx::OvmHexOutput<OpenVolumeMesh::GeometricHexahedralMeshV3d> output(hexes);
/// HexEx::extractHexMesh(HexEx::OvmTetMesh(tets), output);
/// @endcode
/// See Documentation/traits.md.

#include "../Core/Error.hh"
#include "../Core/Vec.hh"
#include "../HexExTraits.hh"
#include "../Preprocessing/SingularityGraph.hh"
#include "../Preprocessing/Transitions.hh"
#include "OvmBulkTables.hh"

#include <OpenVolumeMesh/Core/Handles.hh>
#include <OpenVolumeMesh/Core/Properties/PropertyPtr.hh>
#include <OpenVolumeMesh/Core/TopologyKernel.hh>
#include <OpenVolumeMesh/Geometry/VectorT.hh>
#include <OpenVolumeMesh/Mesh/HexahedralMeshTopologyKernel.hh>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace HexEx {

/// Name of the halfface property holding the map in HexHex and the AlgoHex tools: on a
/// halfface of cell `c`, the parameter (in `c`'s chart) of the vertex of `c` opposite it.
inline constexpr const char* kOvmParametrization = "HexHex::Parametrization";

/// Where an OpenVolumeMesh tet mesh keeps its integer-grid map.
enum class OvmMapStorage {
    /// Halfface property of type Vec3d: the parameter of the cell's vertex opposite the halfface.
    HalffaceOpposite,
    /// Cell property of type `std::map<VertexHandle, Vec3d>`: per cell, the parameter of each of its vertices.
    CellVertexMap,
};

namespace detail {

/// True if @p TetMeshT and @p HexMeshT are OpenVolumeMesh meshes (kernels derived from
/// TopologyKernel): the condition of the one-call overloads of extractHexMesh() below.
template <class TetMeshT, class HexMeshT>
inline constexpr bool isOvmMeshPair = std::is_base_of_v<OpenVolumeMesh::TopologyKernel, TetMeshT> &&
                                      std::is_base_of_v<OpenVolumeMesh::TopologyKernel, HexMeshT>;

/// Reads the corners of tetrahedral cell @p c of @p mesh in OvmTetMesh's order (before the
/// global orientation fix) into @p cv and, per corner, the cell's halfface opposite it into
/// @p opposite. Throws InputError if the cell is not a tetrahedron.
template <class Mesh>
void ovmTetCorners(const Mesh& mesh, std::size_t c, std::array<OpenVolumeMesh::VertexHandle, 4>& cv,
                   std::array<OpenVolumeMesh::HalfFaceHandle, 4>& opposite);

} // namespace detail

/// Properties of the user's tet mesh that the one-call OpenVolumeMesh overloads of
/// extractHexMesh() read (a given matching) or write back (what the extraction found); each
/// optional: null reads or writes nothing. The properties are the caller's (e.g.
/// `tetMesh.request_halfface_property<int>("rotation")`) and must belong to the tet mesh
/// passed to the call.
///
/// The transitions written are those HexEx infers from the corner parameters as given
/// (computeTransitions()), with the given rotations when set; the singular edges those of
/// singularityGraph().
struct OvmTetProperties {
    /// Read: per halfface, the rotation index (0..23) of the transition into the neighbour
    /// (same convention as #rotation), used instead of inferring it from the parameters
    /// (ExtractionOptions::given_rotations; the translations are still inferred). A value
    /// outside 0..23 on an interior halfface is an InputError.
    const OpenVolumeMesh::HalfFacePropertyT<int>* given_rotation = nullptr;
    /// Per halfface `h` of cell `c`: the rotation index (0..23, see Rotation) of the
    /// transition from the chart of `c` into the chart of the cell across `h`; 0 (the
    /// identity) on the boundary.
    OpenVolumeMesh::HalfFacePropertyT<int>* rotation = nullptr;
    /// Per halfface: the integer translation `t` of that transition (`u' = R u + t`).
    OpenVolumeMesh::HalfFacePropertyT<OpenVolumeMesh::Geometry::Vec3i>* translation = nullptr;
    /// Per edge: the valence of a singular edge (quarter turns of parametric angle around
    /// it; 4 would be regular), 0 on every other edge.
    OpenVolumeMesh::EdgePropertyT<int>* singular_valence = nullptr;
};

/// Names of the properties that the one-call OpenVolumeMesh overloads of extractHexMesh()
/// create in the user's hex mesh with the provenance of the output (HexProvenance); an empty
/// name writes nothing, and when all are empty the provenance is not computed (no cost).
/// The properties are persistent: they stay in the mesh after the call, found by name
/// (`get_cell_property<int>("hexex:source_tet")`).
struct OvmHexProperties {
    /// `int` cell property: per hex, the tet mesh cell whose parameter image contains the
    /// hex's centre (HexProvenance::hex_source_tet); -1 on non-hex cells.
    std::string source_tet;
    /// `Vec3i` cell property: per hex, the smallest corner of its integer grid cell in the
    /// chart of its source tet (HexProvenance::hex_grid_cell); (0, 0, 0) on non-hex cells.
    std::string grid_cell;
    /// `Vec3i` vertex property: per vertex, its integer grid coordinates in the chart of the
    /// tet in #vertex_source_tet (HexProvenance::vertex_grid_coords).
    std::string grid_coords;
    /// `int` vertex property: per vertex, a tet mesh cell whose closed parameter image
    /// contains its grid point (HexProvenance::vertex_source_tet; -1 for a vertex of no hex).
    std::string vertex_source_tet;

    /// All four, named "hexex:source_tet", "hexex:grid_cell", "hexex:grid_coords" and
    /// "hexex:vertex_source_tet".
    static OvmHexProperties all() {
        return {"hexex:source_tet", "hexex:grid_cell", "hexex:grid_coords", "hexex:vertex_source_tet"};
    }
    /// True if any property is named.
    bool any() const {
        return !source_tet.empty() || !grid_cell.empty() || !grid_coords.empty() || !vertex_source_tet.empty();
    }
};

/// Extracts the hex mesh of the OpenVolumeMesh tet mesh @p tetMesh into the OpenVolumeMesh
/// hexahedral or polyhedral mesh @p hexMesh, the map given as in the reference HexEx
/// implementation: per cell, a map from each of its vertices to its parameter in the cell's
/// chart.
///
/// The call of the reference implementation's users ports unchanged
/// (`HexEx::extractHexMesh(tetMesh, parameters, hexMesh)`). The tet mesh is read straight into
/// the built-in kernel (corner order and orientation as OvmTetMesh reads it), extracted, and
/// the result written in bulk (see OvmHexOutput; @p hexMesh is cleared first; a hexahedral
/// kernel skips non-hex cells, which the report still counts). Vertex and cell indices are
/// the handles' indices: the mesh must not contain deleted entities. @p results names
/// properties of @p tetMesh that receive the transitions and singular edges (OvmTetProperties),
/// @p hexResults the properties of @p hexMesh that receive the hexes' source tets and grid
/// cells and the vertices' grid coordinates (OvmHexProperties).
///
/// Throws InputError if a cell is not a tetrahedron, lacks the parameter of one of its
/// vertices, or the input is otherwise unusable (see the built-in extractHexMesh()).
template <class TetMeshT, class VecT, class HexMeshT,
          std::enable_if_t<detail::isOvmMeshPair<TetMeshT, HexMeshT>, int> = 0>
ExtractionReport extractHexMesh(const TetMeshT& tetMesh,
                                const OpenVolumeMesh::CellPropertyT<std::map<OpenVolumeMesh::VertexHandle, VecT>>& parameters,
                                HexMeshT& hexMesh, const ExtractionOptions& options = {},
                                const OvmTetProperties& results = {}, const OvmHexProperties& hexResults = {});

/// Extracts the hex mesh of the OpenVolumeMesh tet mesh @p tetMesh into the OpenVolumeMesh
/// hexahedral or polyhedral mesh @p hexMesh, the map given as in HexHex: the value on a
/// halfface of a cell is the parameter, in the cell's chart, of the cell's vertex opposite
/// that halfface (e.g. the property kOvmParametrization of the files HexHex reads and writes).
///
/// Otherwise as the overload taking a cell property. Throws InputError if a cell is not a
/// tetrahedron or the input is otherwise unusable.
template <class TetMeshT, class VecT, class HexMeshT,
          std::enable_if_t<detail::isOvmMeshPair<TetMeshT, HexMeshT>, int> = 0>
ExtractionReport extractHexMesh(const TetMeshT& tetMesh, const OpenVolumeMesh::HalfFacePropertyT<VecT>& parameters,
                                HexMeshT& hexMesh, const ExtractionOptions& options = {},
                                const OvmTetProperties& results = {}, const OvmHexProperties& hexResults = {});

/// Input view of an OpenVolumeMesh tet mesh (any kernel with `Vec3d` geometry whose cells
/// are tetrahedra: TetrahedralMeshTopologyKernel or the polyhedral TopologyKernel) with its
/// map, read by the templated extractHexMesh() through TetMeshTraits.
///
/// Vertex and tet indices are OpenVolumeMesh's handle indices (the mesh must not contain
/// deleted entities: run garbage collection first). The corners of a cell are the loop of
/// its first halfface followed by the fourth vertex, rotated among the first three so that
/// the first corner is opposite the last halfface: a tet `a b c d` stored with the halffaces
/// `a b c`, `a c d`, `a d b`, `b d c` (OpenVolumeMesh's convention: halfface normals point
/// into the cell) reads back as `a b c d`. If the corners so read are negatively oriented
/// in total (a mesh stored with outward halffaces), corners 1 and 2 of every tet are swapped.
///
/// The property is looked up by name, so it must exist when the view is made: properties
/// read from a file are persistent; one made with `request_halfface_property()` must be
/// kept alive or made persistent (`mesh.set_persistent(prop)`).
///
/// The constructor throws InputError if the property is missing or a cell is not a
/// tetrahedron (four triangular halffaces on four vertices), or (CellVertexMap) when a
/// cell's map lacks one of its vertices. The mesh must stay alive and unchanged while the
/// view is used.
template <class Mesh>
class OvmTetMesh {
public:
    /// The OpenVolumeMesh 3D vector type.
    using OvmVec = OpenVolumeMesh::Geometry::Vec3d;

    /// Views @p mesh with the map in the property @p name stored as @p storage.
    explicit OvmTetMesh(const Mesh& mesh, const std::string& name = kOvmParametrization,
                        OvmMapStorage storage = OvmMapStorage::HalffaceOpposite)
        : mesh_(&mesh) {
        const std::size_t nc = mesh.n_cells();
        if (storage == OvmMapStorage::HalffaceOpposite) {
            auto prop = mesh.template get_halfface_property<OvmVec>(name);
            if (!prop)
                throw InputError("OpenVolumeMesh mesh has no halfface property '" + name + "' of type Vec3d");
            readCells(nc, [&](const OpenVolumeMesh::HalfFaceHandle& hf, const OpenVolumeMesh::VertexHandle&) {
                return (*prop)[hf];
            });
        } else {
            using VertexMap = std::map<OpenVolumeMesh::VertexHandle, OvmVec>;
            auto prop = mesh.template get_cell_property<VertexMap>(name);
            if (!prop)
                throw InputError("OpenVolumeMesh mesh has no cell property '" + name +
                                 "' of type std::map<VertexHandle, Vec3d>");
            readCells(nc, [&](const OpenVolumeMesh::HalfFaceHandle& hf, const OpenVolumeMesh::VertexHandle& v) {
                const VertexMap& m = (*prop)[mesh.incident_cell(hf)];
                auto it = m.find(v);
                if (it == m.end())
                    throw InputError("OpenVolumeMesh cell " + std::to_string(mesh.incident_cell(hf).idx()) +
                                     ": property '" + name + "' has no parameter for vertex " +
                                     std::to_string(v.idx()));
                return it->second;
            });
        }
    }

    /// The viewed mesh.
    const Mesh& mesh() const { return *mesh_; }
    /// Number of vertices.
    std::size_t n_vertices() const { return mesh_->n_vertices(); }
    /// Number of tets (cells).
    std::size_t n_tets() const { return corners_.size(); }
    /// Position of vertex @p v.
    Vec3d position(std::size_t v) const {
        const OvmVec& p = mesh_->vertex(OpenVolumeMesh::VertexHandle(static_cast<int>(v)));
        return Vec3d(p[0], p[1], p[2]);
    }
    /// Vertex index of corner @p i (0..3) of tet @p t.
    std::size_t corner(std::size_t t, int i) const { return corners_[t][static_cast<std::size_t>(i)]; }
    /// Parameter of corner @p i of tet @p t.
    Vec3d param(std::size_t t, int i) const { return params_[t][static_cast<std::size_t>(i)]; }

private:
    /// Reads corners and parameters of every cell; @p paramOf(hf, v) is the parameter of
    /// vertex v, the cell's vertex opposite halfface hf.
    template <class ParamOf>
    void readCells(std::size_t nc, ParamOf&& paramOf) {
        corners_.resize(nc);
        params_.resize(nc);
        double volume = 0;
        std::array<OpenVolumeMesh::VertexHandle, 4> cv;
        std::array<OpenVolumeMesh::HalfFaceHandle, 4> opposite;
        for (std::size_t c = 0; c < nc; ++c) {
            detail::ovmTetCorners(*mesh_, c, cv, opposite);
            for (std::size_t i = 0; i < 4; ++i) {
                corners_[c][i] = static_cast<std::size_t>(cv[i].idx());
                const OvmVec u = paramOf(opposite[i], cv[i]);
                params_[c][i] = Vec3d(u[0], u[1], u[2]);
            }
            const Vec3d a = position(corners_[c][0]);
            const Vec3d e1 = position(corners_[c][1]) - a, e2 = position(corners_[c][2]) - a,
                        e3 = position(corners_[c][3]) - a;
            volume += e1[0] * (e2[1] * e3[2] - e2[2] * e3[1]) - e1[1] * (e2[0] * e3[2] - e2[2] * e3[0]) +
                      e1[2] * (e2[0] * e3[1] - e2[1] * e3[0]);
        }
        if (volume < 0)
            for (std::size_t c = 0; c < nc; ++c) {
                std::swap(corners_[c][1], corners_[c][2]);
                std::swap(params_[c][1], params_[c][2]);
            }
    }

    const Mesh* mesh_;
    std::vector<std::array<std::size_t, 4>> corners_;
    std::vector<std::array<Vec3d, 4>> params_;
};

/// Output into an OpenVolumeMesh mesh with `Vec3d` geometry.
///
/// Into a mesh derived from HexahedralMeshTopologyKernel, hexahedra are stored with the
/// kernel's face layout (halffaces bottom, top, then the side pairs; the layout of the hex
/// files OpenVolumeMesh writes), and cells that are not hexahedra cannot be stored: they are
/// skipped and counted in skippedPolyhedra(). Into any other kernel (e.g.
/// GeometricPolyhedralMeshV3d) every cell is added from its faces, hexahedra with the same
/// face layout. Shared faces and edges are created once.
///
/// By default the output is written in bulk: edges and faces are found in this object's
/// own hash tables and added without OpenVolumeMesh's checks or searches. With
/// @p topologyCheck, each cell is instead added through OpenVolumeMesh's own calls
/// (`add_cell(vertices)` of the hexahedral kernel, `find_halfface()`/`add_face()` otherwise)
/// with its topology check on (slower); a rejected cell throws InputError. Both give the
/// same cells with the same oriented halfface loops. The mesh must outlive this object.
template <class Mesh>
class OvmHexOutput {
public:
    /// True if @p Mesh is a hexahedral kernel.
    static constexpr bool kHexKernel = std::is_base_of_v<OpenVolumeMesh::HexahedralMeshTopologyKernel, Mesh>;

    /// Writes into @p mesh (cleared by the first clear()).
    explicit OvmHexOutput(Mesh& mesh, bool topologyCheck = false) : mesh_(&mesh), check_(topologyCheck) {}
    /// Calls finish() and restoreIncidences().
    ~OvmHexOutput() {
        finish();
        restoreIncidences();
    }
    /// Copying would finish the mesh twice.
    OvmHexOutput(const OvmHexOutput&) = delete;
    /// Copying would finish the mesh twice.
    OvmHexOutput& operator=(const OvmHexOutput&) = delete;

    /// The mesh written into.
    Mesh& mesh() { return *mesh_; }
    /// One cell handle per output cell, hexahedra first, then polyhedra (the order of the
    /// extractor's HexMesh::hexes and HexMesh::polyhedra); invalid for a skipped polyhedron.
    const std::vector<OpenVolumeMesh::CellHandle>& cells() const { return cells_; }
    /// Number of non-hex cells that a hexahedral kernel could not store.
    std::size_t skippedPolyhedra() const { return skipped_; }

    /// Removes everything (entities and properties) from the mesh.
    void clear() {
        mesh_->clear();
        cells_.clear();
        skipped_ = 0;
        index_.clear();
        bigFaces_.clear();
    }
    /// Makes room for @p nVertices vertices and @p nHexes hexahedra (and their edges and
    /// faces) in the mesh and in the lookup tables.
    void reserve(std::size_t nVertices, std::size_t nHexes) {
        mesh_->reserve_vertices(nVertices);
        mesh_->reserve_edges(nVertices + 2 * nHexes);
        mesh_->reserve_faces(3 * nHexes + nHexes / 2);
        mesh_->reserve_cells(nHexes);
        cells_.reserve(nHexes);
        if (!check_) {
            index_.reserve(nVertices, nVertices + 2 * nHexes, 3 * nHexes + nHexes / 2);
            // The bulk writer never asks the mesh for incidences: OpenVolumeMesh builds
            // them once, in finish(), instead of cell by cell. Each kind the mesh had on
            // (vertex, edge, face) is turned off and back on; kinds it had off stay off.
            offV_ = offV_ || mesh_->has_vertex_bottom_up_incidences();
            offE_ = offE_ || mesh_->has_edge_bottom_up_incidences();
            offF_ = offF_ || mesh_->has_face_bottom_up_incidences();
            mesh_->enable_vertex_bottom_up_incidences(false);
            mesh_->enable_edge_bottom_up_incidences(false);
            mesh_->enable_face_bottom_up_incidences(false);
        }
    }
    /// Ends the writing: frees the lookup tables, then turns back on the kinds of
    /// OpenVolumeMesh's bottom-up incidences that reserve() turned off (each built in one
    /// pass; with edge and face incidences both on, OpenVolumeMesh also orders the
    /// halffaces around every edge), unless deferIncidences() asked to leave that to
    /// restoreIncidences(). Called by fromHexMesh() after the last cell and by the destructor.
    void finish() {
        index_.clear();
        bigFaces_.clear();
        if (!defer_) restoreIncidences();
    }
    /// Makes finish() leave the incidences off, so that the caller can free memory (its
    /// HexMesh, say) before OpenVolumeMesh builds them in restoreIncidences(); the
    /// destructor restores them at the latest.
    void deferIncidences() { defer_ = true; }
    /// Turns back on the kinds of bottom-up incidences that reserve() turned off (vertex,
    /// edge, then face); nothing if none was. The incidences are then those OpenVolumeMesh
    /// computes when they are enabled on the finished mesh.
    void restoreIncidences() {
        defer_ = false;
        if (offV_) mesh_->enable_vertex_bottom_up_incidences(true);
        if (offE_) mesh_->enable_edge_bottom_up_incidences(true);
        if (offF_) mesh_->enable_face_bottom_up_incidences(true);
        offV_ = offE_ = offF_ = false;
    }
    /// Adds a vertex and returns its index.
    std::size_t addVertex(const Vec3d& p) {
        return static_cast<std::size_t>(mesh_->add_vertex(OpenVolumeMesh::Geometry::Vec3d(p[0], p[1], p[2])).idx());
    }
    /// Adds a hexahedron (vertex indices in VTK order).
    void addHex(const std::array<std::size_t, 8>& v) {
        // The outward halffaces of a VTK hex: bottom, top, then the three pairs of opposite
        // sides. The hexahedral kernel's add_cell(vertices) builds this layout (up to each
        // loop's start vertex) from the vertex order kOrder; checked against sphere_hex.ovmb
        // in the tests.
        static constexpr int kFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {3, 0, 4, 7},
                                             {1, 2, 6, 5}, {2, 3, 7, 6}, {0, 1, 5, 4}};
        if (!check_) {
            hfs_.clear();
            for (const auto& f : kFaces) {
                const std::size_t loop[4] = {v[std::size_t(f[0])], v[std::size_t(f[1])], v[std::size_t(f[2])],
                                             v[std::size_t(f[3])]};
                hfs_.push_back(bulkHalfface(loop, 4));
            }
            finishCell(mesh_->add_cell(hfs_, false));
        } else if constexpr (kHexKernel) {
            static constexpr int kOrder[8] = {2, 3, 0, 1, 6, 5, 4, 7};
            std::vector<OpenVolumeMesh::VertexHandle> vs(8);
            for (std::size_t i = 0; i < 8; ++i) vs[i] = vh(v[static_cast<std::size_t>(kOrder[i])]);
            finishCell(mesh_->add_cell(vs, check_));
        } else {
            std::vector<std::vector<std::size_t>> faces(6, std::vector<std::size_t>(4));
            for (std::size_t f = 0; f < 6; ++f)
                for (std::size_t i = 0; i < 4; ++i) faces[f][i] = v[static_cast<std::size_t>(kFaces[f][i])];
            addPolyhedron(faces);
        }
    }
    /// Adds a non-hex cell given by its outward-oriented faces (skipped by a hexahedral kernel).
    void addPolyhedron(const std::vector<std::vector<std::size_t>>& faces) {
        if constexpr (kHexKernel) {
            ++skipped_;
            cells_.push_back(OpenVolumeMesh::CellHandle());
        } else if (!check_) {
            hfs_.clear();
            for (const auto& f : faces) hfs_.push_back(bulkHalfface(f.data(), f.size()));
            finishCell(mesh_->add_cell(hfs_, false));
        } else {
            std::vector<OpenVolumeMesh::HalfFaceHandle> hfs;
            std::vector<OpenVolumeMesh::VertexHandle> vs;
            for (const auto& f : faces) {
                // OpenVolumeMesh orients a cell's halffaces like the hexahedral kernel does:
                // the outward loop.
                vs.clear();
                for (std::size_t id : f) vs.push_back(vh(id));
                OpenVolumeMesh::HalfFaceHandle hf = mesh_->find_halfface(vs);
                if (!hf.is_valid()) hf = mesh_->halfface_handle(mesh_->add_face(vs), 0);
                hfs.push_back(hf);
            }
            finishCell(mesh_->add_cell(hfs, check_));
        }
    }

private:
    static OpenVolumeMesh::VertexHandle vh(std::size_t i) { return OpenVolumeMesh::VertexHandle(static_cast<int>(i)); }
    void finishCell(const OpenVolumeMesh::CellHandle& ch) {
        if (!ch.is_valid())
            throw InputError("OpenVolumeMesh rejected output cell " + std::to_string(cells_.size()) +
                             (check_ ? " (topology check failed)" : ""));
        cells_.push_back(ch);
    }
    /// The halfedge from vertex @p a to @p b, its edge created on first use.
    OpenVolumeMesh::HalfEdgeHandle bulkHalfedge(std::size_t a, std::size_t b) {
        const std::uint32_t lo = static_cast<std::uint32_t>(std::min(a, b)), hi = static_cast<std::uint32_t>(std::max(a, b));
        std::uint32_t e = index_.findEdge(lo, hi);
        if (e == detail::OvmBulkIndex::kNone) {
            e = static_cast<std::uint32_t>(mesh_->add_edge(vh(lo), vh(hi), /*allowDuplicates=*/true).idx());
            index_.addEdge(lo, hi, e);
        }
        return OpenVolumeMesh::HalfEdgeHandle(static_cast<int>(2 * e + (a == lo ? 0 : 1)));
    }
    /// The halfface with the vertex loop @p loop (@p n vertices, outward for the cell being
    /// added), its face created on first use. Faces are keyed by their sorted vertices; the
    /// successor of the smallest vertex tells the two orientations apart.
    OpenVolumeMesh::HalfFaceHandle bulkHalfface(const std::size_t* loop, std::size_t n) {
        std::size_t first = 0;
        for (std::size_t k = 1; k < n; ++k)
            if (loop[k] < loop[first]) first = k;
        const std::uint32_t succ = static_cast<std::uint32_t>(loop[(first + 1) % n]);
        const std::uint32_t next = static_cast<std::uint32_t>(mesh_->n_faces());
        std::uint32_t key[4] = {detail::OvmBulkIndex::kNone, detail::OvmBulkIndex::kNone, detail::OvmBulkIndex::kNone,
                                detail::OvmBulkIndex::kNone};
        const std::uint32_t* found = nullptr;
        std::uint32_t stored[2];
        if (n <= 4) {
            for (std::size_t k = 0; k < n; ++k) key[k] = static_cast<std::uint32_t>(loop[k]);
            std::sort(key, key + 4);
            found = index_.findFace(key);
        } else {
            std::vector<std::size_t> big(loop, loop + n);
            std::sort(big.begin(), big.end());
            const auto [it, inserted] = bigFaces_.emplace(std::move(big), (std::uint64_t(next) << 32) | succ);
            stored[0] = static_cast<std::uint32_t>(it->second >> 32);
            stored[1] = static_cast<std::uint32_t>(it->second & 0xFFFFFFFFu);
            if (!inserted) found = stored;
        }
        if (found) {
            const OpenVolumeMesh::FaceHandle fh(static_cast<int>(found[0]));
            return mesh_->halfface_handle(fh, found[1] == succ ? 0 : 1);
        }
        hes_.clear();
        for (std::size_t k = 0; k < n; ++k) hes_.push_back(bulkHalfedge(loop[k], loop[(k + 1) % n]));
        const OpenVolumeMesh::FaceHandle fh = mesh_->add_face(hes_, false);
        if (!fh.is_valid() || static_cast<std::uint32_t>(fh.idx()) != next)
            throw InputError("OpenVolumeMesh rejected a face of output cell " + std::to_string(cells_.size()));
        if (n <= 4) index_.addFace(key, next, succ);
        return mesh_->halfface_handle(fh, 0);
    }

    Mesh* mesh_;
    bool check_;
    bool offV_ = false, offE_ = false, offF_ = false;  // incidence kinds reserve() turned off
    bool defer_ = false;                               // finish() leaves them to restoreIncidences()
    std::vector<OpenVolumeMesh::CellHandle> cells_;
    std::size_t skipped_ = 0;
    detail::OvmBulkIndex index_;                                  // edges and faces made so far
    std::map<std::vector<std::size_t>, std::uint64_t> bigFaces_;  // faces of more than 4 vertices
    std::vector<OpenVolumeMesh::HalfFaceHandle> hfs_;             // scratch: halffaces of a cell
    std::vector<OpenVolumeMesh::HalfEdgeHandle> hes_;             // scratch: halfedges of a face
};

/// Writes @p values (one per output cell, in the order of OvmHexOutput::cells()) into the
/// persistent cell property @p name of @p out's mesh (created if missing, so that
/// OpenVolumeMesh's writers save it), skipping cells that were not stored. Throws
/// InputError if the counts differ.
template <class T, class Mesh>
void writeOvmCellProperty(OvmHexOutput<Mesh>& out, const std::string& name, const std::vector<T>& values) {
    if (values.size() != out.cells().size())
        throw InputError("writeOvmCellProperty: " + std::to_string(values.size()) + " values for " +
                         std::to_string(out.cells().size()) + " cells");
    auto prop = out.mesh().template request_cell_property<T>(name);
    out.mesh().set_persistent(prop, true);
    for (std::size_t i = 0; i < values.size(); ++i)
        if (out.cells()[i].is_valid()) prop[out.cells()[i]] = values[i];
}

/// Marks the cells of @p out's mesh that are not hexahedra (HexMesh::polyhedra) in the
/// persistent `bool` cell property @p name (default "HexEx::NonHex"); @p hexes is the
/// number of hexahedra of the extraction (ExtractionReport::output.hexes).
template <class Mesh>
void markOvmNonHexCells(OvmHexOutput<Mesh>& out, std::size_t hexes, const std::string& name = "HexEx::NonHex") {
    std::vector<bool> flags(out.cells().size(), false);
    for (std::size_t i = hexes; i < flags.size(); ++i) flags[i] = true;
    auto prop = out.mesh().template request_cell_property<bool>(name);
    out.mesh().set_persistent(prop, true);
    for (std::size_t i = 0; i < flags.size(); ++i)
        if (out.cells()[i].is_valid()) prop[out.cells()[i]] = flags[i];
}

/// Input traits of OvmTetMesh (see TetMeshTraits).
template <class Mesh>
struct TetMeshTraits<OvmTetMesh<Mesh>> {
    /// Number of vertices.
    static std::size_t n_vertices(const OvmTetMesh<Mesh>& m) { return m.n_vertices(); }
    /// Position of vertex @p v.
    static Vec3d position(const OvmTetMesh<Mesh>& m, std::size_t v) { return m.position(v); }
    /// Number of tets.
    static std::size_t n_tets(const OvmTetMesh<Mesh>& m) { return m.n_tets(); }
    /// The four corners of tet @p t.
    static std::array<std::size_t, 4> tet_vertices(const OvmTetMesh<Mesh>& m, std::size_t t) {
        return {m.corner(t, 0), m.corner(t, 1), m.corner(t, 2), m.corner(t, 3)};
    }
    /// Parameter of corner @p i of tet @p t.
    static Vec3d corner_param(const OvmTetMesh<Mesh>& m, std::size_t t, int i) { return m.param(t, i); }
};

/// Output traits of OvmHexOutput (see HexMeshOutputTraits).
template <class Mesh>
struct HexMeshOutputTraits<OvmHexOutput<Mesh>> {
    /// Clears the mesh.
    static void clear(OvmHexOutput<Mesh>& m) { m.clear(); }
    /// Makes room for @p nVertices vertices and @p nHexes hexahedra.
    static void reserve(OvmHexOutput<Mesh>& m, std::size_t nVertices, std::size_t nHexes) {
        m.reserve(nVertices, nHexes);
    }
    /// Ends the writing (see OvmHexOutput::finish()).
    static void finish(OvmHexOutput<Mesh>& m) { m.finish(); }
    /// Adds a vertex.
    static std::size_t add_vertex(OvmHexOutput<Mesh>& m, const Vec3d& p) { return m.addVertex(p); }
    /// Adds a hexahedron (VTK order).
    static void add_hex(OvmHexOutput<Mesh>& m, const std::array<std::size_t, 8>& v) { m.addHex(v); }
    /// Adds a polyhedron given by its outward-oriented faces.
    static void add_polyhedron(OvmHexOutput<Mesh>& m, const std::vector<std::vector<std::size_t>>& faces) {
        m.addPolyhedron(faces);
    }
};

} // namespace HexEx

#include "OpenVolumeMeshT_impl.hh"
