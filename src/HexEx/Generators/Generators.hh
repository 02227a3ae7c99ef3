#pragma once
/// @file Generators.hh
/// @ingroup io
/// Procedural test inputs: tet meshes with exact integer-grid maps whose hex meshes are
/// known in advance (cube, cylinder with one singular edge, periodic and twisted rings),
/// plus deterministic ways to make the maps harder (random chart changes, parameter noise).
///
/// Every generator returns tets that are positively oriented both in 3D (orient3d of the
/// positions) and in parameter space (orient3d of the four corner parameters), each tet in
/// its own chart. Boxes of the parameter grid are split into six tets around one main
/// diagonal (Kuhn/Freudenthal subdivision), which is conforming across neighbouring boxes.

#include "../Grid/GridTransform.hh"
#include "../Mesh/ParametrizedTetMesh.hh"

#include <vector>

namespace HexEx {

/// The unit cube [0,1]^3 split into @p n^3 boxes of six tets each, with parameters
/// `s * position`. The expected hex mesh has s^3 hexes and (s+1)^3 vertices; @p n may be
/// smaller or larger than @p s. The mesh has 6 n^3 tets, (n+1)^3 vertices and 12 n^2
/// boundary triangles. Throws std::invalid_argument unless n >= 1 and s >= 1.
ParametrizedTetMesh generateCube(int n, int s);

/// A cylinder whose axis is a singular edge chain of valence @p k (4 gives the regular
/// control case). It consists of k wedges; wedge i has the chart (a,b,h) in
/// [0,R] x [0,R] x [0,H], tessellated as n x n x m boxes of six tets. Wedge i's side a=0 is
/// glued to wedge (i+1)%k's side b=0 by the transition (a,b,h) -> (b,-a,h) (a quarter turn
/// about the h axis), so the accumulated transition around the axis is a rotation by
/// k*90 degrees. All wedges share the axis vertices (a = b = 0).
///
/// 3D embedding: point (a,b,h) of wedge i goes to polar angle
/// 2*pi*i/k + (2*pi/k) * atan2(b,a)/(pi/2), radius max(a,b)/R and height h/R. The
/// embedding is a product of a planar map and the height, so a tet is positive iff the
/// image of the planar triangle under its box is; the radius map max(a,b) keeps every
/// such triangle positive for k >= 3 (the generator verifies this exactly and throws
/// std::logic_error otherwise). Expected hexes: k*R*R*H.
/// Throws std::invalid_argument unless k >= 3 and R, H, n, m >= 1.
ParametrizedTetMesh generateCylinder(int k, int R, int H, int n, int m);

/// The box [0,L] x [0,W] x [0,H] in parameter space, periodic in the first coordinate:
/// a closed ring of nu x nv x nw boxes whose last layer reuses the first layer's vertices,
/// seen there with parameter u + L (the transition across the seam is a translation by L).
/// Embedded as an annulus around the z axis (angle -2*pi*u/L, radius W + v, height w);
/// the angle runs clockwise so that tets stay positively oriented. Expected hexes L*W*H;
/// the only boundary is the inner/outer wall and the top/bottom, 4*nu*(nv+nw) triangles.
/// Throws std::invalid_argument unless nu >= 3 (fewer layers would repeat edges) and all
/// other arguments are >= 1.
ParametrizedTetMesh generateRing(int L, int W, int H, int nu, int nv, int nw);

/// Like generateRing() with a square cross-section [0,W]^2 of nv x nv boxes, glued at the
/// seam by a quarter turn about the first axis: the transition from the last layer's
/// chart into the first layer's is (u,v,w) -> (u-L, W-w, v). The 3D cross-section turns
/// continuously by 90 degrees around the ring. To make the seam conforming, boxes use the
/// reflected Kuhn split (box (i,j,k) mirrors its v axis if j is odd and its w axis if k is
/// odd), which needs an even @p nv. The ring radius is chosen (doubling from 2W) so that
/// all straight tets are positive in 3D. Expected hexes L*W*W.
/// Throws std::invalid_argument unless nu >= 3, nv >= 2 is even and L, W >= 1.
ParametrizedTetMesh generateTwistedRing(int L, int W, int nu, int nv);

/// Re-expresses every tet's corner parameters by a random grid automorphism
/// g(u) = R u + t (R uniform over the 24 rotations, t uniform in [-5,5]^3), so that
/// transitions are non-trivial everywhere. Deterministic for a given @p seed on every
/// platform (std::mt19937 with hand-written uniform draws). Returns the transform applied
/// to each cell. Exact whenever the parameters are dyadic with few enough bits (e.g.
/// integers or halves); otherwise adding t rounds like any floating-point sum.
std::vector<GridTransform> applyRandomChartTransforms(ParametrizedTetMesh& pm, unsigned seed);

/// Adds independent uniform noise in [-a, a] to every coordinate of every corner parameter
/// of every tet, except coordinates that lie on a boundary plane: if a corner belongs to a
/// boundary halfface of its tet whose three corner parameters agree exactly in some
/// coordinate, that coordinate of that corner is left unchanged. Builds adjacency if
/// needed. Deterministic for a given @p seed on every platform.
void applyParameterNoise(ParametrizedTetMesh& pm, double a, unsigned seed);

/// Sum of the signed volumes of all tets in parameter space (each in its own chart). For a
/// valid integer-grid map of a generated mesh this is the expected number of hexes.
double totalParametricVolume(const ParametrizedTetMesh& pm);

/// Signed volume of the tet with corners @p p0..p3, i.e. det(p1-p0, p2-p0, p3-p0)/6.
double tetVolume(const Vec3d& p0, const Vec3d& p1, const Vec3d& p2, const Vec3d& p3);

} // namespace HexEx
