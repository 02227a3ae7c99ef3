/// @file HexFaceRecords.cc
/// Sorted face records of a hex mesh (see HexFaceRecords.hh).

#include "HexFaceRecords.hh"

#include "HexArcs.hh"

#include <algorithm>
#include <utility>

namespace HexEx {

std::vector<HexFaceRecord> sortedHexFaces(const HexMesh& mesh) {
    std::vector<HexFaceRecord> faces;
    faces.reserve(mesh.hexes.size() * 6);
    for (std::size_t c = 0; c < mesh.hexes.size(); ++c)
        for (int f = 0; f < 6; ++f) {
            HexFaceRecord r;
            for (int i = 0; i < 4; ++i)
                r.key[static_cast<std::size_t>(i)] = mesh.hexes[c][static_cast<std::size_t>(HexArcs::kHexFaces[f][i])];
            std::sort(r.key.begin(), r.key.end());
            r.hex = static_cast<int>(c);
            r.face = f;
            faces.push_back(r);
        }
    std::sort(faces.begin(), faces.end(), [](const HexFaceRecord& a, const HexFaceRecord& b) {
        return a.key != b.key ? a.key < b.key : std::make_pair(a.hex, a.face) < std::make_pair(b.hex, b.face);
    });
    return faces;
}

} // namespace HexEx
