/// @file UntangleWithRepair.cc
/// untangleWithRepair(): untangle, then optimise when asked, or pillow when untangling alone
/// cannot make every hex certified valid.
#include "UntangleWithRepair.hh"

#include <stdexcept>

namespace HexEx {

RepairReport untangleWithRepair(HexMesh& mesh, const RepairOptions& options, const TriangleSurface* surface) {
    RepairReport r;
    r.untangle = untangleHexMesh(mesh, options.untangle, surface);
    const long not_certified = r.untangle.invalid_after + r.untangle.undecided_after;
    const bool explicit_run = options.optimize_quality || options.pillow == PillowPolicy::Always;
    // Untangling moves vertices only. Some tangles (a flap of hexes outside the input, a hex
    // with two faces on a flat stretch of boundary) have no valid placement with the boundary
    // on its surface; a boundary layer changes the hexes so that one exists.
    bool repair = options.pillow == PillowPolicy::IfNeeded && not_certified > 0;
    if (!explicit_run && !repair) return r;
    const std::string before = "untangling alone left " + std::to_string(not_certified) + " hexes not certified valid; ";
    if (repair && !mesh.polyhedra.empty()) {
        r.note = before + "the pillowing repair needs an all-hex mesh (the mesh has " +
                 std::to_string(mesh.polyhedra.size()) + " polyhedra)";
        repair = false;
    }
    OptimizeOptions o = options.optimize;
    o.pillow = options.pillow == PillowPolicy::Always || repair;
    if (repair) {
        try {
            r.optimize = optimizeHexMesh(mesh, o, surface);
        } catch (const std::invalid_argument& e) {
            r.note = before + "the pillowing repair was not possible: " + e.what();
            repair = false;
            o.pillow = false;
        }
    }
    if (!repair) {
        if (!explicit_run) return r;
        r.optimize = optimizeHexMesh(mesh, o, surface);
        r.optimized = true;
        return r;
    }
    r.optimized = true;
    if (!r.optimize.success) {
        r.note = before + "the pillowing repair did not succeed: " + r.optimize.message;
        return r;
    }
    r.repaired = true;
    r.note = before + "repaired as with --pillow: " + std::to_string(r.optimize.trimmed_hexes) +
             " hexes outside the surface removed, " + std::to_string(r.optimize.pillowed_hexes) +
             " hexes added along the boundary, then untangled and optimised (" +
             std::to_string(r.optimize.invalid_after) + " hexes invalid after)";
    return r;
}

} // namespace HexEx
