/// @file main.cc
/// Entry point of the hexex tool: dispatches to the subcommands.

#include "AllocatorTuning.hh"
#include "Commands.hh"

#include <cstring>
#include <exception>
#include <iostream>
#include <new>

namespace {
const char* kUsage =
    "usage: hexex <command> [options]\n"
    "commands:\n"
    "  info IN [--json]                          statistics of a tet mesh with its map (.hexex .ovm .ovmb)\n"
    "  extract IN -o OUT [--report R.json] [--threads N] [--epsilon E] [--quiet]\n"
    "                                            extract the hex mesh (.vtu, .vtk, .ovm, .ovmb, .mesh)\n"
    "  convert IN OUT [--encoding E]             convert a map (.hexex .ovm .ovmb) or a hex mesh\n"
    "  generate cube|cylinder|ring|twisted-ring [options] -o OUT.hexex\n"
    "  generate from-hex MESH [--perturb A] -o OUT.hexex  map whose hex mesh is MESH\n"
    "  perturb IN -a A --seed S -o OUT.hexex     stress-test perturbation of a map\n"
    "  validate MESH [--json]                    check a hex mesh file\n"
    "  untangle HEX -o OUT [--surface-from MAP]  move vertices so that no hex is inverted\n"
    "  optimize HEX -o OUT [--surface TRI | --surface-from MAP] [--target SJ] [--json]\n"
    "                                            raise the worst scaled Jacobian, boundary on the surface\n"
    "  quad IN.obj -o OUT [--report R.json] [--threads N] [--epsilon E] [--quiet]\n"
    "                                            2D: extract the quad mesh of a triangle mesh\n"
    "                                            with per-corner vt parameters (.obj, .off, .ply, .vtu)\n"
    "  generate square|cone-disk|torus|quarter-seam [options] -o OUT.obj   2D test maps\n"
    "exit status: 0 ok, 2 bad input or usage, 3 output not all-hex (all-quad for quad; untangle: inverted hexes left)\n";
}

int main(int argc, char** argv) {
    if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
        std::cerr << kUsage;
        return argc < 2 ? 2 : 0;
    }
    HexExTool::keepLargeBlocksOnHeap();
    const std::string cmd = argv[1];
    HexExTool::Args args(argv + 2, argv + argc);
    try {
        if (cmd == "info") return HexExTool::runInfo(args);
        if (cmd == "extract") return HexExTool::runExtract(args);
        if (cmd == "generate") return HexExTool::runGenerate(args);
        if (cmd == "perturb") return HexExTool::runPerturb(args);
        if (cmd == "validate") return HexExTool::runValidate(args);
        if (cmd == "quad") return HexExTool::runQuad(args);
        if (cmd == "convert") return HexExTool::runConvert(args);
        if (cmd == "untangle") return HexExTool::runUntangle(args);
        if (cmd == "optimize") return HexExTool::runOptimize(args);
    } catch (const std::bad_alloc&) {
        std::cerr << "hexex " << cmd << ": error: out of memory (std::bad_alloc) outside the extraction (reading or "
                     "writing a mesh); free memory or use a smaller input\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "hexex " << cmd << ": error: " << e.what() << "\n";
        return 2;
    }
    std::cerr << "hexex: unknown command '" << cmd << "'\n" << kUsage;
    return 2;
}
