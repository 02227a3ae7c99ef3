/// @file HexMeshFunctions.cc
/// hexex._core functions on hex meshes: reading, writing and validation. Meshes travel as
/// (points float64 (k,3), hexes int32 (h,8), polyhedra list) triples.

#include "ArrayConversions.hh"
#include "Bindings.hh"

#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/IO/HexMeshWriters.hh>
#include <HexEx/Generators/Perturbation.hh>
#include <HexEx/Mesh/HexMeshCheck.hh>

#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <string>
#include <vector>

namespace HexExPython {

namespace {

/// Reads a hex mesh file; returns (points, hexes, polyhedra).
nb::tuple readHexMeshFile(const std::string& path) {
    HexEx::HexMesh hm;
    {
        nb::gil_scoped_release release;
        hm = HexEx::readHexMesh(path);
    }
    return hexMeshToArrays(std::move(hm));
}

/// Writes a hex mesh (`.vtu` data in the encoding named @p encoding); returns the writer's warnings.
std::vector<std::string> writeHexMeshFile(const std::string& path, const DoubleArray& points, const Int32Array& hexes,
                                          const nb::handle& polyhedra, const std::string& encoding) {
    const HexEx::VtuEncoding enc = HexEx::vtuEncodingFromName(encoding);
    const HexEx::HexMesh hm = hexMeshFromArrays(points, hexes, polyhedra);
    nb::gil_scoped_release release;
    return HexEx::writeHexMesh(path, hm, enc);
}

/// Validates a hex mesh; returns HexMeshCheckResult as a dict.
nb::dict validateHexMesh(const DoubleArray& points, const Int32Array& hexes, const nb::handle& polyhedra) {
    const HexEx::HexMesh hm = hexMeshFromArrays(points, hexes, polyhedra);
    HexEx::HexMeshCheckResult r;
    {
        nb::gil_scoped_release release;
        r = HexEx::checkHexMesh(hm);
    }
    nb::dict d;
    d["valid_all_hex"] = r.valid_all_hex;
    d["cells"] = r.cells;
    d["hexes"] = r.hexes;
    d["non_hex_cells"] = r.non_hex_cells;
    d["vertices"] = r.vertices;
    d["edges"] = r.edges;
    d["faces"] = r.faces;
    d["quads"] = r.quads;
    d["boundary_quads"] = r.boundary_quads;
    d["boundary_faces"] = r.boundary_faces;
    d["quads_shared_by_more_than_two"] = r.quads_shared_by_more_than_two;
    d["nonmanifold_boundary_edges"] = r.nonmanifold_boundary_edges;
    d["nonmanifold_boundary_vertices"] = r.nonmanifold_boundary_vertices;
    d["invalid_cells"] = r.invalid_cells;
    d["euler_characteristic"] = r.euler_characteristic;
    nb::dict q;
    q["min_scaled_jacobian"] = r.quality.min_scaled_jacobian;
    q["mean_scaled_jacobian"] = r.quality.mean_scaled_jacobian;
    q["inverted_hexes"] = r.quality.inverted_hexes;
    q["invalid_hexes"] = r.quality.invalid_hexes;
    q["undecided_hexes"] = r.quality.undecided_hexes;
    q["first_invalid_hex"] = r.quality.first_invalid_hex;
    q["certified_valid"] = r.quality.invalid_hexes == 0 && r.quality.undecided_hexes == 0;
    d["quality"] = q;
    return d;
}

} // namespace

void bindHexMeshFunctions(nb::module_& m) {
    m.def("read_hex_mesh", &readHexMeshFile, nb::arg("path"),
          "Reads .vtu/.vtk/.ovm/.ovmb/.mesh; returns (points, hexes, polyhedra).");
    m.def("write_hex_mesh", &writeHexMeshFile, nb::arg("path"), nb::arg("points"), nb::arg("hexes"),
          nb::arg("polyhedra"), nb::arg("encoding"), "Writes a hex mesh (format by extension); returns warnings.");
    m.def("validate", &validateHexMesh, nb::arg("points"), nb::arg("hexes"), nb::arg("polyhedra"),
          "Checks a hex mesh (HexMeshCheck); returns a dict of counts.");
    m.def(
        "perturb_hex_mesh",
        [](const DoubleArray& points, const Int32Array& hexes, const nb::handle& polyhedra, double fraction,
           unsigned seed) {
            HexEx::HexMesh hm = hexMeshFromArrays(points, hexes, polyhedra);
            HexEx::HexPerturbStats stats;
            HexEx::perturbHexMesh(hm, fraction, seed, &stats);
            nb::dict d;
            d["vertices"] = stats.vertices;
            d["interior_vertices"] = stats.interior_vertices;
            d["moved_vertices"] = stats.moved_vertices;
            d["inverted_before"] = stats.inverted_before;
            d["inverted_after"] = stats.inverted_after;
            d["max_displacement"] = stats.max_displacement;
            nb::tuple mesh = hexMeshToArrays(std::move(hm));
            return nb::make_tuple(mesh[0], mesh[1], mesh[2], d);
        },
        nb::arg("points"), nb::arg("hexes"), nb::arg("polyhedra"), nb::arg("fraction"), nb::arg("seed"),
        "Tangles a hex mesh (HexEx::perturbHexMesh: interior vertices moved by up to fraction x their "
        "mean edge length, boundary bit for bit); returns (points, hexes, polyhedra, stats).");
}

} // namespace HexExPython
