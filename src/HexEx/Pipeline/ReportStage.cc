#include "ReportStage.hh"

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
}

void addToReport(const ConnectOutput& out, ExtractionReport& rep) { rep.darts.asymmetric_links = out.asymmetric_links; }

void addToReport(const AnnihilateOutput& out, ExtractionReport& rep) {
    rep.darts.annihilated_pairs = out.pairs;
    rep.darts.remaining_anti = out.remaining_anti;
}

void addToReport(const MapOutput& out, ExtractionReport& rep) {
    rep.output.unconnected_darts = out.unconnected_darts;
    rep.output.repaired_face_connections = out.repaired_face_connections;
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
    rep.valid_all_hex = rep.validation.valid() && out.stats.non_hex_cells == 0 && rep.darts.remaining_anti == 0;
}

} // namespace HexEx
