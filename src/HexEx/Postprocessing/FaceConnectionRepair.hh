#pragma once
/// @file FaceConnectionRepair.hh
/// @ingroup pipeline
/// Completes partial face connections (paper 5.2, "partial connectivity"): a quad whose
/// darts are linked by alpha_3 to one other quad only in part gets the missing links, when
/// the links it has determine the correspondence and the missing ones are free on both sides.

#include "../GMap/GMap.hh"

namespace HexEx {

/// Sews the missing alpha_3 links of partially connected quads. Returns the number of
/// quads completed. Deterministic (quads visited in order of their smallest dart); @p threads
/// looks for candidate quads in parallel (the result does not depend on it).
long completePartialFaceConnections(GMap<3>& g, int threads = 1);

} // namespace HexEx
