#pragma once
/// @file CornerRepair.hh
/// @ingroup pipeline
/// A corner parameter the sanitization replaced (see sanitizeParameters()).

#include "../Core/Vec.hh"

namespace HexEx {

/// One corner parameter that disagreed with the majority of the tets at its vertex and was
/// replaced by the majority value.
struct CornerRepair {
    int tet = 0;       ///< the tet
    int corner = 0;    ///< its local corner (0..3)
    int vertex = 0;    ///< the mesh vertex at that corner
    Vec3d original;    ///< the parameter as given
    Vec3d repaired;    ///< the parameter after sanitization
};

} // namespace HexEx
