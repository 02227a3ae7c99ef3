#pragma once
/// @file PlanarTransform.hh
/// @ingroup quad
/// The transition between two charts of a 2D integer-grid map: a counter-clockwise
/// rotation by 0..3 quarter turns followed by an integer translation. The planar form of
/// GridTransform (12 bytes instead of 16, no third coordinate); it gives bit for bit what
/// GridTransform(planarRotation(k), (tu, tv, 0)) gives on the (u, v) coordinates.

#include "../Grid/Rotation.hh"
#include "ParametrizedTriMesh.hh"

namespace HexEx {

/// A planar grid transition: rotation by @ref k counter-clockwise quarter turns, then
/// translation by (@ref tu, @ref tv).
struct PlanarTransform {
    int k = 0;   ///< counter-clockwise quarter turns, 0..3
    int tu = 0;  ///< translation, first coordinate
    int tv = 0;  ///< translation, second coordinate

    /// Image of axis direction d (0..3: +u, -u, +v, -v) under q quarter turns.
    static AxisDir turnDir(int q, AxisDir d) {
        static constexpr AxisDir kTurn[4][4] = {{0, 1, 2, 3}, {2, 3, 1, 0}, {1, 0, 3, 2}, {3, 2, 0, 1}};
        return kTurn[q][d];
    }
    /// The rotation alone applied to (x, y) (exact: negation and swap).
    Vec2d rotate(const Vec2d& p) const {
        switch (k) {
            case 0: return p;
            case 1: return Vec2d(-p[1], p[0]);
            case 2: return Vec2d(-p[0], -p[1]);
            default: return Vec2d(p[1], -p[0]);
        }
    }
    /// The rotation alone applied to an integer vector.
    void rotate(int x, int y, int& rx, int& ry) const {
        switch (k) {
            case 0: rx = x; ry = y; break;
            case 1: rx = -y; ry = x; break;
            case 2: rx = -x; ry = -y; break;
            default: rx = y; ry = -x; break;
        }
    }
    /// Image of a point.
    Vec2d apply(const Vec2d& p) const {
        const Vec2d r = rotate(p);
        return Vec2d(r[0] + tu, r[1] + tv);
    }
    /// Image of an integer point.
    void apply(int x, int y, int& rx, int& ry) const {
        rotate(x, y, rx, ry);
        rx += tu;
        ry += tv;
    }
    /// Image of a direction (the translation does not act on directions).
    AxisDir applyDir(AxisDir d) const { return turnDir(k, d); }
    /// Composition (*this) o (o): apply @p o first.
    PlanarTransform operator*(const PlanarTransform& o) const {
        PlanarTransform r;
        r.k = (k + o.k) & 3;
        rotate(o.tu, o.tv, r.tu, r.tv);
        r.tu += tu;
        r.tv += tv;
        return r;
    }
    /// The inverse transition.
    PlanarTransform inverse() const {
        PlanarTransform r;
        r.k = (4 - k) & 3;
        r.rotate(tu, tv, r.tu, r.tv);
        r.tu = -r.tu;
        r.tv = -r.tv;
        return r;
    }
    /// True for the identity.
    bool is_identity() const { return k == 0 && tu == 0 && tv == 0; }
    /// Equality.
    bool operator==(const PlanarTransform& o) const { return k == o.k && tu == o.tu && tv == o.tv; }
};

} // namespace HexEx
