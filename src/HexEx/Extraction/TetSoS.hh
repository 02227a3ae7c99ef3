#pragma once
/// @file TetSoS.hh
/// @ingroup pipeline
/// Symbolic perturbation on one tet's parameter image: decides whether the point
/// z + e*d1 + e^2*d2 + e^3*d3 (e > 0 infinitesimal, d_k axis directions) lies inside,
/// and which face a traced path leaves through. Every decision is a sign of an exact
/// predicate on the sanitized doubles (see DESIGN.md, "one tie-breaking rule").

#include "../Grid/Rotation.hh"

#include <array>
#include <cstdint>

namespace HexEx {

/// Per-tet data for the symbolic predicates. o_j(x) is the orientation of the tet with
/// corner j replaced by x (the barycentric numerator of corner j); x is inside iff every
/// o_j(x) has the sign of the tet's volume.
struct TetSoS {
    const Vec3d* p = nullptr;  ///< the four corner parameters (not owned: they must outlive this object)
    int vol = 0;               ///< sign of the parameter volume (+1 proper, -1 flipped, 0 degenerate)
    std::int8_t g[4][3] = {};  ///< sign of d o_j / d x_k (the gradient of o_j), exact

    /// Empty data (degenerate).
    TetSoS() = default;
    /// Fills the data for @p corners, which must stay alive (and unchanged) while this is used.
    explicit TetSoS(const std::array<Vec3d, 4>& corners);
    /// Sign of o_j(x), exact.
    int side(int j, const Vec3d& x) const;
    /// Signs of o_j(z) for all four faces.
    std::array<int, 4> sides(const Vec3d& z) const;
    /// Sign of o_j at z + e*a + e^2*b + e^3*c given oz = sign of o_j(z).
    int sosSide(int j, int oz, AxisDir a, AxisDir b, AxisDir c) const {
        if (oz != 0) return oz;
        for (AxisDir d : {a, b, c}) {
            const int s = dirSign(d) * g[j][dirAxis(d)];
            if (s != 0) return s;
        }
        return 0;
    }
    /// True if z + e*a + e^2*b + e^3*c lies inside (non-degenerate tets only).
    bool contains(const std::array<int, 4>& oz, AxisDir a, AxisDir b, AxisDir c) const {
        if (vol == 0) return false;
        for (int j = 0; j < 4; ++j)
            if (sosSide(j, oz[j], a, b, c) != vol) return false;
        return true;
    }
    /// Sign of (g_a x g_b) . dir, from the identity g_a x g_b = sigma(a,b,c,d) V (x_d - x_c).
    int gradCrossSign(int a, int b, AxisDir dir) const;
};

} // namespace HexEx
