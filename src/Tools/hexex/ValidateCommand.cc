/// @file ValidateCommand.cc
/// `hexex validate MESH [--json]`: reads a hex mesh (.vtu, .vtk, .ovm, .mesh) and prints the
/// result of HexEx::checkHexMesh(). Exit status 0 if the mesh is a valid all-hex mesh, 3 if
/// it was read but is not, 2 on bad input or usage.

#include "Commands.hh"

#include <HexEx/Core/Error.hh>
#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/Mesh/HexMeshCheck.hh>

#include <charconv>
#include <cmath>
#include <iostream>
#include <string>

namespace HexExTool {

namespace {

/// Shortest round-trip text of a double; "null" for non-finite values.
std::string numText(double x) {
    if (!std::isfinite(x)) return "null";
    char buf[64];
    const auto res = std::to_chars(buf, buf + sizeof buf, x);
    return std::string(buf, res.ptr);
}

const char* kValidateUsage =
    "usage: hexex validate MESH [--json]\n"
    "  MESH  hex mesh file: .vtu, .vtk, .ovm or .mesh\n"
    "exit status: 0 valid all-hex mesh, 3 readable but not a valid all-hex mesh, 2 bad input or usage\n";

} // namespace

int runValidate(const Args& args) {
    std::string input;
    bool json = false;
    for (const auto& a : args) {
        if (a == "--json") {
            json = true;
        } else if (a == "-h" || a == "--help") {
            std::cout << kValidateUsage;
            return 0;
        } else if (!a.empty() && a[0] == '-') {
            std::cerr << "hexex validate: unknown option '" << a << "'\n" << kValidateUsage;
            return 2;
        } else if (input.empty()) {
            input = a;
        } else {
            std::cerr << "hexex validate: more than one input file given\n" << kValidateUsage;
            return 2;
        }
    }
    if (input.empty()) {
        std::cerr << "hexex validate: no input file given\n" << kValidateUsage;
        return 2;
    }

    HexEx::HexMesh mesh;
    try {
        mesh = HexEx::readHexMesh(input);
    } catch (const HexEx::InputError& e) {
        std::cerr << "hexex validate: error: " << e.what() << "\n";
        return 2;
    }
    const HexEx::HexMeshCheckResult r = HexEx::checkHexMesh(mesh);

    if (json) {
        std::cout << "{\n"
                  << "  \"cells\": " << r.cells << ",\n"
                  << "  \"hexes\": " << r.hexes << ",\n"
                  << "  \"non_hex_cells\": " << r.non_hex_cells << ",\n"
                  << "  \"vertices\": " << r.vertices << ",\n"
                  << "  \"edges\": " << r.edges << ",\n"
                  << "  \"faces\": " << r.faces << ",\n"
                  << "  \"quads\": " << r.quads << ",\n"
                  << "  \"boundary_quads\": " << r.boundary_quads << ",\n"
                  << "  \"boundary_faces\": " << r.boundary_faces << ",\n"
                  << "  \"quads_shared_by_more_than_two\": " << r.quads_shared_by_more_than_two << ",\n"
                  << "  \"nonmanifold_boundary_edges\": " << r.nonmanifold_boundary_edges << ",\n"
                  << "  \"invalid_cells\": " << r.invalid_cells << ",\n"
                  << "  \"euler_characteristic\": " << r.euler_characteristic << ",\n"
                  << "  \"min_scaled_jacobian\": " << numText(r.quality.min_scaled_jacobian) << ",\n"
                  << "  \"mean_scaled_jacobian\": " << numText(r.quality.mean_scaled_jacobian) << ",\n"
                  << "  \"inverted_hexes\": " << r.quality.inverted_hexes << ",\n"
                  << "  \"valid_all_hex\": " << (r.valid_all_hex ? "true" : "false") << "\n"
                  << "}\n";
    } else {
        std::cout << "file:                          " << input << "\n"
                  << "cells:                         " << r.cells << "\n"
                  << "hexes:                         " << r.hexes << "\n"
                  << "non-hex cells:                 " << r.non_hex_cells << "\n"
                  << "vertices:                      " << r.vertices << "\n"
                  << "edges:                         " << r.edges << "\n"
                  << "faces:                         " << r.faces << "\n"
                  << "quads:                         " << r.quads << "\n"
                  << "boundary quads:                " << r.boundary_quads << "\n"
                  << "boundary faces:                " << r.boundary_faces << "\n"
                  << "faces shared by > 2 cells:     " << r.quads_shared_by_more_than_two << "\n"
                  << "non-manifold boundary edges:   " << r.nonmanifold_boundary_edges << "\n"
                  << "invalid cells:                 " << r.invalid_cells << "\n"
                  << "Euler characteristic:          " << r.euler_characteristic << "\n"
                  << "min scaled Jacobian:           " << numText(r.quality.min_scaled_jacobian) << "\n"
                  << "mean scaled Jacobian:          " << numText(r.quality.mean_scaled_jacobian) << "\n"
                  << "inverted hexes:                " << r.quality.inverted_hexes << "\n"
                  << "valid all-hex:                 " << (r.valid_all_hex ? "yes" : "no") << "\n";
    }
    return r.valid_all_hex ? 0 : 3;
}

} // namespace HexExTool
