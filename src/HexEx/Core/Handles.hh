#pragma once
/// @file Handles.hh
/// @ingroup kernel
/// Strongly typed entity handles in the style of OpenVolumeMesh.

#include <cstddef>
#include <functional>
#include <ostream>

namespace HexEx {

/// A typed index into one entity kind. Invalid handles have index -1.
/// The tag type keeps vertex, edge, face, halfface and cell handles apart at compile time.
template <class Tag>
class Handle {
public:
    /// Invalid handle.
    constexpr Handle() = default;
    /// Handle of the entity with index @p idx.
    constexpr explicit Handle(int idx) : idx_(idx) {}
    /// The index, -1 if invalid.
    constexpr int idx() const { return idx_; }
    /// The index as an unsigned size, for container access.
    constexpr std::size_t uidx() const { return static_cast<std::size_t>(idx_); }
    /// True if the handle refers to an entity.
    constexpr bool is_valid() const { return idx_ >= 0; }
    /// Equality of indices.
    constexpr bool operator==(const Handle& o) const { return idx_ == o.idx_; }
    /// Inequality of indices.
    constexpr bool operator!=(const Handle& o) const { return idx_ != o.idx_; }
    /// Order by index (for sorted containers).
    constexpr bool operator<(const Handle& o) const { return idx_ < o.idx_; }

private:
    int idx_ = -1;
};

/// Tag types, one per entity kind.
struct VertexTag {};
/// Tag of edges.
struct EdgeTag {};
/// Tag of faces (unordered triangles).
struct FaceTag {};
/// Tag of halffaces (a face seen from one of its two cells).
struct HalfFaceTag {};
/// Tag of cells (tets, hexes, polyhedra).
struct CellTag {};

/// Handle of a vertex.
using VertexHandle = Handle<VertexTag>;
/// Handle of an edge.
using EdgeHandle = Handle<EdgeTag>;
/// Handle of a face.
using FaceHandle = Handle<FaceTag>;
/// Handle of a halfface: in a TetMesh, halfface 4*c+i is the face of cell c opposite its corner i.
using HalfFaceHandle = Handle<HalfFaceTag>;
/// Handle of a cell.
using CellHandle = Handle<CellTag>;

/// Prints "<index>".
template <class Tag>
std::ostream& operator<<(std::ostream& os, const Handle<Tag>& h) { return os << h.idx(); }

} // namespace HexEx

/// Hash support so handles can key unordered containers.
template <class Tag>
struct std::hash<HexEx::Handle<Tag>> {
    /// Hash of the index.
    std::size_t operator()(const HexEx::Handle<Tag>& h) const noexcept { return std::hash<int>()(h.idx()); }
};
