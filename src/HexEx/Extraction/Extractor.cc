#include "../HexEx.hh"

#include "../Core/Parallel.hh"
#include "../Pipeline/AnnihilateStage.hh"
#include "../Pipeline/ArcStage.hh"
#include "../Pipeline/AssembleStage.hh"
#include "../Pipeline/ConnectStage.hh"
#include "../Pipeline/DartStage.hh"
#include "../Pipeline/ImplicitCellPath.hh"
#include "../Pipeline/PlacementStage.hh"
#include "../Pipeline/PreprocessStage.hh"
#include "../Pipeline/ReportStage.hh"

#include <chrono>
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
template <class T>
void release(std::vector<T>& v) {
    std::vector<T>().swap(v);
}
} // namespace

const char* version() { return "0.1.0"; }

// The pipeline (Documentation/algorithm.md, "Stages"): every stage is a function of
// src/HexEx/Pipeline with a plain input and output struct; its counts go into the report
// as they come.
ExtractionReport extractHexMesh(const ParametrizedTetMesh& input, HexMesh& output, const ExtractionOptions& opt) {
    ExtractionReport rep;
    const TetMesh& mesh = input.mesh;
    const int threads = resolveThreadCount(opt.threads);
    rep.threads = threads;
    auto progress = [&](const char* phase, double f) {
        if (opt.progress) opt.progress(phase, f);
    };
    StageClock clock;

    progress("preprocess", 0);
    const PreprocessOutput pre = preprocess({&input, opt.given_rotations, opt.epsilon, opt.max_hexes, threads});
    addToReport(pre, rep);
    rep.timings_s.preprocess = clock.lap();

    progress("darts", 0);
    const bool implicit = useImplicitCells(opt.implicit_cells, pre.stats.flipped_tets);
    DartStageOutput darts = extractDartStage({&mesh, &pre.tets, pre.abs_volume, implicit, threads});
    addToReport(darts, rep);
    rep.timings_s.darts = clock.lap();

    progress("connect", 0);
    ConnectOutput links = connectStage({&mesh, &pre.transitions, &pre.tets, &darts.darts, threads,
                                        [&](double f) { progress("connect", f); }});
    addToReport(links, rep);
    rep.timings_s.connect = clock.lap();

    progress("postprocess", 0);
    AnnihilateOutput survivors = annihilateStage({&links.alpha, &darts.sign, opt.merge, darts.anti});
    addToReport(survivors, rep);
    ImplicitCells cells;
    if (implicit)
        cells.alpha3_occurrence = implicitAlpha3Occurrences(links.alpha, survivors.alive, survivors.new_index, survivors.n_alive, threads);
    const MapOutput map = buildMapStage({std::move(links.alpha), &survivors, opt.merge, threads});
    addToReport(map, rep);
    rep.timings_s.postprocess = clock.lap();

    progress("vertices", 0);
    const DartGeometry geo = placementStage({&mesh, &pre.tets, &darts.darts, &survivors.alive, &survivors.new_index, survivors.n_alive, threads});
    if (implicit) {
        cells.dart_occurrence = implicitDartOccurrences(darts.darts, survivors.alive, survivors.new_index, survivors.n_alive, threads);
        buildImplicitCells(mesh, pre.transitions, pre.tets, darts.darts, threads, cells);
        addToReport(cells, rep);
    }
    rep.timings_s.vertices = clock.lap();
    // The arcs stage (optional) walks from the darts of the hexes: keep them until then.
    const bool arcs = opt.arcs != nullptr;
    std::vector<int> origin;
    if (arcs) origin = mapDartOrigins(survivors.new_index, survivors.n_alive);
    // The extracted darts are not needed any more (the implicit cells keep the dense
    // index): free them before the assembly allocates its labels (peak memory).
    if (!arcs) release(darts.darts.darts);
    release(darts.sign);
    release(survivors.alive);
    release(survivors.new_index);

    progress("assemble", 0);
    AssembleOutput assembled = assembleStage({&map.map, &geo, implicit ? &cells : nullptr, threads, arcs});
    addToReport(assembled, rep);
    output = std::move(assembled.mesh);
    rep.timings_s.assemble = clock.lap();

    if (arcs) {
        progress("arcs", 0);
        *opt.arcs = arcStage({&mesh, &pre.transitions, &pre.tets, &output, &map.map, &assembled.hex_darts, &darts.darts,
                              &origin, implicit ? &cells : nullptr, threads});
        addToReport(*opt.arcs, rep);
        rep.timings_s.arcs = clock.lap();
    }
    progress("done", 1);
    return rep;
}

} // namespace HexEx
