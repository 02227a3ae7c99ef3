/// @file MapStatistics.cc
/// Implementation of computeMapStatistics().

#include "MapStatistics.hh"

#include "../Core/CompensatedSum.hh"

#include "../Predicates/ExactPredicates.hh"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace HexEx {

namespace {

/// Counts faces that occur in exactly one tet, by sorting the sorted vertex triples.
std::size_t countBoundaryFaces(const TetMesh& mesh) {
    std::vector<std::array<int, 3>> faces;
    faces.reserve(mesh.n_halffaces());
    for (std::size_t hf = 0; hf < mesh.n_halffaces(); ++hf) {
        const auto fv = mesh.halfface_vertices(HalfFaceHandle(static_cast<int>(hf)));
        std::array<int, 3> key = {fv[0].idx(), fv[1].idx(), fv[2].idx()};
        std::sort(key.begin(), key.end());
        faces.push_back(key);
    }
    std::sort(faces.begin(), faces.end());
    std::size_t n = 0;
    for (std::size_t i = 0; i < faces.size();) {
        std::size_t j = i + 1;
        while (j < faces.size() && faces[j] == faces[i]) ++j;
        if (j - i == 1) ++n;
        i = j;
    }
    return n;
}

} // namespace

MapStatistics computeMapStatistics(const ParametrizedTetMesh& pm) {
    MapStatistics s;
    const TetMesh& mesh = pm.mesh;
    s.vertices = mesh.n_vertices();
    s.tets = mesh.n_cells();
    s.boundary_faces = mesh.has_adjacency() ? mesh.n_boundary_faces() : countBoundaryFaces(mesh);

    bool first = true;
    CompensatedSum volume6;  // the volume of a large map stays exact to the last digits
    const std::size_t n = std::min(pm.params.size(), mesh.n_cells());
    for (std::size_t c = 0; c < n; ++c) {
        const auto& p = pm.params[c];
        const int sign = orient3d(p[0], p[1], p[2], p[3]);
        if (sign < 0) ++s.flipped_tets;
        if (sign == 0) ++s.degenerate_tets;
        const double det = tetVolume6(p[0], p[1], p[2], p[3]);
        volume6.add(det);
        for (const auto& q : p) {
            if (first) {
                s.param_bbox_min = s.param_bbox_max = q;
                first = false;
            } else {
                s.param_bbox_min.minimize(q);
                s.param_bbox_max.maximize(q);
            }
        }
    }
    s.parametric_volume = volume6.value() / 6.0;
    return s;
}

} // namespace HexEx
