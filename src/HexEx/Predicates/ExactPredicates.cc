#include "ExactPredicates.hh"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <cmath>

namespace HexEx {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
K::Point_3 P3(const Vec3d& v) { return K::Point_3(v[0], v[1], v[2]); }

/// True if x lies on the closed segment [a, b] (exact).
bool onSegment(const Vec3d& a, const Vec3d& b, const Vec3d& x) {
    if (a == b) return x == a;
    if (!CGAL::collinear(P3(a), P3(b), P3(x))) return false;
    return CGAL::collinear_are_ordered_along_line(P3(a), P3(x), P3(b));
}

/// Location of x relative to the closed triangle a, b, c (exact); corners use bits 0,1,2.
PointClassification classifyTriangle(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& x) {
    PointClassification r;
    const Vec3d t[3] = {a, b, c};
    for (int i = 0; i < 3; ++i)
        if (x == t[i]) return {PointLocation::AtVertex, 1u << i};
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        if (onSegment(t[i], t[j], x) && t[i] != t[j]) return {PointLocation::OnEdge, (1u << i) | (1u << j)};
    }
    if (CGAL::collinear(P3(a), P3(b), P3(c))) return r;  // degenerate: only edges and vertices count
    if (orient3d(a, b, c, x) != 0) return r;
    // Coplanar: pick a projection in which the triangle is not degenerate.
    int axis = 0;
    for (int k = 0; k < 3; ++k)
        if (orient2dAxis(a, b, c, k) != 0) { axis = k; break; }
    const int s = orient2dAxis(a, b, c, axis);
    if (orient2dAxis(a, b, x, axis) == s && orient2dAxis(b, c, x, axis) == s && orient2dAxis(c, a, x, axis) == s)
        return {PointLocation::OnFace, 7u};
    return r;
}
} // namespace

// Both predicates first evaluate the determinant in doubles and accept its sign when it
// exceeds a forward error bound (Shewchuk 1997: (7+56e)e and (3+16e)e times the permanent,
// e = 2^-53; we use slightly larger constants). Only uncertain cases, mostly exact zeros
// of points on faces, go to CGAL's exact filtered predicate.
namespace {
/// True if every coordinate, scaled by 64, is an integer of magnitude at most 2^15: then the
/// determinants below are computed without any rounding (products stay below 2^53).
inline bool smallDyadic(const Vec3d& p) {
    for (int k = 0; k < 3; ++k) {
        const double x = p[k] * 64.0;
        // |x| <= 2^15 first (also rejects NaN), so the integer conversion is exact and cheap.
        if (!(std::fabs(x) <= 32768.0) || x != static_cast<double>(static_cast<int>(x))) return false;
    }
    return true;
}
} // namespace

int orient3d(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& d) {
    const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
    const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
    const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
    const double m1 = vy * wz, m2 = vz * wy, m3 = vz * wx, m4 = vx * wz, m5 = vx * wy, m6 = vy * wx;
    const double det = ux * (m1 - m2) + uy * (m3 - m4) + uz * (m5 - m6);
    const double perm = std::fabs(ux) * (std::fabs(m1) + std::fabs(m2)) + std::fabs(uy) * (std::fabs(m3) + std::fabs(m4)) +
                        std::fabs(uz) * (std::fabs(m5) + std::fabs(m6));
    const double bound = 1e-15 * perm;
    if (det > bound) return 1;
    if (-det > bound) return -1;
    // Exact zero: two equal points (a grid point at a tet corner, the common uncertain case).
    if (a == b || a == c || a == d || b == c || b == d || c == d) return 0;
    if (smallDyadic(a) && smallDyadic(b) && smallDyadic(c) && smallDyadic(d)) return (det > 0) - (det < 0);
    return static_cast<int>(CGAL::orientation(P3(a), P3(b), P3(c), P3(d)));
}

int orient2dAxis(const Vec3d& a, const Vec3d& b, const Vec3d& c, int axis) {
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    const double t1 = (b[i] - a[i]) * (c[j] - a[j]), t2 = (b[j] - a[j]) * (c[i] - a[i]);
    const double det = t1 - t2, bound = 5e-16 * (std::fabs(t1) + std::fabs(t2));
    if (det > bound) return 1;
    if (-det > bound) return -1;
    // Exact zero: one factor of each product is an exact zero difference (common for
    // axis-aligned faces, where the filter cannot decide).
    if ((b[i] == a[i] || c[j] == a[j]) && (b[j] == a[j] || c[i] == a[i])) return 0;
    if (smallDyadic(a) && smallDyadic(b) && smallDyadic(c)) return (det > 0) - (det < 0);
    return static_cast<int>(
        CGAL::orientation(K::Point_2(a[i], a[j]), K::Point_2(b[i], b[j]), K::Point_2(c[i], c[j])));
}

PointClassification classifyPoint(const Vec3d p[4], const Vec3d& x) {
    const int vol = orient3d(p[0], p[1], p[2], p[3]);
    if (vol != 0) {
        // o_j: orientation with corner j replaced by x; x is inside iff all have the volume's sign.
        unsigned zero = 0;
        for (int j = 0; j < 4; ++j) {
            Vec3d q[4] = {p[0], p[1], p[2], p[3]};
            q[j] = x;
            const int o = orient3d(q[0], q[1], q[2], q[3]);
            if (o == -vol) return {};
            if (o == 0) zero |= 1u << j;
        }
        const unsigned span = 0xFu & ~zero;
        const int n = __builtin_popcount(span);
        const PointLocation loc = n == 4   ? PointLocation::Inside
                                  : n == 3 ? PointLocation::OnFace
                                  : n == 2 ? PointLocation::OnEdge
                                           : PointLocation::AtVertex;
        return {loc, span};
    }
    // Flat tet: test vertices, edges, then faces (lowest element first).
    for (int i = 0; i < 4; ++i)
        if (x == p[i]) return {PointLocation::AtVertex, 1u << i};
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
            if (p[i] != p[j] && onSegment(p[i], p[j], x)) return {PointLocation::OnEdge, (1u << i) | (1u << j)};
    for (int f = 0; f < 4; ++f) {
        int idx[3], n = 0;
        for (int k = 0; k < 4; ++k)
            if (k != f) idx[n++] = k;
        PointClassification c = classifyTriangle(p[idx[0]], p[idx[1]], p[idx[2]], x);
        if (c.location == PointLocation::OnFace) return {PointLocation::OnFace, 0xFu & ~(1u << f)};
    }
    return {};
}

bool triangleContainsPoint(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& x) {
    return classifyTriangle(a, b, c, x).location != PointLocation::Outside;
}

bool triangleIntersectsSegment(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& p, const Vec3d& q) {
    if (p == q) return triangleContainsPoint(a, b, c, p);
    const K::Segment_3 s(P3(p), P3(q));
    if (CGAL::collinear(P3(a), P3(b), P3(c))) {
        const Vec3d t[3] = {a, b, c};
        for (int i = 0; i < 3; ++i) {
            const Vec3d& u = t[i];
            const Vec3d& v = t[(i + 1) % 3];
            if (u == v ? s.has_on(P3(u)) : CGAL::do_intersect(s, K::Segment_3(P3(u), P3(v)))) return true;
        }
        return false;
    }
    return CGAL::do_intersect(K::Triangle_3(P3(a), P3(b), P3(c)), s);
}

} // namespace HexEx
