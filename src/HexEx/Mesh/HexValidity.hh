#pragma once
/// @file HexValidity.hh
/// @ingroup quality
/// Certified validity of a trilinear hexahedron: is its Jacobian determinant positive on the
/// whole reference cube, not just at the 8 corners?
///
/// Method (Johnen, Weill and Remacle, "Robust and efficient validation of the linear
/// hexahedral element", Procedia Engineering 2017): the Jacobian determinant J of a
/// trilinear hex is a tri-quadratic polynomial, so it has 27 coefficients in the
/// tensor-product Bernstein basis of degree (2,2,2). The Bernstein polynomials are
/// non-negative and sum to 1, hence
///  - all 27 coefficients > 0 proves J > 0 everywhere (the hex is valid);
///  - any value of J <= 0 at a point of the cube proves it invalid (the 8 corner
///    coefficients and the 27 Lagrange node values are such values);
///  - otherwise the cube is split into 8 halves by de Casteljau's algorithm on the
///    coefficients and the test is repeated on each, to a bounded depth.
///
/// The decisions are certified despite rounding: a first pass in double precision decides
/// only with a margin larger than a forward bound of its rounding error; what it cannot
/// decide is redone in interval arithmetic (CGAL::Interval_nt), and a hex whose exact
/// corner orientation (CGAL's exact predicate) is <= 0 is invalid. What is still open after
/// the depth limit is reported as Undecided, never guessed.

#include "../Core/Vec.hh"

#include <array>
#include <cstdint>

namespace HexEx {

/// Outcome of the certified validity test of one hexahedron.
enum class HexValidity : std::uint8_t {
    Valid,      ///< J > 0 on the whole closed reference cube (proved)
    Invalid,    ///< J <= 0 at some point of the cube (proved), or a non-finite coordinate
    Undecided,  ///< neither could be proved within HexValidityOptions::max_depth
};

/// Limits of classifyHexValidity()'s subdivision.
struct HexValidityOptions {
    int max_depth = 8;    ///< levels of de Casteljau subdivision (each halves the box along u, v, w)
    int max_boxes = 4096; ///< sub-boxes examined at most per hex and precision
};

/// The 27 Bernstein coefficients of the Jacobian determinant of the trilinear hex with
/// corners @p p (VTK order), in double precision: entry i + 3 j + 9 k is the coefficient of
/// B_i(u) B_j(v) B_k(w), B the quadratic Bernstein polynomials on [0, 1].
/// Corner coefficients (i, j, k in {0, 2}) are J at the corners.
std::array<double, 27> jacobianBernsteinCoefficients(const std::array<Vec3d, 8>& p);

/// The Jacobian determinant det[dx/du, dx/dv, dx/dw] of the trilinear hex with corners
/// @p p (VTK order) at the reference point (u, v, w), computed directly from the map.
double jacobianDeterminant(const std::array<Vec3d, 8>& p, double u, double v, double w);

/// Evaluates the tri-quadratic Bernstein polynomial with coefficients @p b (layout of
/// jacobianBernsteinCoefficients()) at (u, v, w).
double evaluateBernstein(const std::array<double, 27>& b, double u, double v, double w);

/// Certified validity of the trilinear hex with corners @p p (VTK order); see the file comment.
HexValidity classifyHexValidity(const std::array<Vec3d, 8>& p, const HexValidityOptions& options = {});

/// classifyHexValidity() (default options) of the hexes @p a and @p b into @p out[0] and
/// @p out[1]. The first test runs for both at once, one in each lane of SSE2 registers, with
/// the same operations as classifyHexValidity()'s double-precision pass: a hex whose 27 node
/// values and 27 Bernstein coefficients all exceed the rounding bound is Valid, as there;
/// any other hex is passed to classifyHexValidity(). The verdicts are always the same.
void classifyHexValidityPair(const std::array<Vec3d, 8>& a, const std::array<Vec3d, 8>& b, HexValidity out[2]);

/// Short lower-case name of @p v ("valid", "invalid", "undecided").
const char* toString(HexValidity v);

} // namespace HexEx
