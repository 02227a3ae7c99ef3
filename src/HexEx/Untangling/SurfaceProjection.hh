#pragma once
/// @file SurfaceProjection.hh
/// @ingroup quality
/// Closest-point queries on a TriangleSurface and on its sharp feature curves (CGAL AABB
/// trees), used to keep the boundary vertices of an untangled hex mesh on the input surface.
///
/// Feature edges are surface edges whose two triangles meet at an angle between their
/// normals above the feature angle, and edges with other than two triangles (open borders,
/// non-manifold edges). Feature corners are vertices with one or more than two feature
/// edges, and vertices where two feature edges turn by more than the feature angle.

#include "TriangleSurface.hh"

#include <memory>

namespace HexEx {

/// Closest points on a triangle surface and on its feature curves.
class SurfaceProjection {
public:
    /// Builds the search trees of @p surface (degenerate triangles are left out) with
    /// sharp features above @p feature_angle_deg degrees.
    SurfaceProjection(const TriangleSurface& surface, double feature_angle_deg);
    ~SurfaceProjection();
    SurfaceProjection(const SurfaceProjection&) = delete;             ///< not copyable
    SurfaceProjection& operator=(const SurfaceProjection&) = delete;  ///< not copyable

    /// True if the surface has at least one non-degenerate triangle.
    bool hasSurface() const;
    /// True if there is at least one feature edge.
    bool hasFeatures() const;
    /// Number of feature edges.
    std::size_t featureEdges() const;
    /// Number of feature corners.
    std::size_t featureCorners() const;

    /// Closest point to @p p on the surface; the unit normal of its triangle goes to @p normal.
    /// Requires hasSurface().
    Vec3d closestOnSurface(const Vec3d& p, Vec3d* normal = nullptr) const;
    /// Closest point to @p p on the feature curves; their unit direction there goes to
    /// @p tangent. Requires hasFeatures().
    Vec3d closestOnFeature(const Vec3d& p, Vec3d* tangent = nullptr) const;
    /// Distance from @p p to the nearest feature corner (infinity if there is none).
    double distanceToCorner(const Vec3d& p) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace HexEx
