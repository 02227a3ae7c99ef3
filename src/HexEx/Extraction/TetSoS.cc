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

namespace {
__extension__ typedef __int128 Int128;  // (a GCC/Clang extension: exact products of 41-bit integers)

/// Scale of the fixed-point coordinates of fixedPointSign().
constexpr double kFixedScale = 16777216.0;  // 2^24
/// Largest scaled magnitude: differences stay below 2^41, cross products below 2^83 and
/// the determinant below 3 * 2^124 < 2^127.
constexpr double kFixedMax = 1099511627776.0;  // 2^40

/// @p v times 2^24 in @p out, if that is an integer of magnitude at most 2^40 (the
/// coordinate is a multiple of 2^-24 below 2^16: parameters quantized to 2^-20, as the
/// perturbed maps are, and all small dyadic ones).
bool fixedPoint(const Vec3d& v, long long out[3]) {
    for (int k = 0; k < 3; ++k) {
        const double y = v[k] * kFixedScale;  // exact: a power of two
        if (!(std::fabs(y) <= kFixedMax)) return false;
        out[k] = static_cast<long long>(y);
        if (static_cast<double>(out[k]) != y) return false;
    }
    return true;
}

/// Sign of det(b - a, c - a, x - a), exactly, if every coordinate is fixedPoint(); else
/// false. @p rounded is that determinant as FacePlanes computes it in doubles: it is exact
/// when the coordinates are small dyadic ones (FacePlanes::smallDyadic(): multiples of 2^-6
/// of magnitude at most 2^9), which is then cheaper than the 128-bit integers.
bool fixedPointSign(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& x, double rounded, int& sign) {
    long long A[3], B[3], C[3], X[3];
    if (!fixedPoint(a, A) || !fixedPoint(b, B) || !fixedPoint(c, C) || !fixedPoint(x, X)) return false;
    unsigned long long low = 0, high = 0;  // bits below 2^18 (2^-6 after scaling), magnitude
    for (const long long* v : {A, B, C, X})
        for (int k = 0; k < 3; ++k) {
            low |= static_cast<unsigned long long>(v[k]);
            high |= static_cast<unsigned long long>(v[k] < 0 ? -v[k] : v[k]);
        }
    if ((low & 0x3FFFFu) == 0 && high <= (1ull << 33)) {
        sign = (rounded > 0) - (rounded < 0);
        return true;
    }
    Int128 det = 0;
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, l = (k + 2) % 3;
        const Int128 n = static_cast<Int128>(B[i] - A[i]) * (C[l] - A[l]) - static_cast<Int128>(B[l] - A[l]) * (C[i] - A[i]);
        det += static_cast<Int128>(X[k] - A[k]) * n;
    }
    sign = (det > 0) - (det < 0);
    return true;
}
} // namespace

int TetSoS::side(int j, const Vec3d& x) const {
    // o_j(x) = (-1)^(3-j) det(b - a, c - a, x - a) for the corners (a, b, c) other than j in
    // index order (as FacePlanes). The filter of FacePlanes::side() first; where it cannot
    // decide (x on or next to the face's plane: most grid points a trace asks about lie on
    // a face), 128-bit integers decide exactly for fixed-point parameters, which costs a
    // fraction of orient3d()'s exact stages (pig x2's rotational traces: 52 cycles per
    // call, its perturbed twin 120). Same sign in every case: each path is exact.
    const int a = j == 0 ? 1 : 0, b = j <= 1 ? 2 : 1, c = j <= 2 ? 3 : 2;
    const int parity = (3 - j) % 2 == 0 ? 1 : -1;
    const Vec3d& pa = p[a];
    const Vec3d u = p[b] - pa, v = p[c] - pa, w = x - pa;
    double det = 0, perm = 0;
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, l = (k + 2) % 3;
        const double t1 = u[i] * v[l], t2 = u[l] * v[i];
        det += w[k] * (t1 - t2);
        perm += std::fabs(w[k]) * (std::fabs(t1) + std::fabs(t2));
    }
    const double bound = 1e-15 * perm + 1e-280;
    if (det > bound) return parity;
    if (-det > bound) return -parity;
    int s;
    if (fixedPointSign(pa, p[b], p[c], x, det, s)) return parity * s;
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
