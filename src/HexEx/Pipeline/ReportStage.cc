#include "ReportStage.hh"

#include <algorithm>
#include <string>

namespace HexEx {

namespace {
void appendWarnings(const std::vector<std::string>& w, ExtractionReport& rep) { rep.warnings.insert(rep.warnings.end(), w.begin(), w.end()); }
} // namespace

void addToReport(const PreprocessOutput& out, ExtractionReport& rep) {
    rep.input = out.stats;
    appendWarnings(out.warnings, rep);
}

void addToReport(const DartStageOutput& out, ExtractionReport& rep) {
    rep.darts.extracted = static_cast<long>(out.darts.darts.size());
    rep.darts.anti = out.anti;
    rep.darts.cancelled_fold_points = out.darts.n_cancelled;
}

void addToReport(const ConnectOutput& out, ExtractionReport& rep) { rep.darts.asymmetric_links = out.asymmetric_links; }

void addToReport(const AnnihilateOutput& out, ExtractionReport& rep) {
    rep.darts.annihilated_pairs = out.pairs;
    rep.darts.remaining_anti = out.remaining_anti;
    rep.darts.annihilation_order = out.stats.reordered;
    rep.darts.broken_cells_after_annihilation = out.stats.broken_cells_after;
    rep.darts.reconnected_cells = out.reconnection.reconnected_cells;
    rep.darts.unreconnected_cells = out.reconnection.unresolved_cells;
    rep.darts.unreconnected = out.unreconnected;
    appendWarnings(out.warnings, rep);
}

void addToReport(const MapOutput& out, ExtractionReport& rep) {
    rep.output.unconnected_darts = out.unconnected_darts;
    rep.output.repaired_face_connections = out.repaired_face_connections;
    rep.output.relinked_faces = out.relinked_faces;
    appendWarnings(out.warnings, rep);
}

void addToReport(const ImplicitCells& cells, ExtractionReport& rep) { rep.darts.implicit_cells = static_cast<long>(cells.cells.size()); }

void addToReport(const AssembleOutput& out, ExtractionReport& rep) {
    rep.validation = out.validation;
    rep.output.vertices = static_cast<long>(out.mesh.vertices.size());
    rep.output.hexes = static_cast<long>(out.mesh.hexes.size());
    rep.output.non_hex_cells = out.stats.non_hex_cells;
    rep.output.quads = out.stats.quads;
    rep.output.boundary_quads = out.stats.boundary_quads;
    appendWarnings(out.warnings, rep);
    rep.valid_all_hex = rep.validation.valid() && out.stats.non_hex_cells == 0 && rep.darts.remaining_anti == 0 && out.mesh_agrees;
}

void addToReport(const HexArcs& arcs, ExtractionReport& rep) {
    auto& A = rep.arcs;
    A.edges = static_cast<long>(arcs.edges.size());
    A.faces = static_cast<long>(arcs.faces.size());
    A.failed_edges = static_cast<long>(arcs.failed_edges.size());
    A.failed_faces = static_cast<long>(arcs.failed_faces.size());
    const std::size_t ne = std::min(arcs.failed_edges.size(), ExtractionReport::Arcs::kMaxListed);
    const std::size_t nf = std::min(arcs.failed_faces.size(), ExtractionReport::Arcs::kMaxListed);
    A.failed_edge_ids.assign(arcs.failed_edges.begin(), arcs.failed_edges.begin() + static_cast<long>(ne));
    A.failed_face_ids.assign(arcs.failed_faces.begin(), arcs.failed_faces.begin() + static_cast<long>(nf));
    if (A.failed_edges > 0 || A.failed_faces > 0)
        rep.warnings.push_back(std::to_string(A.failed_edges) + " of " + std::to_string(A.edges) +
                               " hex edges have no arc and " + std::to_string(A.failed_faces) + " of " +
                               std::to_string(A.faces) + " hex faces have no complete patch (defective map there)");
}

} // namespace HexEx
