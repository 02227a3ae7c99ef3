#pragma once
/// @file PlanarRotation.hh
/// @ingroup pipeline
/// The 4 planar rotations (quarter turns about +z) as a subgroup view of the 24 cube
/// rotations, for the 2D (quad) pipeline: a 2D transition is a GridTransform whose rotation
/// fixes the z axis and whose translation has t[2] = 0.

#include "Rotation.hh"

namespace HexEx {

/// The rotation by @p quarter_turns * 90 degrees counter-clockwise about +z (any integer;
/// taken modulo 4).
inline Rotation planarRotation(int quarter_turns) {
    const int k = ((quarter_turns % 4) + 4) % 4;
    // Image of +x and +y under k counter-clockwise quarter turns; +z stays.
    const AxisDir ix[4] = {makeDir(0, 1), makeDir(1, 1), makeDir(0, -1), makeDir(1, -1)};
    const AxisDir iy[4] = {makeDir(1, 1), makeDir(0, -1), makeDir(1, -1), makeDir(0, 1)};
    return Rotation(Rotation::fromColumns({ix[k], iy[k], makeDir(2, 1)}));
}

/// Number of counter-clockwise quarter turns (0..3) of @p r about +z, or -1 if @p r does
/// not fix the z axis (is not a planar rotation).
inline int planarQuarterTurns(Rotation r) {
    if (r.apply(makeDir(2, 1)) != makeDir(2, 1)) return -1;
    const AxisDir x = r.apply(makeDir(0, 1));
    if (x == makeDir(0, 1)) return 0;
    if (x == makeDir(1, 1)) return 1;
    if (x == makeDir(0, -1)) return 2;
    return 3;
}

} // namespace HexEx
