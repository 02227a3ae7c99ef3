#pragma once
/// @file TrianglePreprocessing.hh
/// @ingroup quad
/// Preprocessing of the 2D pipeline (the analogue of Preprocessing/ for tets): transitions
/// per halfedge (paper 4.1.1 in 2D), sanitization (4.1.2 in 2D), the orientation of every
/// triangle's parameter image and the holonomy (cones) of the map.

#include "../Core/DefaultInitAllocator.hh"
#include "ParametrizedTriMesh.hh"
#include "PlanarTransform.hh"

#include <vector>

namespace HexEx {

/// Corner parameters of every triangle, (u, v) per corner, sized without zeroing (the
/// extraction fills them in parallel, so the pages are first touched by the threads that
/// write them).
using TriParams = std::vector<std::array<Vec2d, 3>, DefaultInitAllocator<std::array<Vec2d, 3>>>;

/// The transition of every halfedge into the neighbouring triangle's chart, compact: one
/// byte per halfedge, and the full transition only for the halfedges whose transition is
/// not the identity (seams; usually few).
struct TriTransitions {
    /// Per halfedge: the rotation's quarter turns in bits 0-1, bit 2 (kNotIdentity) set if
    /// the transition is not the identity (boundary halfedges: 0).
    std::vector<unsigned char, DefaultInitAllocator<unsigned char>> kind;
    std::vector<int> seam;                    ///< halfedges whose transition is not the identity, ascending
    std::vector<PlanarTransform> seam_transform;  ///< their transitions (same order)
    /// Bit of `kind` marking a transition that is not the identity.
    static constexpr unsigned char kNotIdentity = 4;
    long ambiguous = 0;   ///< interior edges of (nearly) zero parametric length, whose rotation the edge does not determine
    long unresolved = 0;  ///< of those, not resolvable by vertex consistency (best fit kept)

    /// True if halfedge @p h has the identity transition.
    bool is_identity(std::size_t h) const { return !(kind[h] & kNotIdentity); }
    /// The transition of halfedge @p h (a binary search in `seam` unless it is the identity).
    PlanarTransform at(std::size_t h) const;
};

/// Computes the transition of every interior halfedge: the planar rotation (one of 4)
/// that maps the edge vector in one chart best onto the edge vector in the other, and the
/// rounded mean translation; the opposite halfedge gets the exact inverse. If
/// @p given_quarter_turns is not null it holds the rotation (0..3 counter-clockwise quarter
/// turns) per halfedge and only translations are computed; InputError if a value is out
/// of range or the two halfedges of an edge are not inverse. Ambiguous edges (zero
/// parametric length) get the composition of the other transitions around a regular
/// endpoint (vertex consistency, repeated until nothing changes).
TriTransitions computeTriTransitions(const ParametrizedTriMesh& m, const TriAdjacency& adj, const TriParams& params,
                                     const std::vector<int>* given_quarter_turns, int threads);

/// Sanitizes @p params in place (paper 4.1.2 in 2D): per vertex, its parameter in its
/// lowest-index triangle is quantized (quantizeParameter(), snapping coordinates within
/// @p epsilon of an integer) and propagated through the transitions into every triangle
/// around the vertex. Returns the number of snapped coordinates.
long sanitizeTriParams(const ParametrizedTriMesh& m, const TriAdjacency& adj, TriParams& params,
                       const TriTransitions& tr, double epsilon, int threads);

/// Orientation of every triangle's parameter image (exact): +1 proper, -1 flipped, 0
/// degenerate. Triangles are independent: @p threads only changes the speed.
std::vector<signed char> classifyTriangles(const TriParams& params, int threads = 1);

/// Holonomy of every vertex: the rotation (0..3 counter-clockwise quarter turns) of the
/// composed transitions once around its fan; non-zero marks a cone (valence 4 + k mod 4).
/// -1 for boundary and isolated vertices and, if @p unknown is given, for vertices with an
/// edge whose halfedge is flagged there. Exact, unlike angle sums, which folds change.
/// Vertices are independent: @p threads only changes the speed.
std::vector<int> vertexHolonomy(const ParametrizedTriMesh& m, const TriAdjacency& adj, const TriTransitions& tr,
                                const std::vector<char>* unknown = nullptr, int threads = 1);

} // namespace HexEx
