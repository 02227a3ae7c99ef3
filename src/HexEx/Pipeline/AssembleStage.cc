#include "AssembleStage.hh"

namespace HexEx {

AssembleOutput assembleStage(const AssembleInput& in) {
    AssembleOutput out;
    HexOrbitLabels labels;
    out.validation = validateHexGMap(*in.map, &labels, in.threads);
    out.stats.violations = &out.validation;
    out.mesh = assembleHexMesh(*in.map, *in.geometry, labels, out.stats, in.implicit, in.threads,
                               in.want_hex_darts ? &out.hex_darts : nullptr);
    out.stats.violations = nullptr;
    if (out.stats.degenerate_faces > 0)
        out.warnings.push_back(std::to_string(out.stats.degenerate_faces) +
                               " faces of non-hex cells have fewer than 3 distinct vertices and were left out of their polyhedra");
    if (out.stats.collapsed_cells > 0)
        out.warnings.push_back(std::to_string(out.stats.collapsed_cells) +
                               " non-hex cells collapsed completely (no face with 3 distinct vertices); they are counted but not written");
    return out;
}

} // namespace HexEx
