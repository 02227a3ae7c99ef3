#pragma once
/// @file TetMesh.hh
/// @ingroup kernel
/// The built-in tetrahedral mesh kernel: positions, tets as 4 vertex handles, halffaces
/// indexed 4*c+i (opposite corner i), unique edges and faces with incidences.

#include "../Core/Handles.hh"
#include "../Core/Prefetch.hh"
#include "../Core/Property.hh"
#include "../Core/Vec.hh"

#include <array>
#include <string>
#include <vector>

namespace HexEx {

/// Tetrahedral mesh with compact flat adjacency arrays.
///
/// Add vertices and cells, then call build_adjacency() (the accessors below that concern
/// edges, faces and opposites require it). Halfface `4*c+i` is the face of cell `c` opposite
/// its corner `i`; its vertices are listed so that the normal points out of the cell when
/// the cell is positively oriented.
class TetMesh {
public:
    /// Local corner indices of the halfface opposite corner i, outward orientation.
    static constexpr int kFaceCorners[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
    /// The six local edges of a tet as corner pairs.
    static constexpr int kEdgeCorners[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

    /// Adds a vertex at @p p.
    VertexHandle add_vertex(const Vec3d& p);
    /// Adds a tet with corners @p v (indices must be valid vertices). Invalidates adjacency.
    CellHandle add_cell(const std::array<VertexHandle, 4>& v);
    /// Replaces all vertices and cells at once (what a reader does after parsing: no copy and
    /// no per-element growth of the property arrays). Every corner index must be a valid
    /// vertex. Invalidates adjacency.
    void assign(std::vector<Vec3d>&& positions, std::vector<std::array<VertexHandle, 4>>&& cells);
    /// Reserve room for @p nv vertices and @p nc cells.
    void reserve(std::size_t nv, std::size_t nc);

    /// Number of vertices.
    std::size_t n_vertices() const { return positions_.size(); }
    /// Number of cells (tets).
    std::size_t n_cells() const { return cells_.size(); }
    /// Number of halffaces (4 per cell).
    std::size_t n_halffaces() const { return 4 * cells_.size(); }
    /// Number of unique edges (after build_adjacency()).
    std::size_t n_edges() const { return edges_.size(); }
    /// Number of unique faces (after build_adjacency()).
    std::size_t n_faces() const { return face_halffaces_.size(); }

    /// Position of vertex @p v.
    const Vec3d& position(VertexHandle v) const { return positions_[v.uidx()]; }
    /// Sets the position of vertex @p v.
    void set_position(VertexHandle v, const Vec3d& p) { positions_[v.uidx()] = p; }
    /// The four corners of cell @p c.
    const std::array<VertexHandle, 4>& cell_vertices(CellHandle c) const { return cells_[c.uidx()]; }
    /// Corner @p i of cell @p c.
    VertexHandle cell_vertex(CellHandle c, int i) const { return cells_[c.uidx()][i]; }
    /// Local index (0..3) of vertex @p v among the corners @p cv of a cell, which must contain
    /// it; without branches (which corner it is varies from cell to cell, so a search
    /// mispredicts).
    static int corner_of(const std::array<VertexHandle, 4>& cv, VertexHandle v) {
        return static_cast<int>(cv[1] == v) + 2 * static_cast<int>(cv[2] == v) + 3 * static_cast<int>(cv[3] == v);
    }
    /// Asks the CPU to load the corners of cell @p c and, once built, its four opposite
    /// halffaces early (for per-vertex passes, whose stars are scattered over the arrays).
    void prefetch_cell(CellHandle c) const {
        prefetchKept(&cells_[c.uidx()]);
        if (adjacency_built_) prefetchKept(&opposite_[4 * c.uidx()]);
    }
    /// Swaps corners @p i and @p j of cell @p c (changes its orientation). Invalidates adjacency.
    void swap_corners(CellHandle c, int i, int j);

    /// Halfface of cell @p c opposite its corner @p i.
    static HalfFaceHandle halfface(CellHandle c, int i) { return HalfFaceHandle(4 * c.idx() + i); }
    /// Cell of halfface @p hf.
    static CellHandle cell(HalfFaceHandle hf) { return CellHandle(hf.idx() / 4); }
    /// The corner of its cell that halfface @p hf is opposite to.
    static int opposite_corner(HalfFaceHandle hf) { return hf.idx() % 4; }
    /// The three vertices of halfface @p hf, outward orientation.
    std::array<VertexHandle, 3> halfface_vertices(HalfFaceHandle hf) const;

    /// Builds edges, faces, opposite halffaces and incidence lists.
    /// Throws InputError naming the elements if a face is shared by more than two tets.
    /// @p threads parallelizes the face matching of large meshes (0 = all hardware threads);
    /// the result does not depend on it.
    void build_adjacency(int threads = 0);
    /// True once build_adjacency() ran after the last change.
    bool has_adjacency() const { return adjacency_built_; }

    /// The halfface of the neighbouring cell across @p hf, invalid on the boundary.
    HalfFaceHandle opposite_halfface(HalfFaceHandle hf) const { return HalfFaceHandle(opposite_[hf.uidx()]); }
    /// True if @p hf has no neighbour.
    bool is_boundary(HalfFaceHandle hf) const { return opposite_[hf.uidx()] < 0; }
    /// The unique face of halfface @p hf.
    FaceHandle face(HalfFaceHandle hf) const { return FaceHandle(halfface_face_[hf.uidx()]); }
    /// The one or two halffaces of face @p f (second invalid on the boundary).
    std::array<HalfFaceHandle, 2> face_halffaces(FaceHandle f) const;
    /// True if face @p f lies on the boundary.
    bool is_boundary(FaceHandle f) const { return face_halffaces_[f.uidx()][1] < 0; }
    /// True if vertex @p v lies on the boundary.
    bool is_boundary(VertexHandle v) const { return boundary_vertex_[v.uidx()] != 0; }
    /// True if edge @p e lies on the boundary.
    bool is_boundary(EdgeHandle e) const { return boundary_edge_[e.uidx()] != 0; }
    /// Number of boundary faces.
    std::size_t n_boundary_faces() const { return n_boundary_faces_; }

    /// The two vertices of edge @p e (smaller index first).
    const std::array<VertexHandle, 2>& edge_vertices(EdgeHandle e) const { return edges_[e.uidx()]; }
    /// Edge @p k (0..5, see kEdgeCorners) of cell @p c.
    EdgeHandle cell_edge(CellHandle c, int k) const { return EdgeHandle(cell_edges_[6 * c.uidx() + k]); }
    /// The edge between vertices @p a and @p b, invalid if none.
    EdgeHandle find_edge(VertexHandle a, VertexHandle b) const;

    /// Cells incident to vertex @p v, ascending.
    std::pair<const int*, const int*> vertex_cells(VertexHandle v) const {
        return {vc_idx_.data() + vc_off_[v.uidx()], vc_idx_.data() + vc_off_[v.uidx() + 1]};
    }
    /// Cells around edge @p e in cyclic order (for boundary edges: from one boundary face to the other).
    std::pair<const int*, const int*> edge_cells(EdgeHandle e) const {
        return {ec_idx_.data() + ec_off_[e.uidx()], ec_idx_.data() + ec_off_[e.uidx() + 1]};
    }

    /// A description of the first manifoldness violation found, empty if the mesh is a
    /// 3-manifold with boundary (every face in at most two tets, every edge link a path or
    /// cycle, every vertex link a disk or sphere): the first non-manifold edge, else the
    /// first non-manifold vertex. Requires adjacency. The edges and vertex stars are checked
    /// by build_adjacency() (on its threads, while the stars are in the cache), so this only
    /// words the result; @p threads has no effect (kept for the callers that pass it).
    std::string check_manifold(int threads = 1) const;

    /// Vertex properties.
    PropertyManager<VertexTag>& vertex_props() { return vprops_; }
    /// Cell properties.
    PropertyManager<CellTag>& cell_props() { return cprops_; }
    /// Halfface properties.
    PropertyManager<HalfFaceTag>& halfface_props() { return hfprops_; }
    /// Halfface properties (read-only).
    const PropertyManager<HalfFaceTag>& halfface_props() const { return hfprops_; }
    /// Per-cell-corner properties.
    PropertyManager<CellCornerTag>& corner_props() { return ccprops_; }

private:
    std::vector<Vec3d> positions_;
    std::vector<std::array<VertexHandle, 4>> cells_;
    bool adjacency_built_ = false;
    std::vector<int> opposite_, halfface_face_, cell_edges_;
    std::vector<std::array<int, 2>> face_halffaces_;
    std::vector<std::array<VertexHandle, 2>> edges_;
    std::vector<int> vc_off_, vc_idx_, ec_off_, ec_idx_, ve_off_, ve_idx_;
    std::vector<char> boundary_vertex_, boundary_edge_;
    std::size_t n_boundary_faces_ = 0;
    long long first_bad_edge_ = -1;    // first edge whose tets do not form a single fan, or -1
    long long first_bad_vertex_ = -1;  // first vertex whose star is not connected through its faces, or -1
    PropertyManager<VertexTag> vprops_;
    PropertyManager<CellTag> cprops_;
    PropertyManager<HalfFaceTag> hfprops_;
    PropertyManager<CellCornerTag> ccprops_;
};

} // namespace HexEx
