#include "AssembleStage.hh"

#include "../Postprocessing/AssembledMeshCheck.hh"
#include "../Postprocessing/OccurrenceRanks.hh"

namespace HexEx {

AssembleOutput assembleStage(const AssembleInput& in) {
    AssembleOutput out;
    // Vertices that only implicit cells of one box have, for the mesh check.
    std::vector<std::uint64_t> privateVertices;
    {
        // The orbit labels (about 20 bytes per dart) are freed before the mesh check.
        HexOrbitLabels labels;
        // The occurrences of the vertex union-find do not depend on the validation: with two
        // or more threads they are ranked beside the validator's sequential cell search.
        OccurrenceRanks ranks;
        auto rank = [&](int threads) { ranks = rankOccurrences(*in.map, *in.implicit, threads); };
        out.validation = validateHexGMap(*in.map, &labels, in.threads,
                                         in.implicit ? std::function<void(int)>(rank) : std::function<void(int)>());
        // With the darts grouped by cell (cell_offset), the assembly does not read the cell
        // label per dart: its array (4 bytes per dart) is reused for the vertex labels.
        std::vector<int> storage;
        if (!labels.cell_offset.empty()) storage.swap(labels.cell);
        out.stats.violations = &out.validation;
        out.mesh = assembleHexMesh(*in.map, *in.geometry, labels, out.stats, in.implicit, in.threads,
                                   in.want_hex_darts ? &out.hex_darts : nullptr, &storage, &privateVertices, &ranks);
        out.stats.violations = nullptr;
    }
    if (out.stats.degenerate_faces > 0)
        out.warnings.push_back(std::to_string(out.stats.degenerate_faces) +
                               " faces of non-hex cells have fewer than 3 distinct vertices and were left out of their polyhedra");
    if (out.stats.collapsed_cells > 0)
        out.warnings.push_back(std::to_string(out.stats.collapsed_cells) +
                               " non-hex cells collapsed completely (no face with 3 distinct vertices); they are counted but not written");
    if (out.validation.valid() && out.stats.non_hex_cells == 0 && out.mesh.polyhedra.empty()) {
        // The implicit cells are the last hexes; their twin faces are filed once.
        const std::size_t nImplicit = in.implicit ? in.implicit->cells.size() : 0;
        const AssembledMeshCheck check = checkAssembledHexes(out.mesh, in.threads, in.implicit ? &in.implicit->twin_faces : nullptr,
                                                             out.mesh.hexes.size() - nImplicit,
                                                             in.want_face_neighbours ? &out.face_neighbours : nullptr,
                                                             in.implicit ? &in.implicit->cells : nullptr, &privateVertices);
        out.mesh_agrees = check.agrees(out.stats.quads, out.stats.boundary_quads);
        if (!out.mesh_agrees) out.warnings.push_back(check.warning(out.stats.quads, out.stats.boundary_quads));
        // The table is handed on only for a mesh that is what the map describes.
        if (!out.mesh_agrees) out.face_neighbours = HexFaceNeighbours{};
    }
    return out;
}

} // namespace HexEx
