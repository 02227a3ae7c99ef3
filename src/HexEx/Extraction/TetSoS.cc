#include "TetSoS.hh"

#include "../Predicates/ExactPredicates.hh"

#include <cmath>

namespace HexEx {

namespace {
int permSign(int a, int b, int c, int d) {
    const int p[4] = {a, b, c, d};
    int s = 1;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
            if (p[i] > p[j]) s = -s;
    return s;
}
int signOf(double x) { return (x > 0) - (x < 0); }
} // namespace

TetSoS::TetSoS(const std::array<Vec3d, 4>& corners) : p(corners.data()) {
    vol = orient3d(p[0], p[1], p[2], p[3]);
    for (int j = 0; j < 4; ++j) {
        int o[3], n = 0;
        for (int k = 0; k < 4; ++k)
            if (k != j) o[n++] = k;
        // o_j(x) = (-1)^(3-j) * orient3d(p_o0, p_o1, p_o2, x); its gradient's k-th component
        // is the 2D orientation of the face projected along axis k.
        const int parity = ((3 - j) % 2 == 0) ? 1 : -1;
        // Component k of (b - a) x (c - a) is orient2dAxis(a, b, c, k). The same filtered
        // arithmetic inline, with the differences shared by the three axes; only uncertain
        // components call the predicate.
        const Vec3d& a = p[o[0]];
        const Vec3d u = p[o[1]] - a, v = p[o[2]] - a;
        for (int k = 0; k < 3; ++k) {
            const int i = (k + 1) % 3, m = (k + 2) % 3;
            const double t1 = u[i] * v[m], t2 = u[m] * v[i];
            const double det = t1 - t2, bound = 5e-16 * (std::fabs(t1) + std::fabs(t2));
            int sgn;
            if (det > bound) sgn = 1;
            else if (-det > bound) sgn = -1;
            else if ((u[i] == 0 || v[m] == 0) && (u[m] == 0 || v[i] == 0)) sgn = 0;
            else sgn = orient2dAxis(a, p[o[1]], p[o[2]], k);
            g[j][k] = static_cast<std::int8_t>(parity * sgn);
        }
    }
}

int TetSoS::side(int j, const Vec3d& x) const {
    Vec3d q[4] = {p[0], p[1], p[2], p[3]};
    q[j] = x;
    return orient3d(q[0], q[1], q[2], q[3]);
}

std::array<int, 4> TetSoS::sides(const Vec3d& z) const {
    // At a corner k every face but k passes through z, and o_k(p_k) is the volume itself.
    for (int k = 0; k < 4; ++k)
        if (z == p[k]) {
            std::array<int, 4> oz{0, 0, 0, 0};
            oz[static_cast<std::size_t>(k)] = vol;
            return oz;
        }
    return {side(0, z), side(1, z), side(2, z), side(3, z)};
}

int TetSoS::gradCrossSign(int a, int b, AxisDir dir) const {
    int c = -1, d = -1;
    for (int k = 0; k < 4; ++k)
        if (k != a && k != b) (c < 0 ? c : d) = k;
    const int k = dirAxis(dir);
    return permSign(a, b, c, d) * vol * signOf(p[d][k] - p[c][k]) * dirSign(dir);
}

} // namespace HexEx
