/// @file PerturbCommand.cc
/// `hexex perturb IN -a A --seed S -o OUT.hexex`: consistent parameter noise that keeps
/// boundary planes and singular edges aligned (paper section 5.1), for stress tests.

#include "ArgParser.hh"
#include "Commands.hh"

#include <HexEx/Core/Error.hh>
#include <HexEx/Generators/Perturbation.hh>
#include <HexEx/IO/HexExFile.hh>
#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/IO/HexMeshWriters.hh>
#include <HexEx/IO/TetMeshInput.hh>
#include <HexEx/IO/MapStatistics.hh>

#include <algorithm>
#include <cctype>
#include <iostream>
#include <limits>
#include <string>

namespace HexExTool {

namespace {
const char* kPerturbUsage =
    "usage: hexex perturb IN.hexex -a A [--seed S] [--quiet] -o OUT.hexex\n"
    "  -a, --amplitude A  move every vertex parameter by uniform noise in [-A, A] per axis,\n"
    "                     the same in all its charts; boundary planes and singular edges stay aligned\n"
    "  --seed S           random seed (default 1); the same seed gives the same output\n"
    "  --quiet            print nothing but errors\n"
    "  IN.obj (2D map: triangles with vt parameters) is perturbed the same way, cones stay fixed; writes OBJ\n"
    "  IN a hex mesh (.vtu .vtk .mesh, or .ovm/.ovmb holding hexes): every interior vertex moves by\n"
    "                     uniform noise in [-A l, A l] per axis, l its mean edge length; boundary vertices\n"
    "                     stay bit for bit (A about 1 inverts most hexes); writes a hex mesh (-o extension)\n";

/// Lower-case extension of @p path including the dot ("" if none).
std::string extensionOf(const std::string& path) {
    const std::size_t dot = path.find_last_of('.');
    const std::size_t slash = path.find_last_of("/\\");
    if (dot == std::string::npos || (slash != std::string::npos && slash > dot)) return "";
    std::string e = path.substr(dot);
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return e;
}

/// `hexex perturb` on a hex mesh @p mesh read from @p input.
int perturbHexFile(HexEx::HexMesh mesh, const std::string& input, const std::string& out, double a, unsigned seed,
                   bool quiet) {
    if (mesh.hexes.empty()) {
        std::cerr << "hexex perturb: error: " << input << ": no hexahedra to perturb\n";
        return 2;
    }
    HexEx::HexPerturbStats ps;
    HexEx::perturbHexMesh(mesh, a, seed, &ps);
    try {
        const auto warnings = HexEx::writeHexMesh(out, mesh);
        if (!quiet)
            for (const auto& w : warnings) std::cerr << "hexex perturb: warning: " << w << "\n";
    } catch (const std::exception& e) {
        std::cerr << "hexex perturb: error: " << e.what() << "\n";
        return 2;
    }
    if (!quiet) {
        const double pct = 100.0 * static_cast<double>(ps.inverted_after) / static_cast<double>(mesh.hexes.size());
        std::cout << "wrote " << out << ": " << ps.moved_vertices << " of " << ps.interior_vertices
                  << " interior vertices moved (" << ps.vertices - ps.interior_vertices << " boundary or fixed vertices kept)\n"
                  << "inverted hexes:  " << ps.inverted_before << " -> " << ps.inverted_after << " of "
                  << mesh.hexes.size() << " (" << static_cast<long>(pct * 10 + 0.5) / 10.0 << " %)\n";
    }
    return 0;
}
} // namespace

int runPerturb(const Args& args) {
    const std::vector<OptionSpec> spec = {
        {"--output", true, "-o"}, {"--amplitude", true, "-a"}, {"--seed", true, ""}, {"--quiet", false, "-q"}};
    std::string input, out;
    double a = 0;
    unsigned seed = 1;
    bool quiet = false;
    try {
        const ParsedArgs pa = parseArgs(args, spec);
        if (pa.has("--help")) {
            std::cout << kPerturbUsage;
            return 0;
        }
        if (pa.positional.empty()) throw UsageError("no input file given");
        if (pa.positional.size() > 1) throw UsageError("more than one input file given");
        input = pa.positional[0];
        if (!pa.has("--output")) throw UsageError("no output file given (-o OUT.hexex)");
        if (!pa.has("--amplitude")) throw UsageError("no amplitude given (-a A)");
        out = pa.get("--output");
        a = pa.getDouble("--amplitude", 0, 0, 1e6);
        seed = static_cast<unsigned>(pa.getInt("--seed", 1, 0, static_cast<long>(std::numeric_limits<unsigned>::max())));
        quiet = pa.has("--quiet");
    } catch (const UsageError& e) {
        std::cerr << "hexex perturb: " << e.what() << "\n" << kPerturbUsage;
        return 2;
    }

    if (input.size() >= 4 && input.compare(input.size() - 4, 4, ".obj") == 0) return runPerturb2D(input, out, a, seed, quiet);
    // Hex meshes: by extension (.vtu .vtk .mesh), or .ovm/.ovmb files whose cells are hexes.
    const std::string ext = extensionOf(input);
    if (ext == ".vtu" || ext == ".vtk" || ext == ".mesh" || ext == ".ovm" || ext == ".ovmb") {
        HexEx::HexMesh hm;
        bool is_hex = true;
        try {
            hm = HexEx::readHexMesh(input);
            is_hex = !hm.hexes.empty() || (ext != ".ovm" && ext != ".ovmb");
        } catch (const HexEx::InputError& e) {
            if (ext != ".ovm" && ext != ".ovmb") {
                std::cerr << "hexex perturb: error: " << e.what() << "\n";
                return 2;
            }
            is_hex = false;  // an OpenVolumeMesh tet map: read below
        }
        if (is_hex) return perturbHexFile(std::move(hm), input, out, a, seed, quiet);
    }

    HexEx::ReadReport rr;
    HexEx::ParametrizedTetMesh pm;
    try {
        pm = HexEx::readParametrizedTetMesh(input, &rr);
    } catch (const HexEx::InputError& e) {
        std::cerr << "hexex perturb: error: " << e.what() << "\n";
        return 2;
    }
    if (!quiet)
        for (const auto& w : rr.warnings) std::cerr << "hexex perturb: warning: " << w << "\n";

    const HexEx::MapStatistics before = HexEx::computeMapStatistics(pm);
    HexEx::PerturbStats ps;
    HexEx::perturbParameters(pm, a, seed, &ps);
    const HexEx::MapStatistics after = HexEx::computeMapStatistics(pm);
    try {
        HexEx::writeHexExFile(out, pm);
    } catch (const std::exception& e) {
        std::cerr << "hexex perturb: error: " << e.what() << "\n";
        return 2;
    }
    if (!quiet) {
        std::cout << "wrote " << out << ": " << ps.moved_vertices << " of " << ps.vertices << " vertices moved ("
                  << ps.fixed_vertices << " fixed, " << ps.boundary_vertices << " on boundary planes, "
                  << ps.singular_vertices << " on singular edges)\n"
                  << "flipped tets:    " << before.flipped_tets << " -> " << after.flipped_tets << "\n"
                  << "degenerate tets: " << before.degenerate_tets << " -> " << after.degenerate_tets << "\n";
    }
    return 0;
}

} // namespace HexExTool
