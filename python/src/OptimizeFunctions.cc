/// @file OptimizeFunctions.cc
/// hexex._core.optimize: HexEx::optimizeHexMesh() on a hex mesh given as arrays, with an
/// optional boundary surface (points, triangles).

#include "ArrayConversions.hh"
#include "Bindings.hh"
#include "UntangleReportDict.hh"

#include <HexEx/Untangling/HexOptimizer.hh>
#include <HexEx/Untangling/UntangleWithRepair.hh>

#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>

#include <optional>
#include <stdexcept>
#include <string>

namespace HexExPython {

namespace {

/// A list of the counts of a histogram.
nb::list histogramToList(const std::vector<long>& h) {
    nb::list l;
    for (const long c : h) l.append(c);
    return l;
}

/// The report as a dict with the field names of HexEx::OptimizeReport.
nb::dict optimizeReportToDict(const HexEx::OptimizeReport& r) {
    nb::dict d;
    d["hexes"] = r.hexes;
    d["min_scaled_jacobian_before"] = r.min_scaled_jacobian_before;
    d["mean_scaled_jacobian_before"] = r.mean_scaled_jacobian_before;
    d["min_scaled_jacobian_projected"] = r.min_scaled_jacobian_projected;
    d["min_scaled_jacobian_after"] = r.min_scaled_jacobian_after;
    d["mean_scaled_jacobian_after"] = r.mean_scaled_jacobian_after;
    d["invalid_before"] = r.invalid_before;
    d["invalid_after"] = r.invalid_after;
    d["histogram_before"] = histogramToList(r.histogram_before);
    d["histogram_after"] = histogramToList(r.histogram_after);
    d["free_vertices"] = r.free_vertices;
    d["surface_vertices"] = r.surface_vertices;
    d["curve_vertices"] = r.curve_vertices;
    d["corner_vertices"] = r.corner_vertices;
    d["fixed_vertices"] = r.fixed_vertices;
    d["unprojected_vertices"] = r.unprojected_vertices;
    d["feature_curves"] = r.feature_curves;
    d["feature_corners"] = r.feature_corners;
    d["diagonal"] = r.diagonal;
    d["max_surface_distance"] = r.max_surface_distance;
    d["mean_surface_distance"] = r.mean_surface_distance;
    d["max_feature_distance"] = r.max_feature_distance;
    d["mean_feature_distance"] = r.mean_feature_distance;
    d["global_blocks"] = r.global_blocks;
    d["accepted_blocks"] = r.accepted_blocks;
    d["lbfgs_iterations"] = r.lbfgs_iterations;
    d["local_passes"] = r.local_passes;
    d["local_moves"] = r.local_moves;
    d["seconds"] = r.seconds;
    d["pillowed_hexes"] = r.pillowed_hexes;
    d["pillow_vertices"] = r.pillow_vertices;
    d["trimmed_hexes"] = r.trimmed_hexes;
    d["min_scaled_jacobian_pillowed"] = r.min_scaled_jacobian_pillowed;
    d["pillow_invalid"] = r.pillow_invalid;
    d["reached_target"] = r.reached_target;
    d["success"] = r.success;
    d["message"] = r.message;
    return d;
}

/// Optimises a copy of the mesh; returns (points, hexes, polyhedra, report dict).
nb::tuple optimize(const DoubleArray& points, const Int32Array& hexes, const nb::handle& polyhedra,
                   const std::optional<DoubleArray>& surface_points, const std::optional<Int32Array>& surface_triangles,
                   bool fixed_boundary, int threads, double target, double feature_angle, int max_blocks,
                   int max_passes, bool pillow) {
    HexEx::HexMesh hm = hexMeshFromArrays(points, hexes, polyhedra);
    HexEx::TriangleSurface surface;
    const bool has_surface = surfaceFromArrays(surface_points, surface_triangles, surface);
    HexEx::OptimizeOptions opt;
    opt.boundary = fixed_boundary ? HexEx::BoundaryMode::Fixed : HexEx::BoundaryMode::Surface;
    opt.threads = threads;
    opt.target = target;
    opt.feature_angle_deg = feature_angle;
    opt.max_global_blocks = max_blocks;
    opt.max_local_passes = max_passes;
    opt.pillow = pillow;
    HexEx::OptimizeReport r;
    {
        nb::gil_scoped_release release;
        r = HexEx::optimizeHexMesh(hm, opt, has_surface ? &surface : nullptr);
    }
    nb::tuple mesh = hexMeshToArrays(std::move(hm));
    return nb::make_tuple(mesh[0], mesh[1], mesh[2], optimizeReportToDict(r));
}

/// HexEx::untangleWithRepair() on a copy of the mesh, boundary on the given surface:
/// untangling, then optimisation if @p optimize, and the pillowing repair by @p pillow
/// (0 never, 1 if needed, 2 always). Returns (points, hexes, polyhedra, untangle report,
/// optimize report or None, note).
nb::tuple untangleWithRepair(const DoubleArray& points, const Int32Array& hexes, const nb::handle& polyhedra,
                             const std::optional<DoubleArray>& surface_points,
                             const std::optional<Int32Array>& surface_triangles, int threads, bool optimize,
                             int pillow) {
    if (pillow < 0 || pillow > 2) throw std::invalid_argument("pillow policy must be 0, 1 or 2");
    HexEx::HexMesh hm = hexMeshFromArrays(points, hexes, polyhedra);
    HexEx::TriangleSurface surface;
    const bool has_surface = surfaceFromArrays(surface_points, surface_triangles, surface);
    HexEx::RepairOptions opt;
    opt.untangle.threads = threads;
    opt.optimize.threads = threads;
    opt.optimize_quality = optimize;
    opt.pillow = pillow == 0 ? HexEx::PillowPolicy::Never
                             : (pillow == 1 ? HexEx::PillowPolicy::IfNeeded : HexEx::PillowPolicy::Always);
    HexEx::RepairReport r;
    {
        nb::gil_scoped_release release;
        r = HexEx::untangleWithRepair(hm, opt, has_surface ? &surface : nullptr);
    }
    nb::tuple mesh = hexMeshToArrays(std::move(hm));
    nb::object o = r.optimized ? nb::object(optimizeReportToDict(r.optimize)) : nb::none();
    return nb::make_tuple(mesh[0], mesh[1], mesh[2], untangleReportToDict(r.untangle), o, r.note);
}

} // namespace

void bindOptimizeFunctions(nb::module_& m) {
    m.def("optimize", &optimize, nb::arg("points"), nb::arg("hexes"), nb::arg("polyhedra"),
          nb::arg("surface_points").none(), nb::arg("surface_triangles").none(), nb::arg("fixed_boundary"),
          nb::arg("threads"), nb::arg("target"), nb::arg("feature_angle"), nb::arg("max_blocks"), nb::arg("max_passes"),
          nb::arg("pillow"),
          "Raises the worst scaled Jacobian of a hex mesh (HexEx::optimizeHexMesh); returns (points, hexes, "
          "polyhedra, report dict).");
    m.def("untangle_with_repair", &untangleWithRepair, nb::arg("points"), nb::arg("hexes"), nb::arg("polyhedra"),
          nb::arg("surface_points").none(), nb::arg("surface_triangles").none(), nb::arg("threads"),
          nb::arg("optimize"), nb::arg("pillow"),
          "Untangles, optimises if asked, repairs with the boundary layer as the pillow policy says "
          "(HexEx::untangleWithRepair); returns (points, hexes, polyhedra, untangle report, optimize report "
          "or None, note).");
}

} // namespace HexExPython
