#include "Rotation.hh"

namespace HexEx {

namespace {

/// The group tables, built once from the definition (signed permutations with det +1).
struct RotationTables {
    std::array<std::array<AxisDir, 3>, 24> images{};  // image direction of +x, +y, +z
    std::array<std::array<std::uint8_t, 24>, 24> mul{};
    std::array<std::uint8_t, 24> inv{};
    std::array<std::uint8_t, 24> angle{};

    RotationTables() {
        for (int n = 0; n < 24; ++n)
            for (int j = 0; j < 3; ++j) images[n][j] = detail::kRotationImages.img[n][j];
        for (int a = 0; a < 24; ++a)
            for (int b = 0; b < 24; ++b) {
                std::array<AxisDir, 3> c;
                for (int j = 0; j < 3; ++j) {
                    const AxisDir db = images[b][j];
                    const AxisDir da = images[a][dirAxis(db)];
                    c[j] = dirSign(db) > 0 ? da : dirNeg(da);
                }
                for (int k = 0; k < 24; ++k)
                    if (images[k] == c) mul[a][b] = static_cast<std::uint8_t>(k);
            }
        for (int a = 0; a < 24; ++a)
            for (int b = 0; b < 24; ++b)
                if (mul[a][b] == 0) inv[a] = static_cast<std::uint8_t>(b);
        for (int a = 0; a < 24; ++a) {
            int trace = 0;
            for (int j = 0; j < 3; ++j)
                if (dirAxis(images[a][j]) == j) trace += dirSign(images[a][j]);
            // trace 3: identity, 1: 90 deg, -1: 180 deg, 0: 120 deg
            angle[a] = static_cast<std::uint8_t>(trace == 3 ? 0 : trace == 1 ? 1 : trace == -1 ? 2 : 3);
        }
    }
};

const RotationTables& tables() {
    static const RotationTables t;  // immutable after construction: not mutable global state
    return t;
}

} // namespace

Rotation Rotation::operator*(const Rotation& o) const { return Rotation(tables().mul[idx_][o.idx_]); }
Rotation Rotation::inverse() const { return Rotation(tables().inv[idx_]); }
int Rotation::angleClass() const { return tables().angle[idx_]; }

int Rotation::fromColumns(const std::array<AxisDir, 3>& images) {
    for (int k = 0; k < 24; ++k)
        if (tables().images[k] == images) return k;
    return -1;
}

} // namespace HexEx
