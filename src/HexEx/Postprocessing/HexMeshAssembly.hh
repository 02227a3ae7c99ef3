#pragma once
/// @file HexMeshAssembly.hh
/// @ingroup pipeline
/// Builds the output mesh from the final generalized map: vertices are the
/// <alpha_1, alpha_2, alpha_3> orbits (so h-vertices that annihilation or degenerate tets
/// joined are merged), cells the <alpha_0, alpha_1, alpha_2> orbits.

#include "../Core/DefaultInitAllocator.hh"
#include "../GMap/GMap.hh"
#include "../GMap/GMapValidator.hh"
#include "../Mesh/HexMesh.hh"
#include "VertexMerging.hh"

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace HexEx {

/// Occurrences of the vertex union-find and their ranks (OccurrenceRanks.hh).
struct OccurrenceRanks;

/// Counts produced by the assembly.
struct AssemblyStats {
    long quads = 0;           ///< <alpha_0, alpha_1, alpha_3> orbits
    long boundary_quads = 0;  ///< of those, on the boundary (alpha_3 free)
    long non_hex_cells = 0;   ///< cells written as polyhedra
    long degenerate_faces = 0;  ///< faces of non-hex cells with fewer than 3 distinct vertices (left out)
    long collapsed_cells = 0;   ///< non-hex cells without any proper face (reported, not written)
    long ambiguous_vertices = 0;  ///< vertices with several distinct preimages (chooseVertexPreimages())
    /// If set by the caller, the validation whose violation examples get the output vertices
    /// of their faces (describeViolations()).
    GMapValidation* violations = nullptr;
};

/// Per-dart input of the assembly.
struct DartGeometry {
    const TetMesh* mesh = nullptr;         ///< the input tet mesh (for boundary planes)
    DartPlacement placement;               ///< positions and boundary faces per dart
    std::vector<signed char> handedness;   ///< +1 if the dart's frame (d1, d2, d3) is right-handed
};

/// Unit cells produced without darts (DartSet::implicitCell()) and how the explicit darts
/// meet them. Their corners are "occurrences": grid points in the closed image of one tet.
struct ImplicitCells {
    long n_occurrences = 0;                       ///< number of occurrence ids
    DefaultInitVector<int> dart_occurrence;            ///< per dart: occurrence of its own grid point, or -1 (empty: none has one)
    DefaultInitVector<int> alpha3_occurrence;          ///< per dart: occurrence of its implicit alpha_3 partner, or -1
    /// Pairs of occurrences that are the same grid point seen from the two tets of a shared
    /// face (one vertex).
    std::vector<std::pair<int, int>> joined_occurrences;
    long boundary_quads = 0;                      ///< faces of implicit cells on the boundary
    /// The implicit cells, each as its 8 corner occurrences in VTK order.
    DefaultInitVector<std::array<int, 8>> cells;
    /// Per implicit cell: bit f set if its face f (kHexFaces order) is the opposite face of
    /// the neighbouring implicit cell of the same tet across it (the same four occurrences,
    /// so the same four vertices): checkAssembledHexes() files such pairs once.
    std::vector<unsigned char> twin_faces;
    /// 3D position of an occurrence (used for vertices that no explicit dart touches).
    std::function<Vec3d(long)> position;
    /// Optional: the positions of @p n occurrences @p occ (ascending) into @p out, the same
    /// values as position() (one look-up of the tet per run of occurrences in one tet).
    std::function<void(const long* occ, std::size_t n, Vec3d* out)> positions;
};

/// Assembles vertices (one per <alpha_1, alpha_2, alpha_3> orbit, placed by
/// mergedVertexPositions()), hexes in VTK order (from a right-handed dart of each cell) and polyhedra
/// for every other cell. @p labels are the face, corner and cell orbits from validateHexGMap().
/// With @p implicit, vertex classes also join darts to the occurrences they sit on or link
/// to, and the implicit cells are appended as hexes.
/// @p threads lets independent labellings run side by side (the result does not depend on it).
/// If @p hex_darts is given it receives, per hex built from darts (the hexes before the
/// implicit cells), the dart at its corner 0 whose frame points to corners 1, 3 and 4.
/// If @p label_storage is given, its memory is taken over for the per-dart vertex labels
/// (e.g. a freed label array of the validator: pages already in use); it is left empty.
/// With @p implicit and @p private_vertices, the latter receives one bit per vertex (bit
/// v % 64 of word v / 64), set if vertex v is private: its class is one occurrence that no
/// dart sits on or links to and that is not joined across a face, so the only hexes with
/// corner v are the implicit cells with that corner occurrence (checkAssembledHexes() need
/// not file their twin faces). Without @p implicit it is left empty.
/// With @p implicit, @p occurrence_ranks may hold rankOccurrences() of @p g and @p implicit
/// computed before (it is taken over); if it is not filled, they are computed here.
HexMesh assembleHexMesh(const GMap<3>& g, const DartGeometry& geo, const HexOrbitLabels& labels, AssemblyStats& stats,
                        const ImplicitCells* implicit = nullptr, int threads = 1, std::vector<int>* hex_darts = nullptr,
                        std::vector<int>* label_storage = nullptr, std::vector<std::uint64_t>* private_vertices = nullptr,
                        OccurrenceRanks* occurrence_ranks = nullptr);

} // namespace HexEx
