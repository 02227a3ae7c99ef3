#pragma once
/// @file AnnihilateStage.hh
/// @ingroup pipeline
/// Pipeline stage "annihilate/merge" (paper 4.4.1): cancels regular/anti dart pairs,
/// numbers the survivors and compacts them into a generalized map (missing partners
/// become free links), then completes partially connected quads.

#include "../Extraction/ConnectionTracing.hh"
#include "../Extraction/ExtractionReport.hh"
#include "../GMap/GMap.hh"
#include "../Postprocessing/DartAnnihilation.hh"
#include "../Postprocessing/DartReconnection.hh"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace HexEx {

/// Input of annihilateStage().
struct AnnihilateInput {
    std::vector<DartLinks>* alpha = nullptr;           ///< traced links, updated in place
    const std::vector<signed char>* sign = nullptr;    ///< +1 / -1 per dart
    bool merge = true;                                 ///< annihilate (ExtractionOptions::merge)
    long anti = 0;                                     ///< anti darts extracted (remaining if no merge)
    /// The darts (optional): removed darts at the same grid point of the same tet as the
    /// previous one, with the same heir, are then left out of AnnihilateOutput::heir.
    const DartSet* darts = nullptr;
    int threads = 1;                                   ///< worker threads for the numbering and AnnihilationRetry::threads
    AnnihilationRetry retry;                           ///< local retries of clusters left with broken hex cells
    /// Per tet, its chart component (tets joined by identity transitions), computed only
    /// when broken cells are reconnected (reconnectBrokenCells()); empty: each tet alone.
    std::function<std::vector<int>()> chart_components;
    /// Every link in @p alpha is mutual (true for connectStage()'s output, which cuts the
    /// one-sided ones): passed to annihilateDarts() as mutual_links (same result, less work).
    bool mutual_links = false;
    /// With 2 or more threads, run the phase-by-phase retry beside the first pass
    /// (AnnihilationRetry::threads): the same result, sooner on a free second core, but both
    /// runs hold their own links meanwhile (pig 1.5 seed 21: peak 371 -> 480 MB). False: one
    /// after the other, as on one thread (for callers short of memory; extractHexMesh() sets
    /// it only where budgetAllows() the kBytesPerPhasedTwinDart per dart).
    bool phased_beside = true;
};

/// Output of annihilateStage().
struct AnnihilateOutput {
    std::vector<char> alive;       ///< per dart: survived
    std::vector<int> new_index;    ///< per dart: index among the survivors, or -1
    int n_alive = 0;               ///< survivors
    long pairs = 0;                ///< annihilated regular/anti pairs
    long remaining_anti = 0;       ///< anti darts left
    AnnihilationStats stats;       ///< all counters of annihilateDarts() (with merge)
    /// (removed dart, surviving dart that inherits its h-vertex) pairs, ascending (see
    /// annihilateDarts(); one per grid point and heir if AnnihilateInput::darts is given);
    /// empty without merge.
    std::vector<std::pair<int, int>> heir;
    /// Broken cells after the annihilation and its retries, re-linked into hexes where
    /// possible (reconnectBrokenCells(); only with retries and when cells are broken).
    ReconnectionStats reconnection;
    std::vector<std::string> warnings;  ///< warnings of this stage (broken cells left unreconnected)
    std::vector<ExtractionReport::Darts::Unreconnected> unreconnected;  ///< the groups of broken cells left (ReconnectionStats::unresolved)
};

/// Annihilates (if merge) and numbers the surviving darts in order.
AnnihilateOutput annihilateStage(const AnnihilateInput& in);

/// Input of buildMapStage().
struct MapInput {
    std::vector<DartLinks> alpha;                ///< links after annihilation (consumed)
    const AnnihilateOutput* survivors = nullptr; ///< which darts survived, and their new indices
    bool repair_faces = true;                    ///< complete partially connected quads (with merge)
    int threads = 1;                             ///< worker threads (resolved, >= 1)
};

/// Output of buildMapStage().
struct MapOutput {
    GMap<3> map;                          ///< the surviving darts and their links
    long unconnected_darts = 0;           ///< missing alpha_0..alpha_2 links
    long repaired_face_connections = 0;   ///< alpha_3 links added by the face repair
    long inconsistent_faces = 0;          ///< quads whose alpha_3 links were cut (relinkInconsistentFaces())
    long relinked_faces = 0;              ///< of those, quads linked again by their vertices
    std::vector<std::string> warnings;    ///< warnings of this stage
};

/// Compacts the survivors into a generalized map (chunks in parallel; the result does not
/// depend on the thread count), repairs partial face connections and, after an
/// annihilation, re-pairs the quads it left inconsistently linked (relinkInconsistentFaces()).
MapOutput buildMapStage(MapInput&& in);

} // namespace HexEx
