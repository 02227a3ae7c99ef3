#pragma once
/// @file BoundaryPillowing.hh
/// @ingroup quality
/// Boundary pillowing of all-hex meshes: one layer of new hexes along the whole boundary
/// (Mitchell and Tautges, "Pillowing doublets: refining a mesh to ensure that faces share at
/// most one edge", 1995).
///
/// Why: a hex with two boundary faces that meet at a nearly flat dihedral angle phi has, at
/// the two corners of their common edge, two edges that lie in the two faces and make the
/// angle phi with each other; while both faces stay on the surface its scaled Jacobian there
/// is at most sin(phi), whatever the vertex placement (Documentation/algorithm.md, "Mesh
/// optimisation"). Pillowing changes the topology so that no hex keeps two such faces:
///  - every boundary vertex v gets an inner copy v' (a new vertex);
///  - every boundary quad (a, b, c, d) becomes a new hex whose outer quad is (a, b, c, d) and
///    whose inner quad is (a', b', c', d');
///  - the old hexes are re-pointed from the boundary vertices to their inner copies.
///
/// The boundary vertices keep their positions bit for bit, so the boundary surface and its
/// features are unchanged; the result has hexes + (boundary quads) hexes and vertices +
/// (boundary vertices) vertices. The inner copies are placed inward along the averaged inward
/// normal of the boundary quads at v (lengthened so that the copy lies about the same
/// distance below each of those quads), by PillowOptions::depth times the mean length of
/// the edges at v; where a hex is then not certified valid (classifyHexValidity()), the depths of its copies are halved, up to
/// PillowOptions::max_halvings times. Old hexes that were not certified valid before need
/// not become so, and their boundary quads get no new hex (the layer ends there as on a
/// skipped patch); every other hex is certified
/// valid afterwards, or the mesh is left unchanged and the report says why.
///
/// Example:
/// ```
/// HexEx::HexMesh hm = HexEx::readHexMesh("mesh.vtu");
/// HexEx::PillowReport r = HexEx::pillowBoundary(hm);   // hm gets the layer
/// std::cout << r.hexes_added << " hexes added\n";
/// ```

#include "../Mesh/HexMesh.hh"

#include <string>

namespace HexEx {

/// Settings of pillowBoundary().
struct PillowOptions {
    /// Depth of the inner copies as a fraction of the mean length of the hex edges at the
    /// boundary vertex (before shrinking).
    double depth = 0.3;
    /// How often the depth of a copy may be halved to make the hexes around it certified valid.
    int max_halvings = 20;
    /// Boundary edges whose two quads' normals differ by more than this are feature edges;
    /// they split the boundary into patches.
    double feature_angle_deg = 40;
    /// A patch with a quad whose two edges along feature edges make a corner angle above this
    /// gets no layer: the layer ends on it, and the copies of the vertices where it ends move
    /// along the patch (its quads along the border get a strip of new quads; this splits
    /// their flat corners). 180: pillow the whole boundary.
    double skip_patch_angle_deg = 150;
    /// Keep the layer even if some hexes are still not certified valid after the halvings
    /// (PillowReport::invalid_after counts them; for a caller that untangles afterwards).
    bool allow_invalid = false;
    /// After a layer that skipped patches, a second pass gives the skipped patches (with
    /// their new strips) a layer too, so that their hexes with two flat boundary faces are
    /// also relieved (the other patches then have no second layer). Off by default: on the
    /// cylinders it doubles the added hexes for the same worst SJ.
    bool second_layer = false;
    /// The second pass alone (for a caller that untangles between the passes): if >= 0, the
    /// patch rule is off and every boundary quad gets a new hex except the outer quads
    /// (top faces) of the hexes from this index on, i.e. of the first pass's layer.
    long layered_from = -1;
    int threads = 0;  ///< worker threads for the validity tests (0 = all); the result does not depend on it
};

/// What pillowBoundary() did.
struct PillowReport {
    long hexes_before = 0;        ///< hexes of the input
    long vertices_before = 0;     ///< vertices of the input
    long hexes_added = 0;         ///< new hexes (one per boundary quad); 0 if the mesh was left unchanged
    long vertices_added = 0;      ///< new vertices (one inner copy per boundary vertex)
    long boundary_patches = 0;    ///< patches of the boundary (bounded by feature edges)
    long skipped_patches = 0;     ///< patches that got no layer (PillowOptions::skip_patch_angle_deg)
    long skipped_quads = 0;       ///< boundary quads of hexes that were not certified valid: no new hex on them
    long second_layer_hexes = 0;  ///< of hexes_added, those of the second pass (PillowOptions::second_layer)
    long shrunk_vertices = 0;     ///< inner copies placed at less than the full depth
    double min_depth_fraction = 1;///< smallest depth used, relative to the full depth
    long invalid_before = 0;      ///< hexes of the input that were not certified valid
    long invalid_after = 0;       ///< hexes of the result that are not certified valid
    double seconds = 0;           ///< wall time
    bool success = true;          ///< false if the layer could not be placed validly (mesh unchanged)
    std::string message;          ///< why it failed; empty otherwise
};

/// Inserts one layer of hexes along the whole boundary of @p mesh (see the file comment);
/// new vertices are appended in the order of the boundary vertices' indices, new hexes in
/// the order of the boundary quads (by hex, then face in HexArcs::kHexFaces order).
/// @throws std::invalid_argument (with a message naming the cause) if @p mesh has
/// polyhedra, no hexes, a vertex index out of range, a hex with a repeated vertex, a quad
/// shared by more than two hexes, a boundary edge not in exactly two boundary quads, or a
/// boundary vertex where separate sheets of the boundary meet (non-manifold boundary).
PillowReport pillowBoundary(HexMesh& mesh, const PillowOptions& options = {});

} // namespace HexEx
