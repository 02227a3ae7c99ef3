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

} // namespace HexEx
