#pragma once
/// @file FacePlanes.hh
/// @ingroup pipeline
/// The four face functions of one tet, set up once for many points: TetSoS::side() for
/// every grid point of a tet's box with a few multiplications per point instead of a full
/// orientation predicate. Same signs, exactly: a sign the floating-point filter cannot
/// certify is computed by TetSoS::side() itself.

#include "TetSoS.hh"

#include <cmath>

namespace HexEx {

/// o_j(x) = (-1)^(3-j) det(b - a, c - a, x - a) for the face (a, b, c) of the corners other
/// than j (in index order), evaluated as (x - a) . n with the cross product n = (b - a) x (c - a)
/// computed once. The filter is the one of orient3d(): the determinant's sign is accepted
/// when its magnitude exceeds 1e-15 times the permanent (Shewchuk's bound for an expansion
/// along one row with 2x2 minors of the other two is (7 + 56e)e, e = 2^-53, about 7.8e-16;
/// an absolute 1e-280 is added for underflow); otherwise, unless the arithmetic was exact
/// (smallDyadic() corners and point), TetSoS::side() decides.
class FacePlanes {
public:
    /// Sets up the four faces of @p T (which must outlive this object).
    explicit FacePlanes(const TetSoS& T) : T_(&T) {
        for (int j = 0; j < 4; ++j) {
            int o[3], m = 0;
            for (int k = 0; k < 4; ++k)
                if (k != j) o[m++] = k;
            const Vec3d& a = T.p[o[0]];
            const Vec3d u = T.p[o[1]] - a, v = T.p[o[2]] - a;
            base_[j] = a;
            for (int k = 0; k < 3; ++k) {
                const int i = (k + 1) % 3, l = (k + 2) % 3;
                const double t1 = u[i] * v[l], t2 = u[l] * v[i];
                n_[j][k] = t1 - t2;
                perm_[j][k] = std::fabs(t1) + std::fabs(t2);
            }
            sign_[j] = ((3 - j) % 2 == 0) ? 1 : -1;
        }
        exact_ = smallDyadic(T.p[0]) && smallDyadic(T.p[1]) && smallDyadic(T.p[2]) && smallDyadic(T.p[3]);
    }

    /// True if every coordinate of @p v is a multiple of 1/64 of magnitude at most 512. For
    /// such corners and points the differences, cross products and the dot product of
    /// side() are exact integers in units of 2^-18 below 2^53: the computed sign is exact.
    static bool smallDyadic(const Vec3d& v) {
        for (int k = 0; k < 3; ++k) {
            const double x = v[k] * 64.0;
            if (!(std::fabs(x) <= 32768.0) || x != static_cast<double>(static_cast<int>(x))) return false;
        }
        return true;
    }

    /// Sign of o_j(x): the same value as TetSoS::side(j, x).
    int side(int j, const Vec3d& x) const {
        const double wx = x[0] - base_[j][0], wy = x[1] - base_[j][1], wz = x[2] - base_[j][2];
        const double det = wx * n_[j][0] + wy * n_[j][1] + wz * n_[j][2];
        const double perm = std::fabs(wx) * perm_[j][0] + std::fabs(wy) * perm_[j][1] + std::fabs(wz) * perm_[j][2];
        // The relative bound assumes no underflow; the absolute term covers products of
        // subnormal numbers (their absolute errors are below 1e-300 for |x| <= 1e9).
        const double bound = 1e-15 * perm + 1e-280;
        if (det > bound) return sign_[j];
        if (-det > bound) return -sign_[j];
        if (exact_ && smallDyadic(x)) return det > 0 ? sign_[j] : det < 0 ? -sign_[j] : 0;
        return T_->side(j, x);
    }

private:
    const TetSoS* T_;    ///< the tet (for the uncertain cases)
    Vec3d base_[4];      ///< corner a of face j
    double n_[4][3];     ///< (b - a) x (c - a), rounded
    double perm_[4][3];  ///< |products| of each cross product component (for the error bound)
    int sign_[4];        ///< (-1)^(3-j)
    bool exact_ = false; ///< all corners are smallDyadic()
};

} // namespace HexEx
