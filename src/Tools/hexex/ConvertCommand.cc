/// @file ConvertCommand.cc
/// `hexex convert IN OUT [--encoding E]`: converts a tet mesh with its integer-grid map
/// between .hexex, .ovm and .ovmb, or a hex mesh between .vtu, .vtk, .ovm, .ovmb and .mesh;
/// formats by extension. An .ovm/.ovmb input is a map if it has a parametrization
/// property, a hex mesh otherwise.

#include "ArgParser.hh"
#include "Commands.hh"

#include <HexEx/Core/Error.hh>
#include <HexEx/IO/HexExFile.hh>
#include <HexEx/IO/HexMeshReaders.hh>
#include <HexEx/IO/HexMeshWriters.hh>
#include <HexEx/IO/OvmTetReader.hh>
#include <HexEx/IO/ReaderSupport.hh>

#include <cctype>
#include <iostream>

namespace HexExTool {

namespace {

const char* kConvertUsage =
    "usage: hexex convert IN OUT [--encoding binary|compressed|ascii]\n"
    "  tet mesh with its map: .hexex, .ovm, .ovmb (map as halfface property HexHex::Parametrization)\n"
    "  hex mesh:              .vtu, .vtk, .ovm, .ovmb, .mesh\n"
    "  --encoding E  .vtu data arrays: binary (default), compressed (zlib) or ascii\n"
    "An .ovm/.ovmb input with a parametrization property is a map, otherwise a hex mesh.\n"
    "exit status: 0 written, 2 bad input or usage\n";

std::string extensionOf(const std::string& path) {
    const std::size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
    std::string ext = dot == std::string::npos || (slash != std::string::npos && dot < slash) ? "" : path.substr(dot);
    for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

} // namespace

int runConvert(const Args& args) {
    std::string input, output;
    HexEx::VtuEncoding encoding = HexEx::VtuEncoding::Binary;
    try {
        const ParsedArgs pa = parseArgs(args, {{"--encoding", true, ""}});
        if (pa.has("--help")) {
            std::cout << kConvertUsage;
            return 0;
        }
        if (pa.positional.size() != 2) throw UsageError("expected an input and an output file");
        input = pa.positional[0];
        output = pa.positional[1];
        try {
            encoding = HexEx::vtuEncodingFromName(pa.get("--encoding", "binary"));
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--encoding: ") + e.what());
        }
    } catch (const UsageError& e) {
        std::cerr << "hexex convert: " << e.what() << "\n" << kConvertUsage;
        return 2;
    }
    const std::string in = extensionOf(input), out = extensionOf(output);
    const bool mapOut = out == ".hexex" || out == ".ovm" || out == ".ovmb";
    try {
        bool isMap = in == ".hexex";
        HexEx::ParametrizedTetMesh pm;
        HexEx::HexMesh hm;
        HexEx::ReadReport rr;
        if (in == ".ovm" || in == ".ovmb") {
            std::ifstream f = HexEx::detail::openInputFile(input);
            const HexEx::OvmModel model = HexEx::parseOvm(HexEx::detail::readWholeStream(f, input), input);
            isMap = !model.paramLabel.empty();
            if (isMap) pm = HexEx::tetMeshFromOvm(model, &rr);
            else hm = HexEx::hexMeshFromOvm(model);
        } else if (isMap) {
            pm = HexEx::readHexExFile(input, &rr);
        } else {
            hm = HexEx::readHexMesh(input);
        }
        for (const auto& w : rr.warnings) std::cerr << "hexex convert: warning: " << w << "\n";
        if (isMap) {
            if (!mapOut) {
                std::cerr << "hexex convert: " << input << " is a tet mesh with a map: the output must be .hexex, .ovm "
                          << "or .ovmb, not '" << output << "'\n";
                return 2;
            }
            if (out == ".hexex") HexEx::writeHexExFile(output, pm);
            else HexEx::writeOvmTetMesh(output, pm, out == ".ovmb");
            std::cerr << "hexex convert: wrote " << output << " (" << pm.mesh.n_vertices() << " vertices, "
                      << pm.mesh.n_cells() << " tets with their map)\n";
        } else {
            if (out == ".hexex") {
                std::cerr << "hexex convert: " << input << " is a hex mesh: it cannot be written as .hexex\n";
                return 2;
            }
            for (const auto& w : HexEx::writeHexMesh(output, hm, encoding)) std::cerr << "hexex convert: warning: " << w << "\n";
            std::cerr << "hexex convert: wrote " << output << " (" << hm.vertices.size() << " vertices, "
                      << hm.hexes.size() << " hexes, " << hm.polyhedra.size() << " other cells)\n";
        }
    } catch (const std::exception& e) {
        std::cerr << "hexex convert: error: " << e.what() << "\n";
        return 2;
    }
    return 0;
}

} // namespace HexExTool
