/// @file LocalSurfaceProjection.cc
/// Patches, feature curves and corners of a triangle surface; walking projections.

#include "LocalSurfaceProjection.hh"

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

/// Walk steps at most per projection (each moves to a strictly closer element).
constexpr int kMaxWalk = 100000;
} // namespace

Vec3d closestPointOnSegment(const Vec3d& p, const Vec3d& a, const Vec3d& b) {
    const Vec3d ab = b - a;
    const double l2 = ab.sqrnorm();
    if (!(l2 > 0)) return a;
    const double t = std::clamp(((p - a) | ab) / l2, 0.0, 1.0);
    return a + ab * t;
}

Vec3d closestPointOnTriangle(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
    // Ericson, "Real-Time Collision Detection", 5.1.5: Voronoi regions of the triangle.
    const Vec3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab | ap, d2 = ac | ap;
    if (d1 <= 0 && d2 <= 0) return a;
    const Vec3d bp = p - b;
    const double d3 = ab | bp, d4 = ac | bp;
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
    const Vec3d cp = p - c;
    const double d5 = ab | cp, d6 = ac | cp;
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denom = va + vb + vc;
    if (!(std::abs(denom) > 0)) return a;
    return a + ab * (vb / denom) + ac * (vc / denom);
}

struct LocalSurfaceProjection::Impl {
    std::vector<Vec3d> points;
    std::vector<std::array<int, 3>> tris;      // kept triangles
    std::vector<Vec3d> normals;                // per kept triangle
    std::vector<int> patch;                    // per kept triangle
    std::vector<std::vector<int>> vertex_tris; // point -> kept triangles
    std::vector<std::array<int, 2>> segs;      // feature segments (point indices)
    std::vector<int> seg_curve;                // per segment
    std::vector<std::vector<int>> vertex_segs; // point -> feature segments
    std::vector<char> is_corner;               // per point
    std::vector<Vec3d> corners;
    std::size_t n_patches = 0, n_curves = 0;
    Triangles cgal_tris;
    Segments cgal_segs;
    TriangleTree tri_tree;
    SegmentTree seg_tree;
};

LocalSurfaceProjection::LocalSurfaceProjection(const TriangleSurface& surface, double feature_angle_deg) : impl_(new Impl) {
    Impl& m = *impl_;
    const double cos_limit = std::cos(feature_angle_deg * M_PI / 180.0);
    m.points = surface.points;
    const int np = static_cast<int>(m.points.size());
    auto P = [&](int i) -> const Vec3d& { return m.points[static_cast<std::size_t>(i)]; };
    m.vertex_tris.resize(m.points.size());
    std::map<std::pair<int, int>, std::vector<int>> edge_tris;
    for (const auto& t : surface.triangles) {
        if (t[0] < 0 || t[1] < 0 || t[2] < 0 || t[0] >= np || t[1] >= np || t[2] >= np) continue;
        const Vec3d n = (P(t[1]) - P(t[0])) % (P(t[2]) - P(t[0]));
        const double len = n.norm();
        if (!(len > 0) || !std::isfinite(len)) continue;
        const int id = static_cast<int>(m.tris.size());
        m.tris.push_back(t);
        m.normals.push_back(n / len);
        for (int i = 0; i < 3; ++i) {
            const int a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>((i + 1) % 3)];
            edge_tris[{std::min(a, b), std::max(a, b)}].push_back(id);
            m.vertex_tris[static_cast<std::size_t>(a)].push_back(id);
        }
    }
    // Feature edges; the other edges join their two triangles into one patch.
    std::vector<std::vector<int>> tri_nb(m.tris.size());
    m.vertex_segs.resize(m.points.size());
    for (const auto& [e, tris] : edge_tris) {
        const bool sharp = tris.size() != 2 ||
                           (m.normals[static_cast<std::size_t>(tris[0])] | m.normals[static_cast<std::size_t>(tris[1])]) < cos_limit;
        if (!sharp) {
            tri_nb[static_cast<std::size_t>(tris[0])].push_back(tris[1]);
            tri_nb[static_cast<std::size_t>(tris[1])].push_back(tris[0]);
            continue;
        }
        const int id = static_cast<int>(m.segs.size());
        m.segs.push_back({{e.first, e.second}});
        m.vertex_segs[static_cast<std::size_t>(e.first)].push_back(id);
        m.vertex_segs[static_cast<std::size_t>(e.second)].push_back(id);
    }
    m.patch.assign(m.tris.size(), -1);
    for (std::size_t t = 0; t < m.tris.size(); ++t) {
        if (m.patch[t] >= 0) continue;
        const int pid = static_cast<int>(m.n_patches++);
        std::vector<int> stack{static_cast<int>(t)};
        m.patch[t] = pid;
        while (!stack.empty()) {
            const int u = stack.back();
            stack.pop_back();
            for (const int w : tri_nb[static_cast<std::size_t>(u)])
                if (m.patch[static_cast<std::size_t>(w)] < 0) {
                    m.patch[static_cast<std::size_t>(w)] = pid;
                    stack.push_back(w);
                }
        }
    }
    // Corners.
    m.is_corner.assign(m.points.size(), 0);
    for (std::size_t v = 0; v < m.points.size(); ++v) {
        const auto& s = m.vertex_segs[v];
        if (s.empty()) continue;
        bool corner = s.size() != 2;
        if (!corner) {
            auto dir = [&](int seg) {
                const auto& e = m.segs[static_cast<std::size_t>(seg)];
                return (P(e[1]) - P(e[0])).normalized();
            };
            corner = std::abs(dir(s[0]) | dir(s[1])) < cos_limit;
        }
        if (corner) {
            m.is_corner[v] = 1;
            m.corners.push_back(m.points[v]);
        }
    }
    // Curves: segments connected through non-corner points.
    m.seg_curve.assign(m.segs.size(), -1);
    for (std::size_t s = 0; s < m.segs.size(); ++s) {
        if (m.seg_curve[s] >= 0) continue;
        const int cid = static_cast<int>(m.n_curves++);
        std::vector<int> stack{static_cast<int>(s)};
        m.seg_curve[s] = cid;
        while (!stack.empty()) {
            const int u = stack.back();
            stack.pop_back();
            for (const int v : m.segs[static_cast<std::size_t>(u)]) {
                if (m.is_corner[static_cast<std::size_t>(v)]) continue;
                for (const int w : m.vertex_segs[static_cast<std::size_t>(v)])
                    if (m.seg_curve[static_cast<std::size_t>(w)] < 0) {
                        m.seg_curve[static_cast<std::size_t>(w)] = cid;
                        stack.push_back(w);
                    }
            }
        }
    }
    for (const auto& t : m.tris) m.cgal_tris.emplace_back(toPoint(P(t[0])), toPoint(P(t[1])), toPoint(P(t[2])));
    for (const auto& s : m.segs) m.cgal_segs.emplace_back(toPoint(P(s[0])), toPoint(P(s[1])));
    if (!m.cgal_tris.empty()) {
        m.tri_tree.insert(m.cgal_tris.cbegin(), m.cgal_tris.cend());
        m.tri_tree.build();
        m.tri_tree.accelerate_distance_queries();
    }
    if (!m.cgal_segs.empty()) {
        m.seg_tree.insert(m.cgal_segs.cbegin(), m.cgal_segs.cend());
        m.seg_tree.build();
        m.seg_tree.accelerate_distance_queries();
    }
}

LocalSurfaceProjection::~LocalSurfaceProjection() = default;

std::size_t LocalSurfaceProjection::triangles() const { return impl_->tris.size(); }
std::size_t LocalSurfaceProjection::featureSegments() const { return impl_->segs.size(); }
std::size_t LocalSurfaceProjection::featureCurves() const { return impl_->n_curves; }
std::size_t LocalSurfaceProjection::corners() const { return impl_->corners.size(); }
std::size_t LocalSurfaceProjection::patches() const { return impl_->n_patches; }
Vec3d LocalSurfaceProjection::corner(int c) const { return impl_->corners[static_cast<std::size_t>(c)]; }
int LocalSurfaceProjection::segmentCurve(int segment) const { return impl_->seg_curve[static_cast<std::size_t>(segment)]; }

int LocalSurfaceProjection::nearestCorner(const Vec3d& p, double* distance) const {
    int best = -1;
    double bd = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < impl_->corners.size(); ++c) {
        const double d = (impl_->corners[c] - p).norm();
        if (d < bd) {
            bd = d;
            best = static_cast<int>(c);
        }
    }
    if (distance) *distance = bd;
    return best;
}

int LocalSurfaceProjection::nearestTriangle(const Vec3d& p) const {
    if (impl_->cgal_tris.empty()) return -1;
    const auto r = impl_->tri_tree.closest_point_and_primitive(toPoint(p));
    return static_cast<int>(r.second - impl_->cgal_tris.cbegin());
}

int LocalSurfaceProjection::nearestSegment(const Vec3d& p) const {
    if (impl_->cgal_segs.empty()) return -1;
    const auto r = impl_->seg_tree.closest_point_and_primitive(toPoint(p));
    return static_cast<int>(r.second - impl_->cgal_segs.cbegin());
}

double LocalSurfaceProjection::distanceToSurface(const Vec3d& p) const {
    if (impl_->cgal_tris.empty()) return std::numeric_limits<double>::infinity();
    return std::sqrt(CGAL::to_double(impl_->tri_tree.squared_distance(toPoint(p))));
}

Vec3d LocalSurfaceProjection::projectOnPatch(const Vec3d& p, int& triangle, Vec3d* normal) const {
    const Impl& m = *impl_;
    auto closest = [&](int t) {
        const auto& v = m.tris[static_cast<std::size_t>(t)];
        return closestPointOnTriangle(p, m.points[static_cast<std::size_t>(v[0])], m.points[static_cast<std::size_t>(v[1])],
                                      m.points[static_cast<std::size_t>(v[2])]);
    };
    Vec3d best = closest(triangle);
    double bd = (best - p).sqrnorm();
    const int patch = m.patch[static_cast<std::size_t>(triangle)];
    for (int step = 0; step < kMaxWalk; ++step) {
        int next = -1;
        for (const int v : m.tris[static_cast<std::size_t>(triangle)])
            for (const int t : m.vertex_tris[static_cast<std::size_t>(v)]) {
                if (t == triangle || m.patch[static_cast<std::size_t>(t)] != patch) continue;
                const Vec3d q = closest(t);
                const double d = (q - p).sqrnorm();
                if (d < bd) {
                    bd = d;
                    best = q;
                    next = t;
                }
            }
        if (next < 0) break;
        triangle = next;
    }
    if (normal) *normal = m.normals[static_cast<std::size_t>(triangle)];
    return best;
}

Vec3d LocalSurfaceProjection::projectOnCurve(const Vec3d& p, int& segment, Vec3d* tangent) const {
    const Impl& m = *impl_;
    auto closest = [&](int s) {
        const auto& e = m.segs[static_cast<std::size_t>(s)];
        return closestPointOnSegment(p, m.points[static_cast<std::size_t>(e[0])], m.points[static_cast<std::size_t>(e[1])]);
    };
    Vec3d best = closest(segment);
    double bd = (best - p).sqrnorm();
    const int curve = m.seg_curve[static_cast<std::size_t>(segment)];
    for (int step = 0; step < kMaxWalk; ++step) {
        int next = -1;
        for (const int v : m.segs[static_cast<std::size_t>(segment)])
            for (const int s : m.vertex_segs[static_cast<std::size_t>(v)]) {
                if (s == segment || m.seg_curve[static_cast<std::size_t>(s)] != curve) continue;
                const Vec3d q = closest(s);
                const double d = (q - p).sqrnorm();
                if (d < bd) {
                    bd = d;
                    best = q;
                    next = s;
                }
            }
        if (next < 0) break;
        segment = next;
    }
    if (tangent) {
        const auto& e = m.segs[static_cast<std::size_t>(segment)];
        *tangent = (m.points[static_cast<std::size_t>(e[1])] - m.points[static_cast<std::size_t>(e[0])]).normalized();
    }
    return best;
}

} // namespace HexEx
