/// @file ValidateCommand.cc
/// `hexex validate MESH [--json] [--certified]`: reads a hex mesh (.vtu, .vtk, .ovm, .ovmb,
/// .mesh) and prints the result of HexEx::checkHexMesh(), with the certified validity counts
/// of HexValidity.hh. Exit status 0 if the mesh is a valid all-hex mesh (and, with
/// --certified, every hex is proved valid), 3 if it was read but is not, 2 on bad input or usage.

#include "ArgParser.hh"
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

/// Width of the labels of the text output.
constexpr std::size_t label_width = 32;

const char* kValidateUsage =
    "usage: hexex validate MESH [--json] [--certified]\n"
    "  MESH         hex mesh file: .vtu, .vtk, .ovm, .ovmb or .mesh\n"
    "  --json       print the counts as a JSON object\n"
    "  --certified  also fail (exit 3) unless every hex is proved to have a positive Jacobian\n"
    "               everywhere inside (no invalid or undecided hex)\n"
    "exit status: 0 valid all-hex mesh, 3 readable but not a valid all-hex mesh (or, with --certified,\n"
    "             not certified valid), 2 bad input or usage\n";

} // namespace

int runValidate(const Args& args) {
    std::string input;
    bool json = false, require_certified = false;
    try {
        const ParsedArgs pa = parseArgs(args, {{"--json", false, ""}, {"--certified", false, ""}});
        if (pa.has("--help")) {
            std::cout << kValidateUsage;
            return 0;
        }
        if (pa.positional.size() > 1) throw UsageError("more than one input file given");
        if (pa.positional.empty()) throw UsageError("no input file given");
        input = pa.positional[0];
        json = pa.has("--json");
        require_certified = pa.has("--certified");
    } catch (const UsageError& e) {
        std::cerr << "hexex validate: " << e.what() << "\n" << kValidateUsage;
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
    // Every hex proved positive everywhere inside (HexValidity.hh); independent of valid_all_hex.
    const bool certified = r.quality.invalid_hexes == 0 && r.quality.undecided_hexes == 0;

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
                  << "  \"nonmanifold_boundary_vertices\": " << r.nonmanifold_boundary_vertices << ",\n"
                  << "  \"invalid_cells\": " << r.invalid_cells << ",\n"
                  << "  \"euler_characteristic\": " << r.euler_characteristic << ",\n"
                  << "  \"min_scaled_jacobian\": " << numText(r.quality.min_scaled_jacobian) << ",\n"
                  << "  \"mean_scaled_jacobian\": " << numText(r.quality.mean_scaled_jacobian) << ",\n"
                  << "  \"inverted_hexes\": " << r.quality.inverted_hexes << ",\n"
                  << "  \"invalid_hexes\": " << r.quality.invalid_hexes << ",\n"
                  << "  \"undecided_hexes\": " << r.quality.undecided_hexes << ",\n"
                  << "  \"first_invalid_hex\": " << r.quality.first_invalid_hex << ",\n"
                  << "  \"certified_valid\": " << (certified ? "true" : "false") << ",\n"
                  << "  \"valid_all_hex\": " << (r.valid_all_hex ? "true" : "false") << "\n"
                  << "}\n";
    } else {
        auto row = [](const char* label, const std::string& value) {
            std::cout << label << std::string(label_width - std::string(label).size(), ' ') << value << "\n";
        };
        row("file:", input);
        row("cells:", std::to_string(r.cells));
        row("hexes:", std::to_string(r.hexes));
        row("non-hex cells:", std::to_string(r.non_hex_cells));
        row("vertices:", std::to_string(r.vertices));
        row("edges:", std::to_string(r.edges));
        row("faces:", std::to_string(r.faces));
        row("quads:", std::to_string(r.quads));
        row("boundary quads:", std::to_string(r.boundary_quads));
        row("boundary faces:", std::to_string(r.boundary_faces));
        row("faces shared by > 2 cells:", std::to_string(r.quads_shared_by_more_than_two));
        row("non-manifold boundary edges:", std::to_string(r.nonmanifold_boundary_edges));
        row("non-manifold boundary vertices:", std::to_string(r.nonmanifold_boundary_vertices));
        row("invalid cells:", std::to_string(r.invalid_cells));
        row("Euler characteristic:", std::to_string(r.euler_characteristic));
        row("min scaled Jacobian:", numText(r.quality.min_scaled_jacobian));
        row("mean scaled Jacobian:", numText(r.quality.mean_scaled_jacobian));
        row("inverted hexes (corners):", std::to_string(r.quality.inverted_hexes));
        row("invalid hexes (certified):", std::to_string(r.quality.invalid_hexes) +
                                              (r.quality.first_invalid_hex >= 0
                                                   ? " (first: hex " + std::to_string(r.quality.first_invalid_hex) + ")"
                                                   : std::string()));
        row("undecided hexes:", std::to_string(r.quality.undecided_hexes));
        row("certified valid:", std::string(certified ? "yes" : "no"));
        row("valid all-hex:", std::string(r.valid_all_hex ? "yes" : "no"));
    }
    if (!r.valid_all_hex) return 3;
    return require_certified && !certified ? 3 : 0;
}

} // namespace HexExTool
