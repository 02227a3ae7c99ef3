#pragma once
/// @file EllipticEnergy.hh
/// @ingroup quality
/// The regularised elliptic energy of one tetrahedron (Garanzha, Kaporin, Kudryavtseva,
/// Protais, Ray, Sokolov: "Foldover-free maps in 50 lines of code", ACM TOG 40(4), 2021),
/// evaluated on a corner tet of a hexahedron: the three edges leaving a hex corner.
///
/// With J = [a b c] / h (the edges as columns, h the reference edge length) and D = det J:
///
///     chi(D, eps) = (D + sqrt(eps^2 + D^2)) / 2          (> 0 for every D when eps > 0)
///     f = tr(J^T J) / chi^(2/3)                           (shape term, scale invariant)
///     g = (D^2 + 1) / chi                                 (volume term, minimal at D = 1)
///     F = (1 - theta) f + theta g
///
/// For eps -> 0, chi -> max(D, 0) and F becomes the classical elliptic (barrier) energy,
/// which is infinite for inverted corners; for eps > 0 it is finite and smooth everywhere,
/// so a quasi-Newton method can start from a folded mesh.

#include "../Core/Vec.hh"

#include <array>

namespace HexEx {

/// chi(D, eps) = (D + sqrt(eps^2 + D^2)) / 2, written so that it does not cancel for D < 0.
double regularizedDeterminant(double det, double eps);

/// Energy F of the corner with edges @p a, @p b, @p c (reference edge length @p h,
/// regularisation @p eps, volume weight @p theta); if @p grad is given, stores dF/da,
/// dF/db, dF/dc in it.
double cornerEnergy(const Vec3d& a, const Vec3d& b, const Vec3d& c, double h, double eps, double theta,
                    std::array<Vec3d, 3>* grad);

/// Energy of a whole trilinear hex seen inside, not only at its corners: the sum over the
/// sample points (u, v, w) in {0, 1/(n-1), ..., 1}^3 (n = @p samples_per_axis >= 2) of
/// cornerEnergy()^@p power, evaluated on the columns of the exact Jacobian matrix
/// [dx/du, dx/dv, dx/dw] of the map x(u, v, w) = sum X_ijk B_i(u) B_j(v) B_k(w) (corners
/// @p corners in VTK order). At a corner of the cube the columns are the three edges there,
/// so n = 2 gives the 8 corner tets; n = 3 adds the edge midpoints, face centres and the
/// cell centre (the 27 points where the tri-quadratic det J is sampled to get its Bernstein
/// coefficients). Each sample is a tet spanned by the three partial derivatives, in the
/// spirit of the extra tets per hex of Schaller, Beaufort and Bommes ("Up to 58 tets/hex to
/// untangle hex meshes", 2022). If @p grad is given, stores the gradient with respect to
/// each corner in it; if @p min_det is given, stores the smallest det J / h^3 over the samples.
double hexSampledEnergy(const std::array<Vec3d, 8>& corners, int samples_per_axis, double h, double eps, double theta,
                        double power, std::array<Vec3d, 8>* grad, double* min_det);

} // namespace HexEx
