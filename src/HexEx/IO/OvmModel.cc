/// @file OvmModel.cc
/// Checks and helpers shared by the OpenVolumeMesh readers and writers.

#include "OvmModel.hh"

#include "../Core/Error.hh"

#include <algorithm>
#include <cctype>
#include <cstdint>

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

int OvmBuilder::halfface(const std::vector<int>& loop) {
    std::vector<int> key = loop, other;
    std::sort(key.begin(), key.end());
    std::uint64_t h = 1469598103934665603ull;
    for (const int v : key) h = (h ^ static_cast<std::uint32_t>(v)) * 1099511628211ull;
    for (auto [it, end] = faceId_.equal_range(h); it != end; ++it) {
        const auto& s = loops_[static_cast<std::size_t>(it->second)];
        other.assign(s.begin(), s.end());
        std::sort(other.begin(), other.end());
        if (other != key) continue;
        const std::size_t k = static_cast<std::size_t>(std::find(s.begin(), s.end(), loop[0]) - s.begin());
        return 2 * it->second + (s[(k + 1) % s.size()] == loop[1] ? 0 : 1);
    }
    faceId_.emplace(h, static_cast<int>(loops_.size()));
    loops_.push_back(loop);
    return 2 * static_cast<int>(loops_.size() - 1);
}

void OvmBuilder::finish() {
    std::unordered_map<std::uint64_t, int> edgeId;
    for (const auto& loop : loops_) {
        auto& hes = m_.faces.emplace_back();
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const int a = loop[i], b = loop[(i + 1) % loop.size()];
            const std::uint64_t key = static_cast<std::uint64_t>(static_cast<std::uint32_t>(std::min(a, b))) << 32 |
                                      static_cast<std::uint32_t>(std::max(a, b));
            const int e = edgeId.emplace(key, static_cast<int>(m_.edges.size())).first->second;
            if (e == static_cast<int>(m_.edges.size())) m_.edges.push_back({{a, b}});
            hes.push_back(2 * e + (m_.edges[static_cast<std::size_t>(e)][0] == a ? 0 : 1));
        }
    }
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
