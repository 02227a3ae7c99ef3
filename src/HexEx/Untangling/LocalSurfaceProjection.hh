#pragma once
/// @file LocalSurfaceProjection.hh
/// @ingroup quality
/// Local closest-point queries on a TriangleSurface, split into patches by its sharp feature
/// curves: a point is projected onto the patch it belongs to, and a feature vertex onto its
/// own curve, by walking from the triangle (segment) it was last projected to. A point
/// therefore never jumps to the other side of a thin wall or onto another feature curve, as
/// a global closest-point query can.
///
/// Features are found as in SurfaceProjection: feature edges are edges whose two triangles'
/// normals differ by more than the feature angle, and edges with other than two triangles;
/// corners are vertices with one or more than two feature edges, or where two feature
/// edges turn by more than the feature angle. Patches are the triangles connected across
/// non-feature edges; curves are the chains of feature edges between corners (or closed
/// loops without a corner).

#include "TriangleSurface.hh"

#include <memory>
#include <vector>

namespace HexEx {

/// Patches, feature curves and corners of a triangle surface, with local projections.
class LocalSurfaceProjection {
public:
    /// Analyses @p surface (degenerate and out-of-range triangles are left out) with sharp
    /// features above @p feature_angle_deg degrees.
    LocalSurfaceProjection(const TriangleSurface& surface, double feature_angle_deg);
    ~LocalSurfaceProjection();
    LocalSurfaceProjection(const LocalSurfaceProjection&) = delete;             ///< not copyable
    LocalSurfaceProjection& operator=(const LocalSurfaceProjection&) = delete;  ///< not copyable

    /// Number of kept (non-degenerate) triangles.
    std::size_t triangles() const;
    /// Number of feature edges (segments).
    std::size_t featureSegments() const;
    /// Number of feature curves.
    std::size_t featureCurves() const;
    /// Number of feature corners.
    std::size_t corners() const;
    /// Number of patches.
    std::size_t patches() const;

    /// Position of corner @p c.
    Vec3d corner(int c) const;
    /// Nearest corner to @p p (-1 if there is none); its distance goes to @p distance.
    int nearestCorner(const Vec3d& p, double* distance) const;
    /// Triangle with the closest point to @p p over the whole surface (-1 if there is none).
    int nearestTriangle(const Vec3d& p) const;
    /// Feature segment with the closest point to @p p over all curves (-1 if there is none).
    int nearestSegment(const Vec3d& p) const;
    /// Curve of feature segment @p segment.
    int segmentCurve(int segment) const;
    /// Distance from @p p to the whole surface (infinity if it is empty).
    double distanceToSurface(const Vec3d& p) const;

    /// Closest point to @p p on the patch of triangle @p triangle, found by walking from it
    /// to neighbouring triangles of the same patch while the distance drops; @p triangle is
    /// updated to the triangle of the result and its unit normal goes to @p normal.
    Vec3d projectOnPatch(const Vec3d& p, int& triangle, Vec3d* normal = nullptr) const;
    /// Closest point to @p p on the curve of @p segment, found by walking along the curve
    /// from it; @p segment is updated and the curve's unit direction goes to @p tangent.
    Vec3d projectOnCurve(const Vec3d& p, int& segment, Vec3d* tangent = nullptr) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// Closest point to @p p on the triangle (@p a, @p b, @p c).
Vec3d closestPointOnTriangle(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c);

/// Closest point to @p p on the segment (@p a, @p b).
Vec3d closestPointOnSegment(const Vec3d& p, const Vec3d& a, const Vec3d& b);

} // namespace HexEx
