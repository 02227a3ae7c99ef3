/// @file SurfaceProjection.cc
/// Feature detection and CGAL AABB-tree closest-point queries.

#include "SurfaceProjection.hh"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace HexEx {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangles = std::vector<Kernel::Triangle_3>;
using Segments = std::vector<Kernel::Segment_3>;
using TriangleTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>>>;
using SegmentTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_segment_primitive<Kernel, Segments::const_iterator>>>;

Point toPoint(const Vec3d& v) { return Point(v[0], v[1], v[2]); }
Vec3d toVec(const Point& p) { return Vec3d(p.x(), p.y(), p.z()); }
} // namespace

struct SurfaceProjection::Impl {
    Triangles triangles;
    std::vector<Vec3d> normals;  // per kept triangle
    Segments segments;
    std::vector<Vec3d> tangents;  // per feature segment
    std::vector<Vec3d> corners;
    TriangleTree triangle_tree;
    SegmentTree segment_tree;
};

SurfaceProjection::SurfaceProjection(const TriangleSurface& surface, double feature_angle_deg) : impl_(new Impl) {
    const double cos_limit = std::cos(feature_angle_deg * M_PI / 180.0);
    const auto& pts = surface.points;
    const int np = static_cast<int>(pts.size());
    // Kept triangles and their normals; edges -> incident kept triangles.
    std::map<std::pair<int, int>, std::vector<int>> edge_tris;
    std::vector<Vec3d> tri_normal;
    for (const auto& t : surface.triangles) {
        if (t[0] < 0 || t[1] < 0 || t[2] < 0 || t[0] >= np || t[1] >= np || t[2] >= np) continue;
        const Vec3d n = (pts[static_cast<std::size_t>(t[1])] - pts[static_cast<std::size_t>(t[0])]) %
                        (pts[static_cast<std::size_t>(t[2])] - pts[static_cast<std::size_t>(t[0])]);
        const double len = n.norm();
        if (!(len > 0) || !std::isfinite(len)) continue;
        const int id = static_cast<int>(impl_->triangles.size());
        impl_->triangles.emplace_back(toPoint(pts[static_cast<std::size_t>(t[0])]), toPoint(pts[static_cast<std::size_t>(t[1])]),
                                      toPoint(pts[static_cast<std::size_t>(t[2])]));
        impl_->normals.push_back(n / len);
        for (int i = 0; i < 3; ++i) {
            const int a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>((i + 1) % 3)];
            edge_tris[{std::min(a, b), std::max(a, b)}].push_back(id);
        }
    }
    // Feature edges.
    std::map<int, std::vector<int>> vertex_features;  // vertex -> incident feature segments
    for (const auto& [e, tris] : edge_tris) {
        const bool sharp = tris.size() != 2 ||
                           (impl_->normals[static_cast<std::size_t>(tris[0])] | impl_->normals[static_cast<std::size_t>(tris[1])]) < cos_limit;
        if (!sharp) continue;
        const Vec3d a = pts[static_cast<std::size_t>(e.first)], b = pts[static_cast<std::size_t>(e.second)];
        const int id = static_cast<int>(impl_->segments.size());
        impl_->segments.emplace_back(toPoint(a), toPoint(b));
        impl_->tangents.push_back((b - a).normalized());
        vertex_features[e.first].push_back(id);
        vertex_features[e.second].push_back(id);
    }
    for (const auto& [v, segs] : vertex_features) {
        bool corner = segs.size() != 2;
        if (!corner) {
            const double c = std::abs(impl_->tangents[static_cast<std::size_t>(segs[0])] | impl_->tangents[static_cast<std::size_t>(segs[1])]);
            corner = c < cos_limit;
        }
        if (corner) impl_->corners.push_back(pts[static_cast<std::size_t>(v)]);
    }
    if (!impl_->triangles.empty()) {
        impl_->triangle_tree.insert(impl_->triangles.cbegin(), impl_->triangles.cend());
        impl_->triangle_tree.build();
        impl_->triangle_tree.accelerate_distance_queries();
    }
    if (!impl_->segments.empty()) {
        impl_->segment_tree.insert(impl_->segments.cbegin(), impl_->segments.cend());
        impl_->segment_tree.build();
        impl_->segment_tree.accelerate_distance_queries();
    }
}

SurfaceProjection::~SurfaceProjection() = default;

bool SurfaceProjection::hasSurface() const { return !impl_->triangles.empty(); }
bool SurfaceProjection::hasFeatures() const { return !impl_->segments.empty(); }
std::size_t SurfaceProjection::featureEdges() const { return impl_->segments.size(); }
std::size_t SurfaceProjection::featureCorners() const { return impl_->corners.size(); }

Vec3d SurfaceProjection::closestOnSurface(const Vec3d& p, Vec3d* normal) const {
    const auto r = impl_->triangle_tree.closest_point_and_primitive(toPoint(p));
    if (normal) *normal = impl_->normals[static_cast<std::size_t>(r.second - impl_->triangles.cbegin())];
    return toVec(r.first);
}

Vec3d SurfaceProjection::closestOnFeature(const Vec3d& p, Vec3d* tangent) const {
    const auto r = impl_->segment_tree.closest_point_and_primitive(toPoint(p));
    if (tangent) *tangent = impl_->tangents[static_cast<std::size_t>(r.second - impl_->segments.cbegin())];
    return toVec(r.first);
}

double SurfaceProjection::distanceToCorner(const Vec3d& p) const {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& c : impl_->corners) best = std::min(best, (c - p).norm());
    return best;
}

} // namespace HexEx
