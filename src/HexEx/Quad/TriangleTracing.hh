#pragma once
/// @file TriangleTracing.hh
/// @ingroup quad
/// Connection tracing in 2D (paper 4.3.2 with one dimension less): alpha_0 (the other end
/// of the grid edge), alpha_1 (the other edge at the corner) and alpha_2 (the quad across
/// the edge) of every dart, traced across triangles with the same symbolic perturbation as
/// the darts.

#include "TriangleDarts.hh"

#include <array>
#include <vector>

namespace HexEx {

/// Counters of the tracing.
struct TriTraceStats {
    long unconnected = 0;  ///< links (alpha_0, alpha_1, or alpha_2 inside the surface) not found
    long asymmetric = 0;   ///< traced links whose partner traced elsewhere (dropped)
};

/// Links of the 2D map, alpha_0 .. alpha_2 per dart, sized without zeroing (the passes
/// that fill them run in parallel, so each chunk first touches its own pages).
using TriLinks = std::vector<std::array<int, 3>, DefaultInitAllocator<std::array<int, 3>>>;

/// Traces alpha_0 .. alpha_2 of every dart of @p ds. Returns links[d] = {alpha_0, alpha_1,
/// alpha_2}: a dart index, the dart itself for a free alpha_2 (the quad edge lies on the
/// surface boundary), -1 for an unconnected link. Only mutual links are kept. Runs in
/// parallel; the result does not depend on @p threads.
TriLinks traceTriConnections(const ParametrizedTriMesh& m, const TriAdjacency& adj,
                                                    const TriParams& params, const TriTransitions& tr,
                                                    const std::vector<signed char>& sign, const TriDartSet& ds,
                                                    int threads, TriTraceStats* stats = nullptr);

} // namespace HexEx
