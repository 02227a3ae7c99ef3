#pragma once
/// @file ExactPredicates.hh
/// @ingroup pipeline
/// Exact orientation predicates on doubles (CGAL's filtered kernel) and the classification
/// of an integer grid point against a tet's parameter image.

#include "../Core/Vec.hh"

namespace HexEx {

/// Sign (-1, 0, +1) of det(b-a, c-a, d-a): positive if d lies on the positive side of the
/// plane through a, b, c (a, b, c counter-clockwise seen from d's side is negative). Exact.
int orient3d(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& d);

/// Sign of the 2D orientation of the projections of a, b, c onto the plane of axes
/// ((axis+1)%3, (axis+2)%3), i.e. of (b-a)x(c-a) . e_axis. Exact.
int orient2dAxis(const Vec3d& a, const Vec3d& b, const Vec3d& c, int axis);

/// Where an integer grid point lies relative to a tet's parameter image.
enum class PointLocation {
    Outside,   ///< not in the closed tet
    Inside,    ///< in the open interior
    OnFace,    ///< in the relative interior of a face
    OnEdge,    ///< in the relative interior of an edge
    AtVertex,  ///< at a corner
};

/// Result of classifying a point: the location and the corners of the element it lies in
/// (bit i set if corner i spans it; 0xF for Inside, three bits for a face, two for an edge).
struct PointClassification {
    PointLocation location = PointLocation::Outside;  ///< kind of element
    unsigned corners = 0;                             ///< corners spanning that element
};

/// Classifies point @p x against the tet with corners @p p. Works for flat tets too
/// (zero volume): then only lower-dimensional containment is possible and is decided by
/// projections; a point strictly inside a flat tet's plane region is reported as OnFace of
/// the containing face(s) with the lowest index.
PointClassification classifyPoint(const Vec3d p[4], const Vec3d& x);

} // namespace HexEx

namespace HexEx {
/// True if @p x lies in the closed triangle (a, b, c); handles degenerate triangles. Exact.
bool triangleContainsPoint(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& x);
/// True if the closed segment [p, q] meets the closed triangle (a, b, c). Exact.
bool triangleIntersectsSegment(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& p, const Vec3d& q);
} // namespace HexEx
