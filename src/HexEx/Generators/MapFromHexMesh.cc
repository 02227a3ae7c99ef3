/// @file MapFromHexMesh.cc
/// Hex mesh -> integer-grid map with one random chart per hex (see MapFromHexMesh.hh).

#include "MapFromHexMesh.hh"

#include "../Core/Error.hh"
#include "../Predicates/ExactPredicates.hh"
#include "RandomDraws.hh"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace HexEx {

namespace {

/// The six quads of a VTK hex as corner loops, oriented outward.
constexpr int kHexFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

/// One occurrence of a quad in a hex, for grouping the shared quads.
struct FaceOccurrence {
    std::array<int, 4> key;  ///< sorted vertex indices
    int occurrence;          ///< 6 * hex + local face
};

/// Position of @p v in the corner list of @p hex, or -1.
int cornerIndex(const std::array<int, 8>& hex, int v) {
    for (int i = 0; i < 8; ++i)
        if (hex[i] == v) return i;
    return -1;
}

/// The rotation mapping @p a1 to @p b1 and @p a2 to @p b2 (axis vectors), if one exists.
bool findRotation(const Vec3i& a1, const Vec3i& a2, const Vec3i& b1, const Vec3i& b2, Rotation& out) {
    for (int r = 0; r < Rotation::kCount; ++r) {
        const Rotation rot(r);
        if (rot.apply(a1) == b1 && rot.apply(a2) == b2) {
            out = rot;
            return true;
        }
    }
    return false;
}

/// Outward normal (an axis vector) of VTK hex face @p j in the local lattice.
Vec3i outwardNormal(int j) {
    const int* loop = kHexFaces[j];
    for (int k = 0; k < 3; ++k) {
        bool same = true;
        for (int q = 1; q < 4; ++q) same = same && hexCornerLattice(loop[q])[k] == hexCornerLattice(loop[0])[k];
        if (same) {
            Vec3i n(0, 0, 0);
            n[k] = hexCornerLattice(loop[0])[k] ? 1 : -1;
            return n;
        }
    }
    return Vec3i(0, 0, 0);
}

/// Noise uniform in [-a, a], quantized to multiples of 2^-20 so that charts stay exact.
double quantizedNoise(std::mt19937& gen, double a) {
    const double x = a * (2.0 * uniform01(gen) - 1.0);
    return std::round(x * 1048576.0) / 1048576.0;
}

} // namespace

Vec3i hexCornerLattice(int i) {
    static const int xy[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    return Vec3i(xy[i & 3][0], xy[i & 3][1], i >= 4 ? 1 : 0);
}

MapFromHexResult mapFromHexMesh(const HexMesh& hexes, const MapFromHexOptions& options) {
    if (!(options.perturb >= 0.0 && options.perturb <= 2.0))
        throw std::invalid_argument("mapFromHexMesh: perturbation must lie in [0, 2], got " +
                                    std::to_string(options.perturb));
    if (options.scale < 1 || options.scale > 1000)
        throw std::invalid_argument("mapFromHexMesh: scale must lie in [1, 1000], got " +
                                    std::to_string(options.scale));
    if (!hexes.polyhedra.empty())
        throw InputError("mapFromHexMesh: the mesh has " + std::to_string(hexes.polyhedra.size()) +
                         " non-hex cells; only all-hex meshes can be turned into a map");
    const int nv = static_cast<int>(hexes.vertices.size());
    const int nh = static_cast<int>(hexes.hexes.size());
    if (hexes.hexes.size() > 20000000u) throw InputError("mapFromHexMesh: too many hexes");
    for (int h = 0; h < nh; ++h) {
        const auto& hx = hexes.hexes[h];
        for (int i = 0; i < 8; ++i) {
            if (hx[i] < 0 || hx[i] >= nv)
                throw InputError("mapFromHexMesh: hex " + std::to_string(h) + " has vertex index " +
                                 std::to_string(hx[i]) + " out of range [0, " + std::to_string(nv) + ")");
            for (int j = 0; j < i; ++j)
                if (hx[j] == hx[i])
                    throw InputError("mapFromHexMesh: hex " + std::to_string(h) + " repeats vertex " +
                                     std::to_string(hx[i]));
        }
    }

    // Distinct quads, numbered by first occurrence.
    std::vector<FaceOccurrence> occ;
    occ.reserve(6u * static_cast<std::size_t>(nh));
    for (int h = 0; h < nh; ++h)
        for (int j = 0; j < 6; ++j) {
            FaceOccurrence o;
            for (int k = 0; k < 4; ++k) o.key[k] = hexes.hexes[h][kHexFaces[j][k]];
            std::sort(o.key.begin(), o.key.end());
            o.occurrence = 6 * h + j;
            occ.push_back(o);
        }
    std::sort(occ.begin(), occ.end(), [](const FaceOccurrence& a, const FaceOccurrence& b) {
        return a.key != b.key ? a.key < b.key : a.occurrence < b.occurrence;
    });
    std::vector<int> faceOf(occ.size(), -1);  // per occurrence: face id
    std::vector<int> partner(occ.size(), -1);  // per occurrence: the other occurrence of the face
    {
        std::vector<std::pair<int, int>> groups;  // (first occurrence, second or -1)
        for (std::size_t a = 0; a < occ.size();) {
            std::size_t b = a + 1;
            while (b < occ.size() && occ[b].key == occ[a].key) ++b;
            if (b - a > 2)
                throw InputError("mapFromHexMesh: quad (" + std::to_string(occ[a].key[0]) + ", " +
                                 std::to_string(occ[a].key[1]) + ", " + std::to_string(occ[a].key[2]) + ", " +
                                 std::to_string(occ[a].key[3]) + ") is shared by " + std::to_string(b - a) + " hexes");
            groups.emplace_back(occ[a].occurrence, b - a == 2 ? occ[a + 1].occurrence : -1);
            a = b;
        }
        std::sort(groups.begin(), groups.end());
        for (std::size_t f = 0; f < groups.size(); ++f) {
            faceOf[groups[f].first] = static_cast<int>(f);
            if (groups[f].second >= 0) {
                faceOf[groups[f].second] = static_cast<int>(f);
                partner[groups[f].first] = groups[f].second;
                partner[groups[f].second] = groups[f].first;
            }
        }
    }
    const int nf = static_cast<int>(*std::max_element(faceOf.begin(), faceOf.end()) + 1);

    MapFromHexResult res;
    res.faces = static_cast<std::size_t>(nf);
    const int K = options.scale;
    const double a = options.perturb;
    std::mt19937 gen(options.seed);
    res.charts.reserve(static_cast<std::size_t>(nh));
    for (int h = 0; h < nh; ++h) {
        const Rotation r(static_cast<int>(uniformBelow(gen, Rotation::kCount)));
        Vec3i t;
        for (int d = 0; d < 3; ++d) t[d] = static_cast<int>(uniformBelow(gen, 11)) - 5;
        res.charts.emplace_back(r, t);
    }
    // Face centre displacement, in the local frame of the face's first hex.
    std::vector<Vec3d> faceDelta(static_cast<std::size_t>(nf));
    std::vector<int> faceFirst(static_cast<std::size_t>(nf), -1);
    for (std::size_t o = 0; o < faceOf.size(); ++o)
        if (faceFirst[faceOf[o]] < 0) faceFirst[faceOf[o]] = static_cast<int>(o);
    for (int f = 0; f < nf; ++f) {
        Vec3d d;
        for (int k = 0; k < 3; ++k) d[k] = quantizedNoise(gen, a);
        const int o = faceFirst[f];
        if (partner[o] < 0) {
            ++res.boundary_faces;
            // Keep boundary face centres in their plane: zero the normal axis.
            const int* loop = kHexFaces[o % 6];
            for (int k = 0; k < 3; ++k) {
                bool same = true;
                for (int q = 1; q < 4; ++q) same = same && hexCornerLattice(loop[q])[k] == hexCornerLattice(loop[0])[k];
                if (same) d[k] = 0.0;
            }
        }
        faceDelta[f] = d;
    }
    std::vector<Vec3d> cellDelta(static_cast<std::size_t>(nh));
    for (int h = 0; h < nh; ++h)
        for (int k = 0; k < 3; ++k) cellDelta[h][k] = quantizedNoise(gen, a);

    // Face centre displacement as seen from occurrence o (6 h + j).
    auto localFaceDelta = [&](int o) -> Vec3d {
        const int f = faceOf[o];
        const int first = faceFirst[f];
        if (first == o) return faceDelta[f];
        const auto& ha = hexes.hexes[first / 6];
        const auto& hb = hexes.hexes[o / 6];
        const int* loop = kHexFaces[first % 6];
        Vec3i la[3], lb[3];
        const int pick[3] = {0, 1, 3};
        for (int k = 0; k < 3; ++k) {
            const int v = ha[loop[pick[k]]];
            la[k] = hexCornerLattice(loop[pick[k]]);
            lb[k] = hexCornerLattice(cornerIndex(hb, v));
        }
        Rotation rot;
        // Consistent orientation: A's outward normal becomes B's inward normal.
        if (!findRotation(la[1] - la[0], la[2] - la[0], lb[1] - lb[0], lb[2] - lb[0], rot) ||
            rot.apply(outwardNormal(first % 6)) != -outwardNormal(o % 6))
            throw InputError("mapFromHexMesh: hexes " + std::to_string(first / 6) + " and " + std::to_string(o / 6) +
                             " share a quad with inconsistent orientation or corner order");
        return rot.apply(faceDelta[f]);
    };

    TetMesh& mesh = res.map.mesh;
    mesh.reserve(static_cast<std::size_t>(nv + nf + nh), 24u * static_cast<std::size_t>(nh));
    res.map.params.reserve(24u * static_cast<std::size_t>(nh));
    for (int v = 0; v < nv; ++v) mesh.add_vertex(hexes.vertices[v]);
    std::vector<Vec3d> faceCentre(static_cast<std::size_t>(nf));
    for (int f = 0; f < nf; ++f) {
        const int o = faceFirst[f];
        Vec3d c(0, 0, 0);
        for (int k = 0; k < 4; ++k) c += hexes.vertices[hexes.hexes[o / 6][kHexFaces[o % 6][k]]];
        mesh.add_vertex(c * 0.25);
    }
    for (int h = 0; h < nh; ++h) {
        Vec3d c(0, 0, 0);
        for (int k = 0; k < 8; ++k) c += hexes.vertices[hexes.hexes[h][k]];
        mesh.add_vertex(c * 0.125);
    }
    for (int h = 0; h < nh; ++h) {
        const GridTransform& g = res.charts[h];
        const VertexHandle cellV(nv + nf + h);
        const Vec3d cellLocal = Vec3d(0.5 * K, 0.5 * K, 0.5 * K);
        const Vec3d cellP = g.apply(cellLocal + cellDelta[h]);
        for (int j = 0; j < 6; ++j) {
            const int o = 6 * h + j;
            const int* loop = kHexFaces[j];
            Vec3d faceLocal(0, 0, 0);
            for (int k = 0; k < 4; ++k) faceLocal += toVec3d(hexCornerLattice(loop[k])) * (0.25 * K);
            const Vec3d faceP = g.apply(faceLocal + localFaceDelta(o));
            const VertexHandle faceV(nv + faceOf[o]);
            for (int k = 0; k < 4; ++k) {
                int ca = loop[k], cb = loop[(k + 1) % 4];
                // Unperturbed local orientation decides the corner order (exact: halves and integers).
                const Vec3d la = toVec3d(hexCornerLattice(ca)) * K, lb = toVec3d(hexCornerLattice(cb)) * K;
                if (orient3d(cellLocal, faceLocal, la, lb) < 0) std::swap(ca, cb);
                const VertexHandle va(hexes.hexes[h][ca]), vb(hexes.hexes[h][cb]);
                mesh.add_cell({cellV, faceV, va, vb});
                res.map.params.push_back({cellP, faceP, g.apply(toVec3d(hexCornerLattice(ca)) * K),
                                          g.apply(toVec3d(hexCornerLattice(cb)) * K)});
                if (orient3d(mesh.position(cellV), mesh.position(faceV), mesh.position(va), mesh.position(vb)) <= 0)
                    ++res.negative_tets_3d;
            }
        }
    }
    return res;
}

} // namespace HexEx
