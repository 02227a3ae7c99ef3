/// @file OvmTetReader.cc
/// Tet meshes with their map from the OpenVolumeMesh model (OvmModel.hh), and back.

#include "OvmTetReader.hh"
#include "OvmModel.hh"
#include "ReaderSupport.hh"

#include "../Core/Error.hh"
#include "../Core/UnionFind.hh"
#include "../Predicates/ExactPredicates.hh"

#include <algorithm>
#include <map>

namespace HexEx {

ParametrizedTetMesh tetMeshFromOvm(const OvmModel& m, ReadReport* report) {
    std::vector<std::string> warnings = m.warnings;
    if (m.cells.empty()) m.fail(m.endPos, "mesh has no tets (polyhedron count is 0)");
    for (std::size_t f = 0; f < m.faces.size(); ++f)
        if (m.faces[f].size() != 3)
            m.fail(m.facePos[f], "face " + std::to_string(f) + " has valence " + std::to_string(m.faces[f].size()) +
                                     ": only triangles are supported (tetrahedral meshes)");
    for (std::size_t c = 0; c < m.cells.size(); ++c)
        if (m.cells[c].size() != 4)
            m.fail(m.cellPos[c], "polyhedron " + std::to_string(c) + " has " + std::to_string(m.cells[c].size()) +
                                     " halffaces: only tetrahedra (4 triangular halffaces) are supported");
    const std::vector<int> halffaceCell = m.checkTopology();

    // Corners in file corner order: the first halfface's loop, then the fourth vertex.
    std::vector<std::array<int, 4>> corners(m.cells.size());
    for (std::size_t c = 0; c < m.cells.size(); ++c) {
        const std::string cdesc = "polyhedron " + std::to_string(c);
        std::array<std::vector<int>, 4> loops;
        for (int k = 0; k < 4; ++k) loops[k] = m.halffaceLoop(m.cells[c][k]);
        std::array<int, 4> cv{{loops[0][0], loops[0][1], loops[0][2], -1}};
        std::vector<std::pair<int, int>> directed;
        std::vector<std::vector<int>> sets;
        for (const auto& l : loops) {
            for (int j = 0; j < 3; ++j) {
                if (std::find(cv.begin(), cv.end(), l[j]) == cv.end()) {
                    if (cv[3] >= 0)
                        m.fail(m.cellPos[c], cdesc + " is not a tetrahedron: its halffaces span more than four vertices");
                    cv[3] = l[j];
                }
                directed.emplace_back(l[j], l[(j + 1) % 3]);
            }
            sets.push_back(l);
            std::sort(sets.back().begin(), sets.back().end());
        }
        if (cv[3] < 0) m.fail(m.cellPos[c], cdesc + " is not a tetrahedron: all its halffaces lie on three vertices");
        std::sort(sets.begin(), sets.end());
        if (std::adjacent_find(sets.begin(), sets.end()) != sets.end())
            m.fail(m.cellPos[c], cdesc + " is not a tetrahedron: two of its halffaces lie on the same triangle");
        std::sort(directed.begin(), directed.end());
        if (std::adjacent_find(directed.begin(), directed.end()) != directed.end())
            m.fail(m.cellPos[c], cdesc + ": halffaces are not consistently oriented (an edge is traversed twice "
                                         "in the same direction)");
        corners[c] = cv;
    }

    // The map: per halfface the parameter of the opposite corner, or 12 values per cell.
    if (m.paramLabel.empty()) {
        std::string found;
        for (std::size_t i = 0; i < m.skipped.size() && i < 8; ++i) found += (i ? ", " : "") + m.skipped[i];
        if (m.skipped.size() > 8) found += " and " + std::to_string(m.skipped.size() - 8) + " more";
        m.fail(m.endPos, "no parametrization property: expected a halfface property of type vec3d (e.g. "
                         "'HFProp vec3d \"HexHex::Parametrization\"') or 'CProp vec12d \"NAME\"' with NAME (after any "
                         "'X::' prefix) one of Parametrization, Parameterization, param, params, parameter, "
                         "parameters, uvw, igm; found " +
                             (found.empty() ? std::string("no property blocks") : found));
    }
    if (!m.skipped.empty()) {
        std::string list;
        for (const auto& s : m.skipped) list += (list.empty() ? "" : ", ") + s;
        warnings.push_back(m.name + ": skipped " + std::to_string(m.skipped.size()) + " unused propert" +
                           (m.skipped.size() == 1 ? "y: " : "ies: ") + list);
    }
    CornerParams params(corners.size());
    for (std::size_t c = 0; c < corners.size(); ++c)
        for (int j = 0; j < 4; ++j)
            if (m.cellParams.empty()) {
                // The halfface of c not containing corner j carries its parameter.
                for (const int hf : m.cells[c]) {
                    const auto loop = m.halffaceLoop(hf);
                    if (std::find(loop.begin(), loop.end(), corners[c][j]) == loop.end())
                        params[c][j] = m.halffaceParams[static_cast<std::size_t>(hf)];
                }
            } else {
                for (int k = 0; k < 3; ++k) params[c][j][k] = m.cellParams[c][static_cast<std::size_t>(3 * j + k)];
            }

    // Start at the corner opposite the last halfface (corner a of the halffaces a b c, a c d,
    // a d b, b d c that tet a b c d gets in OpenVolumeMesh), so that a tet written that way
    // reads back with its corners in the original order (an even permutation).
    for (std::size_t c = 0; c < corners.size(); ++c) {
        const auto last = m.halffaceLoop(m.cells[c][3]);
        while (std::find(last.begin(), last.end(), corners[c][0]) != last.end()) {
            std::rotate(corners[c].begin(), corners[c].begin() + 1, corners[c].begin() + 3);
            std::rotate(params[c].begin(), params[c].begin() + 1, params[c].begin() + 3);
        }
    }

    // Orientation: exact sign per cell, uniform per connected component.
    const auto& P = m.vertices;
    std::vector<int> sign(corners.size());
    for (std::size_t c = 0; c < corners.size(); ++c) {
        const auto& cv = corners[c];
        sign[c] = orient3d(P[cv[0]], P[cv[1]], P[cv[2]], P[cv[3]]);
        if (sign[c] == 0) m.fail(m.cellPos[c], "polyhedron " + std::to_string(c) + " is degenerate in 3D (zero volume)");
    }
    UnionFind components(corners.size());
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        const int a = halffaceCell[2 * f], b = halffaceCell[2 * f + 1];
        if (a >= 0 && b >= 0) components.unite(a, b);
    }
    std::map<int, std::array<std::vector<int>, 2>> bySign;  // root -> (positive, negative) cells
    for (std::size_t c = 0; c < corners.size(); ++c)
        bySign[components.find(static_cast<int>(c))][sign[c] > 0 ? 0 : 1].push_back(static_cast<int>(c));
    for (const auto& [root, cs] : bySign) {
        if (cs[0].empty() || cs[1].empty()) continue;
        const auto& minor = cs[1].size() <= cs[0].size() ? cs[1] : cs[0];
        m.fail(m.cellPos[static_cast<std::size_t>(minor[0])],
               "inconsistent orientation: polyhedron " + std::to_string(minor[0]) + " is inverted in 3D relative to its "
               "neighbours (" + std::to_string(minor.size()) + " of " + std::to_string(cs[0].size() + cs[1].size()) +
                   " cells of its connected component disagree with the others)");
    }

    ParametrizedTetMesh pm;
    pm.mesh.reserve(P.size(), corners.size());
    for (const auto& p : P) pm.mesh.add_vertex(p);
    std::vector<char> used(P.size(), 0);
    for (std::size_t c = 0; c < corners.size(); ++c) {
        auto& cv = corners[c];
        if (sign[c] < 0) {
            std::swap(cv[1], cv[2]);
            std::swap(params[c][1], params[c][2]);
        }
        pm.mesh.add_cell({VertexHandle(cv[0]), VertexHandle(cv[1]), VertexHandle(cv[2]), VertexHandle(cv[3])});
        for (const int v : cv) used[static_cast<std::size_t>(v)] = 1;
    }
    pm.params = std::move(params);
    const auto nUnused = std::count(used.begin(), used.end(), 0);
    if (nUnused > 0)
        warnings.push_back(m.name + ": " + std::to_string(nUnused) + " of " + std::to_string(P.size()) +
                           " vertices are not used by any tet");
    detail::finishTetMesh(pm, m.name);
    if (report) report->warnings.insert(report->warnings.end(), warnings.begin(), warnings.end());
    return pm;
}

OvmModel ovmFromTetMesh(const ParametrizedTetMesh& pm) {
    if (pm.params.size() != pm.mesh.n_cells())
        throw std::invalid_argument("ovmFromTetMesh: " + std::to_string(pm.params.size()) + " parameter sets for " +
                                    std::to_string(pm.mesh.n_cells()) + " tets");
    OvmModel m;
    m.topology = OvmTopology::Tetrahedral;
    for (std::size_t v = 0; v < pm.mesh.n_vertices(); ++v) m.vertices.push_back(pm.mesh.position(VertexHandle(static_cast<int>(v))));
    // Halffaces a b c, a c d, a d b, b d c of tet a b c d point into it; opposite corners d, b, c, a.
    static const int kFaces[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
    IntLists loops;
    loops.reserve(4 * pm.mesh.n_cells(), 12 * pm.mesh.n_cells());
    for (std::size_t c = 0; c < pm.mesh.n_cells(); ++c) {
        const auto cv = pm.mesh.cell_vertices(CellHandle(static_cast<int>(c)));
        for (const auto& lf : kFaces) {
            const int t[3] = {cv[lf[0]].idx(), cv[lf[1]].idx(), cv[lf[2]].idx()};
            loops.add(t, t + 3);
        }
    }
    OvmFaces faces = buildOvmFaces(loops, static_cast<int>(m.vertices.size()));
    m.edges = std::move(faces.edges);
    for (std::size_t f = 0; f < faces.faceHalfedges.size(); ++f)
        m.faces.emplace_back(faces.faceHalfedges.begin(f), faces.faceHalfedges.end(f));
    for (std::size_t c = 0; c < pm.mesh.n_cells(); ++c)
        m.cells.emplace_back(faces.halffaces.begin() + static_cast<std::ptrdiff_t>(4 * c),
                             faces.halffaces.begin() + static_cast<std::ptrdiff_t>(4 * c + 4));
    m.halffaceParams.assign(2 * m.faces.size(), Vec3d(0, 0, 0));
    for (std::size_t c = 0; c < m.cells.size(); ++c)
        for (int k = 0; k < 4; ++k) m.halffaceParams[static_cast<std::size_t>(m.cells[c][k])] = pm.params[c][kFaces[k][3]];
    return m;
}

ParametrizedTetMesh readOvmTetBuffer(std::string_view data, const std::string& name, ReadReport* report) {
    return tetMeshFromOvm(parseOvm(data, name), report);
}

ParametrizedTetMesh readOvmTetMesh(const std::string& path, ReadReport* report) {
    return readOvmTetBuffer(detail::readWholeFile(path), path, report);
}

void writeOvmTetMesh(const std::string& path, const ParametrizedTetMesh& pm, bool binary) {
    const OvmModel m = ovmFromTetMesh(pm);
    detail::writeWholeFile(path, binary ? writeOvmBinary(m) : writeOvmAscii(m));
}

} // namespace HexEx
