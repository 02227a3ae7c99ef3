/// @file HexValidity.cc
/// Bernstein coefficients of the trilinear hex Jacobian and the certified validity test.

#include "HexValidity.hh"

#include "../Predicates/ExactPredicates.hh"
#include "PointPairs.hh"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace HexEx {

namespace {

/// VTK corner index of the reference corner (i, j, k), i along u, j along v, k along w.
constexpr int kCorner[2][2][2] = {{{0, 4}, {3, 7}}, {{1, 5}, {2, 6}}};

/// A 3-vector over the number type NT (double or an interval).
template <class NT>
struct V3 {
    NT x, y, z;
};

template <class NT>
V3<NT> sub(const V3<NT>& a, const V3<NT>& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }

template <class NT>
V3<NT> mid(const V3<NT>& a, const V3<NT>& b) { return {(a.x + b.x) * 0.5, (a.y + b.y) * 0.5, (a.z + b.z) * 0.5}; }

template <class NT>
NT det(const V3<NT>& a, const V3<NT>& b, const V3<NT>& c) {
    return a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
}

/// The three Lagrange nodes 0, 1/2, 1 of the segment from @p a to @p b.
template <class NT>
void nodes3(const V3<NT>& a, const V3<NT>& b, V3<NT> out[3]) {
    out[0] = a;
    out[1] = mid(a, b);
    out[2] = b;
}

/// J at the 27 nodes (a/2, b/2, c/2), a, b, c in {0, 1, 2}, of the hex with the corners
/// @p P (indexed by the reference corner); entry a + 3 b + 9 c.
template <class NT>
void jacobianAtNodes(const V3<NT> P[2][2][2], NT f[27]) {
    // Edge vectors along each axis, indexed by the other two corner coordinates.
    V3<NT> eu[2][2], ev[2][2], ew[2][2];
    for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) {
            eu[a][b] = sub(P[1][a][b], P[0][a][b]);  // [j][k]
            ev[a][b] = sub(P[a][1][b], P[a][0][b]);  // [i][k]
            ew[a][b] = sub(P[a][b][1], P[a][b][0]);  // [i][j]
        }
    // dx/du is bilinear in (v, w), dx/dv in (u, w), dx/dw in (u, v): 9 node values each.
    V3<NT> du[3][3], dv[3][3], dw[3][3];
    auto bilinear = [](const V3<NT> e[2][2], V3<NT> out[3][3]) {
        V3<NT> l0[3], l1[3], col[3];
        nodes3(e[0][0], e[1][0], l0);  // first index at the nodes, second index 0
        nodes3(e[0][1], e[1][1], l1);  // second index 1
        for (int s = 0; s < 3; ++s) {
            nodes3(l0[s], l1[s], col);
            for (int t = 0; t < 3; ++t) out[s][t] = col[t];
        }
    };
    bilinear(eu, du);  // du[b][c]
    bilinear(ev, dv);  // dv[a][c]
    bilinear(ew, dw);  // dw[a][b]
    for (int c = 0; c < 3; ++c)
        for (int b = 0; b < 3; ++b)
            for (int a = 0; a < 3; ++a) f[a + 3 * b + 9 * c] = det(du[b][c], dv[a][c], dw[a][b]);
}

/// jacobianAtNodes() of the hex with corners @p p (VTK order).
template <class NT>
void jacobianAtNodes(const std::array<Vec3d, 8>& p, NT f[27]) {
    V3<NT> P[2][2][2];
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k) {
                const Vec3d& q = p[kCorner[i][j][k]];
                P[i][j][k] = {NT(q[0]), NT(q[1]), NT(q[2])};
            }
    jacobianAtNodes(P, f);
}

/// The other two strides of the axis of stride S (1: u, 3: v, 9: w).
template <int S>
constexpr int kOtherStrideA = S == 1 ? 3 : 1;
template <int S>
constexpr int kOtherStrideB = S == 9 ? 3 : 9;

/// Values at the nodes 0, 1/2, 1 -> quadratic Bernstein coefficients, along the axis of
/// stride S (1: u, 3: v, 9: w), in place.
template <int S, class NT>
void lagrangeToBernstein(NT f[27]) {
    for (int x = 0; x < 3; ++x)
        for (int y = 0; y < 3; ++y) {
            const int base = x * kOtherStrideA<S> + y * kOtherStrideB<S>;
            const NT f0 = f[base], fh = f[base + S], f1 = f[base + 2 * S];
            f[base + S] = fh * 2.0 - (f0 + f1) * 0.5;
        }
}

/// All three axes of lagrangeToBernstein().
template <class NT>
void lagrangeToBernstein(NT f[27]) {
    lagrangeToBernstein<1>(f);
    lagrangeToBernstein<3>(f);
    lagrangeToBernstein<9>(f);
}

/// Splits the box coefficients @p b along the axis of stride S into halves @p lo, @p hi.
template <int S, class NT>
void splitAxis(const NT b[27], NT lo[27], NT hi[27]) {
    for (int x = 0; x < 3; ++x)
        for (int y = 0; y < 3; ++y) {
            const int base = x * kOtherStrideA<S> + y * kOtherStrideB<S>;
            const NT b0 = b[base], b1 = b[base + S], b2 = b[base + 2 * S];
            const NT l1 = (b0 + b1) * 0.5, h1 = (b1 + b2) * 0.5;
            const NT m = (l1 + h1) * 0.5;
            lo[base] = b0;
            lo[base + S] = l1;
            lo[base + 2 * S] = m;
            hi[base] = m;
            hi[base + S] = h1;
            hi[base + 2 * S] = b2;
        }
}

/// Certainty tests in double precision: decide only beyond the rounding error bound.
struct DoubleSigns {
    double tol;
    bool surelyPositive(double x) const { return x > tol; }
    bool surelyNonPositive(double x) const { return x < -tol; }
};

using Interval = CGAL::Interval_nt<true>;

/// Certainty tests in interval arithmetic: the interval's bounds are rigorous.
struct IntervalSigns {
    bool surelyPositive(const Interval& x) const { return x.inf() > 0; }
    bool surelyNonPositive(const Interval& x) const { return x.sup() <= 0; }
};

constexpr int kCornerCoefficients[8] = {0, 2, 6, 8, 18, 20, 24, 26};

/// The test of the file comment in number type NT with the certainty tests @p signs.
template <class NT, class Signs>
HexValidity classifyWith(const std::array<Vec3d, 8>& p, const Signs& signs, const HexValidityOptions& opt) {
    NT f[27];
    jacobianAtNodes<NT>(p, f);
    bool all_positive = true;
    for (int i = 0; i < 27; ++i) {
        if (signs.surelyNonPositive(f[i])) return HexValidity::Invalid;
        all_positive = all_positive && signs.surelyPositive(f[i]);
    }
    lagrangeToBernstein(f);
    bool coefficients_positive = all_positive;
    for (int i = 0; i < 27 && coefficients_positive; ++i) coefficients_positive = signs.surelyPositive(f[i]);
    if (coefficients_positive) return HexValidity::Valid;

    struct Box {
        std::array<NT, 27> b;
        int depth;
    };
    std::vector<Box> stack;
    stack.push_back(Box{{}, 0});
    std::copy(f, f + 27, stack.back().b.begin());
    int boxes = 0;
    bool undecided = false;
    while (!stack.empty()) {
        const Box box = stack.back();
        stack.pop_back();
        ++boxes;
        for (const int c : kCornerCoefficients)
            if (signs.surelyNonPositive(box.b[c])) return HexValidity::Invalid;
        bool positive = true;
        for (int i = 0; i < 27 && positive; ++i) positive = signs.surelyPositive(box.b[i]);
        if (positive) continue;
        if (box.depth >= opt.max_depth || boxes + static_cast<int>(stack.size()) >= opt.max_boxes) {
            undecided = true;
            continue;
        }
        NT u0[27], u1[27], v[4][27], w[8][27];
        splitAxis<1>(box.b.data(), u0, u1);
        splitAxis<3>(u0, v[0], v[1]);
        splitAxis<3>(u1, v[2], v[3]);
        for (int q = 0; q < 4; ++q) splitAxis<9>(v[q], w[2 * q], w[2 * q + 1]);
        for (int q = 7; q >= 0; --q) {
            stack.push_back(Box{{}, box.depth + 1});
            std::copy(w[q], w[q] + 27, stack.back().b.begin());
        }
    }
    return undecided ? HexValidity::Undecided : HexValidity::Valid;
}

/// Exact sign of J at every corner: false if one is <= 0.
bool cornersExactlyPositive(const std::array<Vec3d, 8>& p) {
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k) {
                const Vec3d& c = p[kCorner[i][j][k]];
                const Vec3d& nu = p[kCorner[1 - i][j][k]];
                const Vec3d& nv = p[kCorner[i][1 - j][k]];
                const Vec3d& nw = p[kCorner[i][j][1 - k]];
                // J at the corner is det(+-(nu-c), +-(nv-c), +-(nw-c)), '-' where the corner is at 1.
                const int flips = i + j + k;
                const int s = orient3d(c, nu, nv, nw) * ((flips % 2) ? -1 : 1);
                if (s <= 0) return false;
            }
    return true;
}

/// Forward bound of the rounding error of every double coefficient, node value and
/// sub-box coefficient (Documentation/algorithm.md, "Certified validity of the hexes") of a
/// hex whose largest |coordinate| is @p max_coord (C) and whose largest |component| of an
/// edge is @p max_edge (L): |J| <= (sqrt(3) L)^3, the Bernstein conversion grows values by
/// at most 27, the edge vectors carry an error of eps * C, and every de Casteljau level
/// adds a few ulps. NT is double or Lanes2 (one bound per lane, the same operations).
template <class NT>
NT roundingBound(const NT& max_edge, const NT& max_coord) {
    const double eps = std::numeric_limits<double>::epsilon();
    return max_edge * (2048 * eps * 3) * max_edge * (max_edge * 2.0 + max_coord);
}

} // namespace

std::array<double, 27> jacobianBernsteinCoefficients(const std::array<Vec3d, 8>& p) {
    double f[27];
    jacobianAtNodes<double>(p, f);
    lagrangeToBernstein(f);
    std::array<double, 27> out;
    std::copy(f, f + 27, out.begin());
    return out;
}

double jacobianDeterminant(const std::array<Vec3d, 8>& p, double u, double v, double w) {
    // x(u,v,w) = sum X_ijk B_i(u) B_j(v) B_k(w); differentiate one factor at a time.
    const double bu[2] = {1 - u, u}, bv[2] = {1 - v, v}, bw[2] = {1 - w, w};
    const double su[2] = {-1, 1};
    Vec3d du(0, 0, 0), dv(0, 0, 0), dw(0, 0, 0);
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k) {
                const Vec3d& x = p[kCorner[i][j][k]];
                du += x * (su[i] * bv[j] * bw[k]);
                dv += x * (bu[i] * su[j] * bw[k]);
                dw += x * (bu[i] * bv[j] * su[k]);
            }
    return (du % dv) | dw;
}

double evaluateBernstein(const std::array<double, 27>& b, double u, double v, double w) {
    auto basis = [](double t, double out[3]) {
        out[0] = (1 - t) * (1 - t);
        out[1] = 2 * t * (1 - t);
        out[2] = t * t;
    };
    double bu[3], bv[3], bw[3];
    basis(u, bu);
    basis(v, bv);
    basis(w, bw);
    double sum = 0;
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) sum += b[i + 3 * j + 9 * k] * bu[i] * bv[j] * bw[k];
    return sum;
}

HexValidity classifyHexValidity(const std::array<Vec3d, 8>& p, const HexValidityOptions& options) {
    // C: largest |coordinate|; L: largest |component| of a hex edge (the Euclidean edge
    // length is at most sqrt(3) L). Comparisons with NaN are false, so NaN fails the test.
    double max_coord = 0, max_edge = 0;
    for (const Vec3d& q : p)
        for (int d = 0; d < 3; ++d) {
            if (!(std::abs(q[d]) <= std::numeric_limits<double>::max())) return HexValidity::Invalid;
            max_coord = std::max(max_coord, std::abs(q[d]));
        }
    for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
            for (int d = 0; d < 3; ++d) {
                max_edge = std::max(max_edge, std::abs(p[kCorner[1][a][b]][d] - p[kCorner[0][a][b]][d]));
                max_edge = std::max(max_edge, std::abs(p[kCorner[a][1][b]][d] - p[kCorner[a][0][b]][d]));
                max_edge = std::max(max_edge, std::abs(p[kCorner[a][b][1]][d] - p[kCorner[a][b][0]][d]));
            }
    const double tol = roundingBound(max_edge, max_coord);
    if (!std::isfinite(tol)) return HexValidity::Undecided;

    const HexValidity fast = classifyWith<double>(p, DoubleSigns{tol}, options);
    if (fast != HexValidity::Undecided) return fast;
    if (!cornersExactlyPositive(p)) return HexValidity::Invalid;
    return classifyWith<Interval>(p, IntervalSigns{}, options);
}

#if defined(__SSE2__)
namespace {

/// Two doubles in the lanes of an SSE2 register, with the arithmetic jacobianAtNodes(),
/// lagrangeToBernstein() and roundingBound() use: each lane sees the operations of double.
struct Lanes2 {
    __m128d v;
};

Lanes2 operator+(const Lanes2& a, const Lanes2& b) { return {_mm_add_pd(a.v, b.v)}; }
Lanes2 operator-(const Lanes2& a, const Lanes2& b) { return {_mm_sub_pd(a.v, b.v)}; }
Lanes2 operator*(const Lanes2& a, const Lanes2& b) { return {_mm_mul_pd(a.v, b.v)}; }
Lanes2 operator*(const Lanes2& a, double s) { return {_mm_mul_pd(a.v, _mm_set1_pd(s))}; }

/// Lane mask of x > t.
__m128d above(const Lanes2& x, const Lanes2& t) { return _mm_cmpgt_pd(x.v, t.v); }

} // namespace
#endif

void classifyHexValidityPair(const std::array<Vec3d, 8>& a, const std::array<Vec3d, 8>& b, HexValidity out[2]) {
#if defined(__SSE2__)
    const std::array<Vec3d, 8>* hex[2] = {&a, &b};
    V3<Lanes2> P[2][2][2];
    const __m128d largest = _mm_set1_pd(std::numeric_limits<double>::max());
    __m128d finite = _mm_castsi128_pd(_mm_set1_epi64x(-1));
    Lanes2 max_coord{_mm_setzero_pd()}, max_edge{_mm_setzero_pd()};
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k) {
                const int c = kCorner[i][j][k];
                const PointPair q = loadPointPair(a[c], b[c]);
                P[i][j][k] = {{q.x}, {q.y}, {q.z}};
                const __m128d coords[3] = {absPair(q.x), absPair(q.y), absPair(q.z)};
                for (const __m128d x : coords) {
                    finite = _mm_and_pd(finite, _mm_cmple_pd(x, largest));
                    max_coord.v = _mm_max_pd(max_coord.v, x);
                }
            }
    // classifyHexValidity()'s L over the same differences (the maximum of finite values
    // does not depend on the order; a lane with a non-finite coordinate goes there anyway).
    for (int s = 0; s < 2; ++s)
        for (int t = 0; t < 2; ++t)
            for (const V3<Lanes2>& e : {sub(P[1][s][t], P[0][s][t]), sub(P[s][1][t], P[s][0][t]),
                                        sub(P[s][t][1], P[s][t][0])})
                for (const Lanes2& x : {e.x, e.y, e.z}) max_edge.v = _mm_max_pd(max_edge.v, absPair(x.v));
    const Lanes2 tol = roundingBound(max_edge, max_coord);
    Lanes2 f[27];
    jacobianAtNodes(P, f);
    __m128d valid = finite;
    for (const Lanes2& x : f) valid = _mm_and_pd(valid, above(x, tol));
    lagrangeToBernstein(f);
    for (const Lanes2& x : f) valid = _mm_and_pd(valid, above(x, tol));
    const int proved = _mm_movemask_pd(valid);
    for (int l = 0; l < 2; ++l) out[l] = (proved >> l) & 1 ? HexValidity::Valid : classifyHexValidity(*hex[l]);
#else
    out[0] = classifyHexValidity(a);
    out[1] = classifyHexValidity(b);
#endif
}

const char* toString(HexValidity v) {
    switch (v) {
    case HexValidity::Valid: return "valid";
    case HexValidity::Invalid: return "invalid";
    case HexValidity::Undecided: return "undecided";
    }
    return "undecided";
}

} // namespace HexEx
