#pragma once
/// @file ArcTracing.hh
/// @ingroup pipeline
/// The exact image of one hex edge or hex face in the tet mesh: the preimage of a unit
/// grid segment (an edge "arc", a polyline) or of a unit grid square (a face "patch", a
/// triangle soup), found by walking from tet to tet through the halfface transitions.
/// Ties (the segment running along a tet face or edge, the square lying in a tet face) are
/// broken by the same symbolic perturbation as the dart ownership and the tracing.

#include "../Preprocessing/Transitions.hh"
#include "TetSoS.hh"

#include <array>
#include <set>
#include <vector>

namespace HexEx {

class TetMesh;

/// Where a walk starts: a grid point of tet @ref tet's chart and an axis frame, like a dart.
/// The edge runs from z along d[0]; the face spans d[0], d[1]; d[2] points into the hex the
/// walk belongs to (it decides ties, see traceEdgeArc() and traceFacePatch()).
struct ArcStart {
    int tet = -1;                ///< tet whose (closed) image contains z + e d[0] + e^2 d[1] + e^3 d[2]
    Vec3i z{0, 0, 0};            ///< grid point in the tet's chart
    std::array<AxisDir, 3> d{};  ///< frame directions
};

/// Polyline of the preimage of the grid segment [z, z + d[0]]: the position of z in the start
/// tet, one point per tet face crossed, and the position of z + d[0] in the tet where the
/// walk ends (the first tet with the start tet's orientation whose image contains
/// z + d[0] - e d[0] + e^2 d[1] + e^3 d[2]). In flipped tets the walk runs backwards (the
/// preimage folds back), as in the tracing. Appends to @p points; returns false (and
/// leaves @p points as it was) if the walk fails (boundary, no exit face, step limit).
bool traceEdgeArc(const TetMesh& mesh, const Transitions& tr, const std::vector<TetSoS>& tets, const ArcStart& start,
                  std::vector<Vec3d>& points);

/// Triangulated preimage of the unit grid square {z + a d[0] + b d[1] : a, b in [0, 1]},
/// perturbed by an infinitesimal step along d[2]: the square clipped by the image of every
/// tet it meets (found by a flood from the start tet across the tet faces the clipped
/// square crosses, through the transitions), triangulated and mapped back by barycentric
/// coordinates. Triangles are ordered counter-clockwise around d[0] x d[1] in parameter
/// space (in 3D they keep that orientation in proper tets and reverse it in flipped ones).
/// Appends points and triangles (indices into @p points); @p signed_area receives the sum
/// of the pieces' parametric areas, each with its tet's orientation sign (1 for a complete
/// patch of a valid map). Returns false if the flood hit its size limit.
///
/// The flood starts from every entry of @p starts (starts at different corners of the same
/// square, with d[0] x d[1] the same normal, share the visited tets): under a folded map the
/// preimage of the square may fall into pieces that are only joined outside the square, and
/// a start on a fold's closed "bubble" alone reaches a piece of zero signed area.
bool traceFacePatch(const TetMesh& mesh, const Transitions& tr, const std::vector<TetSoS>& tets,
                    const std::vector<ArcStart>& starts, std::vector<Vec3d>& points,
                    std::vector<std::array<int, 3>>& triangles, double& signed_area);

/// Working memory of traceFacePatch(), kept by the caller across calls so that tracing many
/// patches allocates nothing per patch. Its contents between calls are meaningless.
struct PatchScratch {
    /// A visited (tet, square): the tet, the square's smallest corner, its two axes and the
    /// perturbation direction.
    using Key = std::array<int, 7>;
    /// A flood item: a tet and the square in its chart.
    struct Item {
        int tet;                  ///< the tet
        int entry;                ///< local face it was entered through (-1 at a start)
        Vec3i z;                  ///< the square's corner in the tet's chart
        std::array<AxisDir, 3> d;  ///< the square's frame in the tet's chart
    };
    std::vector<Key> few;   ///< visited squares while there are few (searched linearly)
    std::set<Key> many;     ///< visited squares beyond that
    std::vector<Item> queue;  ///< the flood's queue
};

/// traceFacePatch() with caller-provided working memory (same result).
bool traceFacePatch(const TetMesh& mesh, const Transitions& tr, const std::vector<TetSoS>& tets,
                    const std::vector<ArcStart>& starts, std::vector<Vec3d>& points,
                    std::vector<std::array<int, 3>>& triangles, double& signed_area, PatchScratch& scratch);

} // namespace HexEx
