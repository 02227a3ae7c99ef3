#pragma once
/// @file ConnectStage.hh
/// @ingroup pipeline
/// Pipeline stage "connect" (paper 4.3.2): traces the alpha links of every dart and keeps
/// only the mutual ones.

#include "../Extraction/ConnectionTracing.hh"

#include <functional>
#include <vector>

namespace HexEx {

/// Input of connectStage().
struct ConnectInput {
    const TetMesh* mesh = nullptr;              ///< the tet mesh
    const Transitions* transitions = nullptr;   ///< transition per halfface
    const std::vector<TetSoS>* tets = nullptr;  ///< per-tet predicates
    const DartSet* darts = nullptr;             ///< the darts
    int threads = 1;                            ///< worker threads (resolved, >= 1)
    std::function<void(double)> progress;       ///< optional: fraction done
};

/// Output of connectStage().
struct ConnectOutput {
    std::vector<DartLinks> alpha;  ///< links per dart (see traceConnections()); one-sided links cut
    TraceStats trace;              ///< counters of the tracing
    long asymmetric_links = 0;     ///< links whose partner traced elsewhere (cut to kUnconnected)
};

/// Runs the stage. Deterministic for any thread count.
ConnectOutput connectStage(const ConnectInput& in);

} // namespace HexEx
