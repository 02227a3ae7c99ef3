#pragma once
/// @file FoldedBoundary.hh
/// @ingroup quality
/// Diagnosis of a hex mesh whose boundary folds over itself (a fold of the map carried into
/// the extraction): boundary doublets and hexes that lie outside the input volume.
///
/// A boundary doublet is a boundary vertex in exactly two boundary quads that share both of
/// their edges at it. No direction at such a vertex points into both quads' hexes (their
/// normals there are opposite), so a boundary layer (pillowBoundary()) cannot give it a valid
/// inner copy. On S1 x2 the two doublets are where a flap of hexes outside the input volume
/// lies on the input's boundary plane with its quads facing the other way
/// (Documentation/algorithm.md, boundary pillowing).
///
/// Example:
/// ```
/// std::vector<int> d = HexEx::boundaryDoublets(mesh);
/// std::vector<int> flap = HexEx::hexesOutsideSurface(mesh, surface, {bad_hex});
/// std::vector<int> exposed = HexEx::removeHexes(mesh, flap);
/// ```
///
/// OptimizeOptions::pillow uses them: when hexes that are not certified valid belong to a
/// flap outside the input surface, the flap is removed, the whole boundary gets the layer
/// and the exposed vertices are put on the surface before the untangler runs.

#include "../Mesh/HexMesh.hh"
#include "TriangleSurface.hh"

#include <vector>

namespace HexEx {

/// Boundary vertices of the hexes of @p mesh that are in exactly two boundary quads which
/// share both of their edges at the vertex (boundary doublets), in increasing order.
/// Polyhedra are ignored.
std::vector<int> boundaryDoublets(const HexMesh& mesh);

/// Generalised winding number of the closed triangle surface @p surface around @p p (sum of
/// the signed solid angles of its triangles over 4 pi): about 1 inside a closed outward
/// oriented surface, 0 outside.
double windingNumber(const TriangleSurface& surface, const Vec3d& p);

/// Hexes of @p mesh whose centre (mean of the 8 corners) lies outside @p surface (winding
/// number below 1/2 in magnitude, so that a surface oriented inward counts the same) and that are connected to a hex of @p seeds through faces of such
/// hexes: the seeds that are outside, and the outside hexes reached from them across shared
/// quads. In increasing order. A seed out of range is ignored.
std::vector<int> hexesOutsideSurface(const HexMesh& mesh, const TriangleSurface& surface, const std::vector<int>& seeds);

/// Removes the hexes @p hexes (indices, any order, duplicates and out-of-range ones ignored)
/// from @p mesh; vertices that no remaining hex uses are dropped, the others and the hexes
/// keep their order. Returns the new indices of the vertices of the quads that a removed hex
/// shared with a kept one (the boundary that the removal exposes), in increasing order.
/// The mesh must be all-hex (polyhedra are left as they are and not renumbered: throws
/// std::invalid_argument if it has any).
std::vector<int> removeHexes(HexMesh& mesh, const std::vector<int>& hexes);

} // namespace HexEx
