#pragma once
/// @file GridTransform.hh
/// @ingroup pipeline
/// Grid automorphisms g(u) = R u + t with R one of the 24 rotations and t integer.

#include "Rotation.hh"

namespace HexEx {

/// A grid automorphism g(u) = R u + t. Applying it to doubles is exact as long as the
/// results stay below 2^53 in magnitude and the inputs carry no bits below the unit in the
/// last place of the result (guaranteed after sanitization).
struct GridTransform {
    Rotation R;        ///< rotation part
    Vec3i t{0, 0, 0};  ///< integer translation

    /// The identity.
    GridTransform() = default;
    /// From parts.
    GridTransform(Rotation r, const Vec3i& tr) : R(r), t(tr) {}
    /// g(u) for a point.
    Vec3d apply(const Vec3d& u) const { Vec3d r = R.apply(u); return Vec3d(r[0] + t[0], r[1] + t[1], r[2] + t[2]); }
    /// g(z) for an integer point.
    Vec3i apply(const Vec3i& z) const {
        const Vec3i r = R.apply(z);  // per component: see Rotation::apply()
        return Vec3i(r[0] + t[0], r[1] + t[1], r[2] + t[2]);
    }
    /// Image of a direction (translation does not act on directions).
    AxisDir applyDir(AxisDir d) const { return R.apply(d); }
    /// Composition (*this) o (o): apply @p o first.
    GridTransform operator*(const GridTransform& o) const { return GridTransform(R * o.R, R.apply(o.t) + t); }
    /// Inverse transform.
    GridTransform inverse() const { Rotation ri = R.inverse(); Vec3i ti = ri.apply(t); return GridTransform(ri, -ti); }
    /// True for the identity.
    bool is_identity() const { return R.is_identity() && t == Vec3i(0, 0, 0); }
    /// Equality.
    bool operator==(const GridTransform& o) const { return R == o.R && t == o.t; }
    /// Inequality.
    bool operator!=(const GridTransform& o) const { return !(*this == o); }
};

} // namespace HexEx
