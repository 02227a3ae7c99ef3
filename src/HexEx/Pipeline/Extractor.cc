#include "Extractor.hh"

#include "../Core/Error.hh"
#include "../Core/Memory.hh"
#include "../Core/Parallel.hh"
#include "../Extraction/FoldCancellation.hh"
#include "AnnihilateStage.hh"
#include "ArcStage.hh"
#include "AssembleStage.hh"
#include "ConnectStage.hh"
#include "DartStage.hh"
#include "ImplicitCellPath.hh"
#include "MemoryBudget.hh"
#include "PlacementStage.hh"
#include "PreprocessStage.hh"
#include "ProvenanceStage.hh"
#include "ReportStage.hh"

#include <chrono>
#include <new>
#include <string>
#include <utility>

namespace HexEx {

namespace {
/// Wall-clock seconds between successive lap() calls.
class StageClock {
public:
    /// Seconds since construction or the previous lap.
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double s = std::chrono::duration<double>(now - t0_).count();
        t0_ = now;
        return s;
    }

private:
    std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

/// Frees a vector's memory now.
template <class Vector>
void release(Vector& v) {
    Vector().swap(v);
}
} // namespace

namespace {
/// Where the pipeline is, for the message of an allocation failure.
struct PipelineState {
    const char* stage = "preprocess";  ///< stage running now
    MemoryEstimate estimate;           ///< the memory estimate, once made
};

// The pipeline (Documentation/algorithm.md, "Stages"): every stage is a function of
// src/HexEx/Pipeline with a plain input and output struct; its counts go into the report
// as they come.
ExtractionReport runPipeline(const ParametrizedTetMesh& input, CornerParams* ownedParams, HexMesh& output,
                             const ExtractionOptions& opt, PipelineState& state, HexFaceNeighbours* faceNeighbours) {
    ExtractionReport rep;
    const TetMesh& mesh = input.mesh;
    const int threads = resolveThreadCount(opt.threads);
    rep.threads = threads;
    auto progress = [&](const char* phase, double f) {
        if (opt.progress) opt.progress(phase, f);
    };
    auto enter = [&](const char* stage) {
        state.stage = stage;
        progress(stage, 0);
    };
    StageClock clock;

    enter("preprocess");
    const PreprocessOutput pre = preprocess({&input, opt.given_rotations, opt.epsilon, opt.max_hexes, threads, ownedParams});
    addToReport(pre, rep);
    const bool implicit = useImplicitCells(opt.implicit_cells, pre.stats.flipped_tets);
    const bool cheapFolds = opt.cheap_folds && !opt.arcs;
    state.estimate = estimateMemory(pre, implicit, opt.max_memory ? opt.max_memory : defaultMemoryBudget(), cheapFolds);
    checkMemoryBudget(state.estimate);
    rep.timings_s.preprocess = clock.lap();

    enter("darts");
    DartStageOutput darts = extractDartStage({&mesh, &pre.tets, pre.abs_volume, implicit, threads, &state.estimate, &pre.transitions,
                                                   cheapFolds});
    addToReport(darts, rep);
    rep.timings_s.darts = clock.lap();

    enter("connect");
    ConnectOutput links = connectStage({&mesh, &pre.transitions, &pre.tets, &darts.darts, threads,
                                        [&](double f) { progress("connect", f); }});
    addToReport(links, rep);
    rep.timings_s.connect = clock.lap();

    enter("postprocess");
    AnnihilateInput annihilateIn{&links.alpha, &darts.sign, opt.merge, darts.anti, &darts.darts, threads, {}, {}};
    annihilateIn.retry.enabled = opt.annihilation_retries && !implicit;
    annihilateIn.mutual_links = true;  // connectStage() keeps only mutual links
    // The run beside the first pass only saves time; it holds a second copy of the links.
    annihilateIn.phased_beside =
        budgetAllows(state.estimate, kBytesPerPhasedTwinDart * static_cast<double>(darts.darts.darts.size()));
    annihilateIn.chart_components = [&]() { return identityChartComponents(mesh, pre.transitions); };
    AnnihilateOutput survivors = annihilateStage(annihilateIn);
    addToReport(survivors, rep);
    ImplicitCells cells;
    if (implicit)
        cells.alpha3_occurrence = implicitAlpha3Occurrences(links.alpha, survivors.alive, survivors.new_index, survivors.n_alive, threads);
    const MapOutput map = buildMapStage({std::move(links.alpha), &survivors, opt.merge, threads});
    addToReport(map, rep);
    rep.timings_s.postprocess = clock.lap();

    enter("vertices");
    const DartGeometry geo = placementStage({&mesh, &pre.tets, &darts.darts, &survivors.alive, &survivors.new_index, survivors.n_alive, threads, &survivors.heir});
    if (implicit) {
        cells.dart_occurrence = implicitDartOccurrences(darts.darts, survivors.alive, survivors.new_index, survivors.n_alive, threads);
        buildImplicitCells(mesh, pre.transitions, pre.tets, darts.darts, threads, cells);
        addToReport(cells, rep);
    }
    rep.timings_s.vertices = clock.lap();
    // The arcs stage (optional) walks from the darts of the hexes: keep them until then.
    const bool arcs = opt.arcs != nullptr;
    const bool provenance = opt.provenance != nullptr;
    std::vector<int> origin;
    if (arcs || provenance) origin = mapDartOrigins(survivors.new_index, survivors.n_alive);
    // The extracted darts are not needed any more (the implicit cells keep the dense
    // index): free them before the assembly allocates its labels (peak memory).
    if (!arcs && !provenance) release(darts.darts.darts);
    release(darts.sign);
    release(survivors.alive);
    release(survivors.new_index);

    enter("assemble");
    AssembleOutput assembled =
        assembleStage({&map.map, &geo, implicit ? &cells : nullptr, threads, arcs || provenance, faceNeighbours != nullptr});
    addToReport(assembled, rep);
    output = std::move(assembled.mesh);
    if (faceNeighbours) *faceNeighbours = std::move(assembled.face_neighbours);
    if (provenance)
        *opt.provenance = provenanceStage({&mesh, &pre.transitions, &pre.tets, &output, &map.map, &assembled.hex_darts,
                                           &darts.darts, &origin, implicit ? &cells : nullptr, threads});
    rep.timings_s.assemble = clock.lap();

    if (arcs) {
        enter("arcs");
        *opt.arcs = arcStage({&mesh, &pre.transitions, &pre.tets, &output, &map.map, &assembled.hex_darts, &darts.darts,
                              &origin, implicit ? &cells : nullptr, threads});
        addToReport(*opt.arcs, rep);
        rep.timings_s.arcs = clock.lap();
    }
    progress("done", 1);
    return rep;
}

/// Runs the pipeline on @p input (its parameters taken over if @p ownedParams is
/// input.params) and turns an allocation failure into a ResourceError.
ExtractionReport extractGuarded(const ParametrizedTetMesh& input, CornerParams* ownedParams, HexMesh& output,
                                const ExtractionOptions& opt, HexFaceNeighbours* faceNeighbours = nullptr) {
    PipelineState state;
    try {
        return runPipeline(input, ownedParams, output, opt, state, faceNeighbours);
    } catch (const std::bad_alloc&) {
        // Whatever failed to allocate has been freed by the unwinding: there is room for the message.
        const MemoryEstimate& est = state.estimate;
        std::string cause = std::string("out of memory (std::bad_alloc) in the ") + state.stage + " stage";
        if (est.budget > 0 || est.bytes > 0)
            cause += " (memory budget " + (est.budget ? formatBytes(static_cast<double>(est.budget)) : std::string("none")) +
                     ", estimated need " + formatBytes(est.bytes) + ")";
        throw ResourceError(memoryRefusal(cause, est.largest_tets.empty() ? nullptr : &est));
    }
}
} // namespace

ExtractionReport extractHexMesh(const ParametrizedTetMesh& input, HexMesh& output, const ExtractionOptions& opt) {
    return extractGuarded(input, nullptr, output, opt);
}

ExtractionReport extractHexMesh(ParametrizedTetMesh&& input, HexMesh& output, const ExtractionOptions& opt) {
    return extractGuarded(input, &input.params, output, opt);
}

ExtractionReport extractHexMesh(ParametrizedTetMesh&& input, HexMesh& output, const ExtractionOptions& opt,
                                HexFaceNeighbours* faceNeighbours) {
    if (faceNeighbours) *faceNeighbours = HexFaceNeighbours{};
    return extractGuarded(input, &input.params, output, opt, faceNeighbours);
}

} // namespace HexEx
