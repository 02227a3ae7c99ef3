/// @file InfoCommand.cc
/// `hexex info IN [--json]`: statistics of a tet mesh (.hexex, .ovm or .ovmb) with its map.

#include "ArgParser.hh"
#include "Commands.hh"

#include <HexEx/Core/Error.hh>
#include <HexEx/IO/HexExFile.hh>
#include <HexEx/IO/TetMeshInput.hh>
#include <HexEx/IO/MapStatistics.hh>
#include <HexEx/IO/ReportJson.hh>

#include <cmath>
#include <iostream>
#include <string>

namespace HexExTool {

namespace {

using HexEx::jsonNumber;
using HexEx::jsonQuote;

/// "[x, y, z]".
std::string jsonVec(const HexEx::Vec3d& v) {
    return "[" + jsonNumber(v[0]) + ", " + jsonNumber(v[1]) + ", " + jsonNumber(v[2]) + "]";
}

const char* kInfoUsage = "usage: hexex info IN.hexex|IN.ovm|IN.ovmb [--json]\n";

} // namespace

int runInfo(const Args& args) {
    std::string input;
    bool json = false;
    try {
        const InputAndJson a = parseInputAndJson(args);
        if (a.help) {
            std::cout << kInfoUsage;
            return 0;
        }
        input = a.input;
        json = a.json;
    } catch (const UsageError& e) {
        std::cerr << "hexex info: " << e.what() << "\n" << kInfoUsage;
        return 2;
    }

    HexEx::ReadReport report;
    HexEx::ParametrizedTetMesh pm;
    try {
        pm = HexEx::readParametrizedTetMesh(input, &report);
    } catch (const HexEx::InputError& e) {
        std::cerr << "hexex info: error: " << e.what() << "\n";
        return 2;
    }
    const HexEx::MapStatistics s = HexEx::computeMapStatistics(pm);

    if (json) {
        std::cout << "{\n"
                  << "  \"vertices\": " << s.vertices << ",\n"
                  << "  \"tets\": " << s.tets << ",\n"
                  << "  \"boundary_faces\": " << s.boundary_faces << ",\n"
                  << "  \"flipped_tets\": " << s.flipped_tets << ",\n"
                  << "  \"degenerate_tets\": " << s.degenerate_tets << ",\n"
                  << "  \"parametric_volume\": " << jsonNumber(s.parametric_volume) << ",\n"
                  << "  \"param_bbox_min\": " << jsonVec(s.param_bbox_min) << ",\n"
                  << "  \"param_bbox_max\": " << jsonVec(s.param_bbox_max) << ",\n"
                  << "  \"warnings\": [";
        for (std::size_t i = 0; i < report.warnings.size(); ++i)
            std::cout << (i ? ", " : "") << jsonQuote(report.warnings[i]);
        std::cout << "]\n}\n";
    } else {
        std::cout << "file:              " << input << "\n"
                  << "vertices:          " << s.vertices << "\n"
                  << "tets:              " << s.tets << "\n"
                  << "boundary faces:    " << s.boundary_faces << "\n"
                  << "flipped tets:      " << s.flipped_tets << "\n"
                  << "degenerate tets:   " << s.degenerate_tets << "\n"
                  << "parametric volume: " << jsonNumber(s.parametric_volume) << "\n"
                  << "param bbox min:    " << jsonNumber(s.param_bbox_min[0]) << " " << jsonNumber(s.param_bbox_min[1]) << " "
                  << jsonNumber(s.param_bbox_min[2]) << "\n"
                  << "param bbox max:    " << jsonNumber(s.param_bbox_max[0]) << " " << jsonNumber(s.param_bbox_max[1]) << " "
                  << jsonNumber(s.param_bbox_max[2]) << "\n";
        for (const auto& w : report.warnings) std::cout << "warning: " << w << "\n";
    }
    return 0;
}

} // namespace HexExTool
