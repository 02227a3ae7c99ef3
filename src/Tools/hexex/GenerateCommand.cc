/// @file GenerateCommand.cc
/// `hexex generate cube|cylinder|ring|twisted-ring [shape options] [--chart-noise SEED]
/// [--fp-noise A] -o OUT.hexex`: procedural test inputs with known hex meshes; and
/// `hexex generate from-hex MESH [--perturb A] [--seed S] [--scale K] -o OUT.hexex`: a map
/// whose expected hex mesh is a given one.

#include "ArgParser.hh"
#include "Commands.hh"

#include <HexEx/Core/Error.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/Generators/MapFromHexMesh.hh>
#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/IO/HexExFile.hh>
#include <HexEx/IO/MapStatistics.hh>

#include <iostream>
#include <limits>
#include <string>

namespace HexExTool {

namespace {

const char* kGenerateUsage =
    "usage: hexex generate SHAPE [shape options] [--chart-noise SEED] [--fp-noise A] [--quiet] -o OUT.hexex\n"
    "shapes and their options (defaults in brackets):\n"
    "  cube          --n N [3] --scale S [3]\n"
    "                unit cube split into N^3 boxes of 6 tets, map = S * position; S^3 hexes\n"
    "  cylinder      --valence K [3] --radius R [2] --height H [2] --n N [2] --m M [2]\n"
    "                K wedges around a singular axis of valence K; K*R*R*H hexes\n"
    "  ring          --length L [6] --width W [2] --height H [2] --nu NU [6] --nv NV [2] --nw NW [2]\n"
    "                ring periodic in the first parameter; L*W*H hexes\n"
    "  twisted-ring  --length L [8] --width W [2] --nu NU [8] --nv NV [2]\n"
    "                square ring glued with a quarter turn (NV even); L*W*W hexes\n"
    "  from-hex MESH --perturb A [0] --seed S [1] --scale K [1]\n"
    "                MESH (any all-hex file hexex validate reads) as a map: each hex split into\n"
    "                24 tets in its own random chart, face/cell centres moved by up to A grid\n"
    "                units; the expected output is MESH (refined K times per axis)\n"
    "common options:\n"
    "  --chart-noise SEED  re-express every tet in a random grid chart (non-trivial transitions)\n"
    "  --fp-noise A        add uniform noise in [-A, A] to every corner parameter (seed 1)\n"
    "  --quiet             print nothing but errors\n"
    "2D shapes (triangle meshes with vt parameters, written as OBJ; see hexex generate square --help):\n"
    "  square, cone-disk, torus, quarter-seam\n";

/// Usage lines of one shape.
std::string shapeUsage(const std::string& shape) {
    const std::string all = kGenerateUsage;
    const std::size_t at = all.find("  " + shape + " ");
    if (at == std::string::npos) return kGenerateUsage;
    const std::size_t end = all.find('\n', all.find('\n', at) + 1);
    return "usage: hexex generate " + shape + " [options] [--chart-noise SEED] [--fp-noise A] -o OUT.hexex\n" +
           all.substr(at, end + 1 - at);
}

constexpr long kMaxSize = 100000;  ///< upper bound for any size argument (guards overflow)

} // namespace

int runGenerate(const Args& args) {
    if (!args.empty() && isShape2D(args[0])) return runGenerate2D(args);
    const std::vector<OptionSpec> spec = {
        {"--output", true, "-o"}, {"--chart-noise", true, ""}, {"--fp-noise", true, ""}, {"--quiet", false, "-q"},
        {"--n", true, ""},        {"--scale", true, ""},       {"--valence", true, ""},  {"--radius", true, ""},
        {"--height", true, ""},   {"--m", true, ""},           {"--length", true, ""},   {"--width", true, ""},
        {"--nu", true, ""},       {"--nv", true, ""},          {"--nw", true, ""},      {"--perturb", true, ""},
        {"--seed", true, ""},
    };
    std::string shape;
    if (!args.empty() && (args[0] == "cube" || args[0] == "cylinder" || args[0] == "ring" || args[0] == "twisted-ring" ||
                          args[0] == "from-hex"))
        shape = args[0];  // so that early usage errors show this shape's options
    try {
        const ParsedArgs pa = parseArgs(args, spec);
        if (pa.has("--help")) {
            std::cout << kGenerateUsage;
            return 0;
        }
        if (pa.positional.empty()) throw UsageError("no shape given");
        shape = pa.positional[0];
        const std::size_t positionals = shape == "from-hex" ? 2 : 1;
        if (pa.positional.size() < positionals) throw UsageError("no hex mesh file given");
        if (pa.positional.size() > positionals)
            throw UsageError("unexpected argument '" + pa.positional[positionals] + "'");
        // Options each shape accepts.
        std::vector<std::string> allowed;
        if (shape == "cube") allowed = {"--n", "--scale"};
        else if (shape == "cylinder") allowed = {"--valence", "--radius", "--height", "--n", "--m"};
        else if (shape == "ring") allowed = {"--length", "--width", "--height", "--nu", "--nv", "--nw"};
        else if (shape == "twisted-ring") allowed = {"--length", "--width", "--nu", "--nv"};
        else if (shape == "from-hex") allowed = {"--perturb", "--seed", "--scale"};
        else {
            shape.clear();
            throw UsageError("unknown shape '" + pa.positional[0] + "' (cube, cylinder, ring, twisted-ring, from-hex)");
        }
        for (const auto& kv : pa.values) {
            const std::string& k = kv.first;
            if (k == "--output" || k == "--chart-noise" || k == "--fp-noise" || k == "--quiet") continue;
            bool ok = false;
            for (const auto& a : allowed) ok = ok || a == k;
            if (!ok) throw UsageError("option '" + k + "' does not apply to shape " + shape);
        }
        if (!pa.has("--output")) throw UsageError("no output file given (-o OUT.hexex)");
        const std::string out = pa.get("--output");
        const bool quiet = pa.has("--quiet");
        auto sz = [&](const char* name, long def, long lo = 1) {
            return static_cast<int>(pa.getInt(name, def, lo, kMaxSize));
        };

        HexEx::ParametrizedTetMesh pm;
        try {
            if (shape == "cube") {
                pm = HexEx::generateCube(sz("--n", 3), sz("--scale", 3));
            } else if (shape == "cylinder") {
                pm = HexEx::generateCylinder(sz("--valence", 3), sz("--radius", 2), sz("--height", 2), sz("--n", 2),
                                             sz("--m", 2));
            } else if (shape == "ring") {
                pm = HexEx::generateRing(sz("--length", 6), sz("--width", 2), sz("--height", 2), sz("--nu", 6),
                                         sz("--nv", 2), sz("--nw", 2));
            } else if (shape == "from-hex") {
                HexEx::MapFromHexOptions o;
                o.perturb = pa.getDouble("--perturb", 0, 0, 2);
                o.seed = static_cast<unsigned>(
                    pa.getInt("--seed", 1, 0, static_cast<long>(std::numeric_limits<unsigned>::max())));
                o.scale = sz("--scale", 1);
                HexEx::HexMesh source;
                try {
                    source = HexEx::readHexMesh(pa.positional[1]);
                    HexEx::MapFromHexResult r = HexEx::mapFromHexMesh(source, o);
                    if (r.negative_tets_3d > 0 && !quiet)
                        std::cerr << "hexex generate: warning: " << r.negative_tets_3d
                                  << " tets are not positively oriented in 3D (inverted or warped source hexes)\n";
                    pm = std::move(r.map);
                } catch (const HexEx::InputError& e) {
                    std::cerr << "hexex generate: error: " << e.what() << "\n";
                    return 2;
                }
            } else {
                pm = HexEx::generateTwistedRing(sz("--length", 8), sz("--width", 2), sz("--nu", 8), sz("--nv", 2));
            }
        } catch (const std::invalid_argument& e) {
            throw UsageError(e.what());
        }
        const long tets = static_cast<long>(pm.mesh.n_cells());
        if (tets > 50000000) throw UsageError("mesh too large (" + std::to_string(tets) + " tets)");
        if (pa.has("--chart-noise")) {
            const auto seed = static_cast<unsigned>(
                pa.getInt("--chart-noise", 0, 0, static_cast<long>(std::numeric_limits<unsigned>::max())));
            HexEx::applyRandomChartTransforms(pm, seed);
        }
        if (pa.has("--fp-noise")) {
            const double a = pa.getDouble("--fp-noise", 0, 0, 1e6);
            HexEx::applyParameterNoise(pm, a, 1);
        }
        try {
            HexEx::writeHexExFile(out, pm);
        } catch (const std::exception& e) {
            std::cerr << "hexex generate: error: " << e.what() << "\n";
            return 2;
        }
        if (!quiet) {
            const HexEx::MapStatistics s = HexEx::computeMapStatistics(pm);
            std::cout << "wrote " << out << ": " << shape << ", " << s.vertices << " vertices, " << s.tets
                      << " tets, parametric volume " << s.parametric_volume << "\n";
        }
        return 0;
    } catch (const UsageError& e) {
        std::cerr << "hexex generate: " << e.what() << "\n" << (shape.empty() ? kGenerateUsage : shapeUsage(shape));
        return 2;
    }
}

} // namespace HexExTool
