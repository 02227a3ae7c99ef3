/// @file HexGMapFixtures.hh
/// Test support (not installed): separate hexahedra as a 3D generalized map, the input of
/// the GMap kernel, validator, annihilation and relinking tests. Shared so that every test
/// numbers a hex's darts the same way.
#pragma once

#include <HexEx/GMap/GMap.hh>

namespace HexExTestSupport {

/// Darts per hexahedron.
constexpr int kHexDarts = 48;

/// @p hexes separate hexahedra (48 darts each, no alpha_3 links), built from their 6 quads.
/// Dart 48h + 8f + 2k + s: hex h, face f, edge k of the face's loop, s = 0 at the edge's
/// first corner, 1 at its second. Faces by corner ids: {0,3,2,1}, {4,5,6,7}, {0,1,5,4},
/// {1,2,6,5}, {2,3,7,6}, {3,0,4,7}.
inline HexEx::GMap<3> makeHexGMaps(int hexes) {
    using HexEx::DartHandle;
    static const int F[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    HexEx::GMap<3> g;
    g.add_darts(static_cast<std::size_t>(hexes * kHexDarts));
    for (int h = 0; h < hexes; ++h) {
        auto id = [&](int f, int k, int s) { return DartHandle(h * kHexDarts + 8 * f + 2 * k + s); };
        for (int f = 0; f < 6; ++f)
            for (int k = 0; k < 4; ++k) {
                g.sew(id(f, k, 0), id(f, k, 1), 0);
                g.sew(id(f, k, 1), id(f, (k + 1) % 4, 0), 1);
            }
        // alpha_2: the darts of two faces at the same corner of the same edge.
        for (int f = 0; f < 6; ++f)
            for (int k = 0; k < 4; ++k)
                for (int s = 0; s < 2; ++s) {
                    const int v = F[f][(k + s) % 4], w = F[f][(k + 1 - s) % 4];
                    for (int f2 = 0; f2 < 6; ++f2)
                        for (int k2 = 0; k2 < 4 && f2 != f; ++k2)
                            for (int s2 = 0; s2 < 2; ++s2)
                                if (F[f2][(k2 + s2) % 4] == v && F[f2][(k2 + 1 - s2) % 4] == w) g.link(id(f, k, s), id(f2, k2, s2), 2);
                }
    }
    return g;
}

} // namespace HexExTestSupport
