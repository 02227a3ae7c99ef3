/// @file FoldedBoundary.cc
/// Boundary doublets and hexes outside the input surface (see FoldedBoundary.hh).

#include "FoldedBoundary.hh"

#include "../Mesh/HexArcs.hh"
#include "../Mesh/HexFaceRecords.hh"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace HexEx {

std::vector<int> boundaryDoublets(const HexMesh& mesh) {
    const std::vector<HexFaceRecord> faces = sortedHexFaces(mesh);
    // Per boundary vertex: its boundary quads' neighbours along the quad edges at it.
    std::vector<std::pair<int, std::array<int, 2>>> corners;  // (vertex, {next, prev})
    for (std::size_t i = 0; i < faces.size();) {
        std::size_t j = i;
        while (j < faces.size() && faces[j].key == faces[i].key) ++j;
        if (j - i == 1) {
            const auto& h = mesh.hexes[static_cast<std::size_t>(faces[i].hex)];
            for (int k = 0; k < 4; ++k) {
                const int v = h[static_cast<std::size_t>(HexArcs::kHexFaces[faces[i].face][k])];
                int a = h[static_cast<std::size_t>(HexArcs::kHexFaces[faces[i].face][(k + 1) % 4])];
                int b = h[static_cast<std::size_t>(HexArcs::kHexFaces[faces[i].face][(k + 3) % 4])];
                if (a > b) std::swap(a, b);
                corners.push_back({v, {a, b}});
            }
        }
        i = j;
    }
    std::sort(corners.begin(), corners.end());
    std::vector<int> out;
    for (std::size_t i = 0; i < corners.size();) {
        std::size_t j = i;
        while (j < corners.size() && corners[j].first == corners[i].first) ++j;
        if (j - i == 2 && corners[i].second == corners[i + 1].second) out.push_back(corners[i].first);
        i = j;
    }
    return out;
}

double windingNumber(const TriangleSurface& surface, const Vec3d& p) {
    // Van Oosterom and Strackee's formula for the solid angle of each triangle.
    double sum = 0;
    for (const auto& t : surface.triangles) {
        const Vec3d a = surface.points[static_cast<std::size_t>(t[0])] - p;
        const Vec3d b = surface.points[static_cast<std::size_t>(t[1])] - p;
        const Vec3d c = surface.points[static_cast<std::size_t>(t[2])] - p;
        const double la = a.norm(), lb = b.norm(), lc = c.norm();
        const double num = a | (b % c);
        const double den = la * lb * lc + (a | b) * lc + (b | c) * la + (c | a) * lb;
        sum += 2 * std::atan2(num, den);
    }
    return sum / (4 * M_PI);
}

std::vector<int> hexesOutsideSurface(const HexMesh& mesh, const TriangleSurface& surface, const std::vector<int>& seeds) {
    const std::size_t nh = mesh.hexes.size();
    const std::vector<HexFaceRecord> faces = sortedHexFaces(mesh);
    // Face neighbours: position of each (hex, face) record, and the record's partner.
    std::vector<int> partner(nh * 6, -1);
    for (std::size_t i = 0; i + 1 < faces.size(); ++i)
        if (faces[i].key == faces[i + 1].key) {
            partner[static_cast<std::size_t>(faces[i].hex) * 6 + static_cast<std::size_t>(faces[i].face)] = faces[i + 1].hex;
            partner[static_cast<std::size_t>(faces[i + 1].hex) * 6 + static_cast<std::size_t>(faces[i + 1].face)] = faces[i].hex;
        }
    auto outside = [&](int c) {
        Vec3d centre(0, 0, 0);
        for (const int v : mesh.hexes[static_cast<std::size_t>(c)]) centre += mesh.vertices[static_cast<std::size_t>(v)] * 0.125;
        return std::abs(windingNumber(surface, centre)) < 0.5;  // -1 inside an inward-oriented surface
    };
    std::vector<char> seen(nh, 0), out(nh, 0);
    std::vector<int> stack;
    for (const int s : seeds)
        if (s >= 0 && static_cast<std::size_t>(s) < nh && !seen[static_cast<std::size_t>(s)]) {
            seen[static_cast<std::size_t>(s)] = 1;
            stack.push_back(s);
        }
    while (!stack.empty()) {
        const int c = stack.back();
        stack.pop_back();
        if (!outside(c)) continue;
        out[static_cast<std::size_t>(c)] = 1;
        for (std::size_t f = 0; f < 6; ++f) {
            const int d = partner[static_cast<std::size_t>(c) * 6 + f];
            if (d >= 0 && !seen[static_cast<std::size_t>(d)]) {
                seen[static_cast<std::size_t>(d)] = 1;
                stack.push_back(d);
            }
        }
    }
    std::vector<int> result;
    for (std::size_t c = 0; c < nh; ++c)
        if (out[c]) result.push_back(static_cast<int>(c));
    return result;
}

std::vector<int> removeHexes(HexMesh& mesh, const std::vector<int>& hexes) {
    if (!mesh.polyhedra.empty())
        throw std::invalid_argument("removeHexes: the mesh has " + std::to_string(mesh.polyhedra.size()) + " polyhedra");
    const std::size_t nh = mesh.hexes.size(), nv = mesh.vertices.size();
    std::vector<char> gone(nh, 0);
    for (const int c : hexes)
        if (c >= 0 && static_cast<std::size_t>(c) < nh) gone[static_cast<std::size_t>(c)] = 1;
    std::vector<char> exposed(nv, 0);
    const std::vector<HexFaceRecord> faces = sortedHexFaces(mesh);
    for (std::size_t i = 0; i + 1 < faces.size(); ++i)
        if (faces[i].key == faces[i + 1].key &&
            gone[static_cast<std::size_t>(faces[i].hex)] != gone[static_cast<std::size_t>(faces[i + 1].hex)])
            for (const int v : faces[i].key) exposed[static_cast<std::size_t>(v)] = 1;
    std::vector<int> remap(nv, -1);
    std::size_t kept = 0;
    for (std::size_t c = 0; c < nh; ++c)
        if (!gone[c])
            for (const int v : mesh.hexes[c]) remap[static_cast<std::size_t>(v)] = 0;
    std::vector<Vec3d> vertices;
    for (std::size_t v = 0; v < nv; ++v)
        if (remap[v] == 0) {
            remap[v] = static_cast<int>(vertices.size());
            vertices.push_back(mesh.vertices[v]);
        }
    for (std::size_t c = 0; c < nh; ++c) {
        if (gone[c]) continue;
        auto h = mesh.hexes[c];
        for (auto& v : h) v = remap[static_cast<std::size_t>(v)];
        mesh.hexes[kept++] = h;
    }
    mesh.hexes.resize(kept);
    mesh.vertices = std::move(vertices);
    std::vector<int> out;
    for (std::size_t v = 0; v < nv; ++v)
        if (exposed[v] && remap[v] >= 0) out.push_back(remap[v]);
    return out;
}

} // namespace HexEx
