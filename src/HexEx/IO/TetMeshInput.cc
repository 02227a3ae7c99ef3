#include "TetMeshInput.hh"

#include "OvmTetReader.hh"

#include <cctype>
#include <iostream>

namespace HexEx {

ParametrizedTetMesh readParametrizedTetMesh(const std::string& path, ReadReport* report) {
    if (path == "-") return readHexExStream(std::cin, "<stdin>", report);
    std::string ext = path.substr(path.find_last_of('.') == std::string::npos ? path.size() : path.find_last_of('.'));
    for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    return ext == ".ovm" || ext == ".ovmb" ? readOvmTetMesh(path, report) : readHexExFile(path, report);
}

} // namespace HexEx
