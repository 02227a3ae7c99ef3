/// @file UntangleCommand.cc
/// `hexex untangle HEX -o OUT [--surface-from MAP] [options]`: moves the vertices of a hex
/// mesh file so that no hex is inverted (HexEx::untangleHexMesh()) and writes it.
/// Exit status 0 if every hex is certified valid afterwards (classifyHexValidity()), 3 if
/// invalid or undecided hexes remain (the mesh is written anyway), 2 on bad input or usage.

#include "ArgParser.hh"
#include "Commands.hh"
#include "UntangleOutput.hh"

#include <HexEx/Core/Error.hh>
#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/IO/HexMeshWriters.hh>
#include <HexEx/IO/TetMeshInput.hh>
#include <HexEx/Untangling/TriangleSurface.hh>
#include <HexEx/Untangling/Untangler.hh>

#include <iostream>
#include <string>

namespace HexExTool {

namespace {
const char* kUntangleUsage =
    "usage: hexex untangle HEX -o OUT [options]\n"
    "  HEX, -o OUT            hex mesh files: .vtu .vtk .ovm .ovmb .mesh\n"
    "  --surface-from MAP     keep boundary vertices on the boundary of this tet mesh (.hexex .ovm .ovmb);\n"
    "                         default: on the boundary of HEX itself\n"
    "  --fixed-boundary       do not move boundary vertices at all\n"
    "  --feature-angle DEG    surface edges sharper than this are feature curves (default 40)\n"
    "  --keep-features        never let vertices leave feature curves/corners (default: vertices of hexes\n"
    "                         that stay inverted with them kept are released onto the surface)\n"
    "  --quality-iterations N L-BFGS iterations that raise the worst scaled Jacobian of an untangled\n"
    "                         neighbourhood (default 10, 0 = off)\n"
    "  --rings K              hex rings around inverted hexes that move at first (default 1)\n"
    "  --threads N            worker threads (0 = all, default); the output is identical\n"
    "  --encoding E           .vtu data: binary (default), compressed or ascii\n"
    "  -q, --quiet            print nothing but errors\n"
    "exit status: 0 every hex certified valid (J > 0 on the whole hex), 3 written with invalid or\n"
    "             undecided hexes left, 2 bad input or usage\n";
} // namespace

int runUntangle(const Args& args) {
    const std::vector<OptionSpec> spec = {
        {"--output", true, "-o"},         {"--surface-from", true, ""}, {"--fixed-boundary", false, ""},
        {"--feature-angle", true, ""},    {"--keep-features", false, ""}, {"--rings", true, ""},
        {"--quality-iterations", true, ""},        {"--threads", true, ""},
        {"--encoding", true, ""},         {"--quiet", false, "-q"},
    };
    std::string input, output, surface_path;
    HexEx::UntangleOptions opt;
    HexEx::VtuEncoding encoding = HexEx::VtuEncoding::Binary;
    bool quiet = false;
    try {
        const ParsedArgs pa = parseArgs(args, spec);
        if (pa.has("--help")) {
            std::cout << kUntangleUsage;
            return 0;
        }
        if (pa.positional.empty()) throw UsageError("no input file given");
        if (pa.positional.size() > 1) throw UsageError("more than one input file given ('" + pa.positional[1] + "')");
        input = pa.positional[0];
        if (!pa.has("--output")) throw UsageError("no output file given (-o OUT.vtu|.vtk|.ovm|.ovmb|.mesh)");
        output = pa.get("--output");
        surface_path = pa.get("--surface-from");
        if (pa.has("--fixed-boundary") && pa.has("--surface-from"))
            throw UsageError("--fixed-boundary and --surface-from exclude each other");
        if (pa.has("--fixed-boundary")) opt.boundary = HexEx::BoundaryMode::Fixed;
        opt.feature_angle_deg = pa.getDouble("--feature-angle", opt.feature_angle_deg, 0, 180);
        opt.release_features = !pa.has("--keep-features");
        opt.quality_iterations = static_cast<int>(pa.getInt("--quality-iterations", opt.quality_iterations, 0, 1000000));
        opt.rings = static_cast<int>(pa.getInt("--rings", opt.rings, 0, 1000000));
        opt.threads = static_cast<int>(pa.getInt("--threads", 0, 0, 4096));
        quiet = pa.has("--quiet");
        try {
            encoding = HexEx::vtuEncodingFromName(pa.get("--encoding", "binary"));
            HexEx::hexMeshFormatFromPath(output);
            HexEx::hexMeshFormatFromPath(input);
        } catch (const std::exception& e) {
            throw UsageError(e.what());
        }
    } catch (const UsageError& e) {
        std::cerr << "hexex untangle: " << e.what() << "\n" << kUntangleUsage;
        return 2;
    }

    HexEx::HexMesh hm;
    HexEx::TriangleSurface surface;
    try {
        hm = HexEx::readHexMesh(input);
        if (!surface_path.empty()) surface = HexEx::tetMeshBoundary(HexEx::readParametrizedTetMesh(surface_path).mesh);
    } catch (const HexEx::InputError& e) {
        std::cerr << "hexex untangle: error: " << e.what() << "\n";
        return 2;
    }
    if (!surface_path.empty() && surface.triangles.empty()) {
        std::cerr << "hexex untangle: error: " << surface_path << ": the tet mesh has no boundary triangles\n";
        return 2;
    }
    HexEx::UntangleReport rep;
    try {
        rep = HexEx::untangleHexMesh(hm, opt, surface_path.empty() ? nullptr : &surface);
    } catch (const std::invalid_argument& e) {
        std::cerr << "hexex untangle: error: " << input << ": " << e.what() << "\n";
        return 2;
    }
    try {
        for (const auto& w : HexEx::writeHexMesh(output, hm, encoding))
            if (!quiet) std::cerr << "hexex untangle: warning: " << w << "\n";
    } catch (const std::exception& e) {
        std::cerr << "hexex untangle: error: " << e.what() << "\n";
        return 2;
    }
    if (!quiet) {
        printUntangleReport(std::cout, rep);
        std::cout << "wrote " << output << ": " << hm.hexes.size() << " hexes, " << hm.vertices.size() << " vertices\n";
    }
    if (rep.success) return 0;
    std::cerr << "hexex untangle: " << rep.message << "\n";
    return 3;
}

} // namespace HexExTool
