#pragma once
/// @file OvmFaces.hh
/// @ingroup io
/// Faces and edges of an OpenVolumeMesh model from cells given as vertex loops, found by
/// bucketing on the smallest vertex (no node-based maps): a face shared by two cells is
/// stored once, with the orientation of its first occurrence; faces and edges are numbered
/// in order of first use, as OpenVolumeMesh numbers them when cells are added.

#include "../Core/DefaultInitAllocator.hh"

#include <array>
#include <cstddef>
#include <vector>

namespace HexEx {

/// Integer lists stored back to back: list i is values[offsets[i]] .. values[offsets[i + 1] - 1],
/// or, if stride > 0 (lists of one length, such as the quads of an all-hex mesh), values[stride
/// i] .. values[stride (i + 1) - 1] with offsets unused (no offset array to fill and to read).
struct IntLists {
    DefaultInitVector<std::size_t> offsets{0};  ///< start of every list, then the end of the last (stride 0)
    DefaultInitVector<int> values;              ///< the lists' entries
    std::size_t stride = 0;                     ///< length of every list, or 0: lengths from offsets

    /// Number of lists.
    std::size_t size() const { return stride ? values.size() / stride : offsets.size() - 1; }
    /// First entry of list @p i.
    const int* begin(std::size_t i) const { return values.data() + (stride ? stride * i : offsets[i]); }
    /// One past the last entry of list @p i.
    const int* end(std::size_t i) const { return values.data() + (stride ? stride * (i + 1) : offsets[i + 1]); }
    /// Length of list @p i.
    std::size_t length(std::size_t i) const { return stride ? stride : offsets[i + 1] - offsets[i]; }
    /// Makes these @p lists lists of @p length entries each (stride form; entries not initialized).
    void resizeUniform(std::size_t lists, std::size_t length) {
        offsets = DefaultInitVector<std::size_t>{0};
        stride = length;
        values.resize(lists * length);
    }
    /// Appends the list [@p first, @p last) (offset form: stride must be 0).
    template <class It>
    void add(It first, It last) {
        for (; first != last; ++first) values.push_back(*first);
        offsets.push_back(values.size());
    }
    /// Reserves room for @p lists lists of @p entries entries in total.
    void reserve(std::size_t lists, std::size_t entries) {
        offsets.reserve(lists + 1);
        values.reserve(entries);
    }
};

/// The faces and edges found by buildOvmFaces().
struct OvmFaces {
    DefaultInitVector<int> halffaces;       ///< per input loop its halfface (2f + orientation)
    std::vector<std::array<int, 2>> edges;  ///< edge end points, in order of first use
    IntLists faceHalfedges;                 ///< per face its halfedges (2e + orientation)
};

/// Numbers the faces and edges of the halfface vertex @p loops (each >= 1 vertex in
/// [0, @p nVertices)). Two loops over the same vertices (as multisets) are the same face;
/// its halfface is 2f if the later loop follows its first loop's direction at the later
/// loop's first vertex, 2f + 1 otherwise. Halfedge 2e runs from edges[e][0] to edges[e][1].
/// Uses @p threads threads (>= 1); the result does not depend on it.
/// @throws std::invalid_argument for a vertex out of range or more than INT_MAX loops or entries.
OvmFaces buildOvmFaces(const IntLists& loops, int nVertices, int threads = 1);

} // namespace HexEx
