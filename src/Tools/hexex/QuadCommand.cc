/// @file QuadCommand.cc
/// The 2D subcommands: `hexex quad IN.obj -o OUT [options]` (quad mesh extraction),
/// `hexex generate square|cone-disk|torus|quarter-seam ... -o OUT.obj` (2D test maps) and
/// `hexex perturb IN.obj ...` (2D perturbation, dispatched from PerturbCommand.cc).

#include "ArgParser.hh"
#include "Commands.hh"

#include <HexEx/Core/Error.hh>
#include <HexEx/Quad/QuadExtraction.hh>
#include <HexEx/Quad/QuadGenerators.hh>
#include <HexEx/Quad/QuadMeshIO.hh>
#include <HexEx/Quad/QuadReportJson.hh>

#include <chrono>
#include <fstream>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>

namespace HexExTool {

namespace {

const char* kQuadUsage =
    "usage: hexex quad IN.obj -o OUT [options]\n"
    "  IN.obj                  triangle mesh with per-corner parameters ('vt' and 'f v/vt')\n"
    "  -o, --output OUT        quad mesh to write; format by extension: .obj .off .ply (OpenMesh) .vtu\n"
    "  --report R.json         write the extraction report as JSON ('-' for stdout)\n"
    "  --threads N             worker threads (0 = all hardware threads, default; at most one per 10,000\n"
    "                          triangles); output is identical\n"
    "  --epsilon E             snap parameters this close to an integer (default 1e-6)\n"
    "  --no-merge              keep regular/anti dart pairs (skip annihilation)\n"
    "  -q, --quiet             print nothing but errors\n"
    "exit status: 0 all-quad mesh written, 3 written but not all-quad, 2 bad input or usage\n";

const char* kGenerate2DUsage =
    "usage: hexex generate SHAPE [shape options] [--chart-noise SEED] [--fp-noise A] [--quiet] -o OUT.obj\n"
    "2D shapes (triangle meshes with per-corner vt parameters) and their options (defaults in brackets):\n"
    "  square        --n N [4] --scale S [4]\n"
    "                unit square as N x N boxes of 2 triangles, map = S * position; S*S quads\n"
    "  cone-disk     --valence K [5] --radius R [3] --n N [3]\n"
    "                K wedges around a cone of valence K; K*R*R quads, K*R*(R+1)+1 vertices\n"
    "  torus         --length L [6] --width W [4] --nu NU [6] --nv NV [4]\n"
    "                torus periodic in both parameters; L*W quads\n"
    "  quarter-seam  --width W [4] --n N [4]\n"
    "                square whose right half has a chart turned by a quarter turn; W*W quads\n"
    "common options:\n"
    "  --chart-noise SEED  re-express every triangle in a random grid chart\n"
    "  --fp-noise A        add uniform noise in [-A, A] to every corner parameter (seed 1)\n"
    "  --quiet             print nothing but errors\n";

constexpr long kMaxSize = 100000;  ///< upper bound for any size argument

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace

bool isShape2D(const std::string& name) {
    return name == "square" || name == "cone-disk" || name == "torus" || name == "quarter-seam";
}

int runQuad(const Args& args) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<OptionSpec> spec = {{"--output", true, "-o"}, {"--report", true, ""},  {"--threads", true, ""},
                                          {"--epsilon", true, ""},  {"--no-merge", false, ""}, {"--quiet", false, "-q"}};
    std::string input, output, report;
    HexEx::QuadExtractionOptions opt;
    bool quiet = false;
    try {
        const ParsedArgs pa = parseArgs(args, spec);
        if (pa.has("--help")) {
            std::cout << kQuadUsage;
            return 0;
        }
        if (pa.positional.empty()) throw UsageError("no input file given");
        if (pa.positional.size() > 1) throw UsageError("more than one input file given");
        if (!pa.has("--output")) throw UsageError("no output file given (-o OUT)");
        input = pa.positional[0];
        output = pa.get("--output");
        report = pa.get("--report");
        opt.threads = static_cast<int>(pa.getInt("--threads", 0, 0, 1024));
        opt.epsilon = pa.getDouble("--epsilon", 1e-6, 0, 0.5);
        opt.merge = !pa.has("--no-merge");
        quiet = pa.has("--quiet");
    } catch (const UsageError& e) {
        std::cerr << "hexex quad: " << e.what() << "\n" << kQuadUsage;
        return 2;
    }
    HexEx::QuadReportExtras extras;
    HexEx::QuadExtractionReport rep;
    HexEx::QuadMesh qm;
    try {
        auto tr = std::chrono::steady_clock::now();
        const HexEx::ParametrizedTriMesh m = HexEx::readParametrizedTriMesh(input, opt.threads);
        extras.read_s = secondsSince(tr);
        rep = HexEx::extractQuadMesh(m, qm, opt);
        auto tw = std::chrono::steady_clock::now();
        HexEx::writeQuadMesh(output, qm, opt.threads);
        extras.write_s = secondsSince(tw);
    } catch (const HexEx::InputError& e) {
        std::cerr << "hexex quad: error: " << e.what() << "\n";
        return 2;
    }
    extras.total_s = secondsSince(t0);
    if (!report.empty()) {
        const std::string json = HexEx::quadReportToJson(rep, extras);
        if (report == "-") {
            std::cout << json;
        } else {
            std::ofstream f(report);
            if (!(f << json)) {
                std::cerr << "hexex quad: error: " << report << ": cannot write the report\n";
                return 2;
            }
        }
    }
    if (!quiet) {
        for (const auto& w : rep.warnings) std::cerr << "hexex quad: warning: " << w << "\n";
        if (report != "-")
            std::cout << "wrote " << output << ": " << rep.output.quads << " quads, " << rep.output.non_quad_faces
                      << " other faces, " << rep.output.vertices << " vertices ("
                      << (rep.valid_all_quad ? "valid all-quad" : "NOT all-quad") << ")\n";
    }
    return rep.valid_all_quad ? 0 : 3;
}

int runGenerate2D(const Args& args) {
    const std::vector<OptionSpec> spec = {
        {"--output", true, "-o"}, {"--chart-noise", true, ""}, {"--fp-noise", true, ""}, {"--quiet", false, "-q"},
        {"--n", true, ""},        {"--scale", true, ""},       {"--valence", true, ""},  {"--radius", true, ""},
        {"--length", true, ""},   {"--width", true, ""},       {"--nu", true, ""},       {"--nv", true, ""},
    };
    try {
        const ParsedArgs pa = parseArgs(args, spec);
        if (pa.has("--help")) {
            std::cout << kGenerate2DUsage;
            return 0;
        }
        if (pa.positional.size() != 1) throw UsageError("expected one shape");
        const std::string shape = pa.positional[0];
        std::vector<std::string> allowed;
        if (shape == "square") allowed = {"--n", "--scale"};
        else if (shape == "cone-disk") allowed = {"--valence", "--radius", "--n"};
        else if (shape == "torus") allowed = {"--length", "--width", "--nu", "--nv"};
        else allowed = {"--width", "--n"};
        for (const auto& kv : pa.values) {
            const std::string& k = kv.first;
            if (k == "--output" || k == "--chart-noise" || k == "--fp-noise" || k == "--quiet") continue;
            bool ok = false;
            for (const auto& a : allowed) ok = ok || a == k;
            if (!ok) throw UsageError("option '" + k + "' does not apply to shape " + shape);
        }
        if (!pa.has("--output")) throw UsageError("no output file given (-o OUT.obj)");
        const std::string out = pa.get("--output");
        auto sz = [&](const char* name, long def, long lo = 1) { return static_cast<int>(pa.getInt(name, def, lo, kMaxSize)); };
        HexEx::ParametrizedTriMesh m;
        try {
            if (shape == "square") m = HexEx::generateSquare(sz("--n", 4), sz("--scale", 4));
            else if (shape == "cone-disk") m = HexEx::generateConeDisk(sz("--valence", 5), sz("--radius", 3), sz("--n", 3));
            else if (shape == "torus") m = HexEx::generateTorus(sz("--length", 6), sz("--width", 4), sz("--nu", 6), sz("--nv", 4));
            else m = HexEx::generateQuarterTurnSeam(sz("--width", 4), sz("--n", 4));
        } catch (const std::invalid_argument& e) {
            throw UsageError(e.what());
        }
        if (m.triangles.size() > 50000000) throw UsageError("mesh too large (" + std::to_string(m.triangles.size()) + " triangles)");
        if (pa.has("--chart-noise"))
            HexEx::applyRandomTriCharts(m, static_cast<unsigned>(pa.getInt("--chart-noise", 0, 0, std::numeric_limits<unsigned>::max())));
        if (pa.has("--fp-noise")) HexEx::applyTriParameterNoise(m, pa.getDouble("--fp-noise", 0, 0, 1e6), 1);
        try {
            HexEx::writeParametrizedTriMesh(out, m, 0);
        } catch (const std::exception& e) {
            std::cerr << "hexex generate: error: " << e.what() << "\n";
            return 2;
        }
        if (!pa.has("--quiet"))
            std::cout << "wrote " << out << ": " << shape << ", " << m.points.size() << " vertices, " << m.triangles.size()
                      << " triangles, parametric area " << HexEx::totalParametricArea(m) << "\n";
        return 0;
    } catch (const UsageError& e) {
        std::cerr << "hexex generate: " << e.what() << "\n" << kGenerate2DUsage;
        return 2;
    }
}

int runPerturb2D(const std::string& input, const std::string& output, double a, unsigned seed, bool quiet) {
    try {
        HexEx::ParametrizedTriMesh m = HexEx::readParametrizedTriMesh(input, 0);
        HexEx::TriPerturbStats st;
        HexEx::perturbTriParameters(m, a, seed, &st);
        HexEx::writeParametrizedTriMesh(output, m, 0);
        if (!quiet)
            std::cout << "wrote " << output << ": " << st.moved_vertices << " of " << st.vertices << " vertices moved ("
                      << st.fixed_vertices << " fixed, " << st.boundary_vertices << " on the boundary)\n";
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "hexex perturb: error: " << e.what() << "\n";
        return 2;
    }
}

} // namespace HexExTool
