/// @file MapFunctions.cc
/// hexex._core functions on tet meshes with integer-grid maps: I/O, generators,
/// perturbation and statistics. Maps travel as (points, tets, params) arrays.

#include "ArrayConversions.hh"
#include "Bindings.hh"

#include <HexEx/Generators/Generators.hh>
#include <HexEx/Generators/Perturbation.hh>
#include <HexEx/IO/HexExFile.hh>
#include <HexEx/IO/MapStatistics.hh>
#include <HexEx/IO/TetMeshInput.hh>

#include <nanobind/stl/string.h>

#include <stdexcept>
#include <string>

namespace HexExPython {

namespace {

/// Largest generated mesh (tets), as in `hexex generate`: refused before allocating.
constexpr double kMaxGeneratedTets = 5e7;

/// Throws std::invalid_argument unless a generator would make at most kMaxGeneratedTets tets.
void checkGeneratedSize(double tets) {
    if (tets > kMaxGeneratedTets)
        throw std::invalid_argument("mesh too large (" + std::to_string(static_cast<long long>(tets)) +
                                    " tets; at most 50000000)");
}

/// Reads a map file; returns (points, tets, params, warnings).
nb::tuple readMap(const std::string& path) {
    HexEx::ReadReport rr;
    HexEx::ParametrizedTetMesh pm;
    {
        nb::gil_scoped_release release;
        pm = HexEx::readParametrizedTetMesh(path, &rr);
    }
    nb::tuple arrays = mapToArrays(pm);
    nb::list warnings;
    for (const std::string& w : rr.warnings) warnings.append(w);
    return nb::make_tuple(arrays[0], arrays[1], arrays[2], warnings);
}

/// Writes a map as `.hexex`.
void writeMap(const std::string& path, const DoubleArray& points, const nb::handle& tets, const DoubleArray& params) {
    const TetIndices idx = tetIndices(tets);
    nb::gil_scoped_release release;
    HexEx::writeHexExFile(path, toTetMesh(points, idx, params));
}

/// Applies @p change to a copy of the map and returns the changed arrays.
template <class Change>
nb::tuple changedMap(const DoubleArray& points, const nb::handle& tets, const DoubleArray& params, Change&& change) {
    const TetIndices idx = tetIndices(tets);
    HexEx::ParametrizedTetMesh pm;
    {
        nb::gil_scoped_release release;
        pm = toTetMesh(points, idx, params);
        change(pm);
    }
    return mapToArrays(pm);
}

/// Summary statistics of a map as a dict.
nb::dict mapStatistics(const DoubleArray& points, const nb::handle& tets, const DoubleArray& params) {
    const TetIndices idx = tetIndices(tets);
    HexEx::MapStatistics s;
    {
        nb::gil_scoped_release release;
        s = HexEx::computeMapStatistics(toTetMesh(points, idx, params));
    }
    nb::dict d;
    d["vertices"] = s.vertices;
    d["tets"] = s.tets;
    d["boundary_faces"] = s.boundary_faces;
    d["flipped_tets"] = s.flipped_tets;
    d["degenerate_tets"] = s.degenerate_tets;
    d["parametric_volume"] = s.parametric_volume;
    d["param_bbox_min"] = nb::make_tuple(s.param_bbox_min[0], s.param_bbox_min[1], s.param_bbox_min[2]);
    d["param_bbox_max"] = nb::make_tuple(s.param_bbox_max[0], s.param_bbox_max[1], s.param_bbox_max[2]);
    return d;
}

} // namespace

void bindMapFunctions(nb::module_& m) {
    m.def("read_map", &readMap, nb::arg("path"), "Reads .hexex or .ovm; returns (points, tets, params, warnings).");
    m.def("write_map", &writeMap, nb::arg("path"), nb::arg("points"), nb::arg("tets"), nb::arg("params"),
          "Writes a map as .hexex.");
    m.def("map_statistics", &mapStatistics, nb::arg("points"), nb::arg("tets"), nb::arg("params"),
          "Counts and measures of a map as a dict.");
    m.def(
        "generate_cube",
        [](int n, int scale) {
            checkGeneratedSize(6.0 * n * n * n);
            HexEx::ParametrizedTetMesh pm;
            {
                nb::gil_scoped_release release;
                pm = HexEx::generateCube(n, scale);
            }
            return mapToArrays(pm);
        },
        nb::arg("n"), nb::arg("scale"), "Unit cube of 6 n^3 tets with the map scale * position.");
    m.def(
        "generate_cylinder",
        [](int valence, int radius, int height, int n, int m) {
            checkGeneratedSize(6.0 * valence * n * n * m);
            HexEx::ParametrizedTetMesh pm;
            {
                nb::gil_scoped_release release;
                pm = HexEx::generateCylinder(valence, radius, height, n, m);
            }
            return mapToArrays(pm);
        },
        nb::arg("valence"), nb::arg("radius"), nb::arg("height"), nb::arg("n"), nb::arg("m"),
        "Cylinder around a singular edge of the given valence.");
    m.def(
        "generate_ring",
        [](int length, int width, int height, int nu, int nv, int nw) {
            checkGeneratedSize(6.0 * nu * nv * nw);
            HexEx::ParametrizedTetMesh pm;
            {
                nb::gil_scoped_release release;
                pm = HexEx::generateRing(length, width, height, nu, nv, nw);
            }
            return mapToArrays(pm);
        },
        nb::arg("length"), nb::arg("width"), nb::arg("height"), nb::arg("nu"), nb::arg("nv"), nb::arg("nw"),
        "Ring periodic in the first parameter (translation at the seam).");
    m.def(
        "generate_twisted_ring",
        [](int length, int width, int nu, int nv) {
            checkGeneratedSize(6.0 * nu * nv * nv);
            HexEx::ParametrizedTetMesh pm;
            {
                nb::gil_scoped_release release;
                pm = HexEx::generateTwistedRing(length, width, nu, nv);
            }
            return mapToArrays(pm);
        },
        nb::arg("length"), nb::arg("width"), nb::arg("nu"), nb::arg("nv"),
        "Square ring glued with a quarter turn at the seam.");
    m.def(
        "random_charts",
        [](const DoubleArray& points, const nb::handle& tets, const DoubleArray& params, unsigned seed) {
            return changedMap(points, tets, params,
                              [&](HexEx::ParametrizedTetMesh& pm) { HexEx::applyRandomChartTransforms(pm, seed); });
        },
        nb::arg("points"), nb::arg("tets"), nb::arg("params"), nb::arg("seed"),
        "Re-expresses every tet in a random grid chart.");
    m.def(
        "parameter_noise",
        [](const DoubleArray& points, const nb::handle& tets, const DoubleArray& params, double amplitude,
           unsigned seed) {
            if (!(amplitude >= 0 && amplitude <= 1e6))
                throw std::invalid_argument("amplitude must be in [0, 1e6], got " + std::to_string(amplitude));
            return changedMap(points, tets, params,
                              [&](HexEx::ParametrizedTetMesh& pm) { HexEx::applyParameterNoise(pm, amplitude, seed); });
        },
        nb::arg("points"), nb::arg("tets"), nb::arg("params"), nb::arg("amplitude"), nb::arg("seed"),
        "Adds independent uniform noise to every corner parameter.");
    m.def(
        "perturb",
        [](const DoubleArray& points, const nb::handle& tets, const DoubleArray& params, double amplitude,
           unsigned seed) {
            HexEx::PerturbStats stats;
            nb::tuple arrays = changedMap(points, tets, params, [&](HexEx::ParametrizedTetMesh& pm) {
                HexEx::perturbParameters(pm, amplitude, seed, &stats);
            });
            nb::dict d;
            d["vertices"] = stats.vertices;
            d["moved_vertices"] = stats.moved_vertices;
            d["boundary_vertices"] = stats.boundary_vertices;
            d["singular_vertices"] = stats.singular_vertices;
            d["fixed_vertices"] = stats.fixed_vertices;
            d["max_displacement"] = stats.max_displacement;
            return nb::make_tuple(arrays[0], arrays[1], arrays[2], d);
        },
        nb::arg("points"), nb::arg("tets"), nb::arg("params"), nb::arg("amplitude"), nb::arg("seed"),
        "Consistent per-vertex perturbation of the map (paper 5.1); returns (points, tets, params, stats).");
}

} // namespace HexExPython
