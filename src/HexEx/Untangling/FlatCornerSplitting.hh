#pragma once
/// @file FlatCornerSplitting.hh
/// @ingroup quality
/// Local pillows at flat corners along feature curves: a boundary quad whose two edges at a
/// vertex v both run along one feature curve, at a corner angle psi near 180 degrees, bounds
/// the scaled Jacobian of its hex at v by sin(psi) however the vertices move (both edges stay
/// on the curve). A boundary layer (pillowBoundary()) keeps that quad as it is.
///
/// splitFlatFeatureCorners() pillows the hex of such a quad alone (a shrink set of one hex):
/// the hex H = (Q, F) with its boundary quad Q and inner quad F gets a smaller copy H* inside
/// it, and each of its five inner faces a new hex between the face and its copy. On the
/// surface Q is replaced by its copy Q* and a ring of four quads around it, so v gets two
/// boundary quads on Q's side of the curve (its flat corner split in two) and the copy of v
/// lies inside the patch, free to move. The hexes around H keep their vertices; only H
/// changes, into six hexes (5 hexes and 8 vertices are appended, H's index is kept for H*).
///
/// Where the copies go: Q* is Q shrunk by the factor 1 - t about the midpoint of v and the
/// vertex opposite it (in Q's plane if Q is planar), and the copies of F's vertices lie t of
/// the way from them to H's centroid. t starts at FlatCornerOptions::width and is halved
/// until the six hexes are certified valid (classifyHexValidity()); if they never are, H is
/// left as it was.
///
/// Example:
/// ```
/// HexEx::FlatCornerReport r = HexEx::splitFlatFeatureCorners(mesh);   // after pillowBoundary()
/// std::cout << r.split_hexes << " hexes split at flat corners\n";
/// ```

#include "../Mesh/HexMesh.hh"

namespace HexEx {

/// Settings of splitFlatFeatureCorners().
struct FlatCornerOptions {
    /// Boundary edges whose two quads' normals differ by more than this are feature edges.
    double feature_angle_deg = 40;
    /// A boundary quad corner between two feature edges above this angle is flat.
    double flat_angle_deg = 150;
    /// Initial width t of the ring of new quads, as a fraction of the way to the midpoint.
    double width = 0.5;
    /// How often t may be halved to make the six hexes certified valid.
    int max_halvings = 6;
};

/// What splitFlatFeatureCorners() did.
struct FlatCornerReport {
    long flat_corners = 0;    ///< boundary quad corners found flat between two feature edges
    long split_hexes = 0;     ///< hexes pillowed (each into six)
    long hexes_added = 0;     ///< new hexes (5 per split hex)
    long vertices_added = 0;  ///< new vertices (8 per split hex)
    /// Hexes with a flat corner that were not split: not certified valid, more than one
    /// boundary face, a vertex of the opposite face on the boundary, a vertex shared with a
    /// hex split before, or no width that makes the six hexes certified valid.
    long skipped_hexes = 0;
};

/// Splits the hexes of @p mesh that have a boundary quad with a flat corner between two
/// feature edges (see the file comment), in the order of their boundary quads (by hex, then
/// face); hexes that share a vertex with one split before are skipped, so every split is
/// independent of the others. Polyhedra are ignored (their faces do not count as boundary).
/// Deterministic; the result does not depend on anything but @p mesh and @p options.
/// @throws std::invalid_argument if a hex references a vertex out of range.
FlatCornerReport splitFlatFeatureCorners(HexMesh& mesh, const FlatCornerOptions& options = {});

} // namespace HexEx
