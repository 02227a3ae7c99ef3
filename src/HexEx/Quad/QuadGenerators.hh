#pragma once
/// @file QuadGenerators.hh
/// @ingroup quad
/// Procedural 2D test inputs: triangle meshes with exact integer-grid maps whose quad meshes
/// are known in advance (square, disk with a cone, torus, a seam with a quarter turn), and
/// deterministic ways to make the maps harder (random charts per triangle, noise, the
/// consistent perturbation of paper section 5.1 in 2D).
///
/// Every generator returns triangles that are counter-clockwise in parameter space, each in
/// its own chart; boxes of the grid are split into two triangles along their diagonal.

#include "ParametrizedTriMesh.hh"

#include <cstddef>

namespace HexEx {

/// The unit square [0,1]^2 as n x n boxes, parameters `s * position`. Expected quad mesh:
/// s^2 quads, (s+1)^2 vertices. Throws std::invalid_argument unless n, s >= 1.
ParametrizedTriMesh generateSquare(int n, int s);

/// A flat disk whose centre is a cone of valence @p k (4: a regular vertex): k wedges,
/// wedge i with the chart (a, b) in [0,R]^2 as n x n boxes; wedge i's side a = 0 is glued
/// to wedge (i+1)%k's side b = 0 by the transition (a, b) -> (b, -a). Embedded in the
/// plane at polar angle 2 pi (i + atan2(b, a) / (pi/2)) / k and radius max(a, b) / R.
/// Expected: k R^2 quads, k R (R + 1) + 1 vertices, k quads around the centre.
/// Throws std::invalid_argument unless k >= 2 and R, n >= 1.
ParametrizedTriMesh generateConeDisk(int k, int R, int n);

/// A torus, the grid [0,L] x [0,W] periodic in both directions (transitions: translations
/// by L and W), as nu x nv boxes. Expected: L W quads and L W vertices, no boundary.
/// Throws std::invalid_argument unless nu, nv >= 3 and L, W >= 1.
ParametrizedTriMesh generateTorus(int L, int W, int nu, int nv);

/// The square [0,W]^2 as n x n boxes whose right half (box column >= n/2) has a chart
/// turned by a quarter turn and shifted: (u, v) -> (-v, u) + (3, -2). The seam between
/// the halves carries a quarter-turn transition; the quad mesh is that of
/// generateSquare(): W^2 quads, (W+1)^2 vertices. Throws std::invalid_argument unless
/// n >= 2 and W >= 1.
ParametrizedTriMesh generateQuarterTurnSeam(int W, int n);

/// Re-expresses every triangle's corner parameters by a random planar grid automorphism
/// (one of 4 rotations, translation in [-5,5]^2). Deterministic for a given @p seed.
void applyRandomTriCharts(ParametrizedTriMesh& m, unsigned seed);

/// Adds independent uniform noise in [-a, a] to every corner parameter coordinate, except
/// coordinates in which the two corners of a boundary edge agree (boundary alignment).
void applyTriParameterNoise(ParametrizedTriMesh& m, double a, unsigned seed);

/// What perturbTriParameters() did.
struct TriPerturbStats {
    std::size_t vertices = 0;           ///< vertices visited
    std::size_t moved_vertices = 0;     ///< vertices displaced by a non-zero vector
    std::size_t boundary_vertices = 0;  ///< vertices constrained by a boundary edge
    std::size_t fixed_vertices = 0;     ///< vertices not moved at all (cones, corners)
};

/// Moves every vertex's parameter by noise uniform in [-@p a, @p a] per axis, drawn in the
/// chart of its lowest-index triangle and carried into every other triangle around it by
/// the rotations of the transitions, so the map stays seamless with the same transitions
/// (the 2D version of perturbParameters()). A coordinate in which a boundary edge at the
/// vertex is aligned to an integer line stays fixed; cone vertices (vertexHolonomy()) do not move. Two numbers
/// are drawn per vertex in vertex order (std::mt19937, mapped to doubles by hand).
/// @throws std::invalid_argument if @p a is negative or not finite; InputError for a bad mesh.
void perturbTriParameters(ParametrizedTriMesh& m, double a, unsigned seed, TriPerturbStats* stats = nullptr);

/// Sum of the signed parametric areas of all triangles (the expected quad count of a valid map).
double totalParametricArea(const ParametrizedTriMesh& m);

} // namespace HexEx
