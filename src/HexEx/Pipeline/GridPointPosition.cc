#include "GridPointPosition.hh"

#include <algorithm>

namespace HexEx {

TetPointPositions::TetPointPositions(const TetMesh& mesh, const std::vector<TetSoS>& tets, const DartSet& ds, int t)
    : mesh_(&mesh), T_(&tets[static_cast<std::size_t>(t)]), t_(t) {
    const int slot = ds.dense_slot[static_cast<std::size_t>(t)];
    if (slot >= 0 && !ds.dense[static_cast<std::size_t>(slot)].flags.empty()) dense_ = &ds.dense[static_cast<std::size_t>(slot)];
    e1_ = T_->p[1] - T_->p[0];
    e2_ = T_->p[2] - T_->p[0];
    e3_ = T_->p[3] - T_->p[0];
    c12_ = e1_ % e2_;
    V_ = c12_ | e3_;
    const auto& cv = mesh.cell_vertices(CellHandle(t));
    for (int j = 0; j < 4; ++j) x_[static_cast<std::size_t>(j)] = mesh.position(cv[j]);
}

Vec3d TetPointPositions::operator()(const Vec3i& zi, std::array<int, 3>* boundaryHf) const {
    const Vec3d z = toVec3d(zi);
    // Exact zeros: from the implicit-cell flags where the tet has them, else predicates.
    std::array<int, 4> oz;
    const long l = dense_ ? dense_->local(zi) : -1;
    if (l >= 0 && (dense_->flags[static_cast<std::size_t>(l)] & 1)) {
        const unsigned fl = dense_->flags[static_cast<std::size_t>(l)];
        for (int j = 0; j < 4; ++j) oz[static_cast<std::size_t>(j)] = ((fl >> (4 + j)) & 1) ? 0 : T_->vol;
    } else {
        oz = T_->sides(z);
    }
    // Barycentric numerator of corner j: the volume with corner j replaced by z, i.e.
    // ((q1 - q0) x (q2 - q0)) . (q3 - q0) with q_j = z.
    const Vec3d d0 = z - T_->p[0];
    double lam[4];
    double sum = 0;
    for (int j = 0; j < 4; ++j) {
        if (oz[static_cast<std::size_t>(j)] == 0) {
            lam[j] = 0;
            continue;
        }
        double num;
        if (j == 0) num = ((T_->p[1] - z) % (T_->p[2] - z)) | (T_->p[3] - z);
        else if (j == 1) num = (d0 % e2_) | e3_;
        else if (j == 2) num = (e1_ % d0) | e3_;
        else num = c12_ | d0;
        lam[j] = std::max(0.0, num / V_);
        sum += lam[j];
    }
    Vec3d pos(0, 0, 0);
    int nb = 0;
    for (int j = 0; j < 4; ++j) {
        pos += x_[static_cast<std::size_t>(j)] * (sum > 0 ? lam[j] / sum : 0.25);
        if (!boundaryHf || oz[static_cast<std::size_t>(j)] != 0 || nb >= 3) continue;
        const HalfFaceHandle hf = TetMesh::halfface(CellHandle(t_), j);
        if (mesh_->is_boundary(hf)) (*boundaryHf)[static_cast<std::size_t>(nb++)] = hf.idx();
    }
    return pos;
}

Vec3d gridPointPosition(const TetMesh& mesh, const std::vector<TetSoS>& tets, const DartSet& ds, int t, const Vec3i& zi,
                        std::array<int, 3>* boundaryHf) {
    return TetPointPositions(mesh, tets, ds, t)(zi, boundaryHf);
}

} // namespace HexEx
