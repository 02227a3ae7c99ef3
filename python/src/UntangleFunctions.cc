/// @file UntangleFunctions.cc
/// hexex._core.untangle: HexEx::untangleHexMesh() on a hex mesh given as arrays, with an
/// optional boundary surface (points, triangles).

#include "ArrayConversions.hh"
#include "Bindings.hh"
#include "UntangleReportDict.hh"

#include <HexEx/Untangling/Untangler.hh>

#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>

#include <optional>
#include <stdexcept>
#include <string>

namespace HexExPython {

nb::dict untangleReportToDict(const HexEx::UntangleReport& r) {
    nb::dict d;
    d["hexes"] = r.hexes;
    d["inverted_before"] = r.inverted_before;
    d["inverted_after"] = r.inverted_after;
    d["invalid_before"] = r.invalid_before;
    d["invalid_after"] = r.invalid_after;
    d["undecided_before"] = r.undecided_before;
    d["undecided_after"] = r.undecided_after;
    d["min_scaled_jacobian_before"] = r.min_scaled_jacobian_before;
    d["mean_scaled_jacobian_before"] = r.mean_scaled_jacobian_before;
    d["min_scaled_jacobian_after"] = r.min_scaled_jacobian_after;
    d["mean_scaled_jacobian_after"] = r.mean_scaled_jacobian_after;
    d["free_vertices"] = r.free_vertices;
    d["moved_vertices"] = r.moved_vertices;
    d["max_displacement"] = r.max_displacement;
    d["mean_displacement"] = r.mean_displacement;
    d["released_feature_vertices"] = r.released_feature_vertices;
    d["attempts"] = r.attempts;
    d["rings"] = r.rings;
    d["outer_iterations"] = r.outer_iterations;
    d["lbfgs_iterations"] = r.lbfgs_iterations;
    d["quality_iterations"] = r.quality_iterations;
    d["seconds"] = r.seconds;
    d["success"] = r.success;
    d["budget_exhausted"] = r.budget_exhausted;
    d["message"] = r.message;
    return d;
}

namespace {

/// Untangles a copy of the mesh; returns (points, hexes, polyhedra, report dict).
nb::tuple untangle(const DoubleArray& points, const Int32Array& hexes, const nb::handle& polyhedra,
                   const std::optional<DoubleArray>& surface_points, const std::optional<Int32Array>& surface_triangles,
                   bool fixed_boundary, int threads, int rings, double feature_angle, bool keep_features,
                   int quality_iterations) {
    HexEx::HexMesh hm = hexMeshFromArrays(points, hexes, polyhedra);
    HexEx::TriangleSurface surface;
    const bool has_surface = surfaceFromArrays(surface_points, surface_triangles, surface);
    HexEx::UntangleOptions opt;
    opt.boundary = fixed_boundary ? HexEx::BoundaryMode::Fixed : HexEx::BoundaryMode::Surface;
    opt.threads = threads;
    opt.rings = rings;
    opt.feature_angle_deg = feature_angle;
    opt.release_features = !keep_features;
    opt.quality_iterations = quality_iterations;
    HexEx::UntangleReport r;
    {
        nb::gil_scoped_release release;
        r = HexEx::untangleHexMesh(hm, opt, has_surface ? &surface : nullptr);
    }
    nb::tuple mesh = hexMeshToArrays(std::move(hm));
    return nb::make_tuple(mesh[0], mesh[1], mesh[2], untangleReportToDict(r));
}

} // namespace

void bindUntangleFunctions(nb::module_& m) {
    m.def("untangle", &untangle, nb::arg("points"), nb::arg("hexes"), nb::arg("polyhedra"),
          nb::arg("surface_points").none(), nb::arg("surface_triangles").none(), nb::arg("fixed_boundary"),
          nb::arg("threads"), nb::arg("rings"), nb::arg("feature_angle"), nb::arg("keep_features"),
          nb::arg("quality_iterations"),
          "Untangles a hex mesh (HexEx::untangleHexMesh); returns (points, hexes, polyhedra, report dict).");
}

} // namespace HexExPython
