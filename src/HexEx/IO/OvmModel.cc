/// @file OvmModel.cc
/// Checks and helpers shared by the OpenVolumeMesh readers and writers.

#include "OvmModel.hh"

#include "../Core/Error.hh"

#include <algorithm>
#include <cctype>

namespace HexEx {

void OvmModel::fail(long long pos, const std::string& reason) const {
    if (binary) throw InputError(name + ": byte " + std::to_string(pos) + ": " + reason);
    throw InputError(name + ":" + std::to_string(pos) + ": " + reason);
}

std::vector<int> OvmModel::halffaceLoop(int hf) const {
    std::vector<int> loop;
    for (const int he : faces[static_cast<std::size_t>(hf / 2)]) loop.push_back(edges[he / 2][he % 2]);
    if (hf % 2) std::reverse(loop.begin() + 1, loop.end());
    return loop;
}

std::vector<int> OvmModel::checkTopology() const {
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const auto& hes = faces[f];
        const std::vector<int> loop = halffaceLoop(static_cast<int>(2 * f));
        for (std::size_t k = 0; k < hes.size(); ++k) {
            const int he = hes[k], nx = hes[(k + 1) % hes.size()];
            if (edges[he / 2][1 - he % 2] != edges[nx / 2][nx % 2])
                fail(facePos[f], "face " + std::to_string(f) + ": halfedges " + std::to_string(he) + " and " +
                                     std::to_string(nx) + " are not consecutive (the loop is not closed)");
        }
        for (std::size_t k = 0; k < hes.size(); ++k) {
            if (std::count(loop.begin(), loop.end(), loop[k]) != 1)
                fail(facePos[f], "face " + std::to_string(f) + " repeats vertex " + std::to_string(loop[k]));
        }
    }
    std::vector<int> owner(2 * faces.size(), -1);
    for (std::size_t c = 0; c < cells.size(); ++c)
        for (const int hf : cells[c]) {
            int& o = owner[static_cast<std::size_t>(hf)];
            if (o == static_cast<int>(c))
                fail(cellPos[c], "polyhedron " + std::to_string(c) + " lists halfface " + std::to_string(hf) + " twice");
            if (o >= 0)
                fail(cellPos[c], "halfface " + std::to_string(hf) + " is used by polyhedron " + std::to_string(o) +
                                     " and polyhedron " + std::to_string(c));
            o = static_cast<int>(c);
        }
    return owner;
}

OvmFlatMesh flatOvm(const OvmModel& model) {
    OvmFlatMesh f;
    f.topology = model.topology;
    f.vertices = &model.vertices;
    f.edges = model.edges;
    for (const auto& l : model.faces) f.faces.add(l.begin(), l.end());
    for (const auto& l : model.cells) f.cells.add(l.begin(), l.end());
    if (!model.halffaceParams.empty()) f.halffaceParams = &model.halffaceParams;
    return f;
}

bool isParametrizationName(std::string_view name) {
    const std::size_t sep = name.rfind("::");
    if (sep != std::string_view::npos) name.remove_prefix(sep + 2);
    std::string l(name);
    for (auto& c : l) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const char* k : {"parametrization", "parameterization", "param", "params", "parameter", "parameters", "uvw",
                          "igm"})
        if (l == k) return true;
    return false;
}

OvmModel parseOvm(std::string_view data, const std::string& name) {
    if (data.size() >= 4 && data.substr(0, 4) == "OVMB") return parseOvmBinary(data, name);
    return parseOvmAscii(data, name);
}

} // namespace HexEx
