#pragma once
/// @file TriangleDarts.hh
/// @ingroup quad
/// Dart extraction in 2D (paper 4.3.1 with one dimension less): a dart is a quad corner
/// seen from one triangle, an integer grid point z with a frame (d1, d2) of two orthogonal
/// axis directions (8 frames per point). Triangle f owns the dart if it contains the
/// perturbed point z + e d1 + e^2 d2 for infinitesimal e > 0 (the same symbolic tie-breaking
/// rule as for tets); a flipped triangle yields an anti dart.

#include "../Grid/Rotation.hh"
#include "TrianglePreprocessing.hh"

#include <cstdint>
#include <vector>

namespace HexEx {

/// One dart: triangle, grid point (in the triangle's chart), frame and sign.
/// No default member values: arrays of darts are sized without a zeroing pass
/// (TriDartVector) and filled in parallel.
struct TriDart {
    int tri;           ///< owning triangle
    int x;             ///< grid point, first coordinate
    int y;             ///< grid point, second coordinate
    AxisDir d1;        ///< edge direction (0..3: +u, -u, +v, -v)
    AxisDir d2;        ///< face side, orthogonal to d1
    signed char sign;  ///< +1 regular (proper triangle), -1 anti (flipped triangle)
};

/// An array of darts that resize() does not zero (see DefaultInitAllocator).
using TriDartVector = std::vector<TriDart, DefaultInitAllocator<TriDart>>;

/// The darts of all triangles, sorted by triangle, then grid point (v, then u), then frame.
struct TriDartSet {
    TriDartVector darts;                                 ///< all darts
    std::vector<int, DefaultInitAllocator<int>> offset;  ///< darts of triangle f: [offset[f], offset[f+1])
    long anti = 0;               ///< anti darts
};

/// True if the closed parameter triangle @p p (orientation @p sign, +1 or -1) contains
/// z + e d1 + e^2 d2 for infinitesimal e > 0. Exact.
bool triangleOwnsDart(const std::array<Vec2d, 3>& p, int sign, int x, int y, AxisDir d1, AxisDir d2);

/// Extracts the darts of every non-degenerate triangle (in parallel; the output does not
/// depend on @p threads). Throws InputError if the triangles' parameter bounding boxes
/// together hold more than @p max_points grid points (a guard against absurd maps).
TriDartSet extractTriDarts(const TriParams& params, const std::vector<signed char>& sign, double max_points, int threads);

/// Index of the dart (x, y, d1, d2) of triangle @p f, or -1 (binary search).
int findTriDart(const TriDartSet& ds, int f, int x, int y, AxisDir d1, AxisDir d2);

} // namespace HexEx
