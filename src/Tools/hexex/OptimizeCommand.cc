/// @file OptimizeCommand.cc
/// `hexex optimize HEX -o OUT [--surface TRI | --surface-from MAP] [options]`: raises the
/// worst scaled Jacobian of a hex mesh file (HexEx::optimizeHexMesh()) and writes it. A mesh
/// with inverted hexes is untangled first (HexEx::untangleHexMesh(), same surface).
/// Exit status 0 when the result is certified valid, 3 if hexes stay inverted or not
/// certified valid (the mesh is written anyway), 2 on bad input or usage.

#include "ArgParser.hh"
#include "Commands.hh"
#include "OptimizeOutput.hh"
#include "UntangleOutput.hh"

#include <HexEx/Core/Error.hh>
#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/IO/HexMeshWriters.hh>
#include <HexEx/IO/OptimizeReportJson.hh>
#include <HexEx/IO/TetMeshInput.hh>
#include <HexEx/Mesh/HexMeshQuality.hh>
#include <HexEx/Untangling/HexOptimizer.hh>
#include <HexEx/Untangling/TriangleSurface.hh>
#include <HexEx/Untangling/TriangleSurfaceReader.hh>
#include <HexEx/Untangling/Untangler.hh>

#include <iostream>
#include <string>

namespace HexExTool {

namespace {
const char* kOptimizeUsage =
    "usage: hexex optimize HEX -o OUT [options]\n"
    "  HEX, -o OUT            hex mesh files: .vtu .vtk .ovm .ovmb .mesh\n"
    "  --surface TRI          keep boundary vertices on this triangle surface (.obj .off .ply .stl)\n"
    "  --surface-from MAP     keep boundary vertices on the boundary of this tet mesh (.hexex .ovm .ovmb);\n"
    "                         default: on the boundary of HEX itself\n"
    "  --fixed-boundary       do not move boundary vertices at all\n"
    "  --feature-angle DEG    surface edges sharper than this are feature curves (default 40); curve\n"
    "                         vertices stay on their curve, corner vertices at their corner\n"
    "  --target SJ            stop once the worst scaled Jacobian reaches SJ (default 0.9)\n"
    "  --pillow               first insert a layer of hexes along the boundary (one per boundary\n"
    "                         quad; the boundary vertices stay bit for bit; patches with flat corners\n"
    "                         along feature curves get a strip of quads instead): lifts the bound\n"
    "                         sin(angle) of hexes with two boundary faces meeting almost flat\n"
    "  --blocks N             L-BFGS blocks of the global phase at most (default 40)\n"
    "  --passes N             vertex-by-vertex passes of the local phase at most (default 60)\n"
    "  --threads N            worker threads (0 = all, default); the output is identical\n"
    "  --json                 print the report as JSON on stdout (histograms included)\n"
    "  --encoding E           .vtu data: binary (default), compressed or ascii\n"
    "  -q, --quiet            print nothing but errors\n"
    "A mesh with inverted hexes is untangled first on the same surface.\n"
    "exit status: 0 certified valid result, 3 written with hexes not certified valid, 2 bad input or usage\n";
} // namespace

int runOptimize(const Args& args) {
    const std::vector<OptionSpec> spec = {
        {"--output", true, "-o"},      {"--surface", true, ""},  {"--surface-from", true, ""},
        {"--fixed-boundary", false, ""}, {"--feature-angle", true, ""}, {"--target", true, ""},
        {"--blocks", true, ""},        {"--passes", true, ""},   {"--threads", true, ""},
        {"--json", false, ""},         {"--encoding", true, ""}, {"--quiet", false, "-q"},
        {"--pillow", false, ""},
    };
    std::string input, output, surface_path, map_path;
    HexEx::OptimizeOptions opt;
    HexEx::VtuEncoding encoding = HexEx::VtuEncoding::Binary;
    bool quiet = false, json = false;
    try {
        const ParsedArgs pa = parseArgs(args, spec);
        if (pa.has("--help")) {
            std::cout << kOptimizeUsage;
            return 0;
        }
        if (pa.positional.empty()) throw UsageError("no input file given");
        if (pa.positional.size() > 1) throw UsageError("more than one input file given ('" + pa.positional[1] + "')");
        input = pa.positional[0];
        if (!pa.has("--output")) throw UsageError("no output file given (-o OUT.vtu|.vtk|.ovm|.ovmb|.mesh)");
        output = pa.get("--output");
        surface_path = pa.get("--surface");
        map_path = pa.get("--surface-from");
        const int given = pa.has("--surface") + pa.has("--surface-from") + pa.has("--fixed-boundary");
        if (given > 1) throw UsageError("--surface, --surface-from and --fixed-boundary exclude each other");
        if (pa.has("--fixed-boundary")) opt.boundary = HexEx::BoundaryMode::Fixed;
        opt.feature_angle_deg = pa.getDouble("--feature-angle", opt.feature_angle_deg, 0, 180);
        opt.target = pa.getDouble("--target", opt.target, -1, 1);
        opt.max_global_blocks = static_cast<int>(pa.getInt("--blocks", opt.max_global_blocks, 0, 1000000));
        opt.max_local_passes = static_cast<int>(pa.getInt("--passes", opt.max_local_passes, 0, 1000000));
        opt.threads = static_cast<int>(pa.getInt("--threads", 0, 0, 4096));
        quiet = pa.has("--quiet");
        json = pa.has("--json");
        opt.pillow = pa.has("--pillow");
        try {
            encoding = HexEx::vtuEncodingFromName(pa.get("--encoding", "binary"));
            HexEx::hexMeshFormatFromPath(output);
            HexEx::hexMeshFormatFromPath(input);
        } catch (const std::exception& e) {
            throw UsageError(e.what());
        }
    } catch (const UsageError& e) {
        std::cerr << "hexex optimize: " << e.what() << "\n" << kOptimizeUsage;
        return 2;
    }

    HexEx::HexMesh hm;
    HexEx::TriangleSurface surface;
    const bool has_surface = !surface_path.empty() || !map_path.empty();
    try {
        hm = HexEx::readHexMesh(input);
        if (!surface_path.empty()) surface = HexEx::readTriangleSurface(surface_path);
        if (!map_path.empty()) surface = HexEx::tetMeshBoundary(HexEx::readParametrizedTetMesh(map_path).mesh);
    } catch (const HexEx::InputError& e) {
        std::cerr << "hexex optimize: error: " << e.what() << "\n";
        return 2;
    }
    if (!map_path.empty() && surface.triangles.empty()) {
        std::cerr << "hexex optimize: error: " << map_path << ": the tet mesh has no boundary triangles\n";
        return 2;
    }
    std::ostream& os = json ? std::cerr : std::cout;
    HexEx::OptimizeReport rep;
    try {
        const HexEx::QualityStats q = HexEx::computeQuality(hm, opt.threads);
        if (q.inverted_hexes > 0) {
            HexEx::UntangleOptions uo;
            uo.threads = opt.threads;
            uo.boundary = opt.boundary;
            uo.feature_angle_deg = opt.feature_angle_deg;
            if (!quiet) os << "optimize: " << q.inverted_hexes << " inverted hexes: untangling first\n";
            const HexEx::UntangleReport ur = HexEx::untangleHexMesh(hm, uo, has_surface ? &surface : nullptr);
            if (!quiet) printUntangleReport(os, ur);
        }
        rep = HexEx::optimizeHexMesh(hm, opt, has_surface ? &surface : nullptr);
    } catch (const std::invalid_argument& e) {
        std::cerr << "hexex optimize: error: " << input << ": " << e.what() << "\n";
        return 2;
    }
    try {
        for (const auto& w : HexEx::writeHexMesh(output, hm, encoding))
            if (!quiet) std::cerr << "hexex optimize: warning: " << w << "\n";
    } catch (const std::exception& e) {
        std::cerr << "hexex optimize: error: " << e.what() << "\n";
        return 2;
    }
    if (json) std::cout << HexEx::optimizeReportToJson(rep) << "\n";
    if (!quiet) {
        printOptimizeReport(os, rep);
        os << "wrote " << output << ": " << hm.hexes.size() << " hexes, " << hm.vertices.size() << " vertices\n";
    }
    if (!rep.success) {
        std::cerr << "hexex optimize: " << rep.message << "\n";
        return 3;
    }
    if (rep.invalid_after > 0) {
        std::cerr << "hexex optimize: " << rep.invalid_after << " hexes are not certified valid\n";
        return 3;
    }
    return 0;
}

} // namespace HexExTool
