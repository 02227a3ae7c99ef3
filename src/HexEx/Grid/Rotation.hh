#pragma once
/// @file Rotation.hh
/// @ingroup pipeline
/// The chiral cubical group: the 24 rotations that map the coordinate axes onto
/// themselves, as signed axis permutations with composition and inverse tables.

#include "../Core/Vec.hh"

#include <array>
#include <cstdint>

namespace HexEx {

/// An axis direction: 0..5 = +x, -x, +y, -y, +z, -z (axis = code/2, negative if code is odd).
using AxisDir = std::uint8_t;

/// Axis (0,1,2) of a direction code.
inline int dirAxis(AxisDir d) { return d >> 1; }
/// Sign (+1/-1) of a direction code.
inline int dirSign(AxisDir d) { return (d & 1) ? -1 : 1; }
/// The opposite direction.
inline AxisDir dirNeg(AxisDir d) { return static_cast<AxisDir>(d ^ 1); }
/// The direction as an integer vector.
inline Vec3i dirVec(AxisDir d) {
    // Built per component, not stored at a computed index (see Rotation::apply()).
    const int a = dirAxis(d), s = dirSign(d);
    return Vec3i(a == 0 ? s : 0, a == 1 ? s : 0, a == 2 ? s : 0);
}
/// @p z one step along direction @p d (z + dirVec(d)), per component.
inline Vec3i stepAlong(const Vec3i& z, AxisDir d) {
    const int a = dirAxis(d), s = dirSign(d);
    return Vec3i(z[0] + (a == 0 ? s : 0), z[1] + (a == 1 ? s : 0), z[2] + (a == 2 ? s : 0));
}
/// Direction code from axis and sign.
inline AxisDir makeDir(int axis, int sign) { return static_cast<AxisDir>(2 * axis + (sign < 0 ? 1 : 0)); }
/// The direction a x b (a, b on different axes). Inline, as frameHandedness(): both run
/// per dart in the placement and the tracing.
inline AxisDir dirCross(AxisDir a, AxisDir b) {
    const int ia = dirAxis(a), ib = dirAxis(b);
    const int ic = 3 - ia - ib;
    const int cyclic = ((ia + 1) % 3 == ib) ? 1 : -1;
    return makeDir(ic, cyclic * dirSign(a) * dirSign(b));
}
/// Handedness of the frame (a, b, c): +1 if a x b = c, -1 if a x b = -c, 0 if axes repeat.
inline int frameHandedness(AxisDir a, AxisDir b, AxisDir c) {
    if (dirAxis(a) == dirAxis(b) || dirAxis(b) == dirAxis(c) || dirAxis(a) == dirAxis(c)) return 0;
    return dirCross(a, b) == c ? 1 : -1;
}

namespace detail {
/// Image direction of +x, +y, +z for each of the 24 rotations (index 0 = identity),
/// generated at compile time from the definition: signed permutations with det +1.
struct RotationImages {
    AxisDir img[24][3] = {};  ///< img[r][j]: image direction of axis j under rotation r
    /// Builds the table.
    constexpr RotationImages() {
        const int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
        int n = 0;
        for (int p = 0; p < 6; ++p) {
            const int parity = p < 3 ? 1 : -1;
            for (int s = 0; s < 8; ++s) {
                const int sg[3] = {(s & 1) ? -1 : 1, (s & 2) ? -1 : 1, (s & 4) ? -1 : 1};
                if (parity * sg[0] * sg[1] * sg[2] != 1) continue;
                for (int j = 0; j < 3; ++j) img[n][j] = static_cast<AxisDir>(2 * perms[p][j] + (sg[j] < 0 ? 1 : 0));
                ++n;
            }
        }
    }
};
/// The table, a compile-time constant.
inline constexpr RotationImages kRotationImages{};
} // namespace detail

/// One of the 24 orientation-preserving signed axis permutations, stored as an index 0..23.
/// Index 0 is the identity. R maps axis j to axis perm(j) with sign sign(j).
class Rotation {
public:
    /// Number of rotations in the group.
    static constexpr int kCount = 24;
    /// The identity.
    constexpr Rotation() = default;
    /// Rotation number @p idx (0..23).
    explicit constexpr Rotation(int idx) : idx_(static_cast<std::uint8_t>(idx)) {}
    /// Index 0..23.
    int index() const { return idx_; }
    /// True for the identity.
    bool is_identity() const { return idx_ == 0; }
    /// Image axis of axis @p j.
    int perm(int j) const { return detail::kRotationImages.img[idx_][j] >> 1; }
    /// Sign of the image of axis @p j.
    int sign(int j) const { return (detail::kRotationImages.img[idx_][j] & 1) ? -1 : 1; }
    /// Entry (row r, column c) of the matrix.
    int matrix(int r, int c) const { return perm(c) == r ? sign(c) : 0; }
    /// R u for a double vector (exact: only permutes and negates).
    Vec3d apply(const Vec3d& u) const { return gather(u); }
    /// R u for an integer vector.
    Vec3i apply(const Vec3i& u) const { return gather(u); }
    /// Image of a direction code.
    AxisDir apply(AxisDir d) const {
        const AxisDir img = detail::kRotationImages.img[idx_][d >> 1];
        return (d & 1) ? static_cast<AxisDir>(img ^ 1) : img;
    }
    /// Composition: (*this)*(o), i.e. apply @p o first.
    Rotation operator*(const Rotation& o) const;
    /// The inverse rotation.
    Rotation inverse() const;
    /// Equality.
    bool operator==(const Rotation& o) const { return idx_ == o.idx_; }
    /// Inequality.
    bool operator!=(const Rotation& o) const { return idx_ != o.idx_; }
    /// Finds the rotation with the given matrix columns (image of each axis), or -1.
    static int fromColumns(const std::array<AxisDir, 3>& images);
    /// Angle class: 0 (identity), 1 (90 deg), 2 (180 deg), 3 (120 deg about a diagonal).
    int angleClass() const;

private:
    /// R u: component k of the result is sign(j) u[j] for the j with perm(j) = k, each
    /// component gathered and written once at its fixed place. (Stores at computed indices
    /// into a vector that is read whole right after stall the store forwarding; this was
    /// the hottest instruction of the tracing and of the sanitization.)
    template <class V>
    V gather(const V& u) const {
        const AxisDir* img = detail::kRotationImages.img[idx_];
        const auto v0 = (img[0] & 1) ? -u[0] : u[0], v1 = (img[1] & 1) ? -u[1] : u[1], v2 = (img[2] & 1) ? -u[2] : u[2];
        const int a0 = img[0] >> 1, a1 = img[1] >> 1;
        auto pick = [&](int k) { return a0 == k ? v0 : a1 == k ? v1 : v2; };
        return V(pick(0), pick(1), pick(2));
    }

    std::uint8_t idx_ = 0;
};

} // namespace HexEx
