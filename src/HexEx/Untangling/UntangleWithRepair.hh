#pragma once
/// @file UntangleWithRepair.hh
/// The untangle-then-optimise sequence of `hexex extract --untangle/--optimize/--pillow`, as
/// one library call: untangleHexMesh(), then optimizeHexMesh(), and the pillowing repair
/// when untangling alone leaves hexes that are not certified valid.
#include <HexEx/Mesh/HexMesh.hh>
#include <HexEx/Untangling/HexOptimizer.hh>
#include <HexEx/Untangling/TriangleSurface.hh>
#include <HexEx/Untangling/Untangler.hh>
#include <string>

namespace HexEx {

/// When untangleWithRepair() inserts a boundary layer (OptimizeOptions::pillow).
enum class PillowPolicy {
    Never,     ///< never: the hexes stay as given, even if some stay invalid (`--no-pillow`)
    IfNeeded,  ///< only if untangling alone leaves hexes not certified valid (the default)
    Always,    ///< always, before optimising (`--pillow`)
};

/// What untangleWithRepair() does after untangling.
struct RepairOptions {
    UntangleOptions untangle;  ///< options of the first step, untangleHexMesh()
    OptimizeOptions optimize;  ///< options of optimizeHexMesh(); its `pillow` is set from `pillow`
    bool optimize_quality = false;             ///< run optimizeHexMesh() even if untangling succeeds (`--optimize`)
    PillowPolicy pillow = PillowPolicy::IfNeeded;  ///< see PillowPolicy
};

/// What untangleWithRepair() did.
struct RepairReport {
    UntangleReport untangle;   ///< the first step
    bool optimized = false;    ///< optimizeHexMesh() ran and its report is in `optimize`
    OptimizeReport optimize;   ///< valid if `optimized`
    /// The pillowing repair ran because untangling alone left hexes not certified valid
    /// (PillowPolicy::IfNeeded); `note` says so.
    bool repaired = false;
    /// A sentence for the user when the repair ran or was not possible; empty otherwise.
    std::string note;
};

/// Untangles @p mesh in place, boundary vertices on @p surface (null: the mesh's own
/// boundary), then, if asked or needed, optimises it. With PillowPolicy::IfNeeded, when
/// untangling leaves hexes that are invalid or undecided by the certified test
/// (classifyHexValidity()) and the mesh is all-hex, optimizeHexMesh() runs with
/// OptimizeOptions::pillow: hexes outside the surface connected to the bad ones are removed,
/// a layer of hexes is added along the boundary, and the result is untangled and optimised
/// (Documentation/algorithm.md, "Untangling falls back to pillowing"). This changes the hex
/// count; the report says by how much. If the repair is not possible (its input checks
/// fail), the untangled mesh is kept and `note` says why.
/// @throws std::invalid_argument as untangleHexMesh(), and as optimizeHexMesh() when the
/// optimisation or the layer was asked for explicitly.
RepairReport untangleWithRepair(HexMesh& mesh, const RepairOptions& options, const TriangleSurface* surface);

} // namespace HexEx
