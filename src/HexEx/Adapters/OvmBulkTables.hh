#pragma once
/// @file OvmBulkTables.hh
/// @ingroup adapters
/// Lookup tables of the bulk OpenVolumeMesh writer (OvmHexOutput): the edges and the faces
/// of at most four vertices already created, found through lists per vertex (edges from
/// their smaller vertex, faces from their smallest), so that every edge and face of the
/// output is created once without asking the mesh. About 12 bytes per edge, 24 per face and
/// 8 per vertex. Internal to the OpenVolumeMesh adapter; needs no OpenVolumeMesh header.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace HexEx {
namespace detail {

/// Edges (vertex pairs) and faces (up to four vertices, with an orientation tag) of the
/// mesh being written, each mapped to the index the mesh gave it.
class OvmBulkIndex {
public:
    /// "Not found".
    static constexpr std::uint32_t kNone = ~std::uint32_t(0);

    /// Makes room for @p nVertices vertices, @p nEdges edges and @p nFaces faces.
    void reserve(std::size_t nVertices, std::size_t nEdges, std::size_t nFaces) {
        grow(nVertices);
        edges_.reserve(nEdges);
        faces_.reserve(nFaces);
    }
    /// Removes everything and frees the memory.
    void clear() {
        std::vector<std::uint32_t>().swap(edgeHead_);
        std::vector<std::uint32_t>().swap(faceHead_);
        std::vector<Edge>().swap(edges_);
        std::vector<Face>().swap(faces_);
    }
    /// The index of edge (@p lo, @p hi), lo < hi, or kNone.
    std::uint32_t findEdge(std::uint32_t lo, std::uint32_t hi) const {
        if (lo >= edgeHead_.size()) return kNone;
        for (std::uint32_t e = edgeHead_[lo]; e != kNone; e = edges_[e].next)
            if (edges_[e].hi == hi) return edges_[e].index;
        return kNone;
    }
    /// Records edge (@p lo, @p hi) with the mesh's @p index.
    void addEdge(std::uint32_t lo, std::uint32_t hi, std::uint32_t index) {
        grow(std::size_t(lo) + 1);
        edges_.push_back(Edge{hi, edgeHead_[lo], index});
        edgeHead_[lo] = static_cast<std::uint32_t>(edges_.size() - 1);
    }
    /// The face with the ascending vertices @p v (v[0] smallest; unused entries kNone), or
    /// nullptr: its index and orientation tag as stored by addFace().
    const std::uint32_t* findFace(const std::uint32_t v[4]) const {
        if (v[0] >= faceHead_.size()) return nullptr;
        for (std::uint32_t f = faceHead_[v[0]]; f != kNone; f = faces_[f].next) {
            const Face& r = faces_[f];
            if (r.rest[0] == v[1] && r.rest[1] == v[2] && r.rest[2] == v[3]) return r.index;
        }
        return nullptr;
    }
    /// Records the face with the ascending vertices @p v, its mesh @p index and @p tag.
    void addFace(const std::uint32_t v[4], std::uint32_t index, std::uint32_t tag) {
        grow(std::size_t(v[0]) + 1);
        faces_.push_back(Face{{v[1], v[2], v[3]}, faceHead_[v[0]], {index, tag}});
        faceHead_[v[0]] = static_cast<std::uint32_t>(faces_.size() - 1);
    }

private:
    /// An edge in the list of its smaller vertex.
    struct Edge {
        std::uint32_t hi;     ///< larger vertex
        std::uint32_t next;   ///< next edge of the same smaller vertex, or kNone
        std::uint32_t index;  ///< the mesh's edge index
    };
    /// A face in the list of its smallest vertex.
    struct Face {
        std::uint32_t rest[3];  ///< the other vertices, ascending (kNone-padded)
        std::uint32_t next;     ///< next face of the same smallest vertex, or kNone
        std::uint32_t index[2];  ///< the mesh's face index, then the orientation tag
    };
    /// Makes the per-vertex heads cover @p n vertices.
    void grow(std::size_t n) {
        if (n > edgeHead_.size()) {
            edgeHead_.resize(std::max(n, 2 * edgeHead_.size()), kNone);
            faceHead_.resize(edgeHead_.size(), kNone);
        }
    }

    std::vector<std::uint32_t> edgeHead_, faceHead_;  // per vertex: first edge / face, or kNone
    std::vector<Edge> edges_;
    std::vector<Face> faces_;
};

} // namespace detail
} // namespace HexEx
