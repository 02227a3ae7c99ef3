#include "GridPointPosition.hh"

#include <algorithm>

namespace HexEx {

Vec3d gridPointPosition(const TetMesh& mesh, const std::vector<TetSoS>& tets, const DartSet& ds, int t, const Vec3i& zi,
                        std::array<int, 3>* boundaryHf) {
    const TetSoS& T = tets[static_cast<std::size_t>(t)];
    const auto& cv = mesh.cell_vertices(CellHandle(t));
    const Vec3d z = toVec3d(zi);
    // Exact zeros: from the implicit-cell flags where the tet has them, else predicates.
    std::array<int, 4> oz;
    const int slot = ds.dense_slot[static_cast<std::size_t>(t)];
    const DartSet::DenseIndex* di = slot >= 0 ? &ds.dense[static_cast<std::size_t>(slot)] : nullptr;
    const long l = di && !di->flags.empty() ? di->local(zi) : -1;
    if (l >= 0 && (di->flags[static_cast<std::size_t>(l)] & 1)) {
        for (int j = 0; j < 4; ++j) oz[static_cast<std::size_t>(j)] = ((di->flags[static_cast<std::size_t>(l)] >> (4 + j)) & 1) ? 0 : T.vol;
    } else {
        oz = T.sides(z);
    }
    const Vec3d e1 = T.p[1] - T.p[0], e2 = T.p[2] - T.p[0], e3 = T.p[3] - T.p[0];
    const double V = (e1 % e2) | e3;
    double lam[4];
    double sum = 0;
    for (int j = 0; j < 4; ++j) {
        if (oz[j] == 0) {
            lam[j] = 0;
            continue;
        }
        Vec3d q[4] = {T.p[0], T.p[1], T.p[2], T.p[3]};
        q[j] = z;
        lam[j] = std::max(0.0, (((q[1] - q[0]) % (q[2] - q[0])) | (q[3] - q[0])) / V);
        sum += lam[j];
    }
    Vec3d pos(0, 0, 0);
    int nb = 0;
    for (int j = 0; j < 4; ++j) {
        pos += mesh.position(cv[j]) * (sum > 0 ? lam[j] / sum : 0.25);
        const HalfFaceHandle hf = TetMesh::halfface(CellHandle(t), j);
        if (boundaryHf && oz[j] == 0 && mesh.is_boundary(hf) && nb < 3) (*boundaryHf)[nb++] = hf.idx();
    }
    return pos;
}

} // namespace HexEx
