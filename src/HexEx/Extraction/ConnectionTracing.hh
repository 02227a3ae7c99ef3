#pragma once
/// @file ConnectionTracing.hh
/// @ingroup pipeline
/// Connection extraction (paper 4.3.2, Algorithm 2): for every dart and every i, trace
/// from the dart towards its expected partner alpha_i*(d) through the tets, across
/// transitions, swapping start and target whenever the flippedness changes. The face a
/// trace leaves through is chosen by the same symbolic perturbation that assigns darts.

#include "../Preprocessing/Transitions.hh"
#include "DartExtraction.hh"

#include <array>
#include <functional>
#include <vector>

namespace HexEx {

/// Partner value meaning "not connected" (trace failed or ran into the boundary for i < 3).
constexpr int kUnconnected = -1;

/// A partner in an implicit cell (DartSet::implicitCell()) is stored as -2 - occurrence id
/// of its grid point; this decodes it (-1 if @p link is not such a value).
inline long implicitPartnerOccurrence(long link) { return link <= -2 ? -2 - link : -1; }

/// The four alpha links of a dart (dart indices; see traceConnections()).
using DartLinks = std::array<int, 4>;

/// Counters of the tracing.
struct TraceStats {
    long unconnected[4] = {0, 0, 0, 0};  ///< darts without alpha_i partner, per i
    long boundary_alpha3 = 0;            ///< darts whose alpha_3 runs into the boundary (boundary faces)
    long steps = 0;                      ///< total tets visited beyond the first
    long shared_alpha0 = 0;              ///< alpha_0 links taken from a walk shared by the darts of a tet at a grid point with the same d1
    long split_alpha0 = 0;               ///< darts of such groups that left the shared walk at a tie-break depending on d2, d3
};

/// Local index of the face through which the trace of an edge leaves tet @p tet: the line
/// z + e^2 d[1] + e^3 d[2] (e > 0 infinitesimal), followed along d[0], with the symbolic
/// tie-breaking of the alpha_0 tracing (degenerate tets included). @p entry is the face it
/// came in through (-1 at the start). Returns -1 if no face qualifies.
int edgeTraceExitFace(const TetMesh& mesh, const TetSoS& T, int tet, const Vec3i& z, const std::array<AxisDir, 3>& d,
                      int entry);

/// Traces all four alpha links of every dart. alpha[d][3] == d marks a boundary face;
/// kUnconnected marks a failure; values <= -2 are partners in implicit cells
/// (implicitPartnerOccurrence()). Deterministic for any thread count. Throws InputError if
/// there are more darts than an int can index.
/// @p progress, if set, is called from the calling thread with the fraction done (of the
/// first chunk, a good estimate of the whole).
/// @p shareEdgeTraces walks the edge of alpha_0 once for all darts of a tet at a grid point
/// that share d1 when no tie-break on the way depends on d2, d3; the links are the same
/// either way (off: every dart traces alone, for tests).
std::vector<DartLinks> traceConnections(const TetMesh& mesh, const Transitions& tr,
                                                  const std::vector<TetSoS>& tets, const DartSet& darts,
                                                  int threads, TraceStats& stats,
                                                  const std::function<void(double)>& progress = {},
                                                  bool shareEdgeTraces = true);

} // namespace HexEx
