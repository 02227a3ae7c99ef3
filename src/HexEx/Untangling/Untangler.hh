#pragma once
/// @file Untangler.hh
/// @ingroup quality
/// Untangling of hex meshes: moves vertices so that every hexahedron is certified valid
/// (its Jacobian determinant positive on the whole element, classifyHexValidity(), not
/// only at its 8 corners), changing the mesh only near the invalid hexes.
///
/// Method: the regularised elliptic energy of Garanzha, Kaporin, Kudryavtseva, Protais,
/// Ray and Sokolov, "Foldover-free maps in 50 lines of code" (ACM TOG 40(4), 2021), summed
/// over the 8 corner tets of every hex near the invalid ones (EllipticEnergy.hh), is
/// minimised with L-BFGS (Lbfgs.hh) for a decreasing sequence of regularisation parameters
/// eps. Hexes positive at their corners but not certified valid get the energy of the
/// Jacobian at 27, then 125 points inside (hexSampledEnergy()). Only the vertices within
/// `rings` hex rings of an invalid hex move; if hexes stay invalid the ring count grows
/// (x4, twice) and then the whole mesh moves. A heavy tangle (more than global_fraction of
/// the hexes invalid) is untangled on the whole mesh from the start.
///
/// Boundary: with BoundaryMode::Surface, boundary vertices move in the tangent plane of
/// the given surface and are projected back onto it after every outer iteration; vertices
/// on sharp feature curves move along the curve, feature corners stay fixed
/// (SurfaceProjection.hh). With BoundaryMode::Fixed no boundary vertex moves. Vertices of
/// polyhedra (non-hex cells) never move.
///
/// Example:
/// ```
/// HexEx::HexMesh hm = HexEx::readHexMesh("folded.vtu");
/// HexEx::UntangleReport r = HexEx::untangleHexMesh(hm);   // boundary on hm's own boundary
/// if (!r.success) std::cerr << r.message << "\n";
/// ```

#include "../Mesh/HexMesh.hh"
#include "TriangleSurface.hh"

#include <string>

namespace HexEx {

/// How boundary vertices of the hex mesh may move.
enum class BoundaryMode {
    Surface,  ///< along the boundary surface (features kept, corners fixed)
    Fixed,    ///< not at all
};

/// Settings of untangleHexMesh().
struct UntangleOptions {
    BoundaryMode boundary = BoundaryMode::Surface;  ///< boundary vertex handling
    int threads = 0;               ///< worker threads for the energy (0 = all); the result does not depend on it
    int rings = 1;                 ///< hex rings around inverted hexes whose vertices move at first
    int max_outer_iterations = 60; ///< regularisation steps (eps updates) per attempt
    int max_lbfgs_iterations = 300;///< L-BFGS iterations per regularisation step
    /// After a neighbourhood is untangled: L-BFGS iterations at most on the corner energies
    /// to the power quality_power, moving the vertices of its hexes with a scaled Jacobian
    /// below quality_threshold (raises the worst scaled Jacobian; undone if it does not). 0: off.
    int quality_iterations = 10;
    double quality_power = 4;      ///< see quality_iterations
    double quality_threshold = 0.3;///< the quality iterations move the vertices of hexes with a scaled Jacobian below this
    double feature_angle_deg = 40; ///< surface edges with a larger normal angle are feature curves
    double theta = 1.0 / 128;      ///< weight of the volume term g in the energy (shape term f: 1 - theta)
    /// If hexes stay inverted with vertices on feature curves or corners, let those vertices
    /// slide on the surface and retry (the feature is rounded there); false keeps every feature.
    bool release_features = true;
    double on_surface_tolerance = 1e-6;  ///< relative to the bbox diagonal: vertices this close to a feature curve/corner are on it
    /// Work budget: at most max(min_work, work_per_hex * hexes) evaluations of one hex's
    /// energy in total (all attempts); bounds the cost when no untangled placement is found.
    double work_per_hex = 200;
    double min_work = 1e7;  ///< see work_per_hex
    /// If more than this fraction of the hexes is invalid at the start (a heavy tangle), the
    /// whole mesh is untangled at once instead of growing neighbourhoods of rings.
    double global_fraction = 0.25;
};

/// What untangleHexMesh() did. Scaled Jacobians are per hex (minimum over its corners).
struct UntangleReport {
    long hexes = 0;                    ///< hexes in the mesh
    long inverted_before = 0;          ///< hexes with a corner Jacobian <= 0 before
    long inverted_after = 0;           ///< and after
    long invalid_before = 0;           ///< hexes certified invalid before (J <= 0 somewhere in the hex, classifyHexValidity())
    long invalid_after = 0;            ///< and after
    long undecided_before = 0;         ///< hexes the certified test left undecided before
    long undecided_after = 0;          ///< and after
    double min_scaled_jacobian_before = 0;   ///< minimum scaled Jacobian before
    double mean_scaled_jacobian_before = 0;  ///< mean scaled Jacobian before
    double min_scaled_jacobian_after = 0;    ///< minimum scaled Jacobian after
    double mean_scaled_jacobian_after = 0;   ///< mean scaled Jacobian after
    long free_vertices = 0;            ///< vertices that were allowed to move (last attempt)
    long moved_vertices = 0;           ///< vertices whose position changed
    double max_displacement = 0;       ///< largest displacement / bbox diagonal
    double mean_displacement = 0;      ///< mean displacement of the moved vertices / bbox diagonal
    long released_feature_vertices = 0; ///< feature curve/corner vertices let slide on the surface (UntangleOptions::release_features)
    int attempts = 0;                  ///< neighbourhood sizes tried (rings 2, 4, 8, ...)
    int rings = 0;                     ///< ring count of the last attempt (-1: whole mesh)
    int outer_iterations = 0;          ///< regularisation steps in total
    int quality_iterations = 0;        ///< L-BFGS iterations of the quality steps (UntangleOptions::quality_iterations)
    int lbfgs_iterations = 0;          ///< L-BFGS iterations in total
    double seconds = 0;                ///< wall time
    bool success = true;               ///< certified valid: invalid_after == 0 and undecided_after == 0
    bool budget_exhausted = false;     ///< the work budget (UntangleOptions::work_per_hex) stopped the minimisation
    std::string message;               ///< why hexes remain invalid (empty on success)
};

/// Untangles @p mesh in place. @p surface is the surface boundary vertices stay on with
/// BoundaryMode::Surface (e.g. tetMeshBoundary() of the input tet mesh); if null, the
/// boundary of @p mesh itself (hexMeshBoundary()) is used. A mesh without inverted hexes is
/// returned unchanged.
/// @throws std::invalid_argument if a hex references a vertex out of range.
UntangleReport untangleHexMesh(HexMesh& mesh, const UntangleOptions& options = {},
                               const TriangleSurface* surface = nullptr);

} // namespace HexEx
