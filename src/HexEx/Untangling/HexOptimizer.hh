#pragma once
/// @file HexOptimizer.hh
/// @ingroup quality
/// Quality optimisation of valid hex meshes: raises the minimum scaled Jacobian (SJ) of the
/// whole mesh while every hex stays certified valid (classifyHexValidity()), boundary
/// vertices stay on a given surface and its sharp features are kept.
///
/// Method (see Documentation/algorithm.md, "Mesh optimisation"):
///  1. Global phase: the smooth max-min objective F = sum over the corners c of the hexes
///     exp(k (s0 - SJ_c)) (a log-sum-exp soft minimum of the corner scaled Jacobians, s0 the
///     current minimum) is minimised by L-BFGS over the vertices of the hexes whose SJ is
///     below the current minimum plus OptimizeOptions::window, boundary vertices in the
///     tangent plane of the surface, feature vertices along their curve. A block of
///     iterations is accepted only if, after projecting boundary vertices back, every hex it
///     touched is certified valid and the worst SJ has not decreased; otherwise it is undone
///     and k grows (the objective gets closer to the minimum itself).
///  2. Local phase: vertex-by-vertex moves on the vertices of the worst hexes, along the
///     gradient of the soft minimum of the corners around the vertex, accepted only if the
///     smallest SJ of the hexes at the vertex rises and they stay certified valid.
///
/// Guarantees: the worst SJ of the mesh never decreases after the boundary vertices are put
/// on the surface (step 0, needed only when the surface differs from the mesh boundary); no
/// accepted step makes a Valid hex non-valid; corners stay at their surface corner, curve
/// vertices on their own curve, surface vertices on their own patch (projections walk from
/// the vertex's last triangle, see LocalSurfaceProjection). Results do not depend on the
/// thread count.
///
/// Example:
/// ```
/// HexEx::HexMesh hm = HexEx::readHexMesh("mesh.vtu");
/// HexEx::OptimizeOptions o;
/// o.target = 0.5;
/// HexEx::OptimizeReport r = HexEx::optimizeHexMesh(hm, o);   // on hm's own boundary
/// std::cout << r.min_scaled_jacobian_before << " -> " << r.min_scaled_jacobian_after << "\n";
/// ```

#include "../Mesh/HexMesh.hh"
#include "TriangleSurface.hh"
#include "Untangler.hh"

#include <string>
#include <vector>

namespace HexEx {

/// Settings of optimizeHexMesh().
struct OptimizeOptions {
    BoundaryMode boundary = BoundaryMode::Surface;  ///< boundary vertices on the surface, or fixed
    int threads = 0;                 ///< worker threads (0 = all); the result does not depend on it
    double target = 0.9;             ///< stop once the worst scaled Jacobian reaches this
    double feature_angle_deg = 40;   ///< surface edges sharper than this are feature curves
    int max_global_blocks = 40;      ///< L-BFGS blocks of the global phase at most (0: no global phase)
    int block_iterations = 25;       ///< L-BFGS iterations per block
    int max_local_passes = 60;       ///< passes of the local phase at most (0: no local phase)
    double window = 0.35;            ///< the global phase moves the vertices of hexes with SJ below min + window
    double local_window = 0.05;      ///< the local phase moves the vertices of hexes with SJ below min + local_window
    /// Boundary vertices closer than this (relative to the bounding-box diagonal, or 10 % of
    /// their shortest edge if larger) to a surface corner or curve are held on it.
    double feature_tolerance = 1e-6;
    /// Before optimising, insert one layer of hexes along the whole boundary
    /// (pillowBoundary(), BoundaryPillowing.hh): removes the bound sin(dihedral angle) on hexes
    /// with two boundary faces meeting almost flat, at the cost of one hex per boundary quad.
    /// Hexes left not certified valid by it are untangled (untangleHexMesh()) before the
    /// optimisation. Needs an all-hex mesh with a manifold boundary.
    bool pillow = false;
    double pillow_depth = 0.3;  ///< PillowOptions::depth of the layer (fraction of the local edge length)
    double pillow_skip_patch_angle_deg = 150;  ///< PillowOptions::skip_patch_angle_deg (180: a layer on every patch)
    /// After the first layer (and the untangling it may need), give the patches it skipped a
    /// layer too (PillowOptions::layered_from): relieves their hexes with two flat boundary
    /// faces at the cost of more hexes.
    bool pillow_second_layer = false;
    /// After the layer (and the untangling it may need), split the hexes of boundary quads
    /// with a flat corner (above 150 degrees) between two feature edges by a local pillow
    /// (splitFlatFeatureCorners(), FlatCornerSplitting.hh): removes the bound sin(corner
    /// angle) that the layer keeps there. Its hexes and vertices count in pillowed_hexes and
    /// pillow_vertices.
    bool pillow_flat_corners = true;
    /// The global phase hands over to the local phase after the first accepted block over
    /// more than 2,000 hexes that raises the worst scaled Jacobian by less than this (0:
    /// never); if the local phase then gains less than this too, the global phase resumes
    /// with the blocks left. On a large mesh the worst hexes are then a few local spots,
    /// which the local phase's vertex moves raise at a fraction of the cost of more global
    /// blocks over thousands of hexes. Small meshes are not affected.
    double handover_gain = 0.005;
};

/// What optimizeHexMesh() did. Scaled Jacobians are per hex (minimum over its 8 corners).
struct OptimizeReport {
    long hexes = 0;                          ///< hexes in the mesh
    double min_scaled_jacobian_before = 0;   ///< worst SJ of the input
    double mean_scaled_jacobian_before = 0;  ///< mean SJ of the input
    double min_scaled_jacobian_projected = 0;///< worst SJ after step 0 (boundary vertices put on the surface)
    double min_scaled_jacobian_after = 0;    ///< worst SJ of the result
    double mean_scaled_jacobian_after = 0;   ///< mean SJ of the result
    long invalid_before = 0;                 ///< hexes not certified valid (invalid or undecided) before
    long invalid_after = 0;                  ///< and after
    /// Counts of hexes per SJ bin before: bin i covers [-1 + 0.1 i, -0.9 + 0.1 i) (20 bins
    /// over [-1, 1]; SJ = 1 goes to the last bin).
    std::vector<long> histogram_before;
    std::vector<long> histogram_after;  ///< the same bins after
    long free_vertices = 0;                  ///< vertices allowed to move (interior, surface, curve)
    long surface_vertices = 0;               ///< boundary vertices held on a patch of the surface
    long curve_vertices = 0;                 ///< boundary vertices held on a feature curve
    long corner_vertices = 0;                ///< boundary vertices held at a feature corner (fixed)
    long fixed_vertices = 0;                 ///< vertices that do not move (fixed boundary, polyhedra, no surface)
    long unprojected_vertices = 0;           ///< boundary vertices that step 0 could not put on the surface without invalidating a hex (kept fixed)
    long feature_curves = 0;                 ///< feature curves of the surface
    long feature_corners = 0;                ///< feature corners of the surface
    double diagonal = 0;                     ///< bounding-box diagonal of the input
    double max_surface_distance = 0;         ///< largest distance of a boundary vertex to the surface
    double mean_surface_distance = 0;        ///< mean distance of the boundary vertices to the surface
    double max_feature_distance = 0;         ///< largest distance of a curve (corner) vertex to its curve (corner)
    double mean_feature_distance = 0;        ///< mean of those distances
    int global_blocks = 0;                   ///< L-BFGS blocks run
    int accepted_blocks = 0;                 ///< of which accepted
    int lbfgs_iterations = 0;                ///< L-BFGS iterations in total
    int local_passes = 0;                    ///< passes of the local phase
    long local_moves = 0;                    ///< accepted vertex moves of the local phase
    double seconds = 0;                      ///< wall time
    bool reached_target = false;             ///< min_scaled_jacobian_after >= OptimizeOptions::target
    long pillowed_hexes = 0;                 ///< hexes added by OptimizeOptions::pillow (one per boundary quad, 5 per hex split at a flat corner; 0 without)
    long pillow_vertices = 0;                ///< vertices added by the pillowing (one per boundary vertex, 8 per split hex)
    double min_scaled_jacobian_pillowed = 0; ///< worst SJ right after the pillowing (and the untangling it may need)
    long pillow_invalid = 0;                 ///< hexes not certified valid right after the pillowing (the untangler then runs)
    /// Hexes removed before the pillowing: a flap outside the surface that held hexes not
    /// certified valid (hexesOutsideSurface(), FoldedBoundary.hh); `hexes` is then
    /// input - trimmed_hexes + pillowed_hexes. 0 without OptimizeOptions::pillow.
    long trimmed_hexes = 0;
    bool success = true;                     ///< false if the input was refused (see message)
    std::string message;                     ///< why the input was refused, or notes; empty if none
};

/// Optimises @p mesh in place (see the file comment). @p surface is the surface boundary
/// vertices stay on with BoundaryMode::Surface; if null, the boundary of @p mesh itself
/// (hexMeshBoundary()). A mesh with an inverted hex (a corner Jacobian <= 0) is refused:
/// the report has success = false and a message, the mesh is unchanged (untangle it first).
/// Hexes that are not certified valid although their corners are positive may stay; they
/// are not counted as touched-and-valid, and every hex that was Valid stays Valid.
/// With OptimizeOptions::pillow the mesh first gets a boundary layer (hexes and vertices
/// appended, see pillowBoundary()); `hexes` then counts the result's hexes.
/// @throws std::invalid_argument if a hex references a vertex out of range, or, with
/// OptimizeOptions::pillow, the mesh is not all-hex or its boundary not manifold.
OptimizeReport optimizeHexMesh(HexMesh& mesh, const OptimizeOptions& options = {},
                               const TriangleSurface* surface = nullptr);

/// Counts of @p sj values in 20 bins over [-1, 1] (see OptimizeReport::histogram_before).
std::vector<long> scaledJacobianHistogram(const std::vector<double>& sj);

} // namespace HexEx
