#pragma once
/// @file FaceRelinking.hh
/// @ingroup pipeline
/// Re-pairs quads whose alpha_3 links the dart annihilation left inconsistent.
///
/// Where a grid point is covered by several regular layers and a fold layer, the
/// annihilation (paper 4.4.1) can remove one anti dart with a dart of one regular layer and
/// its alpha_3 neighbour with a dart of another; the re-linking then joins quads that do not
/// face each other: alpha_3 no longer commutes with alpha_0 / alpha_1 (equation 2), or a
/// cell is glued to itself, which merges two of its corners into one vertex. The cells
/// (<alpha_0, alpha_1, alpha_2> orbits) are not affected, so such quads can be paired again
/// by the vertices of their corners (Documentation/algorithm.md, "Face relinking").

#include "../GMap/GMap.hh"

namespace HexEx {

/// What relinkInconsistentFaces() did.
struct FaceRelinkStats {
    long inconsistent_faces = 0;  ///< quads whose alpha_3 links were cut (inconsistent ones and the quads they were linked to)
    long relinked_faces = 0;      ///< of those, quads linked again to the quad with the same four vertices
};

/// Finds every dart whose alpha_3 link breaks equation 2 ((alpha_0 alpha_3)^2 = id,
/// (alpha_1 alpha_3)^2 = id) or joins a cell to itself, cuts the alpha_3 links of its quad
/// (<alpha_0, alpha_1> orbit) and, repeatedly, of the quads those were linked to; then,
/// with the vertices (<alpha_1, alpha_2, alpha_3> orbits) labelled before the cut, sews
/// every two cut quads of different cells with the same four vertices, dart to dart (same
/// vertex, same edge). The quads left are paired once more among themselves by the vertices
/// of the map with the cut quads open; if some are still left, the sewn quads with the same
/// four vertices as one of them (crossed the same way, but passing equation 2) are cut too,
/// with their partners, and all of them are paired again, kept only if every one finds a
/// partner. Quads without a partner stay free. Linear time; deterministic (quads in order
/// of their smallest dart).
FaceRelinkStats relinkInconsistentFaces(GMap<3>& g);

} // namespace HexEx
