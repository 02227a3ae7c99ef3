#include "TetMeshInput.hh"

#include "OvmTetReader.hh"

#include <cctype>
#include <iostream>

namespace HexEx {

ParametrizedTetMesh readParametrizedTetMesh(const std::string& path, ReadReport* report) {
    if (path == "-") return readHexExStream(std::cin, "<stdin>", report);
    std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : std::string();
    for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    return ext == ".ovm" ? readOvmTetMesh(path, report) : readHexExFile(path, report);
}

} // namespace HexEx
